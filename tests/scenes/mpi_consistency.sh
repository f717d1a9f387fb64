#!/usr/bin/env bash
# The same scene on 1 and 2 MPI ranks gives the same statistics (relative
# difference below 1e-9 over a short run):
# - the colliding disks, colliding across the rank boundary, with a non-zero
#   total momentum so that it compares meaningfully;
# - the same on a grid refined in a box (hanging nodes whose masters sit on
#   the other rank);
# - cpGIMP with MUSL on the refined grid (particle domains reach into ghost
#   cells);
# - CPDI on the refined grid (corners located in ghost cells) and the
#   quadratic B-spline (3 x 3 node blocks reaching into ghost cells);
# - the 3D elastic column settling (slip walls, gravity, damping, CFL step);
# - total Lagrangian: the 3D column, and the cantilever with the quadratic
#   B-spline (reference stencils reaching into ghost cells);
# - the Newmark particle update on the disks (particles carry their
#   acceleration across the rank boundary);
# - two materials of different stiffness sharing cells (the projectile on
#   its plate, without erosion: the mixed-cell split reads nodes of both
#   ranks; it read the nodal velocity by global index and crashed on
#   rank 1 before issue 13).
# Every run must have particles on both ranks.
set -euo pipefail
dealmpm=$1 compare=$2 mpirun=$3 disks=$4 column=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags=(--oversubscribe)
[ "$(id -u)" = 0 ] && flags+=(--allow-run-as-root)

compare_ranks() { # name scene overrides...
  local name=$1 scene=$2; shift 2
  for n in 1 2; do
    "$mpirun" "${flags[@]}" -np $n "$dealmpm" "$scene" -s "Output/Directory=$work/$name$n" \
      -s "Output/Write particles=false" -s "Output/Progress interval=0" "$@" > "$work/$name$n.log"
  done
  grep -q "2 rank(s) ([1-9][0-9]* to" "$work/${name}2.log" \
    || { echo "$name: a rank without particles:"; head -1 "$work/${name}2.log"; exit 1; }
  echo -n "$name: "
  "$compare" "$work/${name}1/statistics.csv" "$work/${name}2/statistics.csv" 1e-9
}

fast=(-s "Body 1/Velocity=0.5, 0.5" -s "Body 2/Velocity=-0.3, -0.4" -s "Time/End time=0.6" -s "Output/Interval=0.05")
compare_ranks disks "$disks" "${fast[@]}"
compare_ranks refined "$disks" "${fast[@]}" -s "Grid/Local refinement/Levels=1" \
  -s "Grid/Local refinement/Lower corner=-0.25, -0.5" -s "Grid/Local refinement/Upper corner=0.25, 0.5"
compare_ranks gimp "$disks" "${fast[@]}" -s "MPM/Shape function=cpGIMP" -s "MPM/Stress update=MUSL" \
  -s "Grid/Local refinement/Levels=1" -s "Grid/Local refinement/Lower corner=-0.25, -0.5" \
  -s "Grid/Local refinement/Upper corner=0.25, 0.5"
compare_ranks cpdi "$disks" "${fast[@]}" -s "MPM/Shape function=CPDI" \
  -s "Grid/Local refinement/Levels=1" -s "Grid/Local refinement/Lower corner=-0.25, -0.5" \
  -s "Grid/Local refinement/Upper corner=0.25, 0.5"
compare_ranks bspline "$disks" "${fast[@]}" -s "MPM/Shape function=quadratic B-spline"
compare_ranks newmark "$disks" "${fast[@]}" -s "MPM/Particle update=Newmark"
compare_ranks column "$column" -s "Time/End time=0.3" -s "Output/Interval=0.02"
compare_ranks column_tl "$column" -s "Time/End time=0.3" -s "Output/Interval=0.02" \
  -s "MPM/Formulation=total Lagrangian"
compare_ranks cantilever_tl "$(dirname "$disks")/hard-cases/cantilever.prm" -s "Time/End time=0.3" \
  -s "Output/Interval=0.05" -s "Output/Particle CSV=false" -s "MPM/Formulation=total Lagrangian" \
  -s "MPM/Shape function=quadratic B-spline" -s "Grid/Lower corner=0, 0" -s "Grid/Upper corner=4, 1" \
  -s "Grid/Cells=32, 8"
compare_ranks mixed "$(dirname "$disks")/projectile_plate.prm" -s "Effects=" -s "Time/End time=2e-5" \
  -s "Output/Interval=5e-6"
