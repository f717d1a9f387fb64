#!/usr/bin/env bash
# dealmpm as a library others build on: this build is installed into a
# prefix (cmake --install), examples/ is configured against the installed
# tree as a project of its own (find_package(dealmpm)), built and run; the
# example links exactly one deal.II library (libdeal.ii.so or, for a Debug
# dealmpm, libdeal.ii.g.so); a project of the other build type stops at
# configure with one line; the installed program runs from the prefix and
# finds the installed plot script.
# Arguments: cmake, dealmpm's build folder, its build type, examples/, the
# example's scene, a scene with an exact solution (for a one-run study).
set -uo pipefail
cmake=$1 build=$2 build_type=$3 examples=$4 scene=$5 study_scene=$6
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# A fixed folder in the build tree rather than mktemp: ccache then sees the
# same paths on every run (CCACHE_BASEDIR makes them relative) and the
# example compiles once. Kept when a check fails.
work=$PWD/outside_project
rm -rf "$work"
mkdir -p "$work"
cd "$work"
trap '[ $failures = 0 ] && rm -rf "$work"' EXIT
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd "$examples/.." && pwd)}
export CCACHE_NOHASHDIR=1
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

# What the install puts where.
prefix=$work/prefix
"$cmake" --install "$build" --prefix "$prefix" > install.log 2>&1 \
  || { fail "cmake --install: exit $?"; cat install.log; }
config=$(find "$prefix" -name dealmpmConfig.cmake)
config_dir=$(dirname "${config:-none/x}")
for f in bin/dealmpm include/dealmpm/core/simulation.h \
         include/dealmpm/materials/material.h share/dealmpm/plot_study.py; do
  [ -e "$prefix/$f" ] || fail "install: no $f"
done
[ -n "$(find "$prefix" -name libdealmpm.so)" ] || fail "install: no libdealmpm.so"
for f in dealmpmConfig.cmake dealmpmConfigVersion.cmake dealmpmTargets.cmake; do
  [ -e "$config_dir/$f" ] || fail "install: no $f"
done
# Only include/ is public.
private=$(find "$prefix" -name node_accumulator.h)
[ -z "$private" ] || fail "install: private header $private"

# The outside project: dealmpm's build type when it sets none.
other=Debug
[ "$build_type" = Debug ] && other=Release
"$cmake" -S "$examples" -B "$work/build" -Ddealmpm_DIR="$config_dir" \
  "${launcher[@]}" > configure.log 2>&1 \
  || { fail "configure examples: exit $?"; cat configure.log; }
grep -q "dealmpm: CMAKE_BUILD_TYPE set to $build_type" configure.log \
  || fail "configure examples: build type not set to $build_type"
"$cmake" --build "$work/build" > build.log 2>&1 \
  || { fail "build examples: exit $?"; tail -30 build.log; }

# Whether a binary loads the prefix's libdealmpm.so. Paths compared after
# realpath: ldd prints $ORIGIN-relative paths from the physical location,
# while $PWD may reach the same folder through a symlink.
from_prefix() {
  local loaded
  loaded=$(ldd "$1" | sed -n 's/.*libdealmpm\.so => \(.*\) (0x.*/\1/p')
  [ -n "$loaded" ] \
    && [ "$(realpath "$loaded")" = "$(realpath "$(find "$prefix" -name libdealmpm.so | head -1)")" ]
}

# Exactly one deal.II library, of dealmpm's build type; dealmpm from the
# prefix.
example=$work/build/custom_material
deal_ii=$(ldd "$example" | grep -oE 'libdeal\.ii(\.g)?\.so[.0-9]*' | sort -u)
expected=libdeal.ii.so
[ "$build_type" = Debug ] && expected=libdeal.ii.g.so
[ "$(echo "$deal_ii" | wc -l)" = 1 ] && [[ $deal_ii == $expected* ]] \
  || fail "ldd custom_material: deal.II libraries '$(echo $deal_ii)', expected only $expected"
from_prefix "$example" \
  || fail "ldd custom_material: libdealmpm.so not from the prefix: $(ldd "$example" | grep dealmpm)"

# The example runs its scene.
"$example" "$scene" -s "Output/Directory=example_output" -s "Time/End time=0.5" \
  -s "Output/Write particles=false" > run.log 2>&1
code=$?
[ $code = 0 ] || { fail "custom_material: exit $code"; tail -20 run.log; }
[ "$(wc -l < example_output/statistics.csv 2> /dev/null || echo 0)" -ge 2 ] \
  || fail "custom_material: no statistics rows in example_output/statistics.csv"

# The other build type stops at configure, with one line that says why.
"$cmake" -S "$examples" -B "$work/other" -DCMAKE_BUILD_TYPE=$other \
  -Ddealmpm_DIR="$config_dir" > other.log 2>&1
code=$?
line="dealmpm was built as $build_type: configure this project with -DCMAKE_BUILD_TYPE=$build_type, not $other"
[ $code != 0 ] && [ "$(grep -cF "$line" other.log)" = 1 ] \
  || { fail "configure as $other: exit $code without the line"; cat other.log; }
[ -e "$work/other/Makefile" ] && fail "configure as $other: a Makefile was generated"

# The installed program: libdealmpm.so beside it, the installed plot script
# (replaced here by a stub that leaves a mark, so that matplotlib is not
# needed) drawn by a one-run study.
program=$prefix/bin/dealmpm
from_prefix "$program" \
  || fail "ldd dealmpm: libdealmpm.so not from the prefix: $(ldd "$program" | grep dealmpm)"
"$program" --help > help.log 2>&1 || fail "installed dealmpm --help: exit $?"
if [ -x /usr/bin/python3 ]; then
  echo 'import pathlib, sys; pathlib.Path(sys.argv[2], "plotted_by_installed_script").touch()' \
    > "$prefix/share/dealmpm/plot_study.py"
  cat > study.prm <<END
subsection Study
  set Base scene       = $study_scene
  set Output directory = study
  set Refinements      = 0
  set Settings         = Grid/Cells=4, 4; Time/End time=0.005
end
END
  "$program" --study study.prm > study.log 2>&1
  code=$?
  [ $code = 0 ] && grep -q '^1,ok,' study/study.csv \
    || { fail "installed dealmpm --study: exit $code"; cat study.log; }
  [ -e study/plotted_by_installed_script ] \
    || { fail "installed dealmpm --study: the installed plot script did not run"; cat study.log; }
fi

if [ $failures -gt 0 ]; then
  echo "$failures outside project check(s) failed; files in $work"
  exit 1
fi
echo "all outside project checks passed"
