#!/usr/bin/env bash
# ./build.sh (no argument) builds the library and the program alone, which
# need no GoogleTest: configuring with DEALMPM_BUILD_TESTS=OFF on a machine
# without it (simulated: find_package(GTest) disabled) succeeds and makes no
# test target, and build.sh's run mode builds the program target only.
#   build_without_tests.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
if ! cmake -S "$source_dir" -B "$scratch" -DCMAKE_BUILD_TYPE=Release \
     -DDEALMPM_BUILD_TESTS=OFF -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON \
     > "$scratch/configure.log" 2>&1; then
  tail -20 "$scratch/configure.log"
  echo "FAIL: the library and the program do not configure without GoogleTest"
  exit 1
fi
targets=$(cmake --build "$scratch" --target help)
grep -q 'dealmpm_program' <<< "$targets" \
  || { echo "FAIL: no dealmpm_program target"; exit 1; }
if grep -q -E 'unit_tests|scene_tests' <<< "$targets"; then
  echo "FAIL: DEALMPM_BUILD_TESTS=OFF still makes the test targets"; exit 1
fi
grep -q -- '--target dealmpm_program' "$source_dir/build.sh" \
  || { echo "FAIL: ./build.sh does not build the program target alone"; exit 1; }
# With the tests asked for and GoogleTest missing: one clear line.
if cmake -S "$source_dir" -B "$scratch/with" -DDEALMPM_BUILD_TESTS=ON \
     -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON > "$scratch/with.log" 2>&1; then
  echo "FAIL: the tests configured without GoogleTest"; exit 1
fi
grep -q 'the tests need GoogleTest' "$scratch/with.log" \
  || { tail -20 "$scratch/with.log"; echo "FAIL: no clear line for a missing GoogleTest"; exit 1; }
echo "ok: the program builds without GoogleTest; the tests ask for it"
