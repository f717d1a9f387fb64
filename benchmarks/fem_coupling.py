#!/usr/bin/python3
"""FEM regions coupled to MPM (issue 15): cost and accuracy against cost.

    benchmarks/fem_coupling.py build/dealmpm [work folder] [--repeats N]

Writes into benchmarks/fem-coupling/ (beside this script):

1. cost.csv, cost.md: the cost per step of FE regions and of their coupling
   against MPM alone, best of N runs (default 3, interleaved):
   - prm/fem_incline.prm (an MPM block on an FE base, frictional contact)
     against the same block on a slip floor at the same height (no region:
     the grid moved up by the base's 0.1 m, the same 48 x 12 cells, its
     bottom a slip wall), with and without 'boundary friction' mu = 0.2;
   - prm/bonded_bar.prm (left half FE, bonded to the right half, MPM)
     against the all-MPM bar (the body on [0, 1], no region, a no-slip wall
     at x = 0).
   Microseconds per step: the whole run (timing table's total / steps),
   the step's stages (all sections but output), and each stage.
2. study.csv, study.md, study.svg, study.png: the bonded bar's accuracy
   against its cost over grid resolutions (RESOLUTIONS below: cells along
   x on [0, 1.2]; the region's node spacing equal to the background cells',
   the time step scaled with the cells: CFL 0.4)
   for (a) the bonded bar, (b) the all-MPM bar, (c) the bar all FE (a
   region on [0, 1] fixed at x = 0; the program needs one body, so a
   resting MPM block 0.1 x 0.025 sits at x = 1.1 .. 1.2, touching nothing).
   Errors against the exact solution (prm/bonded_bar.prm's header):
   |momentum_x(0.2) + 2.5e-4| / 2.5e-4, the worst |energy_drift| over the
   run, |strain_energy(0.1) - 1.25e-6| / 1.25e-6. Cost: the wall time of
   the run without its 'output' row (the FE region writes its .vtu series
   at every output and cannot be switched off, the particles' output is
   off; the total is in study.csv as well), best of N runs.

Runs one process at a time; run it under nice on a shared machine.
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
OUT = os.path.join(HERE, "fem-coupling")

QUIET = ["Output/Write particles=false", "Output/Particle CSV=false",
         "Output/Progress interval=0"]

P_END, E_TOTAL = -2.5e-4, 1.25e-6     # bonded_bar.prm's header: exact values


def without_regions(scene, work, name):
    """A copy of @p scene in @p work without its 'FEM region N' sections
    and with 'Number of FEM regions = 0' (the program refuses a section
    beyond the count, so -s alone cannot remove a region)."""
    lines, depth, skipping = [], 0, False
    with open(os.path.join(ROOT, scene)) as f:
        for line in f:
            code = line.split("#")[0].strip()
            if not skipping and re.match(r"subsection\s+FEM region\s+\d+$", code):
                skipping, depth = True, 0
            if skipping:
                if code.startswith("subsection"):
                    depth += 1
                elif code == "end":
                    depth -= 1
                    if depth == 0:
                        skipping = False
                continue
            if re.match(r"set\s+Number of FEM regions\s*=", code):
                line = "set Number of FEM regions = 0\n"
            lines.append(line)
    path = os.path.join(work, name + ".prm")
    with open(path, "w") as f:
        f.writelines(lines)
    return path


def run(dealmpm, scene, settings, folder):
    """Runs a scene; returns a dict with the statistics rows, the timing
    table ({section: (calls, seconds)}), the total wall time, steps,
    particles, grid cells and the exit code, or None if it did not finish
    (the reason printed)."""
    args = ["nice", dealmpm, scene, "-s", "Output/Directory=" + folder]
    for s in QUIET + settings:
        args += ["-s", s]
    done = subprocess.run(args, capture_output=True, text=True)
    out = done.stdout
    total = re.search(r"Total wallclock time elapsed since start\s*\|\s*([0-9.e+-]+)s", out)
    steps = re.search(r"(\d+) steps to t = ", out)
    if not total or not steps:
        err = [l for l in done.stderr.splitlines() if l.strip()] or ["no message"]
        stopped = [l for l in err if l.startswith("dealmpm: stopped:")]
        reason = (stopped or err)[0].replace("dealmpm: ", "")
        reason = re.sub(r"particle \d+ at \(([^)]*)\): deformation gradient with J <= 0.*",
                        r"J <= 0 at (\1)", reason)[:120]
        try:
            with open(os.path.join(folder, "statistics.csv")) as f:
                last = list(csv.DictReader(f))[-1]["time"]
            reason += "; statistics end at t = %.4g" % float(last)
        except (OSError, IndexError):
            pass
        print("  failed (exit %d): %s" % (done.returncode, reason), file=sys.stderr)
        return dict(failed="exit %d: %s" % (done.returncode, reason))
    sections = {}
    for name, calls, seconds in re.findall(
            r"^\|\s*([^|]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.e+-]+)s\s*\|", out, re.M):
        sections[name] = (int(calls), float(seconds))
    with open(os.path.join(folder, "statistics.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    head = re.search(r"(\d+) cells, \d+ nodes, (\d+) particles", out)
    if done.returncode != 0:
        err = [l for l in done.stderr.splitlines() if l.strip()]
        print("  note: finished but exit code %d (%s)" % (done.returncode, err[0][:100] if err else ""),
              file=sys.stderr)
    return dict(rows=rows, sections=sections, total=float(total.group(1)),
                steps=int(steps.group(1)), cells=int(head.group(1)),
                particles=int(head.group(2)), rc=done.returncode)


def step_seconds(r):
    """The step's own time: every timed section but output."""
    return sum(s for name, (_, s) in r["sections"].items() if name != "output")


def best(dealmpm, cases, repeats, work, key):
    """Runs every case @p repeats times, interleaved; keeps each case's run
    with the smallest key(run)."""
    kept = {}
    for k in range(repeats):
        for name, scene, settings in cases:
            print("run %d/%d: %s" % (k + 1, repeats, name), file=sys.stderr, flush=True)
            r = run(dealmpm, scene, settings, os.path.join(work, re.sub(r"\W+", "_", name)))
            if "failed" in r:
                kept.setdefault(name, r)
            elif "failed" in kept.get(name, {"failed": 1}) or key(r) < key(kept[name]):
                kept[name] = r
    return kept


def at(rows, t):
    return min(rows, key=lambda r: abs(r["time"] - t))


# ---------------------------------------------------------------- part 1

def cost_part(dealmpm, work, repeats):
    incline_mpm = without_regions("prm/fem_incline.prm", work, "incline_no_region")
    bar_mpm = without_regions("prm/bonded_bar.prm", work, "bar_all_mpm")
    floor = ["Grid/Lower corner=0, 0.1", "Grid/Upper corner=1.2, 0.4",
             "Grid/Cells=48, 12", "Grid/Boundary conditions=2: slip"]
    cases = [
        ("incline: FE base 48 x 4 Q1, contact mu = 0.2", os.path.join(ROOT, "prm/fem_incline.prm"), []),
        ("incline: slip floor, no region", incline_mpm, floor),
        ("incline: slip floor + boundary friction mu = 0.2, no region", incline_mpm,
         floor + ["Effects=gravity, boundary friction", "Boundary friction/Coefficients=2: 0.2"]),
        ("bar: FE [0, 0.5] 20 x 1 Q1 bonded to MPM [0.5, 1]", os.path.join(ROOT, "prm/bonded_bar.prm"), []),
        ("bar: all MPM [0, 1], no-slip wall at x = 0", bar_mpm,
         ["Body 1/Lower corner=0, 0", "Grid/Boundary conditions=0: no-slip, 2: slip, 3: slip"]),
    ]
    region_cells = {cases[0][0]: 48 * 4, cases[3][0]: 20 * 1}
    kept = best(dealmpm, cases, repeats, work, lambda r: step_seconds(r) / r["steps"])

    stages = []
    for r in kept.values():
        for name in r["sections"]:
            if name != "output" and name not in stages:
                stages.append(name)
    stages.sort(key=lambda s: (not s.startswith("FEM"), s))
    header = ["case", "region cells", "particles", "grid cells", "steps",
              "total us/step", "step us/step", "output s"] + ["%s us/step" % s for s in stages] + \
             ["momentum_x end", "momentum_y min", "E_g MPM end", "exit code"]
    table = []
    for name, _, _ in cases:
        if "failed" in kept[name]:
            table.append([name, region_cells.get(name, 0), "failed: " + kept[name]["failed"]]
                         + [""] * (len(header) - 3))
            continue
        r = kept[name]
        rows = r["rows"]
        gravity = [row["gravitational_energy"] - row.get("fem1_gravitational_energy", 0) for row in rows]
        us = lambda s: 1e6 * s / r["steps"]
        table.append([name, region_cells.get(name, 0), r["particles"], r["cells"], r["steps"],
                      "%.1f" % us(r["total"]), "%.1f" % us(step_seconds(r)),
                      "%.3f" % r["sections"].get("output", (0, 0))[1]] +
                     ["%.1f" % us(r["sections"][s][1]) if s in r["sections"] else "-" for s in stages] +
                     ["%.5g" % rows[-1]["momentum_x"], "%.3g" % min(row["momentum_y"] for row in rows),
                      "%.5g" % gravity[-1], r["rc"]])
    with open(os.path.join(OUT, "cost.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(table)
    # The markdown table: the cost columns only (the checks are in cost.csv).
    keep = header.index("momentum_x end")
    md = ["| " + " | ".join(header[:keep]) + " |", "|---" * keep + "|"]
    md += ["| " + " | ".join(str(c) for c in row[:keep]) + " |" for row in table]
    with open(os.path.join(OUT, "cost.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))
    print()
    print("checks (the block rests on a floor at the same height, momentum):")
    for row in table:
        print("  %s: momentum_x end %s, min momentum_y %s, MPM gravitational energy end %s "
              "(0 at the start), exit %s"
              % tuple([row[0]] + row[keep:]))
    print()


# ---------------------------------------------------------------- part 2

# Grid cells along x on [0, 1.2] (the bar has 5/6 of them). The grid is
# one cell high (0.025, the bar's height) up to 48 cells and has square cells
# from there on (n / 48 rows): the program compares the bonded boundary's
# node spacing (across the bar) with the background cells' smallest size,
# so a bar one cell high on cells finer along x is refused.
RESOLUTIONS = [24, 48, 96, 192, 288, 384]


def study_part(dealmpm, work, repeats):
    bar_mpm = without_regions("prm/bonded_bar.prm", work, "bar_all_mpm")
    bar = os.path.join(ROOT, "prm/bonded_bar.prm")
    cases = []
    for n in RESOLUTIONS:
        along = n * 5 // 6                       # cells along the bar, h = 1 / along
        rows = max(1, n // 48)                   # across the bar (0.025 high): cells square from 48 on
        common = ["Grid/Cells=%d, %d" % (n, rows), "Time/Time step=%.10g" % (0.048 / n)]
        cases.append(("bonded|%d" % n, bar, common + [
            "FEM region 1/Cells=%d, %d" % (along // 2, rows)]))
        cases.append(("all MPM|%d" % n, bar_mpm, common + [
            "Body 1/Lower corner=0, 0", "Grid/Boundary conditions=0: no-slip, 2: slip, 3: slip"]))
        cases.append(("all FE|%d" % n, bar, common + [
            "FEM region 1/Upper corner=1, 0.025", "FEM region 1/Cells=%d, %d" % (along, rows),
            "FEM region 1/Bonded boundaries=", "Body 1/Lower corner=1.1, 0",
            "Body 1/Upper corner=1.2, 0.025", "Body 1/Velocity=0, 0"]))
    cost = lambda r: r["total"] - r["sections"].get("output", (0, 0))[1]
    kept = best(dealmpm, cases, repeats, work, cost)

    header = ["configuration", "grid cells x", "grid", "h", "dt", "steps", "particles", "region cells",
              "momentum_x end", "momentum error", "worst |energy_drift|",
              "strain_energy(0.1)", "strain energy error", "wall s (total)", "output s",
              "wall s (without output)", "FEM forces s", "FEM update s", "exit code"]
    table = []
    for name, _, settings in cases:
        config, n = name.split("|")
        n = int(n)
        h, dt = 1.2 / n, 0.048 / n
        if "failed" in kept[name]:
            table.append([config, n, "%d x %d" % (n, max(1, n // 48)), "%.6g" % h, "%.6g" % dt]
                         + ["failed: " + kept[name]["failed"]] + [""] * (len(header) - 6))
            continue
        r = kept[name]
        rows = r["rows"]
        region = [s for s in settings if s.startswith("FEM region 1/Cells=")]
        end, mid = rows[-1], at(rows, 0.1)
        sections = r["sections"]
        table.append([config, n, "%d x %d" % (n, max(1, n // 48)), "%.6g" % h, "%.6g" % dt, r["steps"],
                      r["particles"] if config != "all FE" else "%d (resting)" % r["particles"],
                      "x".join(region[0].split("=")[1].replace(" ", "").split(",")) if region else 0,
                      "%.6g" % end["momentum_x"], "%.3e" % (abs(end["momentum_x"] - P_END) / abs(P_END)),
                      "%.3e" % max(abs(row["energy_drift"]) for row in rows),
                      "%.6g" % mid["strain_energy"], "%.3e" % (abs(mid["strain_energy"] - E_TOTAL) / E_TOTAL),
                      "%.3f" % r["total"], "%.3f" % sections.get("output", (0, 0))[1],
                      "%.3f" % cost(r), "%.3f" % sections.get("FEM forces", (0, 0))[1],
                      "%.3f" % sections.get("FEM update", (0, 0))[1], r["rc"]])
    with open(os.path.join(OUT, "study.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(table)
    shown = ["configuration", "grid", "steps", "particles", "region cells",
             "momentum error", "worst |energy_drift|", "strain energy error",
             "wall s (total)", "wall s (without output)"]
    idx = [header.index(c) for c in shown]
    md = ["| " + " | ".join(shown) + " |", "|---" * len(shown) + "|"]
    md += ["| " + " | ".join(str(row[i]) for i in idx) + " |"
           for row in sorted(table, key=lambda row: (row[0], row[1]))]
    with open(os.path.join(OUT, "study.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))
    plot(table, header)


MEASURES = [("momentum error", "|p_x(0.2) + 2.5e-4| / 2.5e-4"),
            ("worst |energy_drift|", "worst |energy drift| over the run"),
            ("strain energy error", "|W(0.1) - 1.25e-6| / 1.25e-6")]
COLOURS = {"bonded": "tab:blue", "all MPM": "tab:red", "all FE": "tab:green"}
MARKERS = {"bonded": "o", "all MPM": "s", "all FE": "^"}


def series(table, header):
    x = header.index("wall s (without output)")
    lines = {}
    for row in table:
        try:
            point = [float(row[x])] + [float(row[header.index(m)]) for m, _ in MEASURES]
        except ValueError:
            continue
        lines.setdefault(row[0], []).append((point, row[1]))
    return lines


def plot(table, header):
    lines = series(table, header)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not importable: study.svg drawn by hand, no study.png")
        return svg_by_hand(lines)
    fig, axes = plt.subplots(1, len(MEASURES), figsize=(15, 5))
    for k, (ax, (_, label)) in enumerate(zip(axes, MEASURES)):
        for config in sorted(lines):
            points = sorted(lines[config], key=lambda p: p[1])
            xs = [p[0][0] for p in points]
            ys = [max(p[0][k + 1], 1e-16) for p in points]
            ax.loglog(xs, ys, marker=MARKERS.get(config, "x"), color=COLOURS.get(config, "black"),
                      label=config)
            for (xv, yv, (_, n)) in zip(xs, ys, points):
                ax.annotate(str(n), (xv, yv), textcoords="offset points", xytext=(4, 4), fontsize=7,
                            color=COLOURS.get(config, "black"))
        ax.set_xlabel("wall time of the run without output [s] (one core)")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("Bonded bar (half FE, half MPM) against all MPM and all FE: error against cost; "
                 "points labelled by grid cells along x on [0, 1.2] (h = 1.2 / n)", fontsize=10)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(OUT, "study." + ext), dpi=110)
    plt.close(fig)


def svg_by_hand(lines):
    """A plain log-log SVG, one panel per measure (no matplotlib)."""
    w, h, pad = 420, 320, 60
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
             'font-size="10">' % (w * len(MEASURES), h + 20)]
    xs = [p[0][0] for pts in lines.values() for p in pts]
    for k, (_, label) in enumerate(MEASURES):
        ys = [max(p[0][k + 1], 1e-16) for pts in lines.values() for p in pts]
        if not xs:
            break
        x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
        y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
        x1, y1 = max(x1, x0 + 1), max(y1, y0 + 1)
        px = lambda v: k * w + pad + (math.log10(v) - x0) / (x1 - x0) * (w - pad - 20)
        py = lambda v: h - pad + 20 - (math.log10(max(v, 1e-16)) - y0) / (y1 - y0) * (h - pad - 20)
        parts.append('<rect x="%d" y="20" width="%d" height="%d" fill="none" stroke="black"/>'
                     % (k * w + pad, w - pad - 20, h - pad - 20))
        for e in range(x0, x1 + 1):
            parts.append('<text x="%.1f" y="%d" text-anchor="middle">1e%d</text>' % (px(10 ** e), h - pad + 35, e))
        for e in range(y0, y1 + 1):
            parts.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (k * w + pad - 4, py(10 ** e) + 3, e))
        parts.append('<text x="%d" y="%d" text-anchor="middle">wall s without output</text>'
                     % (k * w + w / 2 + 20, h + 10))
        parts.append('<text x="%d" y="14">%s</text>' % (k * w + pad, label))
        for config, pts in sorted(lines.items()):
            pts = sorted(pts, key=lambda p: p[1])
            colour = {"tab:blue": "#1f77b4", "tab:red": "#d62728", "tab:green": "#2ca02c"}[
                COLOURS.get(config, "tab:blue")]
            path = " ".join("%.1f,%.1f" % (px(p[0][0]), py(p[0][k + 1])) for p in pts)
            parts.append('<polyline points="%s" fill="none" stroke="%s"/>' % (path, colour))
            for p in pts:
                parts.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/><text x="%.1f" y="%.1f" fill="%s">%d</text>'
                             % (px(p[0][0]), py(p[0][k + 1]), colour, px(p[0][0]) + 4,
                                py(p[0][k + 1]) - 4, colour, p[1]))
            if k == 0:
                parts.append('<text x="%d" y="%d" fill="%s">%s</text>'
                             % (pad + 10, 40 + 14 * sorted(lines).index(config), colour, config))
    parts.append("</svg>")
    with open(os.path.join(OUT, "study.svg"), "w") as f:
        f.write("\n".join(parts) + "\n")


def main():
    args = sys.argv[1:]
    repeats = 3
    if "--repeats" in args:
        i = args.index("--repeats")
        repeats = int(args[i + 1])
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    dealmpm = os.path.abspath(args[0])
    work = args[1] if len(args) > 1 else tempfile.mkdtemp(prefix="fem_coupling_")
    os.makedirs(OUT, exist_ok=True)
    os.makedirs(work, exist_ok=True)
    commit = subprocess.run(["git", "-C", ROOT, "log", "-1", "--format=%h"],
                            capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no",
                            "--", "source", "include"], capture_output=True, text=True).stdout.strip()
    print("commit %s%s, best of %d runs, work folder %s\n"
          % (commit, " (sources modified since)" if dirty else "", repeats, work))
    print("## cost per step\n")
    cost_part(dealmpm, work, repeats)
    print("## bonded bar: accuracy against cost\n")
    study_part(dealmpm, work, repeats)


if __name__ == "__main__":
    main()
