#!/usr/bin/env bash
# Runs that cannot go on stop with the step, the particle and the reason
# (exit 3) and leave their last good output; particles that leave the grid
# are removed and counted, or stop the run, as the scene says.
source "$(dirname "$0")/check_lib.sh"

# A fixed time step far above the stability limit (particle CFL 13) stops
# at once with the fastest particle and the largest stable step.
"$dealmpm" "$scene" -s "Output/Directory=unstable" -s "Time/Time step method=fixed" -s "Time/Time step=0.5" \
  -s "Time/End time=100" -s "Output/Interval=0.5" > out.txt 2> err.txt
code=$?
[ $code = 3 ] || fail "unstable run: exit $code, expected 3"
grep -Eq "stopped: step 1 \(t = 0\): particle [0-9]+ at \(.*\): the fixed time step 0.5 gives a particle CFL number .* of 13(\.[0-9]*)? > 1, which is unstable; the largest stable step here is 0.038[0-9]*: " err.txt \
  || { fail "unstable run: message"; cat err.txt; }
[ -s unstable/particles.pvd ] && [ -s unstable/statistics.csv ] \
  || fail "unstable run: last good output missing"
grep -q "steps/particles_00000.pvtu" unstable/particles.pvd || fail "pvd lacks the first output"

# Between 'Checks/CFL warning' and 1: one warning, the run goes on.
"$dealmpm" "$scene" -s "Output/Directory=warned" -s "Time/Time step method=fixed" -s "Time/Time step=0.025" \
  -s "Time/End time=0.2" -s "Output/Write particles=false" > out.txt 2> err.txt
code=$?
[ $code = 0 ] || fail "warned run: exit $code"
[ "$(grep -c "^dealmpm: warning: step 1 .*particle CFL number .* of 0.65.*above 'Checks/CFL warning' = 0.5" err.txt)" = 1 ] \
  || { fail "warned run: one warning on standard error expected"; cat err.txt; }
grep -q "warning" out.txt && fail "warned run: a warning on standard output"

# Energy that grows (the disks with the CFL step at 1, above USL's stable
# c dt / h = 1 / sqrt(2) for linear shape functions in 2D: the energy grows
# from t = 1.4) stops the run with the particle whose energy grew most;
# unguarded, it rises past 10 % of the energy put in.
growth=(-s "Time/Time step method=CFL" -s "Time/CFL number=1" -s "MPM/Stress update=USL"
        -s "MPM/Shape function=linear" -s "Output/Write particles=false")
"$dealmpm" "$scene" "${growth[@]}" -s "Output/Directory=growth" > out.txt 2> err.txt
code=$?
[ $code = 3 ] || fail "energy growth: exit $code, expected 3"
grep -Eq "stopped: step [0-9]+ \(t = 1\.[0-9]+\): the total energy grew by [0-9.]+ % of the energy put in \(limit 'Checks/Energy growth limit' = 10 %\); the particle whose energy grew most: particle [0-9]+ at \(.*\) \(\+[0-9.e-]+ J\)\. .*try a smaller 'Time/CFL number'.*The last good output" err.txt \
  || { fail "energy growth: message"; cat err.txt; }
last_drift=$(tail -1 growth/statistics.csv | awk -F, '{print $13}')
awk -v d="$last_drift" 'BEGIN { exit !(d < 0.1) }' || fail "energy growth: last row drift $last_drift"
"$dealmpm" "$scene" "${growth[@]}" -s "Output/Directory=unguarded" -s "Checks/Energy growth limit=0" > out.txt 2> err.txt
most=$(awk -F, 'NR > 1 && $13 > m { m = $13 } END { print m + 0 }' unguarded/statistics.csv)
awk -v d="$most" 'BEGIN { exit !(d > 0.1) }' \
  || fail "energy growth: without the guard the energy should grow past 10 %, not $most"

# Disks flying out of a grid with free boundaries.
flying=(-s "Body 1/Velocity=-2, 0" -s "Body 2/Velocity=2, 0" -s "Time/End time=0.1"
        -s "Output/Write particles=false")
# By default a run that loses more than 1 % of its mass stops (exit 3),
# at the first step past it, and says how much went: it exited 0 after
# losing half its mass.
"$dealmpm" "$scene" "${flying[@]}" -s "Output/Directory=mass_lost" > out.txt 2> err.txt
code=$?
[ $code = 3 ] || fail "mass loss limit: exit $code, expected 3"
line=$(grep "^dealmpm: stopped: .*particle(s) left the grid .*the particles removed so far carried [0-9.e+-]* % of the mass (limit 'Checks/Mass loss limit' = 1 %)" err.txt)
[ -n "$line" ] || { fail "mass loss limit: no line naming the limit"; cat err.txt; }
# Past 1 %, by at most the particles of one step (a row of a disk, 16 of 416).
percent=$(echo "$line" | sed 's/.*carried \([0-9.e+-]*\) % of the mass.*/\1/')
awk -v p="$percent" 'BEGIN { exit !(p > 1 && p <= 1 + 100 * 16 / 416) }' \
  || fail "mass loss limit: stopped at $percent % of the mass"
# A limit the run stays under: it runs to its end, and the summary says
# how much mass went.
"$dealmpm" "$scene" "${flying[@]}" -s "Output/Directory=removed" -s "Checks/Mass loss limit=0.9" > out.txt 2> err.txt
code=$?
[ $code = 0 ] || fail "remove policy: exit $code"
grep -Eq "particle\(s\) left the grid \([0-9.e+-]+ % of the mass\)" out.txt \
  || fail "remove policy: the summary does not say how much mass left"
# Warnings go to standard error, once per kind, with a count at the end
# (the disks leave over many steps; it was a line a step on stdout).
[ "$(grep -c "^dealmpm: warning: step .* particle(s) left the grid (first: id" err.txt)" = 1 ] \
  || { fail "remove policy: one warning on standard error expected"; cat err.txt; }
grep -Eq "^dealmpm: warning: [0-9]+ more 'particles left the grid' warnings? after the first \(above\)$" err.txt \
  || { fail "remove policy: no count of the later warnings"; cat err.txt; }
grep -q "warning" out.txt && fail "remove policy: a warning on standard output"
lost=$(tail -1 removed/statistics.csv | awk -F, '{print $(NF-1)}')
particles=$(tail -1 removed/statistics.csv | awk -F, '{print $4}')
[ "$lost" != 0 ] && [ "$((lost + particles))" = 416 ] || fail "remove policy: lost $lost + left $particles != 416"

"$dealmpm" "$scene" "${flying[@]}" -s "Output/Directory=stopped" \
  -s "MPM/Particles leaving the grid=stop" > out.txt 2> err.txt
code=$?
[ $code = 3 ] || fail "stop policy: exit $code, expected 3"
grep -q "left the grid (first: id [0-9]* at (" err.txt || fail "stop policy: message"

# When the last particle has left, the run stops and says so.
"$dealmpm" "$scene" "${flying[@]}" -s "Time/End time=1" -s "Output/Directory=empty" \
  -s "Time/Time step method=CFL" -s "Checks/Mass loss limit=0" > out.txt 2> err.txt
code=$?
[ $code = 3 ] || fail "all particles gone: exit $code, expected 3"
grep -q "no particles are left in the grid" err.txt || { fail "all particles gone: message"; cat err.txt; }

# CPDI domains sheared past the cells next to theirs (the vortex twisted by
# a full radian): a stop naming the particle, not wrong weights.
"$dealmpm" "$(dirname "$scene")/generalized_vortex.prm" -s "Output/Directory=cpdi" \
  -s "MPM/Shape function=CPDI" -s "Generalized vortex/Amplitude=1" \
  -s "Grid/Cells=24, 24" -s "Output/Write particles=false" > out.txt 2> err.txt
code=$?
[ $code = 3 ] || fail "CPDI domain: exit $code, expected 3"
grep -q "particle [0-9]* at (.*): its CPDI domain reaches past the cells" err.txt \
  || { fail "CPDI domain: message"; cat err.txt; }

# A bonded FEM region whose coupling nodes leave the grid (the bar moving
# left at 5 m/s, nothing holding it): the run stops at the step's
# reduction with the node's position, on 1 and 2 ranks (the nodes go
# point to point; before 2026-11-30 the stop came from a sum over all
# ranks inside the step and named no step).
leaving=(-s "FEM region 1/Fixed boundaries=" -s "FEM region 1/Initial velocity=-5, 0"
         -s "Body 1/Velocity=-5, 0" -s "Output/Write particles=false")
for ranks in 1 2; do
  mpirun "${mpirun_flags[@]}" -np $ranks "$dealmpm" "$(dirname "$scene")/bonded_bar.prm" \
    "${leaving[@]}" -s "Output/Directory=bonded_$ranks" > out.txt 2> err.txt
  code=$?
  [ $code = 3 ] || fail "bonded node off the grid on $ranks rank(s): exit $code, expected 3"
  grep -q "stopped: step 102 (t = 0.102): a coupling node of an FEM region at (-0.005, 0) left the background grid" err.txt \
    || { fail "bonded node off the grid on $ranks rank(s): message"; cat err.txt; }
  [ -s "bonded_$ranks/statistics.csv" ] || fail "bonded node off the grid: last good output missing"
done

# A section the scene sets but does not use is named, not ignored silently:
# gravity's entry without gravity in 'Effects', a model's subsection other
# than the material's model.
"$dealmpm" "$scene" -s "Output/Directory=unused" -s "Time/Maximum number of steps=2" \
  -s "Gravity/Acceleration=0, -9.81" -s "Material 1/neo-Hookean/Young's modulus=5" > out.txt 2> err.txt
code=$?
[ $code = 0 ] || fail "unused sections: exit $code"
grep -q "^dealmpm: warning: command line: -s 'Gravity/Acceleration=0, -9.81': 'Gravity/Acceleration' is set, but 'gravity' is not in 'Effects': add it there, or the entry does nothing$" err.txt \
  || { fail "unused sections: no warning for gravity"; cat err.txt; }
grep -q "^dealmpm: warning: command line: -s 'Material 1/neo-Hookean/Young's modulus=5': 'Material 1/neo-Hookean/Young's modulus' is set, but 'Material 1/Model' is 'linear elastic': the entry does nothing$" err.txt \
  || { fail "unused sections: no warning for the model"; cat err.txt; }
sed 's/^set Effects.*//' "$scene" > no_effects.prm
printf 'subsection Gravity\n  set Acceleration = 0, -9.81\nend\n' >> no_effects.prm
"$dealmpm" no_effects.prm -s "Output/Directory=unused2" -s "Time/Maximum number of steps=2" > out.txt 2> err.txt
grep -Eq "^dealmpm: warning: no_effects.prm: line [0-9]+: 'Gravity/Acceleration' is set, but 'gravity' is not in 'Effects'" err.txt \
  || { fail "unused sections: no warning for the file's gravity"; cat err.txt; }
# The shipped scene sets nothing it does not use: no warning.
"$dealmpm" "$scene" -s "Output/Directory=used" -s "Time/Maximum number of steps=2" > out.txt 2> err.txt
[ -s err.txt ] && { fail "the shipped scene warns"; cat err.txt; }
# The accuracy line checks momentum only where the scene conserves it: the
# disks (no walls, no forces) get a number, the column between walls under
# gravity "n/a" (it read a drift of 196 % there, which meant nothing).
grep -Eq "^dealmpm: accuracy: .*, momentum drift [0-9.e+-]+ %, mass loss" out.txt \
  || fail "the disks: no momentum drift in $(grep accuracy out.txt)"
column=$(dirname "$scene")/elastic_column_2d.prm
"$dealmpm" "$column" -s "Output/Directory=column" -s "Time/Maximum number of steps=5" > out.txt 2> err.txt
grep -q "^dealmpm: accuracy: .*, momentum drift n/a (walls, loads or body forces act), mass loss" out.txt \
  || fail "the column: momentum drift not n/a in $(grep accuracy out.txt)"

finish run-stop
