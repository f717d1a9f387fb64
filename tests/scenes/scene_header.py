#!/usr/bin/env python3
"""Checks a scene file's header against a run of the scene, so that the
numbers a user reads there cannot drift from what the scene gives.

    scene_header.py path/to/dealmpm scene.prm [work folder]

The header's checked lines have the form

    #   expect <quantity>: <value> +- <tolerance>

with <quantity> one of
    <column> at t = <time>     the statistics.csv row at that output time
    <column> at end            the last row
    max <column>, min <column> over all rows
    time of max <column>       the output time where the column peaks
    mean <column> after t = T  mean over the output rows from time T on
    mean <column> from t = A to B  mean over the output rows in [A, B]
    steps                      the number of steps to the end
    cells at end               the grid's cells the closing summary gives
                               after adaptations ("(N cells now)")
and <column> any statistics.csv column. The scene must run to its end
(exit code 0); particle output is switched off for the check.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

dealmpm, scene = sys.argv[1], sys.argv[2]
line_form = re.compile(r"#\s+expect\s+(.+?):\s+(\S+)\s+\+-\s+(\S+)\s*$")
expectations = []
with open(scene) as f:
    for line in f:
        if not line.startswith("#"):
            break
        match = line_form.match(line)
        if match:
            expectations.append((match.group(1), float(match.group(2)),
                                 float(match.group(3))))
        elif re.match(r"#\s+expect\b", line):
            sys.exit("%s: malformed expect line: %s" % (scene, line.strip()))
if not expectations:
    sys.exit("%s: no '#   expect ...' lines in its header" % scene)

work = sys.argv[3] if len(sys.argv) > 3 else tempfile.mkdtemp()
folder = os.path.join(work, os.path.basename(scene) + ".out")
run = subprocess.run([dealmpm, scene, "-s", "Output/Directory=" + folder,
                      "-s", "Output/Write particles=false",
                      "-s", "Output/Particle CSV=false",
                      "-s", "Output/Progress interval=0"],
                     capture_output=True, text=True)
if run.returncode != 0:
    sys.exit("%s: exit code %d: %s" % (scene, run.returncode,
                                       run.stderr.strip()[-500:]))
with open(os.path.join(folder, "statistics.csv")) as f:
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def measure(quantity):
    if quantity == "steps":
        return rows[-1]["step"]
    if quantity == "cells at end":
        cells = re.search(r"\((\d+) cells now\)", run.stdout)
        if not cells:
            raise KeyError("the summary names no cells (no adaptation?)")
        return float(cells.group(1))
    match = re.fullmatch(r"time of max (\w+)", quantity)
    if match:
        return max(rows, key=lambda r: r[match.group(1)])["time"]
    match = re.fullmatch(r"(max|min) (\w+)", quantity)
    if match:
        pick = max if match.group(1) == "max" else min
        return pick(r[match.group(2)] for r in rows)
    match = re.fullmatch(r"mean (\w+) (after t = (\S+)|from t = (\S+) to (\S+))",
                         quantity)
    if match:
        start = float(match.group(3) or match.group(4))
        end = float(match.group(5)) if match.group(5) else float("inf")
        late = [r[match.group(1)] for r in rows if start <= r["time"] <= end]
        if not late:
            raise KeyError("no output in t = [%g, %g]" % (start, end))
        return sum(late) / len(late)
    match = re.fullmatch(r"(\w+) at end", quantity)
    if match:
        return rows[-1][match.group(1)]
    match = re.fullmatch(r"(\w+) at t = (\S+)", quantity)
    if match:
        t = float(match.group(2))
        near = [r for r in rows if abs(r["time"] - t) <= 1e-6 * (1 + abs(t))]
        if not near:
            raise KeyError("no output at t = %g" % t)
        return near[0][match.group(1)]
    raise KeyError("unknown quantity")


failures = 0
for quantity, value, tolerance in expectations:
    try:
        got = measure(quantity)
    except KeyError as e:
        print("FAIL: %s: expect %s: %s" % (scene, quantity, e))
        failures += 1
        continue
    ok = abs(got - value) <= tolerance
    print("%s: %s: %s = %.6g (header: %g +- %g)" %
          ("ok" if ok else "FAIL", os.path.basename(scene), quantity, got,
           value, tolerance))
    failures += not ok
sys.exit(1 if failures else 0)
