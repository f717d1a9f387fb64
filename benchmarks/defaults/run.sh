#!/usr/bin/env bash
# The defaults study (issue "trustworthy by default"): every shape function,
# stress update and CFL number on the colliding disks (20, 40, 80 cells per
# side), the cube drop and the elastic column; then defaults.md, the table
# the shipped defaults were chosen from.
#   benchmarks/defaults/run.sh [path/to/dealmpm]     (from anywhere; ~1 h on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dealmpm=$(realpath "${1:-$here/../../build/dealmpm}")
cd "$here/../.."
for case in disks cube_drop cube_drop_high column; do
  "$dealmpm" --study "benchmarks/defaults/$case.prm"
done
python3 "$here/summarize.py" "$here"
