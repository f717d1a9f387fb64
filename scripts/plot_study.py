#!/usr/bin/python3
"""Plots of a dealmpm study: plot_study.py study.csv folder

study.png/.svg: error against wall time (log-log), one marker per shape
function, one colour per stress update, the Pareto front drawn.
convergence.png/.svg: error against cell size for each setting with two or
more refinements, the observed rate between the two finest in the legend.
rates.md: those errors and observed rates as a table.
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"linear": "o", "uGIMP": "s", "cpGIMP": "D", "CPDI": "^",
           "quadratic B-spline": "v"}
COLOURS = {"USL": "tab:blue", "USF": "tab:green", "MUSL": "tab:red"}


def number(text):
    try:
        value = float(text)
        return value if math.isfinite(value) else None
    except ValueError:
        return None


def main(study_csv, folder):
    with open(study_csv, newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    done = [r for r in rows if r["status"] == "ok"
            and number(r["error_L2"]) and number(r["wall_time"])]
    if not done:
        print("no finished runs with an error norm to plot")
        return

    # Error against wall time.
    fig, ax = plt.subplots(figsize=(9.5, 5.5))
    seen = set()
    for r in done:
        kernel, scheme = kernel_label(r), r["stress_update"]
        label = f"{kernel}, {scheme}"
        ax.loglog(number(r["wall_time"]), number(r["error_L2"]),
                  **marker_style(r),
                  color=COLOURS.get(scheme, "black"), linestyle="none",
                  markersize=7, alpha=0.85,
                  label=None if label in seen else label)
        seen.add(label)
    front = sorted((number(r["wall_time"]), number(r["error_L2"]))
                   for r in done if r["pareto_optimal"] == "1")
    if front:
        ax.step([p[0] for p in front], [p[1] for p in front], where="post",
                color="gray", linewidth=1.2, label="Pareto front")
    ax.set_xlabel("wall time of the run [s] (one core)")
    ax.set_ylabel("L2 displacement error")
    ax.set_title("Accuracy against cost")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(f"{folder}/study.{ext}", dpi=120)
    plt.close(fig)

    # Convergence: error against h per setting.
    groups = defaultdict(list)
    styles = {}
    for r in done:
        key = (kernel_label(r), r["stress_update"], r["velocity_update"],
               r["particles_per_cell"], r["cfl_number"])
        groups[key].append((number(r["h"]), number(r["error_L2"])))
        styles[key] = marker_style(r)
    fig, ax = plt.subplots(figsize=(11, 6))
    for key, points in sorted(groups.items()):
        points.sort()
        if len(points) < 2:
            continue
        (h1, e1), (h2, e2) = points[0], points[1]
        rate = math.log(e2 / e1) / math.log(h2 / h1)
        kernel, scheme, velocity, ppc, cfl = key
        ax.loglog([p[0] for p in points], [p[1] for p in points],
                  **styles[key],
                  color=COLOURS.get(scheme, "black"),
                  label=f"{kernel}, {scheme}, {velocity}, {ppc} ppc, "
                        f"CFL {cfl}: rate {rate:.2f}")
    write_rates(groups, f"{folder}/rates.md")
    ax.set_xlabel("cell size h")
    ax.set_ylabel("L2 displacement error")
    ax.set_title("Convergence (rate between the two finest grids)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1))
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(f"{folder}/convergence.{ext}", dpi=120)
    plt.close(fig)


def kernel_label(r):
    """The shape function, marked TL for total-Lagrangian runs and
    "adaptive" for runs on an adaptive grid (studies written before those
    axes have no such columns)."""
    total = r.get("formulation") == "total Lagrangian"
    adaptive = r.get("adaptivity") == "on"
    return ("TL " if total else "") + r["shape_function"] + (" adaptive" if adaptive else "")


def marker_style(r):
    """The shape function's marker, hollow for total-Lagrangian runs, with
    a thick black edge on an adaptive grid."""
    total = r.get("formulation") == "total Lagrangian"
    style = dict(marker=MARKERS.get(r["shape_function"], "x"),
                 fillstyle="none" if total else "full")
    if r.get("adaptivity") == "on":
        style.update(markeredgecolor="black", markeredgewidth=1.8)
    return style


def write_rates(groups, path):
    """Errors from coarse to fine and the rate of each refinement step."""
    sizes = sorted({h for points in groups.values() for h, _ in points},
                   reverse=True)
    with open(path, "w") as out:
        out.write("| shape function | stress | velocity | ppc | CFL | "
                  + " | ".join(f"h = {h:.4g}" for h in sizes)
                  + " | rates (coarse to fine) |\n")
        out.write("|---" * (6 + len(sizes)) + "|\n")
        for key, points in sorted(groups.items()):
            error = dict(points)
            row = [f"{error[h]:.3g}" if h in error else "" for h in sizes]
            known = sorted(points, reverse=True)
            rates = [math.log(e1 / e2) / math.log(h1 / h2)
                     for (h1, e1), (h2, e2) in zip(known, known[1:])]
            out.write("| " + " | ".join(key) + " | " + " | ".join(row)
                      + " | " + ", ".join(f"{r:.2f}" for r in rates)
                      + " |\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_study.py study.csv folder")
    main(sys.argv[1], sys.argv[2])
