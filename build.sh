#!/usr/bin/env bash
# One command for everything on Debian 12 (root or sudo, apt reachable):
#   ./build.sh        install what is missing, build the library and the
#                     program, run the default scene
#   ./build.sh test   install what is missing, build everything (tests and
#                     examples too), run the whole test suite
# Both are idempotent: a second call only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")"
mode=${1:-run}
case "$mode" in run|test) ;; *) echo "usage: ./build.sh [run|test]" >&2; exit 1 ;; esac
say() { echo "build.sh: $*"; }
start=$SECONDS

packages="cmake g++ binutils make libdeal.ii-dev libeigen3-dev openmpi-bin libopenmpi-dev ccache python3 python3-matplotlib"
# The tests need GoogleTest, clang-format (the code's style) and ParaView's
# pvpython (they open the HDF5/XDMF output); running scenes needs none.
if [ "$mode" = test ]; then packages="$packages libgtest-dev clang-format python3-paraview"; fi
missing=""
for p in $packages; do
  # No "| grep -q": under pipefail its early exit can fail the pipeline.
  [[ $(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) == *"install ok installed" ]] \
    || missing="$missing $p"
done
if [ -n "$missing" ]; then
  say "installing$missing (a few minutes on a fresh machine)"
  sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends $missing
fi

jobs=$(nproc 2>/dev/null || echo 2)
# ccache hits across clones of the project (CI builds a fresh clone): paths
# relative to the clone, and the build folder left out of the hash (deal.II's
# flags have -g, which would otherwise hash it).
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
configure() {
  say "configuring build/ (Release$2)"
  mkdir -p build
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDEALMPM_BUILD_TESTS="$1" > build/configure.log 2>&1 \
    || { cat build/configure.log; exit 1; }
}
if [ ! -f build/CMakeCache.txt ]; then
  if [ "$mode" = test ]; then configure ON ", with the tests"; else configure OFF ""; fi
elif [ "$mode" = test ] && grep -q '^DEALMPM_BUILD_TESTS:BOOL=OFF' build/CMakeCache.txt; then
  configure ON ", now with the tests"
fi

if [ "$mode" = run ]; then
  # Measured on a fresh clone, 2 cores, empty ccache (README).
  say "building the library and the program on $jobs cores (the first time about 23 minutes on 2 cores; later only what changed)"
  cmake --build build -j "$jobs" --target dealmpm_program
else
  say "building the library, the program, the examples and the tests on $jobs cores (the first time about 40 minutes on 2 cores; later only what changed)"
  # The build prints no compiler warning: the suite (and CI) fails on one.
  cmake --build build -j "$jobs" 2>&1 | tee build/build.log
  if grep -q "warning:" build/build.log; then
    grep "warning:" build/build.log
    say "the build printed compiler warnings (above): fix them"
    exit 1
  fi
fi
say "built in $(( (SECONDS - start) / 60 )) min $(( (SECONDS - start) % 60 )) s"

# Open MPI refuses to start as root unless told; ordinary users need nothing.
if [ "$(id -u)" = 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

if [ "$mode" = run ]; then
  say "running the default scene: build/dealmpm prm/colliding_disks.prm"
  ./build/dealmpm prm/colliding_disks.prm
  say "open output/colliding_disks/particles.pvd in ParaView"
else
  say "running the test suite (ctest)"
  cd build && ctest --output-on-failure -j "$jobs"
fi
