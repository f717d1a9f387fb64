#!/usr/bin/env bash
# The pressure a J2 rod keeps after an impact (prm/projectile_fem_plate.prm,
# run on to t = 3e-4 s, when the rod has flown back off the plate): with
# the scene's 'MPM/Anti-locking = F-bar' it is a smooth residual stress,
# without it the locking of isochoric plastic flow leaves a pressure that
# alternates between neighbouring particles. Measured over the pairs of
# neighbours (0.5 mm apart) whose pressures both exceed a tenth of the
# yield stress (50 MPa), the share of opposite signs: none with F-bar, 41 %
# without (+0.57 / -0.45 GPa at most, against +0.13 / -0.19 GPa with
# F-bar; measured 2026-12-03). A smooth field has the same sign on both sides of nearly every
# pair; the check allows 5 %, and asks the run without anti-locking for
# 20 % or more (that the measure sees the defect).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
prm=$(dirname "$scene")/projectile_fem_plate.prm

run() { # folder, overrides...
  local out=$1; shift
  timeout 300 "$dealmpm" "$prm" -s "Output/Directory=$out" -s "Time/End time=3e-4" \
    -s "Output/Interval=1e-4" -s "Output/Progress interval=0" "$@" > "$out.log" 2>&1 \
    || fail "$out: exit code $? ($(tail -1 "$out.log"))"
}
run shipped # with F-bar, as the scene ships
run none -s "MPM/Anti-locking=none"

PYTHONPATH=$here python3 - <<'PY' || fail "rod pressure"
import math, sys
from vtk_files import read_vtu, pvd_files, pvtu_pieces

def opposite_share(folder):
    last = folder + "/" + pvd_files(folder + "/particles.pvd")[-1][1]
    base = last.rsplit("/", 1)[0]
    points = []
    for piece in pvtu_pieces(last):
        v = read_vtu(base + "/" + piece)
        n, s = v["arrays"]["stress"][1], v["arrays"]["stress"][2]
        points += [(v["points"][3 * i], v["points"][3 * i + 1],
                    -(s[n * i] + s[n * i + 4] + s[n * i + 8]) / 3) for i in range(v["n_points"])]
    opposite = pairs = 0
    for i, (x, y, p) in enumerate(points):
        for u, w, q in points[i + 1:]:
            if math.hypot(u - x, w - y) < 0.6e-3 and min(abs(p), abs(q)) > 50e6:
                pairs += 1
                opposite += p * q < 0
    largest = max(abs(p) for _, _, p in points)
    print("%s: %d of %d strong neighbour pairs of opposite sign, largest |p| %.2f GPa"
          % (folder, opposite, pairs, largest / 1e9))
    return opposite / max(pairs, 1)

smooth, locked = opposite_share("shipped"), opposite_share("none")
ok = smooth <= 0.05 and locked >= 0.2
print(("ok" if ok else "FAIL") + ": opposite signs %.3f as shipped, with F-bar (<= 0.05), %.3f without (>= 0.2)" % (smooth, locked))
sys.exit(0 if ok else 1)
PY
finish "rod pressure"
