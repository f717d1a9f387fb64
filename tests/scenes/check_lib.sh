# Sourced by the program checks: arguments "dealmpm scene", a scratch folder
# as working directory (removed at exit), a failure counter and a summary.
set -uo pipefail
dealmpm=$1 scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
finish() { # what was checked
  if [ $failures -gt 0 ]; then echo "$failures $1 check(s) failed"; exit 1; fi
  echo "all $1 checks passed"
}
# mpirun's options for the checks: more ranks than cores, and root (CI).
mpirun_flags=(--oversubscribe)
[ "$(id -u)" = 0 ] && mpirun_flags+=(--allow-run-as-root)
