#!/usr/bin/env bash
# Strain softening and its regularisation on a plane-strain biaxial test
# (tests/data/biaxial_softening.prm: a softening Mohr-Coulomb specimen
# 0.1 x 0.24 m, phi = 30 deg, psi = 0, c = 20 kPa -> 2 kPa at eps_p = 0.05,
# unconfined, pressed by a smooth platen on a rough base, F-bar, a weaker
# cell at its left side):
# - the peak load is the unconfined plane-strain strength 2 c cos(phi) /
#   (1 - sin(phi)) times the width, 6,928 N/m, within 5 % (the weak cell
#   and the cells' stiffness; measured +3.2 %);
# - one shear band forms, inclined between Roscoe's 45 + psi/2 = 45 deg
#   and Coulomb's 45 + phi/2 = 60 deg to the horizontal (measured 47.5
#   deg on 5 mm cells, 49 on 2.5 mm);
# - the load falls below 0.45 of the peak as the band softens;
# - with 'Regularisation length' = 5 mm (the coarse cells), the 2.5 mm
#   grid's load falls from the peak over the same platen displacement as
#   the 5 mm grid's, within 20 % at 0.6 and 0.45 of the peak (measured 1.0
#   and 1.07 of it), where without it the finer grid falls over about
#   half (0.48, 0.46: benchmarks/README.md, "Softening and its
#   regularisation").
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
prm=$here/../data/biaxial_softening.prm

run() { # folder, overrides...
  local out=$1; shift
  timeout 600 "$dealmpm" "$prm" -s "Output/Directory=$out" -s "Output/Progress interval=0" \
    -s "Time/End time=0.045" -s "Output/Interval=0.001" "$@" > "$out.log" 2>&1 \
    || fail "$out: exit code $? ($(tail -1 "$out.log"))"
}
l=0.005
run coarse &
run fine -s "Grid/Cells=80, 120" -s "Material 1/Mohr-Coulomb/Regularisation length=$l" \
  -s "Material 2/Mohr-Coulomb/Regularisation length=$l"
wait

PYTHONPATH=$here python3 - <<'PY' || fail "biaxial checks"
import csv, math, sys
from vtk_files import read_vtu, pvd_files, pvtu_pieces

failures = []
def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)

def load_curve(folder):
    rows = list(csv.DictReader(open(folder + "/statistics.csv")))
    return [(-float(r["rigid_displacement_y"]), float(r["rigid_force_y"])) for r in rows]

def softening(curve, fraction):
    """The peak, and the platen displacement from it to where the load
    first falls below fraction of it."""
    k = max(range(len(curve)), key=lambda i: curve[i][1])
    u = next((u for u, P in curve[k:] if P < fraction * curve[k][1]), None)
    return curve[k][1], None if u is None else u - curve[k][0]

def band_angle(folder):
    """The inclination to the horizontal (deg) of the principal axis of the
    particles whose plastic strain is over half the largest, weighted by it."""
    last = folder + "/" + pvd_files(folder + "/particles.pvd")[-1][1]
    base = last.rsplit("/", 1)[0]
    points = []
    for piece in pvtu_pieces(last):
        v = read_vtu(base + "/" + piece)
        e = v["arrays"]["plastic_strain"][2]
        points += [(v["points"][3 * i], v["points"][3 * i + 1], e[i]) for i in range(v["n_points"])]
    top = max(e for _, _, e in points)
    band = [(x, y, e) for x, y, e in points if e > 0.5 * top]
    w = sum(e for _, _, e in band)
    mx = sum(x * e for x, _, e in band) / w
    my = sum(y * e for _, y, e in band) / w
    sxx = sum(e * (x - mx) ** 2 for x, _, e in band)
    syy = sum(e * (y - my) ** 2 for _, y, e in band)
    sxy = sum(e * (x - mx) * (y - my) for x, y, e in band)
    return abs(0.5 * math.degrees(math.atan2(2 * sxy, sxx - syy)))

c, phi, width = 2e4, math.radians(30), 0.1
strength = 2 * c * math.cos(phi) / (1 - math.sin(phi)) * width
curves = {f: load_curve(f) for f in ("coarse", "fine")}
for f in curves:
    peak, u45 = softening(curves[f], 0.45)
    check(abs(peak / strength - 1) < 0.05,
          "%s: peak %.0f N/m, %.3f of 2 c cos(phi) / (1 - sin(phi)) W = %.0f" % (f, peak, peak / strength, strength))
    check(u45 is not None, "%s: the load falls below 0.45 of its peak (%s mm past it)"
          % (f, None if u45 is None else round(u45 * 1e3, 3)))
    angle = band_angle(f)
    check(45 <= angle <= 60, "%s: band at %.1f deg, between 45 (Roscoe) and 60 (Coulomb)" % (f, angle))
for fraction in (0.6, 0.45):
    u_coarse, u_fine = softening(curves["coarse"], fraction)[1], softening(curves["fine"], fraction)[1]
    ratio = u_fine / u_coarse if u_coarse and u_fine else float("nan")
    check(0.8 <= ratio <= 1.25,
          "regularised: to %.2f of the peak the 2.5 mm grid takes %.3f of the 5 mm grid's platen displacement" % (fraction, ratio))
sys.exit(1 if failures else 0)
PY
finish "biaxial"
