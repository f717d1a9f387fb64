#!/usr/bin/env bash
# No MMX register in the compiled library. GCC 12 at -O2 once moved values
# through %mm0 without emms, which left the x87 stack full: p4est's long
# double partition cuts became NaN and the weighted repartition hung (the
# cantilever on 2 ranks). CMakeLists.txt passes -mno-mmx; this checks it.
set -euo pipefail
library=$1
command -v objdump > /dev/null || { echo "objdump not found (binutils)"; exit 1; }
count=$(objdump -d --no-show-raw-insn "$library" | grep -c '%mm[0-7]' || true)
echo "instructions using MMX registers in $(basename "$library"): $count"
[ "$count" = 0 ]
