#!/usr/bin/env bash
# A run into a folder that holds an earlier run's output removes that
# output's files first (and says how many), so that only its own series
# remain; the user's own files and subfolders stay.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
fixed=(-s "Time/Time step method=fixed" -s "Time/Time step=0.001") # outputs at known steps

"$dealmpm" "$scene" -s "Output/Directory=out" -s "Time/End time=0.1" -s "Output/Interval=0.01" "${fixed[@]}" \
  -s "Output/Write grid=true" -s "Output/Particle CSV=true" -s "Output/Progress interval=0" \
  > first.txt 2>&1 || fail "first run: exit code $?"
# The run's own files: the series and statistics at the top, each output's
# files in steps/ (run.prm and run.log are written over, not removed).
first=$(( $(ls out | grep -cv '^steps$\|^run\.prm$\|^run\.log$') + $(ls out/steps | wc -l) ))
echo "mine" > out/notes.txt
mkdir out/sub && echo "mine" > out/sub/particles.pvd && echo "mine" > out/sub/statistics.csv
"$dealmpm" "$scene" -s "Output/Directory=out" -s "Time/End time=0.03" -s "Output/Interval=0.01" "${fixed[@]}" \
  -s "Output/Progress interval=0" > second.txt 2>&1 || fail "second run: exit code $?"
grep -q "removed $first files of an earlier run" second.txt \
  || fail "start line: $(grep 'output in' second.txt)"
expected="notes.txt particles.pvd run.log run.prm statistics.csv steps sub"
[ "$(ls out | LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//')" = "$expected" ] \
  || fail "files after the second run: $(ls out | tr '\n' ' ')"
expected="particles_00000.0.vtu particles_00000.pvtu particles_00001.0.vtu particles_00001.pvtu particles_00002.0.vtu particles_00002.pvtu particles_00003.0.vtu particles_00003.pvtu"
[ "$(ls out/steps | LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//')" = "$expected" ] \
  || fail "files in steps/ after the second run: $(ls out/steps | tr '\n' ' ')"
[ "$(cat out/sub/particles.pvd out/sub/statistics.csv)" = "$(printf 'mine\nmine')" ] \
  || fail "the subfolder's files changed"
grep -q "output in out/$" first.txt || fail "a first run should remove nothing: $(grep 'output in' first.txt)"

finish "stale files"
