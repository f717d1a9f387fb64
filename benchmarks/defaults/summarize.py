#!/usr/bin/env python3
"""Reads the defaults study (study.csv of each case and every run's
statistics.csv) and writes defaults.md and defaults.csv: per setting (shape
function, stress update, CFL number) whether each case ran to its end with
its energy within 5 %, and its cost: the seconds the five runs spent after
set-up (start-up, the same for all, would hide the differences on cases
this small). The cheapest passing setting is marked, and the cheapest one
whose shape function works on every grid the program accepts (linear,
CPDI: GIMP needs axis-aligned box cells, the B-spline a uniform box grid
without local refinement), which is the one a default can be.

Energy criteria (fractions of the energy put in, see the accuracy report):
- disks: |energy drift| <= 5 % at every output (elastic: nothing may be lost
  or gained);
- cube drop (the shipped one, and from 0.5 m): energy growth <= 5 % (grid
  contact at the floor takes energy out; that loss is how the method
  treats the impact, growth is not);
- column: energy growth <= 5 % and the settled strain energy within 5 % of
  W = (rho g)^2 H^3 / (6 E) = 1603.9 J (local damping takes the rest out).
"""
import csv
import os
import sys

folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(__file__)
column_energy = 9810.0 ** 2 * 10.0 ** 3 / (6 * 1e7)
cases = [("disks", 0, "disks 20"), ("disks", 1, "disks 40"),
         ("disks", 2, "disks 80"), ("cube_drop", 0, "cube drop"),
         ("cube_drop_high", 0, "cube drop 0.5 m"), ("column", 0, "column")]
any_grid = ("linear", "CPDI")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def judge(case, run_folder, status, reason):
    """(passed, short text, seconds after set-up) for one run."""
    path = os.path.join(run_folder, "statistics.csv")
    stats = rows(path) if os.path.exists(path) else []
    if status != "ok":
        why = reason.split(":")[-1].strip()[:40] if reason else status
        when = "t=%.2g" % float(stats[-1]["time"]) if stats else "at start"
        return False, "%s %s (%s)" % (status, when, why), 0.0
    seconds = float(stats[-1]["wall_time"])
    drift = [float(r["energy_drift"]) for r in stats]
    gain, loss = max(drift), min(drift)
    if case == "disks":
        worst = gain if abs(gain) > abs(loss) else loss
        return abs(worst) <= 0.05, "%+.1f %%" % (100 * worst), seconds
    if case.startswith("cube_drop"):
        return gain <= 0.05, "gain %.1f %%" % (100 * gain), seconds
    strain = float(stats[-1]["strain_energy"])
    error = strain / column_energy - 1
    return gain <= 0.05 and abs(error) <= 0.05, \
        "W %+.1f %%, gain %.1f %%" % (100 * error, 100 * gain), seconds


settings = {}
for case, refinement, label in cases:
    study = os.path.join(folder, case, "study.csv")
    if not os.path.exists(study):
        sys.exit("summarize.py: %s missing: run benchmarks/defaults/run.sh" % study)
    for r in rows(study):
        if int(r["refinement"]) != refinement:
            continue
        key = (r["shape_function"], r["stress_update"], float(r["cfl_number"]))
        run_folder = os.path.join(folder, case, "runs", "%03d" % int(r["run"]))
        passed, text, seconds = judge(case, run_folder, r["status"],
                                      r["reason"])
        entry = settings.setdefault(key, {"cases": {}, "time": 0.0})
        entry["cases"][label] = (passed, text)
        entry["time"] += seconds

labels = [c[2] for c in cases]
passing = [k for k, e in settings.items()
           if all(e["cases"].get(l, (False,))[0] for l in labels)]
def cheapest_of(keys):
    return min(keys, key=lambda k: settings[k]["time"]) if keys else None


cheapest = cheapest_of(passing)
chosen = cheapest_of([k for k in passing if k[0] in any_grid])

with open(os.path.join(folder, "defaults.csv"), "w", newline="") as f:
    out = csv.writer(f)
    out.writerow(["shape_function", "stress_update", "cfl_number", "passes",
                  "cost_seconds"] + labels)
    for key in sorted(settings):
        e = settings[key]
        out.writerow(list(key) + [int(key in passing), "%.2f" % e["time"]] +
                     [e["cases"].get(l, (False, "-"))[1] for l in labels])

with open(os.path.join(folder, "defaults.md"), "w") as md:
    md.write("# Defaults study\n\n"
             "Made by `benchmarks/defaults/run.sh`. A setting passes when "
             "every case runs to its end with its energy within 5 % "
             "(disks: |drift|; cube drop: growth; column: growth and settled "
             "strain energy against W). Cost: seconds of all runs after "
             "set-up, one core each (failed runs count 0). **cheapest**: the "
             "cheapest setting that passes; **default**: the cheapest that "
             "passes with a shape function that works on every grid "
             "(linear, CPDI).\n\n")
    md.write("| shape function | stress | CFL | passes | cost s | " +
             " | ".join(labels) + " |\n")
    md.write("|---" * (5 + len(labels)) + "|\n")
    order = sorted(settings, key=lambda k: (k not in passing,
                                            settings[k]["time"]))
    for key in order:
        e = settings[key]
        mark = " ".join(m for m, on in (("**cheapest**", key == cheapest),
                                         ("**default**", key == chosen))
                        if on) or ("yes" if key in passing else "")
        md.write("| %s | %s | %g | %s | %.2f | " % (key + (mark, e["time"])) +
                 " | ".join(e["cases"].get(l, (False, "-"))[1] for l in labels) +
                 " |\n")
print("summarize.py: %d settings, %d pass; cheapest: %s; default: %s" %
      (len(settings), len(passing), cheapest, chosen))
