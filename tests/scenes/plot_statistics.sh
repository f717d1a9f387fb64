#!/usr/bin/env bash
# scripts/plot_statistics.py draws a run's statistics.csv: the energies and
# the balance by default, any columns against any other (negated with a
# leading '-'); a column that is not there is one line and exit 2.
#   plot_statistics.sh DEALMPM SCENE SOURCE_DIR
source "$(dirname "$0")/check_lib.sh"
script=$3/scripts/plot_statistics.py
# python3 as a user types it (the script finds Debian's matplotlib itself
# when a python3 earlier on PATH lacks it).
python=python3
"$dealmpm" "$scene" -s "Output/Directory=run" -s "Time/End time=0.5" -s "Output/Write particles=false" \
  > run.log 2>&1 || fail "the run failed: $(tail -2 run.log)"
is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] && [ "$(wc -c < "$1")" -gt 10000 ]; }
[ "$("$python" "$script" run/statistics.csv)" = run/statistics.png ] || fail "default: not written where said"
is_png run/statistics.png || fail "default: run/statistics.png is not a picture"
"$python" "$script" run/statistics.csv --y kinetic_energy,strain_energy --x=-time -o pair.svg > /dev/null \
  || fail "two columns against a negated one failed"
grep -q "<svg" pair.svg && grep -q "kinetic_energy" pair.svg || fail "pair.svg lacks the plot or its legend"
"$python" "$script" run/statistics.csv --y kinetic_enrgy > out.txt 2> err.txt
code=$?
[ $code = 2 ] && [ "$(wc -l < err.txt)" = 1 ] && grep -q "no column 'kinetic_enrgy' (the columns: step, time" err.txt \
  || fail "a missing column: exit $code, $(cat err.txt)"
finish plot-statistics
