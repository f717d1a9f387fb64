#!/usr/bin/env bash
# A run stopped by SIGTERM or SIGINT ends after its current step with a last
# output: exit code 128 + signal, one line that says so, particles.pvd
# parses and lists only files that exist, and statistics.csv has a row for
# every listed output (the last one included). Killed with SIGKILL at
# random moments, the series on disk still parses and is complete (it is
# written to a temporary file and renamed). Also under mpirun.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
mpirun=$3
export PYTHONPATH="$here"
flags=("${mpirun_flags[@]}")
# Long runs with an output every few steps (the grid too).
long=(-s "Time/End time=1000" -s "Output/Interval=0.005" -s "Output/Write grid=true"
      -s "Output/Progress interval=0")

# The series in $1 is whole: every .pvd parses and lists existing files, the
# particles' and the grid's list the same outputs, and statistics.csv has
# one row per listed output, at its time, and at most one more (written
# before the .pvd entries).
series_complete() {
  python3 - "$1" <<'PY'
import csv, os, sys
from vtk_files import pvd_files, check_series
folder = sys.argv[1]
problems = []
if os.path.exists(folder + "/particles.pvd"):
    entries = pvd_files(folder + "/particles.pvd")
    problems += check_series(folder, "particles.pvd")
    if os.path.exists(folder + "/grid.pvd"):
        problems += check_series(folder, "grid.pvd")
        grid = pvd_files(folder + "/grid.pvd")
        if [t for t, _ in grid] != [t for t, _ in entries][:len(grid)] or len(grid) + 1 < len(entries):
            problems.append("grid.pvd and particles.pvd list different outputs")
    rows = list(csv.DictReader(open(folder + "/statistics.csv")))
    if not len(entries) <= len(rows) <= len(entries) + 1:
        problems.append("%d statistics rows for %d outputs" % (len(rows), len(entries)))
    for (t, _), row in zip(entries, rows):
        if abs(float(row["time"]) - t) > 1e-9 * max(1, t):
            problems.append("output at t = %g has the row of t = %s" % (t, row["time"]))
    if not entries:
        problems.append("particles.pvd lists nothing")
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
PY
}

# Wait until the run writing into $1 is stepping (its signal handlers are
# in place): start-up takes longer on a loaded machine than any fixed pause.
wait_until_stepping() {
  for _ in $(seq 600); do
    [ "$(cat "$1/statistics.csv" 2> /dev/null | wc -l)" -ge 3 ] && break
    sleep 0.1
  done
}

# $1 signal, $2 expected exit code, $3 folder, $4 whom to signal (the
# process started, or its children: mpirun's ranks), then the command.
stop_with() {
  local signal=$1 code=$2 folder=$3 whom=$4; shift 4
  "$@" -s "Output/Directory=$folder" "${long[@]}" > "$folder.log" 2>&1 &
  local pid=$!
  wait_until_stepping "$folder"
  if [ "$whom" = children ]; then kill -"$signal" $(pgrep -P $pid); else kill -"$signal" $pid; fi
  wait $pid
  local got=$?
  [ $got = $code ] || fail "$folder: SIG$signal gave exit code $got, expected $code: $(tail -3 "$folder.log")"
  grep -Eq "^dealmpm: stopped by SIG$signal at step [0-9]+ \(t = [0-9.e+-]+\); output in $folder/ is complete$" "$folder.log" \
    || fail "$folder: no stop line: $(tail -2 "$folder.log")"
  series_complete "$folder" || fail "$folder: series incomplete"
  # The last output is the state at the stop.
  local step
  step=$(grep -o "stopped by SIG$signal at step [0-9]*" "$folder.log" | grep -o "[0-9]*$")
  [ "$(tail -1 "$folder/statistics.csv" | cut -d, -f1)" = "$step" ] \
    || fail "$folder: the last statistics row is not of step $step"
}

stop_with TERM 143 term self "$dealmpm" "$scene"
stop_with INT 130 int self "$dealmpm" "$scene"
# A batch system signals every rank: they stop at the same step.
stop_with TERM 143 ranks children "$mpirun" "${flags[@]}" -np 2 "$dealmpm" "$scene"
# mpirun forwards SIGTERM to the ranks and kills them a second later; its
# own exit code is then 1. On a loaded machine the last output and the
# checkpoint may not finish in that second (doc/guide/output.md): then the series on
# disk must still be whole, up to the output before.
"$mpirun" "${flags[@]}" -np 2 "$dealmpm" "$scene" -s "Output/Directory=mpirun" "${long[@]}" \
  > mpirun.log 2>&1 &
pid=$!
wait_until_stepping mpirun
kill -TERM $pid
wait $pid
got=$?
[ $got = 1 ] || fail "mpirun: SIGTERM gave exit code $got, expected 1: $(tail -3 mpirun.log)"
series_complete mpirun || fail "mpirun: series incomplete"
if grep -Eq "^dealmpm: stopped by SIGTERM at step [0-9]+ " mpirun.log; then
  step=$(grep -o "stopped by SIGTERM at step [0-9]*" mpirun.log | grep -o "[0-9]*$")
  [ "$(tail -1 mpirun/statistics.csv | cut -d, -f1)" = "$step" ] \
    || fail "mpirun: the last statistics row is not of step $step"
else
  echo "mpirun: the ranks were killed before their last output (loaded machine); the series is whole"
fi

for i in 1 2 3 4 5 6 7 8; do
  "$dealmpm" "$scene" -s "Output/Directory=killed" "${long[@]}" -s "Output/Interval=0.001" \
    > killed.log 2>&1 &
  pid=$!
  sleep "$(python3 -c "import random; print(random.uniform(0.8, 2.5))")"
  kill -KILL $pid
  wait $pid 2> /dev/null
  series_complete killed || fail "SIGKILL $i: series incomplete"
done

finish "stop signal"
