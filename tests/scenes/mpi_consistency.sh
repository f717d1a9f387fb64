#!/usr/bin/env bash
# The same scene on 1 and 2 MPI ranks gives the same statistics (relative
# difference below 1e-9 over a short run; the disks collide across the rank
# boundary, and their total momentum is not zero so that it compares
# meaningfully).
set -euo pipefail
dealmpm=$1 compare=$2 mpirun=$3 scene=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags=(--oversubscribe)
[ "$(id -u)" = 0 ] && flags+=(--allow-run-as-root)
for n in 1 2; do
  "$mpirun" "${flags[@]}" -np $n "$dealmpm" "$scene" -s "Output/Directory=$work/np$n" \
    -s "Time/End time=0.6" -s "Output/Interval=0.05" -s "Output/Write particles=false" \
    -s "Body 1/Velocity=0.5, 0.5" -s "Body 2/Velocity=-0.3, -0.4" > "$work/np$n.log"
done
grep -q "2 rank(s)" "$work/np2.log"
"$compare" "$work/np1/statistics.csv" "$work/np2/statistics.csv" 1e-9
