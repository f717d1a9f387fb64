#!/usr/bin/env python3
"""The hard-case suite: scenes where MPM is known to break, each run with
every shape function and stress update it allows, each checked for its
invariants and against its reference.

    hard_cases.py DEALMPM                  run every case and combination,
                                           write benchmarks/hard-cases.md
    hard_cases.py DEALMPM --check CASE     run CASE as shipped (its scene's
                                           own settings), exit 1 if an
                                           invariant or the answer fails
    hard_cases.py DEALMPM --cases A,B      only these cases (table mode)

Invariants of every run: it reaches its end time (the program stops on a
non-finite value, J <= 0 or energy growth), no particle leaves the grid,
the total energy (with plastic work, gravity and external work) never
rises above its start by more than the case's bound, and momentum is kept
where nothing external acts. Each case then measures its physical answer
against its reference (analytic or tests/data/). Python's standard library
only, so that CI can run it.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "scenes"))
import vtk_files  # noqa: E402  (the project's reader of its own .vtu files)
SCENES = os.path.join(ROOT, "prm", "hard-cases")
DATA = os.path.join(ROOT, "tests", "data")

KERNELS = ["linear", "uGIMP", "cpGIMP", "CPDI", "quadratic B-spline"]
# Total Lagrangian makes its stencil once, undeformed: cpGIMP is uGIMP
# there, and CPDI's domains never deform.
TL_KERNELS = ["linear", "uGIMP", "quadratic B-spline"]
SCHEMES = ["USL", "USF", "MUSL"]


def read_csv(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def particles(folder, k):
    rows = read_csv(os.path.join(folder, "steps", "particles_%05d.csv" % k))
    return [{key: (float(v) if key != "id" else int(v)) for key, v in r.items()}
            for r in rows]


class Run:
    """One run of a scene: its statistics and where its output is."""

    def __init__(self, dealmpm, scene, overrides, folder, csv_output,
                 vtu_output=False):
        settings = ["Output/Directory=" + folder,
                    "Output/Write particles=" + ("true" if vtu_output else "false"),
                    "Output/Particle CSV=" + ("true" if csv_output else "false"),
                    "Output/Progress interval=0"] + overrides
        command = [dealmpm, scene]
        for s in settings:
            command += ["-s", s]
        start = time.time()
        done = subprocess.run(command, capture_output=True, text=True)
        self.seconds = time.time() - start
        self.folder = folder
        self.finished = done.returncode == 0
        self.reason = ""
        if not self.finished:
            lines = [line for line in done.stderr.splitlines() if line.strip()]
            self.reason = lines[-1][:160] if lines else "exit %d" % done.returncode
        path = os.path.join(folder, "statistics.csv")
        self.rows = [{k: float(v) for k, v in r.items()}
                     for r in read_csv(path)] if os.path.exists(path) else []

    def column(self, name):
        return [r[name] for r in self.rows]


# Each case: the scene, its variants (label, overrides), the invariant
# bounds and its answer (a function of the run returning (value, text,
# passes)).

def rigid_motion(run, speeds):
    """Velocity spread within each body relative to its speed (largest over
    the outputs) and the centroid error against x0 + v t in cells."""
    first = particles(run.folder, 0)
    n_out = len(run.rows)
    h = run.h
    spread, centroid_error = 0.0, 0.0
    for k in range(n_out):
        ps = particles(run.folder, k)
        t = run.rows[k]["time"]
        for body, speed in enumerate(speeds, start=1):  # 'Body N' counts from 1
            mine = [p for p in ps if p["body"] == body]
            if not mine:
                return float("inf"), float("inf")
            n = len(mine)
            axes = [v for v in ("vx", "vy", "vz") if v in mine[0]]
            mean_v = {v: sum(p[v] for p in mine) / n for v in axes}
            rms = math.sqrt(sum((p[v] - mean_v[v]) ** 2
                                for p in mine for v in axes) / n)
            spread = max(spread, rms / abs(speed))
            start = [p["x"] for p in first if p["body"] == body]
            x0 = sum(start) / len(start)
            x = sum(p["x"] for p in mine) / n
            centroid_error = max(centroid_error, abs(x - (x0 + speed * t)) / h)
    return spread, centroid_error


def crossing_answer(run):
    spread, error = rigid_motion(run, [2.0, -2.0])
    ok = spread <= 0.02 and error <= 0.1
    return ("velocity spread %.2g, centroid off by %.2g cells" % (spread, error), ok)


def disks_answer(run):
    ke = run.column("kinetic_energy")
    ratio = ke[-1] / ke[0]
    # Sulsky et al.: the disks bounce apart and most kinetic energy comes
    # back (some stays as vibration); a run that sticks or blows up fails.
    return ("kinetic energy back to %.0f %% of the start" % (100 * ratio),
            0.75 <= ratio <= 1.05)


def cantilever_answer(run):
    first = particles(run.folder, 0)
    x_end = max(p["x"] for p in first)
    tip_ids = {p["id"] for p in first if p["x"] > x_end - 1e-6}
    deflection = []
    for k, r in enumerate(run.rows):
        tip = [p["uy"] for p in particles(run.folder, k) if p["id"] in tip_ids]
        deflection.append((r["time"], -sum(tip) / len(tip) if tip else float("nan")))
    # The first peak: the first output not exceeded by the next four.
    peak_time, peak = deflection[-1]
    for k in range(len(deflection) - 4):
        if all(deflection[k][1] >= d for _, d in deflection[k + 1:k + 5]):
            peak_time, peak = deflection[k]
            break
    ok = abs(peak - 3.3) <= 0.2 * 3.3 and abs(peak_time - 1.05) <= 0.2
    return ("first peak %.2f m at t = %.2f s (about 3.3 m near 1.05 s)" % (peak, peak_time), ok)


def granular_answer(run, toe_bound=0.1):
    """The final surface against Bui et al.'s within 10 % of the column's
    height (rms), and the toe (the third particle from the front) within
    @p toe_bound of their 0.44 m (None: reported, not bounded)."""
    final = particles(run.folder, len(run.rows) - 1)
    h = run.h
    reference = [(float(r["x_m"]), float(r["y_m"]))
                 for r in read_csv(os.path.join(DATA, "bui2008_column_collapse_final_surface.csv"))]
    squares = []
    for x, y in reference:
        near = [p["y"] for p in final if abs(p["x"] - x) <= h]
        squares.append(((max(near) if near else 0.0) - y) ** 2)
    rms = math.sqrt(sum(squares) / len(squares)) / 0.1
    xs = sorted(p["x"] for p in final)
    toe = xs[-3]
    ok = rms <= 0.1 and (toe_bound is None or abs(toe - 0.44) <= toe_bound * 0.44)
    return ("toe at x = %.3f m (0.44), surface rms error %.1f %% of the height"
            % (toe, 100 * rms), ok)


def dam_answer(run):
    a = 0.05715
    scale = math.sqrt(2 * 9.81 / a)
    fronts = []
    for k, r in enumerate(run.rows):
        xs = sorted(p["x"] for p in particles(run.folder, k))
        fronts.append((r["time"] * scale, xs[-3] / a))
    reference = [(float(r["T"]), float(r["Z"]))
                 for r in read_csv(os.path.join(DATA, "martin_moyce1952_dam_break_front.csv"))
                 if float(r["a_in"]) == 2.25 and float(r["T"]) <= fronts[-1][0]]
    worst = 0.0
    for T, Z in reference:
        for (T0, Z0), (T1, Z1) in zip(fronts, fronts[1:]):
            if T0 <= T <= T1:
                ours = Z0 + (Z1 - Z0) * (T - T0) / (T1 - T0)
                worst = max(worst, abs(ours - Z) / Z)
    # Computed fronts lead the measured one, as the published SPH and MPM
    # runs do (the experiment's gate took time to lift): 20 % allowed.
    return ("front ahead by at most %.1f %% of the measured one (%d points)"
            % (100 * worst, len(reference)), worst <= 0.2)


def static_stress_answer(run):
    """The largest difference of the particles' sigma_yy from the static
    -rho g (H - Y) (rho = 1000, g = 9.81, H = 1), over rho g H."""
    _, last = vtk_files.pvd_files(os.path.join(run.folder, "particles.pvd"))[-1]
    worst, scale = 0.0, 1000 * 9.81 * 1.0
    record = os.path.join(run.folder, last)
    for piece in vtk_files.pvtu_pieces(record):
        d = vtk_files.read_vtu(os.path.join(os.path.dirname(record), piece))
        u, stress = d["arrays"]["displacement"][2], d["arrays"]["stress"][2]
        for i in range(d["n_points"]):
            Y = d["points"][3 * i + 1] - u[3 * i + 1]
            worst = max(worst, abs(stress[9 * i + 4] + scale * (1 - Y)) / scale)
    ke, se = run.rows[-1]["kinetic_energy"], run.rows[-1]["strain_energy"]
    return ("particle stress off the static one by up to %.1f %% of rho g H "
            "(kinetic / strain energy %.2g)" % (100 * worst, ke / se), worst <= 0.05)


def rod_outline(run, spacing):
    """Final length and largest diameter of a rod standing on z = 0, from
    the particles' deformed domains: a particle spans spacing * F e_j
    (j = 1..3) about its centre, so it reaches 0.5 spacing sum_j |n . F e_j|
    along a direction n (the surface, not the particle centres, which lie
    half a particle inside it). The diameter counts the particles within
    1 mm of the wall."""
    _, last = vtk_files.pvd_files(os.path.join(run.folder, "particles.pvd"))[-1]
    length, radius = 0.0, 0.0
    record = os.path.join(run.folder, last)
    for piece in vtk_files.pvtu_pieces(record):
        d = vtk_files.read_vtu(os.path.join(os.path.dirname(record), piece))
        F = d["arrays"]["deformation gradient"][2]
        for i in range(d["n_points"]):
            x, y, z = d["points"][3 * i:3 * i + 3]
            f = F[9 * i:9 * i + 9]
            length = max(length, z + 0.5 * spacing * sum(abs(f[6 + j]) for j in range(3)))
            if z < 1e-3:
                r = math.hypot(x, y)
                nx, ny = (x / r, y / r) if r > 0 else (1.0, 0.0)
                reach = 0.5 * spacing * sum(abs(nx * f[j] + ny * f[3 + j]) for j in range(3))
                radius = max(radius, r + reach)
    return 1e3 * length, 2e3 * radius


def taylor_references(case):
    rows = [r for r in read_csv(os.path.join(DATA, "taylor_bar_references.csv"))
            if r["case"] == case]
    mean = lambda key: sum(float(r[key]) for r in rows) / len(rows)  # noqa: E731
    return mean("Lf"), mean("Df")


def taylor_answer(case, length_bound, diameter_bound):
    """Final length and diameter against the case's references (their
    means) within the relative bounds."""
    def answer(run):
        # The Taylor scenes place 2 particles per cell along each axis.
        length, diameter = rod_outline(run, run.h / 2)
        ref_length, ref_diameter = taylor_references(case)
        dl, dd = length / ref_length - 1, diameter / ref_diameter - 1
        return ("final length %.2f mm (%.2f, %+.1f %%), diameter %.2f mm (%.2f, %+.1f %%)"
                % (length, ref_length, 100 * dl, diameter, ref_diameter, 100 * dd),
                abs(dl) <= length_bound and abs(dd) <= diameter_bound)
    return answer


def bar_answer(run):
    drift = run.column("energy_drift")
    periods = run.rows[-1]["time"] / 10.0
    per_period = max(abs(d) for d in drift) / periods
    return ("largest |energy drift| %.2g, %.2g per period over %d periods"
            % (max(abs(d) for d in drift), per_period, periods), per_period <= 1e-4)


def all_combinations():
    updated = [("%s, %s" % (k, s), ["MPM/Shape function=" + k, "MPM/Stress update=" + s])
               for k in KERNELS for s in SCHEMES]
    total = [("total Lagrangian, %s, %s" % (k, s),
              ["MPM/Formulation=total Lagrangian", "MPM/Shape function=" + k,
               "MPM/Stress update=" + s])
             for k in TL_KERNELS for s in SCHEMES]
    return updated + total


def f_bar_collapse(extra, label, h=0.005):
    """The granular collapse under F-bar with @p extra overrides (cells of
    size @p h): the invariants and the surface, the toe reported only."""
    return dict(scene=os.path.join(SCENES, "granular_collapse.prm"),
                overrides=["MPM/Anti-locking=F-bar"] + extra, variants=[(label, [])],
                h=h, growth=0.02, answer=lambda run: granular_answer(run, None))


CASES = {
    "colliding_disks_20": dict(scene=os.path.join(ROOT, "prm", "colliding_disks.prm"),
                               overrides=["Grid/Cells=20, 20"], h=0.05, growth=0.05,
                               momentum=1e-10, answer=disks_answer, csv=False),
    "colliding_disks_40": dict(scene=os.path.join(ROOT, "prm", "colliding_disks.prm"),
                               overrides=["Grid/Cells=40, 40"], h=0.025, growth=0.05,
                               momentum=1e-10, answer=disks_answer, csv=False),
    "colliding_disks_80": dict(scene=os.path.join(ROOT, "prm", "colliding_disks.prm"),
                               overrides=["Grid/Cells=80, 80"], h=0.0125, growth=0.05,
                               momentum=1e-10, answer=disks_answer, csv=False),
    "crossing_bodies_2d": dict(scene=os.path.join(SCENES, "crossing_bodies_2d.prm"),
                               h=0.025, growth=0.001, momentum=1e-10,
                               answer=crossing_answer),
    "crossing_bodies_3d": dict(scene=os.path.join(SCENES, "crossing_bodies_3d.prm"),
                               h=0.05, growth=0.001, momentum=1e-10,
                               answer=crossing_answer),
    "cantilever": dict(scene=os.path.join(SCENES, "cantilever.prm"), h=0.125,
                       growth=0.05, answer=cantilever_answer),
    # The scene as shipped, F-bar by default since 2026-12-02 ('automatic'
    # with Drucker-Prager; weighted by the particles' reference volumes:
    # with current volumes it stopped with J <= 0 at t = 0.54 s). Its toe
    # runs further than the experiment's (0.49 m against 0.44; 'none' on
    # cells half as large runs to 0.57 m as well), so only the surface is
    # held to the reference (doc/guide/limits.md).
    "granular_collapse": dict(scene=os.path.join(SCENES, "granular_collapse.prm"),
                              h=0.005, growth=0.02,
                              answer=lambda run: granular_answer(run, None)),
    # Without anti-locking, as the scene ran before 2026-12-02: the toe
    # within 10 % of the experiment's at this resolution (0.480 m).
    "granular_collapse_none": dict(scene=os.path.join(SCENES, "granular_collapse.prm"),
                                   overrides=["MPM/Anti-locking=none"],
                                   variants=[("cpGIMP, USL, none", [])], h=0.005,
                                   growth=0.02, answer=granular_answer),
    # On cells half as large: with the scaled increment (dJbar / dJ)^(1/dim)
    # dF, which stretches a grain whose own increment nearly collapsed, it
    # stopped with J <= 0 at t = 0.24 s; with the shared volume rate it
    # runs to rest. With cpGIMP's light-node weights alone (below), a floor
    # grain sheared without end reached a condition number of F of 1e8
    # and went non-finite at t = 0.59 s: the Hencky models now renormalise
    # such an F (2026-12-02).
    "granular_collapse_f_bar_fine": f_bar_collapse(
        ["Grid/Cells=240, 50"], "cpGIMP, USL, F-bar, 240 x 50 cells", h=0.0025),
    # The same at CFL 0.3: a front grain whose cpGIMP domain F had squashed
    # to a sliver across a row of nodes took the full gradient 1/h on that
    # sliver of mass and turned inside out at t = 0.25 s, until cpGIMP took
    # USL's light-node weights as linear functions do (2026-12-02).
    "granular_collapse_fine_cfl_0.3": f_bar_collapse(
        ["Grid/Cells=240, 50", "Time/CFL number=0.3"],
        "cpGIMP, USL, F-bar, 240 x 50 cells, CFL 0.3", h=0.0025),
    "dam_break": dict(scene=os.path.join(SCENES, "dam_break.prm"), h=0.05715 / 16,
                      growth=0.02, answer=dam_answer),
    "resting_column": dict(scene=os.path.join(SCENES, "resting_column.prm"), h=0.05,
                           growth=0.02, answer=static_stress_answer, csv=False, vtu=True),
    "stiff_on_soft": dict(scene=os.path.join(SCENES, "stiff_on_soft.prm"), h=0.05,
                          growth=0.02, answer=static_stress_answer, csv=False, vtu=True),
    # Against the experiment: bounds for the Johnson-Cook fit's own error.
    # The refinements (the shipped combination on finer cells, the same
    # domain) show the answers converging.
    "taylor_bar": dict(scene=os.path.join(SCENES, "taylor_bar.prm"), h=0.0008,
                       growth=0.02, answer=taylor_answer("copper", 0.05, 0.10),
                       csv=False, vtu=True,
                       refinements=[(0.024 / 45, ["Grid/Cells=36, 36, 45"]),
                                    (0.0004, ["Grid/Cells=48, 48, 60"])]),
    # Against two codes running the same model: the code's own error.
    "taylor_bar_steel": dict(scene=os.path.join(SCENES, "taylor_bar_steel.prm"),
                             h=0.0008, growth=0.02, csv=False, vtu=True,
                             answer=taylor_answer("steel", 0.01, 0.05),
                             # Cells with a whole number of particle layers
                             # in the 32.4 mm bar (0.0648 / h), so that no
                             # layer of centres lies on its end faces.
                             refinements=[(0.0648 / 122, ["Grid/Cells=27, 27, 62",
                                                          "Grid/Lower corner=%.8g, %.8g, 0"
                                                          % (-13.5 * 0.0648 / 122,
                                                             -13.5 * 0.0648 / 122),
                                                          "Grid/Upper corner=%.8g, %.8g, %.8g"
                                                          % (13.5 * 0.0648 / 122,
                                                             13.5 * 0.0648 / 122,
                                                             62 * 0.0648 / 122)]),
                                          (0.0004, ["Grid/Cells=36, 36, 82"])]),
    "long_vibrating_bar": dict(scene=os.path.join(ROOT, "prm", "vibrating_bar.prm"),
                               overrides=["Time/End time=1000", "Output/Interval=10"],
                               h=1.0, growth=0.01, momentum=None, answer=bar_answer,
                               csv=False,
                               recommended=["MPM/Velocity update=APIC"],
                               variants=[("linear, %s, %s" % (s, v),
                                          ["MPM/Stress update=" + s, "MPM/Velocity update=" + v])
                                         for s in SCHEMES for v in ("FLIP", "APIC")]),
}


def run_case(dealmpm, name, label, extra, work, h=None):
    case = CASES[name]
    folder = os.path.join(work, name, label.replace(", ", "-").replace(" ", "_")
                          .replace("(", "").replace(")", ""))
    run = Run(dealmpm, case["scene"], case.get("overrides", []) + extra, folder,
              case.get("csv", True), case.get("vtu", False))
    run.h = h or case["h"]
    result = dict(case=name, label=label, seconds=run.seconds, finished=run.finished,
                  reason=run.reason, failures=[])
    if not run.rows:
        result["failures"].append("no statistics" + (": " + run.reason if run.reason else ""))
        return result
    growth = max(run.column("energy_drift"))
    result["growth"] = growth
    lost = run.rows[-1]["lost_particles"]
    result["lost"] = lost
    if not run.finished:
        result["failures"].append("stopped: " + run.reason)
    if growth > case["growth"]:
        result["failures"].append("energy +%.2g%% > %.2g%%" % (100 * growth, 100 * case["growth"]))
    if lost > 0:
        result["failures"].append("%d particles lost" % lost)
    if case.get("momentum") is not None:
        momentum = max(run.column("momentum_drift"))
        result["momentum"] = momentum
        if momentum > case["momentum"]:
            result["failures"].append("momentum drift %.2g" % momentum)
    if run.finished:
        text, ok = case["answer"](run)
        result["answer"] = text
        if not ok:
            result["failures"].append("answer off")
    return result


def describe(result):
    status = "; ".join(result["failures"]) if result["failures"] else "holds"
    return "| %s | %s | %s | %s | %s | %s | %.1f |" % (
        result["case"], result["label"],
        "%+.2g %%" % (100 * result["growth"]) if "growth" in result else "-",
        "%.2g" % result["momentum"] if "momentum" in result else "-",
        result.get("answer", "-"), status, result["seconds"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dealmpm")
    parser.add_argument("--check", metavar="CASE")
    parser.add_argument("--cases")
    parser.add_argument("--work", default=os.path.join(os.getcwd(), "hard-cases-output"))
    parser.add_argument("--out", default=os.path.join(HERE, "hard-cases.md"))
    args = parser.parse_args()

    if args.check:
        if args.check not in CASES:
            sys.exit("hard_cases.py: unknown case '%s' (expected one of %s)"
                     % (args.check, ", ".join(CASES)))
        result = run_case(args.dealmpm, args.check, "as shipped",
                          CASES[args.check].get("recommended", []), args.work)
        print(describe(result))
        sys.exit(1 if result["failures"] else 0)

    names = args.cases.split(",") if args.cases else list(CASES)
    rows = {name: [] for name in CASES}
    for line in old_rows(args.out):
        name = line.split("|")[1].strip()
        if name in rows and name not in names:
            rows[name].append(line)
    for name in names:
        case = CASES[name]
        variants = case.get("variants", all_combinations()) + [
            ("as shipped, %.2g mm cells" % (1e3 * h), case.get("recommended", []) + overrides, h)
            for h, overrides in case.get("refinements", [])]
        for label, extra, *h in variants:
            result = run_case(args.dealmpm, name, label, extra, args.work, *h)
            rows[name].append(describe(result))
            print(rows[name][-1], flush=True)
    lines = [HEADER] + [line for name in CASES for line in rows[name]]
    write_table(args.out, "\n".join(lines) + "\n")


HEADER = ("| case | shape function, scheme | largest energy gain | momentum drift "
          "| answer (reference) | invariants and answer | seconds |\n"
          "|---|---|---|---|---|---|---|")
BEGIN, END = "<!-- hard_cases.py table -->", "<!-- end of table -->"


def old_rows(path):
    """The rows of the table in @p path (none when there is none)."""
    if not os.path.exists(path) or BEGIN not in open(path).read():
        return []
    table = open(path).read().split(BEGIN, 1)[1].split(END, 1)[0]
    return [line for line in table.splitlines()[2:] if line.startswith("|")]


def write_table(path, table):
    """Put the table between the markers of @p path, keeping the text
    around it (the findings are written by hand)."""
    text = open(path).read() if os.path.exists(path) else BEGIN + "\n" + END + "\n"
    head, rest = text.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    with open(path, "w") as f:
        f.write(head + BEGIN + "\n" + table + END + tail)


if __name__ == "__main__":
    main()
