#!/usr/bin/env bash
# Run every shipped scene (prm/ and prm/hard-cases/) with two dealmpm
# programs for a few hundred steps and compare their statistics.csv with
# compare_statistics: a refactoring must leave them equal to round-off.
#
#   scripts/compare_scenes.sh OLD_DEALMPM NEW_DEALMPM COMPARE_STATISTICS \
#       [steps=200] [tolerance=1e-12]
#
# Prints one line per scene (same / DIFFERENT / failed) and exits 1 when
# any scene differs or fails in one program only.
set -uo pipefail
old=$1 new=$2 compare=$3 steps=${4:-200} tol=${5:-1e-12}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for scene in "$root"/prm/*.prm "$root"/prm/hard-cases/*.prm; do
  name=$(basename "$scene" .prm)
  codes=""
  for which in old new; do
    program=$old; [ $which = new ] && program=$new
    "$program" "$scene" -s "Time/Maximum number of steps=$steps" \
      -s "Output/Directory=$work/$which-$name" \
      -s "Output/Write particles=false" \
      > "$work/$which-$name.log" 2>&1
    codes="$codes $?"
  done
  a=$work/old-$name/statistics.csv b=$work/new-$name/statistics.csv
  if [ "$codes" != " 0 0" ]; then
    if [ "$(echo $codes | tr ' ' '\n' | sort -u | wc -l)" = 1 ] && [ -f "$a" ] && [ -f "$b" ] \
       && "$compare" "$a" "$b" "$tol" > /dev/null 2>&1; then
      echo "same (both exit$codes): $name"
    else
      echo "failed (exit$codes): $name"; tail -2 "$work/new-$name.log"; status=1
    fi
  elif "$compare" "$a" "$b" "$tol" > "$work/$name.cmp" 2>&1; then
    echo "same: $name ($(($(wc -l < "$b") - 1)) rows)"
  else
    echo "DIFFERENT: $name"; head -3 "$work/$name.cmp"; status=1
  fi
done
exit $status
