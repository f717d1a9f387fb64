#!/usr/bin/python3
"""The cost of an FEM region per cell and step (issue 34, item 6).

    benchmarks/fem_region_cost.py build/dealmpm [other/dealmpm ...] [--repeats N]

A neo-Hookean block under gravity, fixed at its bottom, alone in a coarse
background grid (one resting particle block beside it, which the program
needs): 200 x 200 Q1 cells in 2D, 32^3 in 3D, and Q2 on as many nodes
(100 x 100, 16^3). Microseconds per cell and step: the timer table's total
without its output row, over the steps and the region's cells; everything
a step does for the region (its force loop, its update, the time step's
rate) and the tiny rest. Best of N runs (default 3), the binaries
interleaved, so that a comparison on a shared machine holds.
"""
import argparse
import os
import re
import subprocess
import tempfile

SCENE = """set Dimension             = {dim}
set Number of FEM regions = 1
set Effects               = gravity
subsection Gravity
  set Acceleration = {gravity}
end
subsection Grid
  set Upper corner = {grid}
  set Cells        = {grid_cells}
end
subsection Material 1
  set Model   = neo-Hookean
  set Density = 1000
  subsection neo-Hookean
    set Young's modulus = 1e7
  end
end
subsection FEM region 1
  set Upper corner     = {region}
  set Cells            = {cells}
  set Degree           = {degree}
  set Fixed boundaries = {bottom}
end
subsection Body 1
  set Lower corner = {body_low}
  set Upper corner = {body_high}
end
subsection Time
  set End time = {end}
end
subsection Output
  set Directory         = {out}
  set Interval          = 1
  set Write particles   = false
  set Progress interval = 0
end
"""


def scene(dim, n, degree, folder):
    """The block of n^dim cells of degree @p degree in @p folder."""
    path = os.path.join(folder, f"region_{dim}d_q{degree}.prm")
    ones = ", ".join(["1"] * dim)
    with open(path, "w") as f:
        f.write(SCENE.format(
            dim=dim, degree=degree, cells=", ".join([str(n)] * dim),
            gravity=", ".join(["0"] * (dim - 1) + ["-9.81"]),
            grid=", ".join(["1.2"] * dim), grid_cells=", ".join(["2"] * dim),
            region=ones, bottom=2 * (dim - 1),
            body_low=", ".join(["0.6"] * (dim - 1) + ["1.02"]),
            body_high=", ".join(["0.9"] * (dim - 1) + ["1.2"]),
            end=4e-3 if dim == 2 else 6e-3,
            out=os.path.join(folder, "out")))
    return path, n ** dim


def microseconds_per_cell_step(dealmpm, path, cells):
    out = subprocess.run([dealmpm, path], capture_output=True, text=True,
                         check=True).stdout
    total = float(re.search(r"Total wallclock time elapsed since start\s*\|"
                            r"\s*([\d.e+-]+)s", out).group(1))
    output = re.search(r"\| output\s*\|\s*\d+\s*\|\s*([\d.e+-]+)s", out)
    steps = int(re.search(r"(\d+) steps to", out).group(1))
    return (total - (float(output.group(1)) if output else 0)) / steps / \
        cells * 1e6


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("binaries", nargs="+", help="dealmpm programs")
    parser.add_argument("--repeats", type=int, default=3)
    options = parser.parse_args()
    args, repeats = options.binaries, options.repeats
    with tempfile.TemporaryDirectory() as folder:
        cases = [(2, 200, 1), (3, 32, 1), (2, 100, 2), (3, 16, 2)]
        scenes = [(case, *scene(*case, folder)) for case in cases]
        best = {}
        for _ in range(repeats):
            for case, path, cells in scenes:
                for binary in args:
                    t = microseconds_per_cell_step(binary, path, cells)
                    key = (case, binary)
                    best[key] = min(best.get(key, t), t)
        print("| region | " + " | ".join(args) + " |")
        print("|---|" + "---|" * len(args))
        for (dim, n, degree), _, cells in scenes:
            row = [f"{best[((dim, n, degree), b)]:.3f}" for b in args]
            print(f"| {dim}D Q{degree}, {cells} cells | " + " | ".join(row)
                  + " |")


if __name__ == "__main__":
    main()
