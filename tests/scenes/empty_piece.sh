#!/usr/bin/env bash
# A rank without particles writes a valid empty piece: NumberOfPoints="0",
# Points and every array declared with the same types and component counts
# as the other rank's piece and the .pvtu. The dropped cube sits on one of
# two ranks when cells are shared by count (load balance off).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
mpirun=$3
export PYTHONPATH="$here"
flags=("${mpirun_flags[@]}")

timeout 300 "$mpirun" "${flags[@]}" -np 2 "$dealmpm" "$scene" -s "Output/Directory=out" \
  -s "Time/End time=0.02" -s "Output/Interval=0.01" -s "Output/Progress interval=0" \
  -s "Load balance/Enabled=false" > log.txt 2>&1 || fail "exit code $?"
grep -q "2 rank(s) (0 to" log.txt || fail "expected a rank without particles: $(grep 'rank(s)' log.txt)"

python3 - <<'PY' || fail "empty piece"
import sys
from vtk_files import read_vtu, parse_xml, declared_arrays, check_series, pvd_files

failures = []
def check(condition, what):
    if not condition:
        failures.append(what)

check(len(pvd_files("out/particles.pvd")) == 3, "particles.pvd should list 3 outputs")
check(not check_series("out", "particles.pvd"), "series incomplete: %s" % check_series("out", "particles.pvd"))
for counter in range(3):
    pieces = [read_vtu("out/steps/particles_%05d.%d.vtu" % (counter, r)) for r in (0, 1)]
    sizes = sorted(p["n_points"] for p in pieces)
    check(sizes[0] == 0 and sizes[1] > 0, "output %d: piece sizes %s" % (counter, sizes))
    kinds = [{k: a[:2] for k, a in p["arrays"].items()} for p in pieces]
    check(kinds[0] == kinds[1], "output %d: the pieces declare different arrays: %s" % (counter, kinds))
    check(kinds[0].get("stress") == ("Float32", 9), "output %d: stress %s" % (counter, kinds[0].get("stress")))
    # Each piece's particles name the rank that wrote it.
    for r, p in enumerate(pieces):
        ranks = set(p["arrays"].get("mpi_rank", (0, 0, [-1]))[2]) if p["n_points"] else {r}
        check(ranks == {r}, "output %d: piece %d has mpi_rank %s" % (counter, r, ranks))
    for p in pieces:
        check(p["points_declared"] == 3, "output %d: Points not declared with 3 components" % counter)
        check(all(len(a[2]) == p["n_points"] * a[1] for a in p["arrays"].values()),
              "output %d: array lengths" % counter)
    record = parse_xml("out/steps/particles_%05d.pvtu" % counter)
    check(declared_arrays(record.find("PUnstructuredGrid/PPointData")) == kinds[0],
          "output %d: the .pvtu declares other arrays" % counter)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY

finish "empty piece"
