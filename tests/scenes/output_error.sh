#!/usr/bin/env bash
# Output that cannot be written stops the run with one line naming the file
# and the reason, exit code 5, and a consistent folder: every .pvd entry's
# files exist and have their statistics row.
#   output_error.sh dealmpm scene full-disk: a tmpfs of 600 KB fills up
#     mid-run (needs root and mount; skipped with exit code 77 otherwise);
#   output_error.sh dealmpm scene occupied: a folder named like the fourth
#     particle piece stands in its way (works without root; a file size
#     limit does not: Open MPI's start-up needs large files).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
mode=$3
export PYTHONPATH="$here"

consistent() { # folder
  python3 - "$1" <<'PY'
import csv, os, sys
from vtk_files import pvd_files, check_series
folder = sys.argv[1]
entries = pvd_files(folder + "/particles.pvd") if os.path.exists(folder + "/particles.pvd") else []
rows = list(csv.DictReader(open(folder + "/statistics.csv")))
problems = check_series(folder, "particles.pvd") if entries else []
if not len(entries) <= len(rows) <= len(entries) + 1:
    problems.append("%d statistics rows for %d outputs" % (len(rows), len(entries)))
left = [f for f in os.listdir(folder) if f.endswith(".tmp")]
if left:
    problems.append("temporary files left: %s" % left)
print("%d outputs listed, %d statistics rows" % (len(entries), len(rows)))
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
PY
}

# $1 folder, $2 expected reason; the run's exit code in $code.
check_stop() {
  [ "$code" = 5 ] || fail "exit code $code, expected 5"
  [ "$(wc -l < err.txt)" = 1 ] || fail "expected one line on stderr, got: $(cat err.txt)"
  grep -Eq "^dealmpm: output error: cannot write $1/(steps/)?[a-z_0-9.]+: $2" err.txt \
    || fail "message: $(cat err.txt)"
  consistent "$1" || fail "inconsistent output"
}

# The fixed step of the old default scene: outputs at known times.
run=(-s "Time/End time=1" -s "Output/Interval=0.01" -s "Output/Progress interval=0"
     -s "Time/Time step method=fixed" -s "Time/Time step=0.001")
case "$mode" in
  full-disk)
    mkdir disk
    if ! mount -t tmpfs -o size=600k tmpfs disk 2> mount.txt; then
      echo "SKIP: cannot mount a tmpfs here ($(cat mount.txt))"
      exit 77
    fi
    trap 'umount "$work/disk"; rm -rf "$work"' EXIT
    "$dealmpm" "$scene" -s "Output/Directory=disk/out" "${run[@]}" > out.txt 2> err.txt
    code=$?
    check_stop disk/out "No space left on device"
    grep -q "steps/particles_00000.pvtu" disk/out/particles.pvd || fail "the outputs before the disk was full are not listed"
    ;;
  occupied)
    mkdir -p out/steps/particles_00003.0.vtu
    "$dealmpm" "$scene" -s "Output/Directory=out" "${run[@]}" > out.txt 2> err.txt
    code=$?
    check_stop out "Is a directory"
    grep -q "particles_00003.0.vtu: Is a directory; the output in out/ is complete up to t = 0.02$" err.txt \
      || fail "message: $(cat err.txt)"
    [ "$(grep -c DataSet out/particles.pvd)" = 3 ] || fail "particles.pvd should list 3 outputs"
    ;;
  *) fail "unknown mode $mode" ;;
esac

finish "output error ($mode)"
