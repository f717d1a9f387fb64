#!/usr/bin/env bash
# One command for everything on Debian 12 (root or sudo, apt reachable):
#   ./build.sh        install what is missing, build, run the default scene
#   ./build.sh test   install what is missing, build, run the whole test suite
# Both are idempotent: a second call only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")"
mode=${1:-run}
case "$mode" in run|test) ;; *) echo "usage: ./build.sh [run|test]" >&2; exit 1 ;; esac

packages="cmake g++ binutils make libdeal.ii-dev libeigen3-dev libgtest-dev openmpi-bin libopenmpi-dev ccache python3 python3-matplotlib clang-format"
# The tests open the HDF5/XDMF output in ParaView's pvpython.
if [ "$mode" = test ]; then packages="$packages python3-paraview"; fi
missing=""
for p in $packages; do
  # No "| grep -q": under pipefail its early exit can fail the pipeline.
  [[ $(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) == *"install ok installed" ]] \
    || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "build.sh: installing$missing"
  sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends $missing
fi

jobs=$(nproc 2>/dev/null || echo 2)
# ccache hits across clones of the project (CI builds a fresh clone): paths
# relative to the clone, and the build folder left out of the hash (deal.II's
# flags have -g, which would otherwise hash it).
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
[ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs"

# Open MPI refuses to start as root unless told; ordinary users need nothing.
if [ "$(id -u)" = 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

if [ "$mode" = run ]; then
  ./build/dealmpm prm/colliding_disks.prm
  echo "build.sh: open output/colliding_disks/particles.pvd in ParaView"
else
  cd build && ctest --output-on-failure -j "$jobs"
fi
