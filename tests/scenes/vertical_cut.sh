#!/usr/bin/env bash
# Anti-locking (F-bar) on a vertical cut in Tresca clay (prm/vertical_cut.prm,
# 5 cells over its height H = 1 m): at N = rho g H / c = 6, above Taylor's
# 3.83, the cut fails with F-bar (a Coulomb wedge of the face's height
# releases 2000 J/m or more when its centroid drops 0.2 m), where without
# anti-locking it locks and stands (under 300 J/m: the elastic settlement
# and a yielded toe); at N = 3 it stands with F-bar and without (under
# 50 J/m).
# 2 ranks release the same energy as 1 (to 1e-9). F-bar is refused, with
# one line, where it is not built (total Lagrangian,
# Newmark).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
prm=$(dirname "$scene") mpirun=$3

released() { # folder: the potential energy released by the end (J/m)
  python3 -c "
import csv
rows = list(csv.DictReader(open('$1/statistics.csv')))
print(float(rows[0]['gravitational_energy']) - float(rows[-1]['gravitational_energy']))"
}
run() { # folder, overrides...
  local out=$1; shift
  timeout 300 "$dealmpm" "$prm/vertical_cut.prm" -s "Output/Directory=$out" -s "Output/Write particles=false" \
    -s "Output/Progress interval=0" "$@" > "$out.log" 2>&1 || fail "$out: exit code $? ($(tail -1 "$out.log"))"
}
run fails
run locked -s "MPM/Anti-locking=none"
run stands -s "Material 1/Drucker-Prager/Cohesion=6540"
run stands_none -s "Material 1/Drucker-Prager/Cohesion=6540" -s "MPM/Anti-locking=none"
for case in "fails 2000 1e9" "locked 0 300" "stands 0 50" "stands_none 0 50"; do
  set -- $case
  e=$(released "$1")
  python3 -c "import sys; sys.exit(not ($2 <= $e <= $3))" \
    || fail "$1: released $e J/m, expected between $2 and $3"
  echo "$1: released $e J/m"
done

# On 2 ranks (a cell's particles are on its owner: no communication) the
# same, to the round-off of sums in another order.
timeout 300 "$mpirun" "${mpirun_flags[@]}" -np 2 "$dealmpm" "$prm/vertical_cut.prm" -s "Output/Directory=ranks" \
  -s "Output/Write particles=false" -s "Output/Progress interval=0" -s "Load balance/Enabled=false" \
  > ranks.log 2>&1 || fail "2 ranks: exit code $? ($(tail -1 ranks.log))"
one=$(released fails) two=$(released ranks)
python3 -c "import sys; sys.exit(not abs($one - $two) <= 1e-9 * abs($one))" \
  || fail "2 ranks released $two J/m, 1 rank $one"

for bad in "MPM/Formulation=total Lagrangian" "MPM/Particle update=Newmark"; do
  if "$dealmpm" "$prm/vertical_cut.prm" -s "$bad" -s "Body 1/Initial stress=none" \
       -s "Output/Directory=bad" > bad.log 2>&1; then
    fail "F-bar with $bad ran"
  fi
  [ "$(wc -l < bad.log)" = 1 ] && grep -q "entry 'MPM/Anti-locking' = 'F-bar'.*expected 'none'" bad.log \
    || fail "F-bar with $bad: $(cat bad.log)"
done
finish "vertical cut"
