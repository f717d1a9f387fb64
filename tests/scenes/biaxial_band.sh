#!/usr/bin/env bash
# Strain softening and its regularisation on a plane-strain biaxial test
# (tests/data/biaxial_softening.prm: a softening Mohr-Coulomb specimen
# 0.1 x 0.24 m, phi = 30 deg, psi = 0, c = 20 kPa -> 2 kPa at eps_p = 0.05,
# unconfined, pressed by a smooth platen on a rough base, F-bar, a weaker
# cell at its left side). The softening runs take PIC, whose load falls
# smoothly (FLIP's falls within 0.4 mm of platen and rings, which 0.05 mm
# outputs resolve too coarsely for the ratios below); the residual run
# takes FLIP, the scene's own:
# - the peak load is the unconfined plane-strain strength 2 c cos(phi) /
#   (1 - sin(phi)) times the width, 6,928 N/m, within 5 % (the weak cell
#   and the cells' stiffness; measured +3.2 %);
# - one shear band forms, inclined between Roscoe's 45 + psi/2 = 45 deg
#   and Coulomb's 45 + phi/2 = 60 deg to the horizontal (measured 47.4
#   deg on 5 mm cells, 48.9 on 2.5 mm, 49.9 with FLIP);
# - the load falls below 0.45 of the peak as the band softens;
# - the load then settles on the residual strength: from 0.06 to 0.12 s
#   (5 mm cells, FLIP) its mean lies between 0.9 of the material's
#   residual strength 2 c_r cos(phi) / (1 - sin(phi)) W = 693 N/m (the
#   least load on any band) and 1.1 of the load that slides the measured
#   band at c_r (789 N/m at 49.9 deg; measured 792; PIC's transfer, a
#   shear viscosity, carries 2,108);
# - with 'Regularisation length' = 5 mm (the coarse cells), the 2.5 mm
#   grid's load falls from the peak over the same platen displacement as
#   the 5 mm grid's, within a factor 1.25 at 0.6 and 0.45 of the peak (1.00
#   and 1.07 measured), where without it the finer grid falls over about
#   half (benchmarks/README.md, "Softening and its regularisation").
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
prm=$here/../data/biaxial_softening.prm

run() { # folder, end time, overrides...
  local out=$1 end=$2; shift 2
  timeout 600 "$dealmpm" "$prm" -s "Output/Directory=$out" -s "Output/Progress interval=0" \
    -s "Time/End time=$end" -s "Output/Interval=0.001" "$@" > "$out.log" 2>&1 \
    || fail "$out: exit code $? ($(tail -1 "$out.log"))"
}
l=0.005
pic="MPM/Velocity update=PIC"
(run coarse 0.045 -s "$pic"; run residual 0.12) &
run fine 0.045 -s "$pic" -s "Grid/Cells=80, 120" -s "Material 1/Mohr-Coulomb/Regularisation length=$l" \
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
    """The inclination to the horizontal (deg) at t = 0.045 s of the
    principal axis of the particles whose plastic strain is over half the
    largest, weighted by it."""
    last = folder + "/" + min(pvd_files(folder + "/particles.pvd"), key=lambda f: abs(f[0] - 0.045))[1]
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

c, c_r, phi, width = 2e4, 2e3, math.radians(30), 0.1
strength = 2 * c * math.cos(phi) / (1 - math.sin(phi)) * width
residual = 2 * c_r * math.cos(phi) / (1 - math.sin(phi)) * width
curves = {f: load_curve(f) for f in ("coarse", "fine")}
angles = {}
for f in curves:
    peak, u45 = softening(curves[f], 0.45)
    check(abs(peak / strength - 1) < 0.05,
          "%s: peak %.0f N/m, %.3f of 2 c cos(phi) / (1 - sin(phi)) W = %.0f" % (f, peak, peak / strength, strength))
    check(u45 is not None, "%s: the load falls below 0.45 of its peak (%s mm past it)"
          % (f, None if u45 is None else round(u45 * 1e3, 3)))
    angle = angles[f] = band_angle(f)
    check(45 <= angle <= 60, "%s: band at %.1f deg, between 45 (Roscoe) and 60 (Coulomb)" % (f, angle))
# Sliding on a band at theta to the horizontal takes sigma (sin theta cos
# theta - cos^2 theta tan phi) = c_r: the residual strength at Coulomb's
# 60 deg, more on a steeper or flatter band.
theta = math.radians(band_angle("residual"))
on_band = c_r / (math.sin(theta) * math.cos(theta) - math.cos(theta) ** 2 * math.tan(phi)) * width
late = [float(r["rigid_force_y"]) for r in csv.DictReader(open("residual/statistics.csv"))
        if float(r["time"]) > 0.06]
mean = sum(late) / len(late)
check(0.9 * residual <= mean <= 1.1 * on_band,
      "FLIP: the load from 0.06 to 0.12 s averages %.0f N/m, between 0.9 of the residual strength %.0f "
      "and 1.1 of sliding on the band at %.1f deg, %.0f" % (mean, residual, math.degrees(theta), on_band))
for fraction in (0.6, 0.45):
    u_coarse, u_fine = softening(curves["coarse"], fraction)[1], softening(curves["fine"], fraction)[1]
    ratio = u_fine / u_coarse if u_coarse and u_fine else float("nan")
    check(0.8 <= ratio <= 1.25,
          "regularised: to %.2f of the peak the 2.5 mm grid takes %.3f of the 5 mm grid's platen displacement" % (fraction, ratio))
sys.exit(1 if failures else 0)
PY
finish "biaxial"
