#!/usr/bin/env bash
# Speed of the explicit step on the elastic column (USL, linear shape
# functions, 2^dim particles per cell, 200 steps, no output), one rank:
# particle-steps per second per core (best of 3 runs: the machine is shared
# and noisy), and memory per particle as the growth of peak resident memory
# between sizes divided by the growth in particles.
# Then the same per shape function, relative to linear.
#   benchmarks/run_benchmarks.sh [path/to/dealmpm] [sizes|kernels|all]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dealmpm=${1:-$here/../build/dealmpm}
part=${2:-all}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

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
  particles=$(grep -o '[0-9]* particles,' "$work/log" | grep -o '[0-9]*')
  mb=$(grep -o 'peak memory [0-9]* MB' "$work/log" | grep -o '[0-9]*')
  local marginal="-"
  if [ -n "${previous_particles:-}" ]; then
    marginal=$(( (mb - previous_mb) * 1048576 / (particles - previous_particles) ))
  fi
  echo "| ${dim}D | $cells | $particles | $rate | $mb | $marginal |"
  previous_particles=$particles previous_mb=$mb
}
if [ "$part" != kernels ]; then
echo "| dim | cells | particles | M particle-steps/s/core | peak MB | bytes/particle (marginal) |"
echo "|---|---|---|---|---|---|"
previous_particles=""
for cells in "32, 144" "64, 288" "128, 576" "256, 1152"; do run 2 "$cells"; done
previous_particles=""
for cells in "8, 8, 36" "16, 16, 72" "24, 24, 108"; do run 3 "$cells"; done
fi

if [ "$part" != sizes ]; then
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
