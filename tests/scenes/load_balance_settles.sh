#!/usr/bin/env bash
# The loop's load balance repartitions when a repartition would even out
# the load, and not at every check when it cannot:
# - a block at rest in a box of many empty cells (2 and 3 ranks): the
#   partition shares the cells' weights 1 + 10 n, so one rank holds all
#   particles and most others none; a trigger on the particle imbalance
#   repartitioned at every check (24 times in 233 steps before 2026-11-30,
#   and the 3D cube in a large box 159 times in 1,598 steps, 14x slower
#   than 1 rank). Only the start's repartition is allowed, and none where
#   the box is refined from coarse cells (its refinement shares the cells
#   by the particles to come);
# - a grid of 4 cells on 3 ranks, checked every step: no partition comes
#   within the limit, so after the start's repartition the check waits for
#   the imbalance to grow past the limit times what it reached;
# - the same box with the block crossing it and particles weighing most
#   (Particle weight = 1000): the partition follows the block.
set -euo pipefail
dealmpm=$1 mpirun=$2 scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags=(--oversubscribe)
[ "$(id -u)" = 0 ] && flags+=(--allow-run-as-root)

repartitions() { # name ranks overrides...: prints the run's repartitions
  local name=$1 n=$2; shift 2
  "$mpirun" "${flags[@]}" -np "$n" "$dealmpm" "$scene" -s "Output/Directory=$work/$name" \
    -s "Output/Write particles=false" -s "Output/Progress interval=0" "$@" > "$work/$name.log"
  grep -o "[0-9]* repartition(s)" "$work/$name.log" | cut -d' ' -f1 || echo 0
}
expect() { # name found wanted-test wanted-text
  echo "$1: $2 repartition(s), expected $4"
  [ "$2" $3 ] || exit 1
}

# The box as its own coarse mesh (40,000 cells, above 'auto''s 1e4), so
# that the start repartitions.
box=(-s "Grid/Upper corner=20, 5" -s "Grid/Cells=400, 100" -s "Time/End time=0.5"
  -s "Grid/Most coarse cells=1e5")
for n in 2 3; do
  expect "block at rest in a large box, $n ranks" \
    "$(repartitions box$n $n "${box[@]}" -s "Body 1/Velocity=0, 0")" "-eq 1" 1
done
# Refined from 100 x 25 coarse cells ('auto'), the refinement shares the
# cells by the particles the bodies will make: no repartition at all.
expect "block at rest in a large box refined from coarse cells, 2 ranks" \
  "$(repartitions refined 2 "${box[@]::6}" -s "Body 1/Velocity=0, 0")" "-eq 0" 0
expect "4 cells on 3 ranks, checked every step" \
  "$(repartitions coarse 3 -s "Grid/Cells=4, 1" -s "Body 1/Velocity=0, 0" \
    -s "Time/End time=0.5" -s "Load balance/Check interval=1")" "-eq 1" 1
expect "block crossing the box, particles weigh most" \
  "$(repartitions crossing 2 "${box[@]}" -s "Body 1/Velocity=20, 0" \
    -s "Load balance/Particle weight=1000")" "-ge 3" "3 or more"
