#!/usr/bin/env python3
"""Prandtl's strip footing against resolution, with and without F-bar.

Runs prm/punch.prm (a smooth rigid punch B = 0.2 m wide pressed into a
weightless Tresca layer, c = 10 kPa) at three grids, h = 0.05, 0.025 and
0.0125 m (the punch's edges on grid lines), with 'MPM/Anti-locking' none
and F-bar, and prints the mean force on the plateau (t > 0.15 s) against
Prandtl's limit load (2 + pi) c B. The grid holds the nodes under the punch,
so the nodal footing is B + h wide: the table gives both ratios. With
--plot FILE (needs matplotlib) it draws the ratio to (2 + pi) c B against h.

    benchmarks/footing_study.py build/dealmpm [--plot FILE] [work folder]
    benchmarks/footing_study.py build/dealmpm --check [work folder]

About 10 min on this 2-core machine (the finest grid takes most of it).
With --check (the test program.footing_convergence, about a minute) it
runs F-bar at h = 0.05, 0.025 and 0.02 (the shipped 50 x 35) and `none`
at the two finer ones, and fails unless F-bar's error against Prandtl for
B + h falls with h to within 5 % (the issue's bound) and `none` stays
more than 5 % above it, above F-bar, at both (a locked layer carries
more than the limit load).
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

args = sys.argv[1:]
plot = args[args.index("--plot") + 1] if "--plot" in args else None
check = "--check" in args
rest = [a for i, a in enumerate(args)
        if a not in ("--plot", "--check") and (i == 0 or args[i - 1] != "--plot")]
program = os.path.abspath(rest[0])
work = rest[1] if len(rest) > 1 else tempfile.mkdtemp(prefix="footing_")
here = os.path.dirname(os.path.abspath(__file__))
scene = os.path.join(here, "..", "prm", "punch.prm")

c, B = 1e4, 0.2
prandtl = (2 + math.pi) * c * B
grids = [(20, 14), (40, 28), (50, 35)] if check else [(20, 14), (40, 28), (80, 56)]
rows = []
for nx, ny in grids:
    h = 1.0 / nx
    for anti_locking in ["none", "F-bar"]:
        if check and anti_locking == "none" and nx == 20:
            continue
        folder = os.path.join(work, f"{nx}x{ny}_{anti_locking}")
        subprocess.run([program, scene,
                        "-s", f"Grid/Cells={nx}, {ny}",
                        "-s", f"MPM/Anti-locking={anti_locking}",
                        "-s", f"Output/Directory={folder}",
                        "-s", "Output/Interval=0.005"],
                       check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(folder, "statistics.csv")) as f:
            forces = [float(r["rigid_force_y"]) for r in csv.DictReader(f)
                      if float(r["time"]) > 0.15]
        mean = sum(forces) / len(forces)
        rows.append((h, anti_locking, mean))
        print(f"h = {h:<7} {anti_locking:6} mean force {mean:8.0f} N/m  "
              f"/ (2+pi) c B {mean / prandtl:.3f}  "
              f"/ (2+pi) c (B+h) {mean / (prandtl * (B + h) / B):.3f}",
              flush=True)

if check:
    def ratio(h, anti_locking):
        return next(r[2] for r in rows if r[0] == h and r[1] == anti_locking) \
            / (prandtl * (B + h) / B)
    hs = [1.0 / g[0] for g in grids]
    errors = [abs(ratio(h, "F-bar") - 1) for h in hs]
    failures = []
    if not all(a > b for a, b in zip(errors, errors[1:])):
        failures.append(f"F-bar's error does not fall with h: {errors}")
    if errors[-1] > 0.05:
        failures.append(f"F-bar at h = {hs[-1]}: {errors[-1]:.3f} off (> 0.05)")
    for h in hs[1:]:
        if ratio(h, "none") < max(1.05, ratio(h, "F-bar")):
            failures.append(f"none at h = {h}: {ratio(h, 'none'):.3f}, "
                            "not above 1.05 and F-bar's")
    print("\n".join(failures) or "footing converges with F-bar, "
          "too high without")
    sys.exit(1 if failures else 0)

if plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for anti_locking, marker in [("none", "o"), ("F-bar", "s")]:
        hs = [r[0] for r in rows if r[1] == anti_locking]
        ratios = [r[2] / prandtl for r in rows if r[1] == anti_locking]
        ax.plot(hs, ratios, marker=marker, label=f"Anti-locking = {anti_locking}")
    hs = [1.0 / g[0] for g in grids]
    ax.plot(hs, [(B + h) / B for h in hs], "k--", lw=1,
            label="Prandtl for the nodal footing B + h")
    ax.axhline(1.0, color="k", lw=1)
    ax.set_xscale("log")
    ax.set_xlabel("cell size h (m)")
    ax.set_ylabel("mean force on the plateau / (2 + pi) c B")
    ax.set_title("Smooth strip footing on a Tresca layer (prm/punch.prm)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(plot, dpi=120)
    print("wrote", plot)
