#!/usr/bin/env bash
# dealmpm --study on a tiny sweep (a few seconds): study.csv has one row per
# combination with its columns, runs that cannot work are rows with their
# reason (the B-spline refuses a locally refined grid, a run over the time
# limit is stopped)
# rather than an aborted study, the
# table and the plots are written, and a bad study file gets one line and
# exit code 2.
source "$(dirname "$0")/check_lib.sh"
base=$(dirname "$scene")/manufactured_solution_2d.prm

cat > tiny.prm <<END
subsection Study
  set Base scene       = $base
  set Output directory = tiny
  set Refinements      = 0, 1
  set Shape functions  = CPDI, quadratic B-spline
  set Stress updates   = USL, MUSL
  set Velocity updates = APIC
  set Settings         = Grid/Cells=4, 4; Time/End time=0.005; Grid/Local refinement/Levels=1; Grid/Local refinement/Lower corner=0, 0; Grid/Local refinement/Upper corner=0.5, 0.5
  set Jobs             = 2
end
END
"$dealmpm" --study tiny.prm > out.txt 2> err.txt
code=$?
[ $code = 0 ] || { fail "study: exit $code"; cat err.txt; }
grep -q "study: 8 of 8 done" out.txt || fail "study: no progress line for the last run"
grep -q "ETA" out.txt || fail "study: progress without ETA"
csv=tiny/study.csv
[ -s $csv ] || fail "study: no study.csv"
header="run,status,formulation,shape_function,stress_update,velocity_update,particles_per_cell,refinement,h,cfl_number,error_L2,error_max,wall_time,steps,particles,particle_steps_per_second,peak_memory_MB,energy_drift,momentum_drift,min_J,max_cfl,pareto_optimal,reason,adaptivity"
[ "$(head -1 $csv)" = "$header" ] || fail "study: header $(head -1 $csv)"
[ "$(wc -l < $csv)" = 9 ] || fail "study: $(($(wc -l < $csv) - 1)) rows, expected 8"
ok=$(grep -c ",ok,updated Lagrangian,CPDI,.*,APIC," $csv)
[ "$ok" = 4 ] || fail "study: $ok finished CPDI runs, expected 4"
refused=$(grep -c ',failed,updated Lagrangian,quadratic B-spline,.*B-spline needs a grid without hanging nodes' $csv)
[ "$refused" = 4 ] || fail "study: $refused refused B-spline rows, expected 4"
# Finished runs have an error, a wall time and a memory figure; h halves.
awk -F, '$2 == "ok" && ($11 == "" || $13 == "" || $17 == "") {exit 1}' $csv \
  || fail "study: a finished run without error, time or memory"
grep -q "^1,ok,updated Lagrangian,CPDI,USL,APIC,2,0,0.25," $csv || fail "study: run 1 settings"
grep -q "^2,ok,updated Lagrangian,CPDI,USL,APIC,2,1,0.125," $csv || fail "study: run 2 settings"
[ "$(awk -F, '$22 == 1' $csv | wc -l)" -ge 1 ] || fail "study: no Pareto-optimal run"
grep -q "Pareto" tiny/study.md || fail "study: study.md"
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  for f in study.png study.svg convergence.png convergence.svg; do
    [ -s tiny/$f ] || fail "study: no $f"
  done
fi

# A run over the time limit is killed and recorded; the study goes on.
cat > limit.prm <<END
subsection Study
  set Base scene         = $base
  set Output directory   = limit
  set Refinements        = 0, 5
  set Settings           = Grid/Cells=4, 4
  set Time limit per run = 1.5
end
END
"$dealmpm" --study limit.prm > out.txt 2> err.txt
code=$?
[ $code = 0 ] || { fail "time limit: exit $code"; cat err.txt; }
grep -q '^1,ok,' limit/study.csv || fail "time limit: the short run"
grep -q '^2,stopped,.*exceeded the time limit of 1.5 s' limit/study.csv \
  || { fail "time limit: the long run"; cat limit/study.csv; }

printf 'subsection Study\n  set Base scene = nowhere.prm\nend\n' > bad.prm
"$dealmpm" --study bad.prm > out.txt 2> err.txt
code=$?
[ $code = 2 ] && [ "$(wc -l < err.txt)" = 1 ] && grep -q "bad.prm.*Base scene" err.txt \
  || { fail "bad study: exit $code"; cat err.txt; }

finish study
