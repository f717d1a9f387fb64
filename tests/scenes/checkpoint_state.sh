#!/usr/bin/env bash
# A run resumed from its checkpoint at step 30 ends, at step 60, exactly
# where the uninterrupted run ends (every statistics column but wall_time,
# and every particle of the final particle CSV, bit for bit): the
# checkpoint holds all the state of the methods and effects each case
# uses (APIC's matrices, Newmark's accelerations and last step, the
# frictional contact's and boundary friction's work, heat conduction's
# temperatures and heat, the rigid body's
# motion, damage and plastic internal variables, the exact solution's
# error, the rotating frame's, local damping's, cpGIMP and CPDI domains, the
# B-spline's grid, 3D, FEM regions bonded and in contact; an adaptive grid
# with split particles to
# round-off, 1e-12). Total Lagrangian takes its reference positions
# X = x - u again and agrees to round-off (1e-12).
# Arguments: dealmpm, the prm folder, compare_statistics.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
prm=$2 compare=$3

resumes_exactly() { # name tolerance scene overrides...
  local name=$1 tolerance=$2 scene=$3; shift 3
  local common=(-s "Time/Maximum number of steps=60" -s "Checkpoint/Steps between checkpoints=30"
                -s "Output/Interval=0" -s "Output/Particle CSV=true" -s "Output/Write particles=false"
                -s "Output/Progress interval=0" "$@")
  "$dealmpm" "$scene" -s "Output/Directory=$name" "${common[@]}" > "$name.log" 2>&1 \
    || { fail "$name: the run failed: $(tail -1 "$name.log")"; return; }
  cp -r "$name" "$name-resumed"
  "$dealmpm" "$scene" -s "Output/Directory=$name-resumed" "${common[@]}" \
    --resume "$name-resumed/checkpoints/checkpoint-00000030" > "$name-resumed.log" 2>&1 \
    || { fail "$name: the resume failed: $(tail -1 "$name-resumed.log")"; return; }
  grep -q "^dealmpm: resumed from $name-resumed/checkpoints/checkpoint-00000030 at step 30 " "$name-resumed.log" \
    || fail "$name: no line that says where the run resumed"
  echo -n "$name: "
  "$compare" "$name/statistics.csv" "$name-resumed/statistics.csv" "$tolerance" \
    || fail "$name: the statistics differ"
  if [ "$tolerance" = 0 ]; then
    cmp -s "$name/steps/particles_00001.csv" "$name-resumed/steps/particles_00001.csv" \
      || fail "$name: the final particles differ"
  else
    python3 "$here/same_particles.py" "$name/steps/particles_00001.csv" "$name-resumed/steps/particles_00001.csv" \
      "$tolerance" || fail "$name: the final particles differ"
  fi
}

resumes_exactly disks 0 "$prm/colliding_disks.prm"
resumes_exactly apic 0 "$prm/colliding_disks.prm" -s "MPM/Velocity update=APIC" -s "MPM/Stress update=USL"
resumes_exactly newmark 0 "$prm/colliding_disks.prm" -s "MPM/Particle update=Newmark"
resumes_exactly contact 0 "$prm/colliding_disks.prm" -s "Effects=frictional contact" \
  -s "MPM/Velocity update=PIC"
resumes_exactly cpdi 0 "$prm/colliding_disks.prm" -s "MPM/Shape function=CPDI"
resumes_exactly incline 0 "$prm/incline_block.prm"
# Heat: temperatures and their gradients, friction heating, expansion.
resumes_exactly heat 0 "$prm/incline_block.prm" -s "Effects=gravity, boundary friction, heat conduction" \
  -s "Heat conduction/Specific heat=500" -s "Heat conduction/Conductivity=50" -s "Heat conduction/Thermal expansion=1e-4"
resumes_exactly punch 0 "$prm/punch.prm"
resumes_exactly projectile 0 "$prm/projectile_plate.prm"
resumes_exactly centrifuge 0 "$prm/centrifuge_slope.prm"
resumes_exactly manufactured 0 "$prm/manufactured_solution_2d.prm"
resumes_exactly vortex 0 "$prm/generalized_vortex.prm"
resumes_exactly column 0 "$prm/elastic_column_2d.prm" -s "MPM/Shape function=quadratic B-spline"
resumes_exactly cube 0 "$prm/cube_drop_3d.prm"
# The adaptive grid is loaded, not refined step by step: its grid comes
# back with other vertex and node numbers, and sums over nodes differ in
# the last bit (4e-16 seen).
resumes_exactly adaptive 1e-12 "$prm/colliding_disks.prm" -s "Adaptivity/Criteria=particles, velocity jump" \
  -s "Adaptivity/Steps between adaptations=7" -s "Body 1/Velocity=0.5, 0.5" -s "Body 2/Velocity=-0.3, -0.4"
# FEM regions: their displacement, velocity and quadrature-point state,
# bonded to a body and in frictional contact with one.
resumes_exactly bonded 0 "$prm/bonded_bar.prm"
# The region's temperatures, heat passing the bond.
resumes_exactly bonded-heat 0 "$prm/bonded_bar.prm" -s "Effects=heat conduction" \
  -s "Heat conduction/Specific heat=1" -s "Heat conduction/Conductivity=1e-3" \
  -s "Heat conduction/Initial temperature=x < 0.5 ? 400 : 300" -s "FEM region 1/Fixed temperatures=0: 500"
# APIC: the bonded nodes' affine velocity (the grid shifted so that they
# sit off its node lines, where the affine part counts).
resumes_exactly bonded_apic 0 "$prm/bonded_bar.prm" -s "MPM/Velocity update=APIC" -s "Grid/Cells=47, 1"
resumes_exactly fem_incline 0 "$prm/fem_incline.prm"
resumes_exactly total_lagrangian 1e-12 "$prm/elastic_column_2d.prm" \
  -s "MPM/Formulation=total Lagrangian" -s "Effects=gravity"

finish "checkpoint state"
