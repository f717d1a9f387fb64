#!/usr/bin/env bash
# Bodies that come to rest under a constant load: the load does no more
# work, friction without slip dissipates nothing, and the energy guard lets
# them run (the energy they were given is near zero; the guard's scale is
# then the work of gravity and the loads over a thousandth of a cell,
# (m |g| + F) h / 1000, and
# the report says so).
#   at_rest.sh dealmpm prm/incline_block.prm
source "$(dirname "$0")/check_lib.sh"

# column NAME FILE -> the column's values, one per row
column() {
  awk -F, -v name="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
                        { print $c }' "$2"
}
# value of column NAME at the first row with time >= T
at_time() {
  awk -F, -v name="$1" -v t="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == name) c = i; if ($i == "time") k = i }; next }
                                  $k >= t { print $c; exit }' "$2"
}
close_to() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= tol) }'; }

# A block on an incline that friction holds: the incline of doc/guide/effects.md with mu =
# 0.6 > tan 30 deg, and tan theta = 0.466 < mu = 0.55. The friction work
# is spent while the block settles and then stays; the energy does not
# grow (the drift stays below 1 %; PIC dissipates while the block
# settles, so it may fall).
quiet=(-s "Output/Write particles=false" -s "Output/Interval=0.05")
run_incline() { # name overrides...
  local name=$1; shift
  "$dealmpm" "$scene" "${quiet[@]}" -s "Time/End time=1" -s "Output/Directory=$name" "$@" > out.txt 2> err.txt
  local code=$?
  [ $code = 0 ] || { fail "$name: exit $code"; cat err.txt; return; }
  local settled last
  settled=$(at_time boundary_friction_work "$name/statistics.csv" 0.3)
  last=$(column boundary_friction_work "$name/statistics.csv" | tail -1)
  echo "$name: friction work $settled J at t = 0.3, $last J at t = 1"
  # A sliding block would dissipate mu m g cos(theta) per metre: 1e-6 J is
  # a slide of about 1e-8 m.
  close_to "$settled" "$last" 1e-6 || fail "$name: friction work changed at rest ($settled -> $last)"
  local drift
  for drift in $(column energy_drift "$name/statistics.csv"); do
    awk -v d="$drift" 'BEGIN { exit !(d < 0.01) }' || { fail "$name: energy drift $drift"; break; }
  done
}
run_incline incline_06 -s "Boundary friction/Coefficients=2: 0.6"
run_incline incline_055 -s "Boundary friction/Coefficients=2: 0.55" -s "Gravity/Acceleration=4.14381, -8.89175"

# A block pulled onto a fixed rigid box by a constant traction on its
# bottom face (inside its corners: the faces all face down), where the box
# holds the nodes the load pushes: once it rests, the load does no work.
cat > pulled.prm <<'PRM'
set Dimension           = 2
set Number of bodies    = 1
set Number of materials = 1
set Effects             = traction, rigid body, local damping
subsection Traction
  set Bodies            = 1
  set Surface selection = y < 0.11 & x > 0.11 & x < 0.29
  set Traction          = 0; -1e4
  set Load curve        = 0: 0, 0.1: 1
end
subsection Rigid body
  set Lower corner = -1, -1
  set Upper corner = 2, 0.1
  set Velocity     = 0; 0
end
subsection Local damping
  set Coefficient = 0.2
end
subsection Grid
  set Type         = rectangle
  set Lower corner = 0, 0
  set Upper corner = 0.4, 0.4
  set Cells        = 32, 32
end
subsection Material 1
  set Model   = linear elastic
  set Density = 1000
  subsection linear elastic
    set Young's modulus = 1e6
    set Poisson's ratio = 0.3
  end
end
subsection MPM
  set Velocity update = PIC
end
subsection Body 1
  set Lower corner = 0.1, 0.1
  set Upper corner = 0.3, 0.3
end
subsection Time
  set End time = 0.8
end
PRM
"$dealmpm" pulled.prm "${quiet[@]}" -s "Output/Directory=pulled" > out.txt 2> err.txt
code=$?
if [ $code = 0 ]; then
  settled=$(at_time traction_work pulled/statistics.csv 0.5)
  last=$(column traction_work pulled/statistics.csv | tail -1)
  echo "pulled block: traction work $settled J at t = 0.5, $last J at t = 0.8"
  # The box holds every node the load pushes, so the block never moves:
  # 1e-6 of the load's work over one cell (1800 N/m x 0.0125 m) is the
  # tolerance; counted before the box's correction, it grew by 70 J.
  close_to "$settled" "$last" 2e-5 \
    || fail "pulled block: traction work changed at rest ($settled -> $last)"
  # Nothing moves, so nothing is put in: the drift is measured against the
  # floor, and the report says so.
  grep -Fq "% of (m |g| + F) h / 1000" out.txt || fail "pulled block: the report should name the scale (m |g| + F) h / 1000"
else
  fail "pulled block: exit $code"; cat err.txt
fi
finish "at rest"
