#!/usr/bin/env bash
# Speed of the explicit step on the elastic column (USL, linear shape
# functions, 2^dim particles per cell, 200 steps, no output), one rank:
# particle-steps per second per core (best of 3 runs: the machine is shared
# and noisy), and memory per particle as the growth of peak resident memory
# between sizes divided by the growth in particles.
# Then the same per shape function, relative to linear; then the column
# flowing: lifted off the floor (no wall holds it) in a grid three times
# as tall and given 250 m/s upwards, about twice its wave speed, so that
# a particle changes cell every third step, against the same column at
# rest in the same grid (the particles' sort is what differs).
# Then the particles' own memory: the growth of peak memory on a fixed grid
# when the particles per cell rise (2 to 4 per direction in 2D, 2 to 3 in
# 3D), per particle added.
#   benchmarks/run_benchmarks.sh [path/to/dealmpm] [sizes|kernels|flowing|memory|all]
# With `setup`, the set-up of the 1 M-particle column against 1, 2 and 4
# ranks (mpirun).
# With `compare OLD [rounds]`, the column at each size from 65k particles
# up, run by OLD and by this dealmpm in turn (rounds times, default 3; the
# best of each): the speed-up measured in one run, as the machine's load
# changes for both alike.
#   benchmarks/run_benchmarks.sh path/to/dealmpm compare path/to/old [rounds]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dealmpm=${1:-$here/../build/dealmpm}
part=${2:-all}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The particles and peak MB a run printed in $work/log.
log_particles() { grep -o '[0-9]* particles,' "$work/log" | grep -o '[0-9]*'; }
log_mb() { grep -o 'peak memory [0-9]* MB' "$work/log" | grep -o '[0-9]*'; }

best_rate() { # dim cells overrides... -> best of 3 M particle-steps/s
  local dim=$1 cells=$2 rate="" r; shift 2
  for repeat in 1 2 3; do
    "$dealmpm" "$here/elastic_column_${dim}d.prm" -s "Grid/Cells=$cells" \
      -s "Output/Directory=$work/out" "$@" > "$work/log" 2>&1
    r=$(grep -o '([0-9.e+-]* M per core)' "$work/log" | grep -o '[0-9.e+-]*' | head -1)
    rate=$(printf '%s\n%s\n' "$rate" "$r" | sort -g | tail -1)
  done
  echo "$rate"
}

run() { # dim cells
  local dim=$1 cells=$2
  local particles rate="" mb r
  for repeat in 1 2 3; do
    "$dealmpm" "$here/elastic_column_${dim}d.prm" -s "Grid/Cells=$cells" \
      -s "Output/Directory=$work/out" > "$work/log" 2>&1
    r=$(grep -o '([0-9.e+-]* M per core)' "$work/log" | grep -o '[0-9.e+-]*' | head -1)
    rate=$(printf '%s\n%s\n' "$rate" "$r" | sort -g | tail -1)
  done
  particles=$(log_particles)
  mb=$(log_mb)
  local marginal="-"
  if [ -n "${previous_particles:-}" ]; then
    marginal=$(( (mb - previous_mb) * 1048576 / (particles - previous_particles) ))
  fi
  echo "| ${dim}D | $cells | $particles | $rate | $mb | $marginal |"
  previous_particles=$particles previous_mb=$mb
}
if [ "$part" = compare ]; then
  old=${3:?"compare needs the old dealmpm: run_benchmarks.sh NEW compare OLD [rounds]"}
  rounds=${4:-3}
  rate_of() { # binary dim cells -> M particle-steps/s per core of one run
    "$1" "$here/elastic_column_${2}d.prm" -s "Grid/Cells=$3" \
      -s "Output/Directory=$work/out" > "$work/log" 2>&1
    grep -o '([0-9.e+-]* M per core)' "$work/log" | grep -o '[0-9.e+-]*' | head -1
  }
  echo "| dim | cells | particles | old, M p-steps/s | new | new / old |"
  echo "|---|---|---|---|---|---|"
  for size in "2|64, 288" "2|128, 576" "2|256, 1152" "3|16, 16, 72" "3|24, 24, 108"; do
    dim=${size%%|*} cells=${size#*|} best_old="" best_new=""
    for round in $(seq "$rounds"); do
      r=$(rate_of "$old" "$dim" "$cells")
      best_old=$(printf '%s\n%s\n' "$best_old" "$r" | sort -g | tail -1)
      r=$(rate_of "$dealmpm" "$dim" "$cells")
      best_new=$(printf '%s\n%s\n' "$best_new" "$r" | sort -g | tail -1)
    done
    echo "| ${dim}D | $cells | $(log_particles) | $best_old | $best_new | $(awk "BEGIN {printf \"%.2f\", $best_new / $best_old}") |"
  done
  exit 0
fi

if [ "$part" = setup ]; then
  # The 1 M-particle 2D column's set-up (the program's set-up line, slowest
  # rank per stage) and 20 steps, on 1, 2 and 4 ranks (more ranks than
  # cores share them: their times are an upper bound), best of 2.
  flags=(--oversubscribe)
  [ "$(id -u)" = 0 ] && flags+=(--allow-run-as-root)
  echo "| ranks | set-up s | grid s | particles s | load balance s | 20 steps s | peak MB rank 0 |"
  echo "|---|---|---|---|---|---|---|"
  for n in 1 2 4; do
    best=""
    for repeat in 1 2; do
      mpirun "${flags[@]}" -np $n "$dealmpm" "$here/elastic_column_2d.prm" \
        -s "Grid/Cells=256, 1152" -s "Time/Maximum number of steps=20" \
        -s "Output/Directory=$work/out" > "$work/log" 2>&1
      stage() { grep -o "$1 [0-9.]* s" "$work/log" | head -1 | grep -o '[0-9.]*'; }
      steps=$(grep 'Total wallclock time elapsed' "$work/log" \
        | grep -oE '[0-9][0-9.e+-]*s( |$)' | tail -1 | tr -d 's ')
      row="| $n | $(stage 'set-up took') | $(stage grid) | $(stage particles) | $(stage 'load balance') | $steps | $(log_mb) |"
      total=$(stage 'set-up took')
      if [ -z "$best" ] || awk "BEGIN {exit !($total < $best_total)}"; then
        best=$row best_total=$total
      fi
    done
    echo "$best"
  done
  exit 0
fi
if [ "$part" = all ] || [ "$part" = sizes ]; then
echo "| dim | cells | particles | M particle-steps/s/core | peak MB | bytes/particle (marginal) |"
echo "|---|---|---|---|---|---|"
previous_particles=""
for cells in "32, 144" "64, 288" "128, 576" "256, 1152"; do run 2 "$cells"; done
previous_particles=""
for cells in "8, 8, 36" "16, 16, 72" "24, 24, 108"; do run 3 "$cells"; done
fi

if [ "$part" = all ] || [ "$part" = kernels ]; then
  echo
  echo "| shape function | 2D, 262144 particles | / linear | 3D, 131072 particles | / linear |"
  echo "|---|---|---|---|---|"
  for kernel in linear uGIMP cpGIMP CPDI "quadratic B-spline"; do
    r2=$(best_rate 2 "128, 576" -s "MPM/Shape function=$kernel")
    r3=$(best_rate 3 "16, 16, 72" -s "MPM/Shape function=$kernel")
    [ "$kernel" = linear ] && { linear2=$r2 linear3=$r3; }
    echo "| $kernel | $r2 | $(awk "BEGIN {printf \"%.2f\", $linear2 / $r2}") | $r3 | $(awk "BEGIN {printf \"%.2f\", $linear3 / $r3}") |"
  done
fi

if [ "$part" = all ] || [ "$part" = flowing ]; then
  echo
  echo "| dim | cells | at rest, M p-steps/s | flowing | flowing / at rest |"
  echo "|---|---|---|---|---|"
  flow() { # dim cells upper lower upper_body walls velocity
    local dim=$1 cells=$2 common rest moving
    common=(-s "Grid/Upper corner=$3" -s "Body 1/Lower corner=$4"
      -s "Body 1/Upper corner=$5" -s "Grid/Boundary conditions=$6")
    rest=$(best_rate "$dim" "$cells" "${common[@]}")
    moving=$(best_rate "$dim" "$cells" "${common[@]}" -s "Body 1/Velocity=$7")
    echo "| ${dim}D | $cells | $rest | $moving | $(awk "BEGIN {printf \"%.2f\", $moving / $rest}") |"
  }
  for cells in "64, 768" "128, 1536"; do
    flow 2 "$cells" "1, 12" "0, 0.5" "1, 4.5" "0: slip, 1: slip" "0, 250"
  done
  flow 3 "16, 16, 192" "1, 1, 12" "0, 0, 0.5" "1, 1, 4.5" \
    "0: slip, 1: slip, 2: slip, 3: slip" "0, 0, 250"
fi

if [ "$part" = all ] || [ "$part" = memory ]; then
  echo
  echo "| dim | cells | particles per cell | particles | peak MB | own bytes/particle |"
  echo "|---|---|---|---|---|---|"
  own() { # dim cells ppc_low ppc_high
    local dim=$1 cells=$2 n mb n0="" mb0=""
    for ppc in "$3" "$4"; do
      "$dealmpm" "$here/elastic_column_${dim}d.prm" -s "Grid/Cells=$cells" \
        -s "Body 1/Particles per cell=$ppc" -s "Time/Maximum number of steps=20" \
        -s "Output/Directory=$work/out" > "$work/log" 2>&1
      n=$(log_particles)
      mb=$(log_mb)
      local per="-"
      [ -n "$n0" ] && per=$(( (mb - mb0) * 1048576 / (n - n0) ))
      echo "| ${dim}D | $cells | $ppc | $n | $mb | $per |"
      n0=$n mb0=$mb
    done
  }
  own 2 "128, 576" 2 4
  own 3 "16, 16, 72" 2 3
fi
