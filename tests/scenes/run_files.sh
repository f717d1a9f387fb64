#!/usr/bin/env bash
# The output folder explains itself: run.prm is the scene as it ran (every
# entry, the -s overrides applied), which runs again to the same statistics
# without a warning; run.log holds every line the run printed, on standard
# output and on standard error, and a resumed run appends to it.
# Arguments: dealmpm, the colliding disks, compare_statistics.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
compare=$3
# Overrides of a body, the time and the grid; gravity's section set while
# gravity is not listed, for a warning on standard error.
run=(-s "Body 1/Velocity=0.5, 0.25" -s "Time/End time=0.05" -s "Output/Interval=0.01"
     -s "Grid/Global refinements=2" -s "Output/Progress interval=0"
     -s "Gravity/Acceleration=0, -9.81")
"$dealmpm" "$scene" "${run[@]}" -s "Output/Directory=out" > out.txt 2> err.txt || fail "the run failed: $(cat err.txt)"
[ -s out/run.prm ] || fail "no out/run.prm"
head -1 out/run.prm | grep -q "^# dealmpm: the scene as it ran" || fail "run.prm: no first line saying what it is"
# The overrides applied, in their sections; an entry the scene left at its
# default is there too.
python3 - out/run.prm <<'PY' || fail "run.prm does not hold the scene as it ran"
import re, sys
path, entries = [], {}
for line in open(sys.argv[1]):
    text = line.split("#")[0].strip()
    if text.startswith("subsection "):
        path.append(text[11:].strip())
    elif text == "end":
        path.pop()
    elif text.startswith("set "):
        name, value = text[4:].split("=", 1)
        entries["/".join(path + [name.strip()])] = value.strip()
want = {"Body 1/Velocity": "0.5, 0.25", "Time/End time": "0.05",
        "Grid/Global refinements": "2", "Output/Directory": "out",
        "Checks/Mass loss limit": "0.01"}
bad = [(k, entries.get(k), v) for k, v in want.items() if entries.get(k) != v]
print("\n".join("%s = %s, expected %s" % b for b in bad))
sys.exit(1 if bad or len(entries) < 100 else 0)
PY
# Every line printed, in the log; the warning among them.
grep -q "^dealmpm: warning: .*'Gravity/Acceleration' is set" err.txt || fail "no warning to look for: $(cat err.txt)"
[ -s out/run.log ] || fail "no out/run.log"
while IFS= read -r line; do
  grep -qxF -- "$line" out/run.log || fail "run.log lacks the line: $line"
done < <(cat out.txt err.txt)

# run.prm runs again, to the same statistics, and says nothing on
# standard error (it sets every entry on purpose).
"$dealmpm" out/run.prm -s "Output/Directory=again" > again.txt 2> again-err.txt || fail "run.prm does not run: $(cat again-err.txt)"
[ -s again-err.txt ] && fail "run.prm: standard error is not empty: $(cat again-err.txt)"
echo -n "run.prm vs the run: "
"$compare" out/statistics.csv again/statistics.csv 0 || fail "run.prm ran to other statistics"

# A resumed run appends to the log.
DEALMPM_TERM_AT_STEP=5 "$dealmpm" "$scene" "${run[@]}" -s "Output/Directory=resumed" > /dev/null 2>&1
[ $? = 143 ] || fail "resumed: not stopped at step 5"
"$dealmpm" "$scene" "${run[@]}" -s "Output/Directory=resumed" --resume > /dev/null 2>&1 || fail "resumed: the resume failed"
grep -q "^dealmpm: stopped by SIGTERM at step 5 " resumed/run.log || fail "resumed: the stopped run's lines are gone from run.log"
grep -q "^dealmpm: resumed from " resumed/run.log || fail "resumed: the resumed run's lines are not in run.log"
finish "run files"
