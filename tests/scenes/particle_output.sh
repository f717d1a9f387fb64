#!/usr/bin/env bash
# The particle files a user opens in ParaView: exact integer ids (Int64,
# unique past 2^24, where Float32 ids collide), body and material as Int32,
# Float64 points with z = 0 in 2D and one vertex cell each, velocity and
# displacement as 3-component vectors, the stress as a 9-component tensor
# with the plane-strain sigma_zz in 2D (nu (sigma_xx + sigma_yy) for the
# linear elastic disks), symmetric in 3D, the deformation gradient as a
# 9-component tensor (det F = J, plane strain in 2D), and the materials' internal
# variables by name. Body and material count from 1, as 'Body N' and
# 'Material N' do, and each particle names its rank (mpi_rank). A 2D
# Drucker-Prager soil shows its sigma_zz in 'stress' only (it also wrote a
# separate stress_zz).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
export PYTHONPATH="$here"

# 2D: the disks collide (fast) so that they carry stress. 3D: a second,
# small body with 10^3 particles per cell on a grid of 26^3 cells, so that
# its ids ((body x cells + cell) x 1000 + k) pass 2^24.
"$dealmpm" "$scene" -s "Output/Directory=disks" -s "Time/End time=0.25" -s "Output/Interval=0.25" \
  -s "Body 1/Velocity=1, 1" -s "Body 2/Velocity=-1, -1" -s "Output/Particle CSV=true" \
  -s "Output/Progress interval=0" > disks.log 2>&1 || fail "2D run: exit code $?"
"$dealmpm" "$(dirname "$scene")/cube_drop_3d.prm" -s "Output/Directory=ids" -s "Time/End time=0.002" \
  -s "Number of bodies=2" -s "Grid/Cells=26, 26, 26" -s "Body 2/Shape=box" \
  -s "Body 2/Lower corner=0.8, 0.8, 0.8" -s "Body 2/Upper corner=0.84, 0.84, 0.84" \
  -s "Body 2/Particles per cell=10" -s "Body 2/Material=1" -s "Output/Particle CSV=true" \
  -s "Output/Progress interval=0" > ids.log 2>&1 || fail "ids run: exit code $?"
"$dealmpm" "$(dirname "$scene")/pile_in_sand.prm" -s "Output/Directory=pile" \
  -s "Time/Maximum number of steps=20" -s "Output/Interval=1e-9" -s "Output/Progress interval=0" \
  > pile.log 2>&1 || fail "pile run: exit code $?"
"$dealmpm" "$(dirname "$scene")/elastic_column_3d.prm" -s "Output/Directory=column" \
  -s "Time/End time=0.05" -s "Output/Interval=0.05" -s "Output/Progress interval=0" \
  > column.log 2>&1 || fail "3D run: exit code $?"

python3 - <<'PY' || fail "particle files"
import csv, sys
from vtk_files import read_vtu, pvd_files, check_series, parse_xml, declared_arrays

failures = []
def check(condition, what):
    if not condition:
        failures.append(what)

def common(folder, counter, dim):
    v = read_vtu("%s/steps/particles_%05d.0.vtu" % (folder, counter))
    a = v["arrays"]
    n = v["n_points"]
    expected = {"id": ("Int64", 1), "body": ("Int32", 1), "material": ("Int32", 1),
                "velocity": ("Float32", 3), "displacement": ("Float32", 3),
                "stress": ("Float32", 9), "deformation gradient": ("Float32", 9),
                "J": ("Float32", 1), "volume": ("Float32", 1),
                "mass": ("Float32", 1), "mpi_rank": ("Int32", 1)}
    if folder != "ids":  # linear elastic
        expected["stress_work"] = ("Float32", 1)
    for name, kind in expected.items():
        check(name in a and a[name][:2] == kind,
              "%s: %s should be %s, is %s" % (folder, name, kind, a.get(name, [None])[:2]))
    if any(name not in a for name in expected):
        return v
    check(n > 0 and v["n_cells"] == n, "%s: one cell per point" % folder)
    check(set(a["material"][2]) == {1}, "%s: material values %s, expected 1 (Material 1)" % (folder, set(a["material"][2])))
    check(set(a["mpi_rank"][2]) == {0}, "%s: mpi_rank on one rank" % folder)
    check(v["points_declared"] == 3 and len(v["points"]) == 3 * n, "%s: 3D points" % folder)
    cells = v.get("cells", {})
    if "connectivity" not in cells:
        check(False, "%s: no cells" % folder)
        return v
    check(list(cells["connectivity"]) == list(range(n)), "%s: connectivity" % folder)
    check(list(cells["offsets"]) == list(range(1, n + 1)), "%s: offsets" % folder)
    check(set(cells["types"]) == {1}, "%s: VTK_VERTEX cells" % folder)
    check(not check_series(folder, "particles.pvd"), "%s: series" % folder)
    record = parse_xml("%s/steps/particles_%05d.pvtu" % (folder, counter))
    declared = declared_arrays(record.find("PUnstructuredGrid/PPointData"))
    check(declared == {k: a[k][:2] for k in a}, "%s: .pvtu arrays differ" % folder)
    # det F is J, and in 2D F is plane strain (F_zz = 1, no z coupling).
    F, J = a["deformation gradient"][2], a["J"][2]
    for i in range(n):
        f = F[9 * i:9 * i + 9]
        det = (f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6])
               + f[2] * (f[3] * f[7] - f[4] * f[6]))
        check(abs(det - J[i]) <= 1e-5 * abs(J[i]), "%s: det F %r of point %d is not J %r" % (folder, det, i, J[i]))
        if dim == 2:
            check(f[8] == 1 and f[2] == f[5] == f[6] == f[7] == 0, "%s: F of point %d is not plane strain: %r" % (folder, i, f))
        if failures:
            break
    if dim == 2:
        for name in ("velocity", "displacement"):
            check(all(x == 0 for x in a[name][2][2::3]), "%s: %s z should be 0" % (folder, name))
        check(all(z == 0 for z in v["points"][2::3]), "%s: point z should be 0" % folder)
    return v

# 2D: sigma_zz = nu (sigma_xx + sigma_yy), nu = 0.3; the in-plane part
# symmetric; some stress at all.
v = common("disks", 1, 2)
if "stress" in v["arrays"]:
    s = v["arrays"]["stress"][2]
    largest = max(abs(x) for x in s)
    check(largest > 0, "disks: no stress")
    check(len(s) == 9 * v["n_points"], "disks: the stress should have 9 components")
    for i in range(v["n_points"] if len(s) == 9 * v["n_points"] else 0):
        t = s[9 * i:9 * i + 9]
        check(abs(t[8] - 0.3 * (t[0] + t[4])) <= 1e-6 * largest, "disks: sigma_zz of point %d: %r" % (i, t))
        check(t[1] == t[3] and t[2] == t[5] == t[6] == t[7] == 0, "disks: stress layout of point %d" % i)
        if failures:
            break
    check(len(s) == 9 * v["n_points"] and max(abs(x) for x in s[8::9]) > 0.1 * largest,
          "disks: sigma_zz is missing")
    # The CSV (text, exact) against the binary file, point by point.
    rows = {int(r["id"]): r for r in csv.DictReader(open("disks/steps/particles_00001.csv"))}
    a = v["arrays"]
    for i, pid in enumerate(a["id"][2]):
        r = rows[int(pid)]
        check(abs(float(r["vx"]) - a["velocity"][2][3 * i]) <= 1e-6 and
              abs(float(r["uy"]) - a["displacement"][2][3 * i + 1]) <= 1e-6 and
              int(r["body"]) == a["body"][2][i], "disks: particle %d differs from the CSV" % pid)
        if failures:
            break

# Ids past 2^24: unique and the same as the CSV's.
v = common("ids", 1, 3)
if "id" in v["arrays"]:
    ids = [int(i) for i in v["arrays"]["id"][2]]
    csv_ids = [int(r["id"]) for r in csv.DictReader(open("ids/steps/particles_00001.csv"))]
    check(max(ids) > 2**24, "ids: the largest id %d should pass 2^24" % max(ids))
    check(len(set(ids)) == len(ids), "ids: %d of %d ids are unique" % (len(set(ids)), len(ids)))
    check(sorted(ids) == sorted(csv_ids), "ids: not the CSV's ids")
    check(set(v["arrays"]["body"][2]) == {1, 2}, "ids: body values (from 1, as Body 1 and Body 2)")

# 2D Drucker-Prager sand: sigma_zz (compressive under the sand's weight)
# only as the stress's zz component.
v = read_vtu("pile/steps/particles_00020.0.vtu")
check("stress_zz" not in v["arrays"], "pile: the particles still carry stress_zz")
check("plastic_strain" in v["arrays"], "pile: the soil's internal variables are missing")
check(min(v["arrays"]["stress"][2][8::9]) < 0, "pile: sigma_zz should be compressive")

# 3D: symmetric tensor, compressed column (sigma_zz < 0).
v = common("column", 1, 3)
if "stress" in v["arrays"]:
    s = v["arrays"]["stress"][2]
    check(min(s[8::9]) < 0, "column: sigma_zz should be compressive")
    for i in range(v["n_points"] if len(s) == 9 * v["n_points"] else 0):
        t = s[9 * i:9 * i + 9]
        check(t[1] == t[3] and t[2] == t[6] and t[5] == t[7], "column: stress of point %d not symmetric" % i)
        if failures:
            break

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY

finish "particle output"
