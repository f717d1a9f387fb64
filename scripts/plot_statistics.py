#!/usr/bin/env python3
"""Plot a run's statistics.csv (python3 and matplotlib).

    plot_statistics.py OUTPUT/statistics.csv                # energies and balance
    plot_statistics.py OUTPUT/statistics.csv --y rigid_force_y --x=-rigid_displacement_y
    plot_statistics.py OUTPUT/statistics.csv --y kinetic_energy,strain_energy -o energies.png

Without --y: the energies against time (kinetic, strain, gravitational
relative to the start, dissipated work, external work, total), and the
balance (energy drift, momentum drift, mass loss) below. With --y: those
columns (comma-separated) against --x (default: time). A column name with
a leading '-' is plotted negated (a force or a displacement pointing
down). Writes OUTPUT/statistics.png (or -o FILE: .png, .svg or .pdf) and
prints its path.
"""
import argparse
import csv
import os
import sys

ENERGIES = ["kinetic_energy", "strain_energy", "gravitational_energy",
            "dissipated_work", "external_work", "total_energy"]
BALANCE = ["energy_drift", "momentum_drift", "mass_loss"]


def read_columns(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        raise ValueError(f"{path}: no rows below the header")
    header = [h.strip() for h in rows[0]]
    columns = {h: [] for h in header}
    for row in rows[1:]:
        if len(row) != len(header):
            continue  # a row cut by a stopped run
        for name, value in zip(header, row):
            try:
                columns[name].append(float(value))
            except ValueError:
                columns[name].append(float("nan"))
    return columns


def column(columns, name, path):
    sign = -1.0 if name.startswith("-") else 1.0
    key = name.lstrip("-")
    if key not in columns:
        raise ValueError(f"{path}: no column '{key}' (the columns: "
                         f"{', '.join(columns)})")
    return [sign * v for v in columns[key]], name


def plot(columns, args, plt):
    if args.y:
        figure, axis = plt.subplots(figsize=(8, 5))
        x, x_label = column(columns, args.x, args.csv)
        for name in args.y.split(","):
            y, label = column(columns, name.strip(), args.csv)
            axis.plot(x, y, label=label)
        axis.set_xlabel(x_label)
        axis.legend()
        axis.grid(True, alpha=0.3)
        return figure
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    time, _ = column(columns, "time", args.csv)
    for name in ENERGIES:
        if name in columns:
            values = columns[name]
            if name == "gravitational_energy":
                values = [v - values[0] for v in values]
                name += " - start"
            top.plot(time, values, label=name)
    top.set_ylabel("J (per unit thickness in 2D)")
    top.legend(fontsize="small")
    top.grid(True, alpha=0.3)
    for name in BALANCE:
        if name in columns:
            bottom.plot(time, columns[name], label=name)
    bottom.set_xlabel("time")
    bottom.set_ylabel("fraction")
    bottom.legend(fontsize="small")
    bottom.grid(True, alpha=0.3)
    return figure


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", help="a run's statistics.csv")
    parser.add_argument("--x", default="time", help="the column along x")
    parser.add_argument("--y", default="",
                        help="comma-separated columns to plot against x")
    parser.add_argument("-o", "--output", default="",
                        help="the picture (default: statistics.png beside "
                             "the csv)")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        # Debian's matplotlib belongs to the system python; a python3 found
        # earlier on PATH (pyenv, a virtualenv) may lack it.
        system = "/usr/bin/python3"
        if os.path.realpath(sys.executable) != os.path.realpath(system) and \
                os.access(system, os.X_OK):
            os.execv(system, [system] + sys.argv)
        print("plot_statistics.py: error: needs matplotlib (Debian: "
              "apt-get install python3-matplotlib)", file=sys.stderr)
        return 2
    try:
        columns = read_columns(args.csv)
        figure = plot(columns, args, plt)
    except (OSError, ValueError) as e:
        print(f"plot_statistics.py: error: {e}", file=sys.stderr)
        return 2
    output = args.output or os.path.join(os.path.dirname(args.csv) or ".",
                                         "statistics.png")
    figure.suptitle(os.path.dirname(os.path.abspath(args.csv)))
    figure.tight_layout()
    figure.savefig(output, dpi=100)
    print(output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
