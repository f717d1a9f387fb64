#!/usr/bin/env bash
# The library's instruction set (CMakeLists.txt, DEALMPM_X86_64_V3): with
# the option on, AVX arithmetic (the three-operand v...sd/pd forms) is in
# it, and never a fused multiply-add, which would round differently from a
# build for any x86-64 (GCC forms them from a*b +- c*d in its vectorizer
# even under -ffp-contract=off: -mno-fma forbids them); with it off, no AVX
# arithmetic at all.
#   instruction_set.sh LIBRARY ON|OFF
set -euo pipefail
library=$1 v3=$2
command -v objdump > /dev/null || { echo "objdump not found (binutils)"; exit 1; }
code=$(objdump -d --no-show-raw-insn "$library")
fused=$(grep -cE 'vf(n)?m(add|sub)' <<< "$code" || true)
avx=$(grep -cE '\sv(add|sub|mul|div)[sp]d\s' <<< "$code" || true)
echo "$(basename "$library") (DEALMPM_X86_64_V3=$v3): $avx AVX arithmetic instructions, $fused fused multiply-adds"
[ "$fused" = 0 ] || { echo "fused multiply-adds: the numbers would differ from a generic build"; exit 1; }
if [ "$v3" = ON ]; then
  [ "$avx" -gt 0 ] || { echo "built for x86-64-v3 but no AVX arithmetic"; exit 1; }
else
  [ "$avx" = 0 ] || { echo "a generic build with AVX arithmetic"; exit 1; }
fi
