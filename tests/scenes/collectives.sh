#!/usr/bin/env bash
# What a step sends between ranks, counted on rank 0 of 2 by the MPI
# wrapper tests/tools/mpi_count.cc (LD_PRELOAD): the difference between
# runs of 40 and 20 steps of the 2D elastic column, per step, so that
# set-up and output cancel. USL and MUSL with linear shape functions
# (weights computed where used), USL with cpGIMP and the B-spline (a
# stored stencil, which cannot fail: no check of it across ranks) and with
# CPDI (whose stencil can fail: the step's reduction carries that; a
# reduction of its own before 2026-11-30, 3 a step); the imbalance check (one reduction every 'Check interval' steps) is moved
# out of reach. Then three scenes with FEM regions (prm/): bonded
# (bonded_bar), in contact (pile_in_sand) and both with friction
# (fem_incline). Their coupling nodes go point to point to the ranks that
# place them (NodesOnGrid); before 2026-11-30 every rank gathered every
# coupling node and summed the answers over all ranks, 5 collectives a
# step.
# - Collectives (reductions, barriers, ...): at most 2 per step, the
#   step's own reduction (time step, smallest J, failed particles,
#   particles that left their cell) and the run's agreement on stop
#   signals and checkpoints. The MPI-aware step timer alone cost a barrier
#   and three reductions per section and step (28 reductions and 8
#   barriers per step before 2026-11-29).
# - Point-to-point sends: one message per neighbour for the sums of a P2G
#   (mass, momentum, force together) and one for the ghosts of the grid
#   update (v*, increment, light-node weights together): 2 per step for
#   USL, 4 for MUSL (its second P2G and its velocity from momentum), with
#   one neighbour. Before NodalExchange (2026-11-29) each vector was a
#   message of its own: 10 for USL, 14 for MUSL, 9 with a stored stencil.
set -euo pipefail
dealmpm=$1 mpirun=$2 counter=$3 scene=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags=(--oversubscribe)
[ "$(id -u)" = 0 ] && flags+=(--allow-run-as-root)

count() { # scene steps overrides... -> "collectives point_to_point" of rank 0
  local run_scene=$1 steps=$2; shift 2
  rm -f "$work/count"
  "$mpirun" "${flags[@]}" -np 2 -x LD_PRELOAD="$counter" -x MPI_COUNT_FILE="$work/count" \
    "$dealmpm" "$run_scene" -s "Time/Maximum number of steps=$steps" -s "Output/Interval=1e9" \
    -s "Output/Directory=$work/out" -s "Load balance/Check interval=1000" "$@" > "$work/log"
  grep -q "2 rank(s) ([1-9][0-9]* to" "$work/log" || { echo "a rank without particles"; exit 1; }
  awk '{ print $2, $4 }' "$work/count"
}

per_step() { # what sends scene overrides... -> a line; fails above 2 collectives or the sends
  local what=$1 sends=$2 run_scene=$3; shift 3
  read -r c20 p20 < <(count "$run_scene" 20 "$@")
  read -r c40 p40 < <(count "$run_scene" 40 "$@")
  awk -v s="$what" -v c=$((c40 - c20)) -v p=$((p40 - p20)) -v sends="$sends" 'BEGIN {
    printf "%s: %.2f collectives and %.2f sends per step on rank 0 of 2\n", s, c / 20, p / 20
    if (c / 20 > 2) { print "  more than 2 collectives per step"; exit 1 }
    if (sends != "" && p / 20 > sends) { print "  more than " sends " sends per step"; exit 1 } }'
}

for limits in USL:linear:2 MUSL:linear:4 USL:cpGIMP:2 "USL:quadratic B-spline:2" USL:CPDI:2; do
  IFS=: read -r scheme kernel sends <<< "$limits"
  per_step "$scheme, $kernel" "$sends" "$scene" -s "Grid/Cells=32, 144" \
    -s "MPM/Stress update=$scheme" -s "MPM/Shape function=$kernel"
done
# Half the column moving sideways at 3 m/s: particles change cells every
# few steps (within their rank), and relocation agrees in the step's
# reduction. Before 2026-11-30 relocation had reductions of its own (the
# largest plan, then the held and lost particles): 2.6 a step here.
per_step "USL, linear, moving" 2 "$scene" -s "Grid/Cells=32, 144" \
  -s "Body 1/Upper corner=0.5, 4" -s "Body 1/Velocity=3, 0"
prm=$(dirname "$scene")/../prm
for fem_scene in bonded_bar pile_in_sand fem_incline; do
  per_step "$fem_scene" "" "$prm/$fem_scene.prm"
done
