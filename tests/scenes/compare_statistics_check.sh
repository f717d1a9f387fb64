#!/usr/bin/env bash
# compare_statistics itself: equal files pass; a difference past the
# tolerance, a NaN, an inf and a short row each fail.
compare=$1
failures=0
cd "$(mktemp -d)" || exit 1
printf 'time,mass,energy,wall_time\n0,1,2,0.1\n1,1,2.5,0.2\n' > a.csv
check() { # expected_exit file description
  "$compare" a.csv "$2" 1e-12 > out.txt 2>&1
  local code=$?
  if { [ "$1" = 0 ] && [ $code != 0 ]; } || { [ "$1" != 0 ] && [ $code = 0 ]; }; then
    echo "FAIL: $3: exit $code"; cat out.txt; failures=$((failures + 1))
  else
    echo "ok: $3 (exit $code)"
  fi
}
sed 's/0\.2$/9.9/' a.csv > wall.csv
check 0 wall.csv "only wall_time differs"
sed 's/2\.5/2.6/' a.csv > differs.csv
check 1 differs.csv "an energy differs"
sed 's/2\.5/nan/' a.csv > nan.csv
check 1 nan.csv "a NaN"
sed 's/2\.5/inf/' a.csv > inf.csv
check 1 inf.csv "an inf"
sed 's/,2\.5,0\.2$/,2.5/' a.csv > short.csv
check 1 short.csv "a short row"
[ $failures = 0 ] && echo "compare_statistics: all checks passed"
exit $((failures > 0))
