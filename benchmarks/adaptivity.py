#!/usr/bin/env python3
"""Adaptive against uniform grids: each case runs on its coarse grid, on
the grid one refinement finer everywhere, and on the coarse grid refined
one level where the particles are ('Adaptivity/Criteria = particles', a
buffer of one cell, particles split). Prints a markdown table of each
case's measure, its error against the fine grid's (and the exact value
where there is one), the cells (the largest number during the run for the
adaptive grid) and the wall time.

    benchmarks/adaptivity.py build/dealmpm [work folder]
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

dealmpm = sys.argv[1]
work = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp()
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

ADAPTIVE = ["Adaptivity/Criteria=particles", "Adaptivity/Maximum level=1",
            "Adaptivity/Steps between adaptations=10"]


def run(name, scene, settings):
    folder = os.path.join(work, name)
    args = [dealmpm, os.path.join(root, scene), "-s", "Output/Directory=" + folder,
            "-s", "Output/Write particles=false", "-s", "Output/Progress interval=0"]
    for s in settings:
        args += ["-s", s]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    with open(os.path.join(folder, "statistics.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    cells = int(re.search(r"(\d+) cells,", out).group(1))
    now = re.search(r"\((\d+) cells now\)", out)
    timer = re.search(r"Total wallclock time elapsed since start\s*\|\s*([0-9.e+-]+)s", out)
    return rows, max(cells, int(now.group(1)) if now else 0), float(timer.group(1))


def column_energy(rows):
    return rows[-1]["strain_energy"]


def largest_drop(rows):
    """The centre of mass's largest drop (m): (E_g(0) - min E_g) / (M g)."""
    g = 10.0
    return (rows[0]["gravitational_energy"] - min(r["gravitational_energy"] for r in rows)) / (rows[0]["mass"] * g)


def peak_strain_energy(rows):
    return max(r["strain_energy"] for r in rows)


CASES = [
    # The elastic column settling, in a grid 6 m taller than the column:
    # W = (rho g)^2 H^3 / (6 E) = 1603.9 J exactly.
    ("column (settled strain energy, J)", "prm/elastic_column_2d.prm",
     ["Grid/Upper corner=1, 16", "Grid/Cells=2, 32", "MPM/Shape function=cpGIMP"],
     "Grid/Global refinements=1", column_energy, 1603.9),
    # The cantilever under self-weight, updated Lagrangian with CPDI (the
    # kernel that holds it there): the beam's largest sag.
    ("cantilever, CPDI (largest drop of the centre of mass, m)",
     "prm/hard-cases/cantilever.prm",
     ["MPM/Formulation=updated Lagrangian", "MPM/Shape function=CPDI", "Time/End time=1.5",
      "Output/Interval=0.01"],
     "Grid/Global refinements=1", largest_drop, None),
    # A block dropped onto the floor (examples/custom_refinement.prm's
    # scene): the strain energy of the impact.
    ("block impact, cpGIMP (peak strain energy, J)", "examples/custom_refinement.prm",
     ["Adaptivity/Criteria=", "MPM/Shape function=cpGIMP", "Time/End time=0.4",
      "Output/Interval=0.002"],
     "Grid/Global refinements=1", peak_strain_energy, None),
]

print("| case | grid | measure | vs fine | vs exact | cells | wall s |")
print("|---|---|---|---|---|---|---|")
for title, scene, base, finer, measure, exact in CASES:
    results = {}
    for grid, extra in (("coarse", []), ("fine", [finer]), ("adaptive", ADAPTIVE)):
        rows, cells, wall = run(re.sub(r"\W+", "_", title)[:20] + "_" + grid, scene, base + extra)
        results[grid] = (measure(rows), cells, wall)
    fine = results["fine"][0]
    for grid in ("coarse", "fine", "adaptive"):
        value, cells, wall = results[grid]
        vs_exact = "%.2f %%" % (100 * (value - exact) / exact) if exact else ""
        print("| %s | %s | %.6g | %+.2f %% | %s | %d (%.0f %%) | %.2f (%.0f %%) |" % (
            title, grid, value, 100 * (value - fine) / fine, vs_exact,
            cells, 100 * cells / results["fine"][1], wall, 100 * wall / results["fine"][2]))
