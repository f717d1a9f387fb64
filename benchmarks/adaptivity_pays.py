#!/usr/bin/env python3
"""Adaptivity where it pays: benchmarks/cube_in_large_box_3d.prm (a cube
falling in a box 125 times its volume) on its uniform grid and on a coarse
grid refined twice where the particles are, interleaved. Prints the
answers of both (and how far apart), the wall times and their ratio, and
what a grid change costs (deal.II's refinement with p4est and the particle
transfer, dealmpm's rebuild) against a step.

    benchmarks/adaptivity_pays.py build/dealmpm [--rounds N] [--small]
                                  [--check] [work folder]

--small: 40^3 cells against 10^3 refined twice, to t = 0.4 s (seconds).
--check (the test verification.adaptivity_pays, with --small): fails
unless every measure of the adaptive run is within 1 % of the uniform
grid's (the time of the peak within one output interval) on fewer cells.
Wall times are reported, never checked.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

args = sys.argv[1:]
check = "--check" in args
small = "--small" in args
rounds = int(args[args.index("--rounds") + 1]) if "--rounds" in args else 1
rest = [a for i, a in enumerate(args)
        if not a.startswith("--") and (i == 0 or args[i - 1] != "--rounds")]
dealmpm = rest[0]
work = rest[1] if len(rest) > 1 else tempfile.mkdtemp()
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "benchmarks", "cube_in_large_box_3d.prm")

n = 10 if small else 20
GRIDS = {
    "uniform": ["Grid/Cells=%d,%d,%d" % ((4 * n,) * 3)],
    "adaptive": ["Grid/Cells=%d,%d,%d" % ((n,) * 3), "Adaptivity/Criteria=particles",
                 "Adaptivity/Maximum level=2"],
}
COMMON = ["Output/Progress interval=0"] + (["Time/End time=0.4"] if small else [])
INTERVAL = 0.005


def timer_row(out, name):
    m = re.search(r"\| %s\s*\|\s*(\d+)\s*\|\s*([0-9.e+-]+)s" % re.escape(name), out)
    return (int(m.group(1)), float(m.group(2))) if m else (0, 0.0)


def run(grid, k):
    folder = os.path.join(work, "%s_%d" % (grid, k))
    command = [dealmpm, scene, "-s", "Output/Directory=" + folder]
    for s in COMMON + GRIDS[grid]:
        command += ["-s", s]
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit("%s grid failed: %s" % (grid, done.stderr.strip()[-300:]))
    out = done.stdout
    with open(os.path.join(folder, "statistics.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    now = re.search(r"\((\d+) cells now\)", out)
    result = {
        "wall": wall,
        "set-up": float(re.search(r"set-up took ([0-9.]+) s", out).group(1)),
        "steps": int(re.search(r"(\d+) steps to", out).group(1)),
        "cells": int(re.search(r"(\d+) cells,", out).group(1)),
        "cells at the end": int(now.group(1)) if now else None,
        "memory": int(re.search(r"peak memory (\d+) MB", out).group(1)),
        "timing total": float(re.search(
            r"Total wallclock time elapsed since start\s*\|\s*([0-9.e+-]+)s", out).group(1)),
    }
    for row in ("grid change", "grid change: deal.II and p4est",
                "grid change: rebuild", "adaptivity: criteria", "output"):
        result[row] = timer_row(out, row)
    peak = max(rows, key=lambda r: r["strain_energy"])
    result["measures"] = {
        "peak strain energy (J)": peak["strain_energy"],
        "time of the peak (s)": peak["time"],
        "largest downward momentum (kg m/s)": -min(r["momentum_z"] for r in rows),
        "largest upward momentum (kg m/s)": max(r["momentum_z"] for r in rows),
        "smallest J": min(r["min_J"] for r in rows),
    }
    return result


results = {grid: [] for grid in GRIDS}
for k in range(rounds):
    for grid in GRIDS:
        results[grid].append(run(grid, k))

uniform, adaptive = results["uniform"][0], results["adaptive"][0]
print("| measure | uniform | adaptive | difference |")
print("|---|---|---|---|")
failures = []
for name, u in uniform["measures"].items():
    a = adaptive["measures"][name]
    difference = (a - u) / abs(u)
    print("| %s | %.6g | %.6g | %+.3f %% |" % (name, u, a, 100 * difference))
    allowed = INTERVAL * 1.01 if name.startswith("time") else 0.01 * abs(u)
    if abs(a - u) > allowed:
        failures.append("%s: adaptive %.6g, uniform %.6g" % (name, a, u))
if adaptive["cells"] >= uniform["cells"]:
    failures.append("adaptive grid of %d cells, uniform %d" % (adaptive["cells"], uniform["cells"]))

print()
print("| round | grid | cells at the start, end | steps | set-up s | wall s | wall / uniform | peak MB |")
print("|---|---|---|---|---|---|---|---|")
for k in range(rounds):
    for grid in GRIDS:
        r = results[grid][k]
        end = r["cells at the end"] or r["cells"]
        print("| %d | %s | %d, %d | %d | %.2f | %.2f | %.2f | %d |" % (
            k + 1, grid, r["cells"], end, r["steps"], r["set-up"], r["wall"],
            r["wall"] / results["uniform"][k]["wall"], r["memory"]))

print()
print("| round | grid changes | ms each | deal.II and p4est | rebuild | in steps | criteria calls | ms each |")
print("|---|---|---|---|---|---|---|---|")
for k in range(rounds):
    r = results["adaptive"][k]
    changes, change = r["grid change"]
    calls, criteria = r["adaptivity: criteria"]
    step = (r["timing total"] - change - criteria - r["output"][1]) / r["steps"]
    if changes:
        print("| %d | %d | %.1f | %.1f | %.1f | %.1f | %d | %.2f |" % (
            k + 1, changes, 1e3 * change / changes,
            1e3 * r["grid change: deal.II and p4est"][1] / changes,
            1e3 * r["grid change: rebuild"][1] / changes, change / changes / step,
            calls, 1e3 * criteria / max(calls, 1)))
if check:
    for f in failures:
        print("FAIL: " + f)
    sys.exit(1 if failures else 0)
