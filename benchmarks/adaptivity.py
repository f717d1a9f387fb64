#!/usr/bin/env python3
"""Adaptive against uniform grids: each case runs on its coarse grid, on
the grid one refinement finer everywhere, and on the coarse grid refined
one level where the particles are ('Adaptivity/Criteria = particles', a
buffer of one cell, every 20 steps), with particles split and without. Prints a markdown table of each
case's measure, its error against the fine grid's (and the exact value
where there is one), the cells (the largest number during the run for the
adaptive grid) and the wall time.

    benchmarks/adaptivity.py build/dealmpm [work folder] [--check]

With --check (the test verification.adaptivity) it fails unless every
adaptive run (particles split) is within its case's tolerance of the fine
grid's answer on fewer cells than the fine grid (wall times are reported,
never checked).
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

check = "--check" in sys.argv
arguments = [a for a in sys.argv[1:] if a != "--check"]
dealmpm = arguments[0]
work = arguments[1] if len(arguments) > 1 else tempfile.mkdtemp()
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

ADAPTIVE = ["Adaptivity/Criteria=particles", "Adaptivity/Maximum level=1",
            "Adaptivity/Steps between adaptations=20"]


def run(name, scene, settings):
    folder = os.path.join(work, name)
    args = [dealmpm, os.path.join(root, scene), "-s", "Output/Directory=" + folder,
            "-s", "Output/Write particles=false", "-s", "Output/Particle CSV=false",
            "-s", "Output/Progress interval=0"]
    for s in settings:
        args += ["-s", s]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        return done.stderr.strip().splitlines()[-1][:160], 0, 0
    out = done.stdout
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
     "Grid/Global refinements=1", column_energy, 1603.9, 0.001),
    # The cantilever under self-weight, updated Lagrangian with CPDI (the
    # kernel that holds it there): the beam's largest sag.
    ("cantilever, CPDI (largest drop of the centre of mass, m)",
     "prm/hard-cases/cantilever.prm",
     ["MPM/Formulation=updated Lagrangian", "MPM/Shape function=CPDI", "Time/End time=1.2",
      "Output/Interval=0.01"],
     "Grid/Global refinements=1", largest_drop, None, 0.03),
    # A block dropped onto the floor: the strain energy of the impact.
    ("block impact, cpGIMP (peak strain energy, J)", "benchmarks/block_impact_2d.prm",
     ["MPM/Shape function=cpGIMP"],
     "Grid/Global refinements=1", peak_strain_energy, None, 0.005),
    # The cube dropped in 3D (prm/cube_drop_3d.prm, 0.3 s: the impact),
    # MUSL with linear shape functions: the peak strain energy.
    ("cube drop 3D (peak strain energy, J)", "prm/cube_drop_3d.prm",
     ["Time/End time=0.3", "Output/Interval=0.005"],
     "Grid/Global refinements=1", peak_strain_energy, None, 0.005),
]

print("| case | grid | measure | vs fine | vs exact | cells | wall s |")
print("|---|---|---|---|---|---|---|")
failures = []
for title, scene, base, finer, measure, exact, tolerance in CASES:
    results = {}
    for grid, extra in (("coarse", []), ("fine", [finer]), ("adaptive", ADAPTIVE),
                        ("adaptive, no split", ADAPTIVE + ["Adaptivity/Split particles=false"])):
        rows, cells, wall = run(re.sub(r"\W+", "_", title + " " + grid), scene, base + extra)
        results[grid] = (measure(rows) if cells else rows, cells, wall)
    fine = results["fine"][0]
    for grid in results:
        value, cells, wall = results[grid]
        if not cells:
            print("| %s | %s | %s | | | | |" % (title, grid, value))
            continue
        vs_exact = "%.2f %%" % (100 * (value - exact) / exact) if exact else ""
        print("| %s | %s | %.6g | %+.2f %% | %s | %d (%.0f %%) | %.2f (%.0f %%) |" % (
            title, grid, value, 100 * (value - fine) / fine, vs_exact,
            cells, 100 * cells / results["fine"][1], wall, 100 * wall / results["fine"][2]))
    adaptive, fine_result = results["adaptive"], results["fine"]
    if not adaptive[1] or abs(adaptive[0] - fine) > tolerance * abs(fine) \
            or adaptive[1] >= fine_result[1]:
        failures.append("%s: adaptive %s (%s cells) vs fine %s (%d cells), tolerance %g"
                        % (title, adaptive[0], adaptive[1], fine, fine_result[1], tolerance))
if check:
    for f in failures:
        print("FAIL: " + f)
    sys.exit(1 if failures else 0)
