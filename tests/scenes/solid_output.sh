#!/usr/bin/env bash
# What ParaView shows of the solids beside the particles.
# FEM regions (fem_region_N.pvd): their arrays named and typed as the
# particles' (one 9-component `stress` tensor, with the plane-strain
# sigma_zz = nu (sigma_xx + sigma_yy) of a linear elastic 2D region, which
# six scalars of deal.II's writer could not carry as one tensor), constant
# in each cell and symmetric, its von Mises stress at most `von_mises` (the
# mean of the quadrature points'), on
# the deformed mesh (each point its undeformed lattice point plus its
# displacement), Q1 as one VTK cell a cell and Q2 as 2^dim; 2D on 2 ranks
# and 3D. Rigid bodies (rigid_body_N.pvd): one entry per output, each the
# body's outline moved by the statistics' rigid_displacement of that row,
# for the box, the cylinder and the half-space in 2D and 3D, with its
# velocity; the same in .h5/.xdmf as in .vtu (pvpython), and a resumed run
# continues the series.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
export PYTHONPATH="$here"
mpirun=$3 prm=$(dirname "$scene")

run() { # folder scene overrides...
  local out=$1 file=$2; shift 2
  timeout 600 "$dealmpm" "$file" -s "Output/Directory=$out" -s "Output/Progress interval=0" "$@" \
    > "$out.log" 2>&1 || fail "$out: exit code $? ($(tail -1 "$out.log"))"
}

# FEM regions. The bonded bar with a Poisson's ratio (its own is 0), on 2
# ranks; Q2; a plate of Q1 and of Q2 under a cube falling in 3D.
bar=(-s "Material 1/linear elastic/Poisson's ratio=0.3" -s "Time/End time=0.02" -s "Output/Interval=0.01")
timeout 600 "$mpirun" "${mpirun_flags[@]}" -np 2 "$dealmpm" "$prm/bonded_bar.prm" -s "Output/Directory=bar" \
  -s "Output/Progress interval=0" "${bar[@]}" > bar.log 2>&1 || fail "bar: exit code $? ($(tail -1 bar.log))"
run bar_q2 "$prm/bonded_bar.prm" "${bar[@]}" -s "FEM region 1/Degree=2" -s "Time/Time step method=CFL"
plate=(-s "Number of FEM regions=1" -s "FEM region 1/Type=rectangle" -s "FEM region 1/Lower corner=0.2, 0.2, 0"
  -s "FEM region 1/Upper corner=0.8, 0.8, 0.1" -s "FEM region 1/Cells=6, 6, 1" -s "FEM region 1/Material=1"
  -s "FEM region 1/Fixed boundaries=4" -s "MPM/Stress update=USL" -s "Time/End time=0.02" -s "Output/Interval=0.01")
run plate "$prm/cube_drop_3d.prm" "${plate[@]}"
run plate_q2 "$prm/cube_drop_3d.prm" "${plate[@]}" -s "FEM region 1/Degree=2"

# Rigid bodies: the punch's box, and the other shapes in its place; in 3D
# beside the falling cube.
punch=(-s "Time/End time=0.08" -s "Output/Interval=0.02")
run punch "$prm/punch.prm" "${punch[@]}"
run disk "$prm/punch.prm" "${punch[@]}" -s "Rigid body/Shape=cylinder" -s "Rigid body/Center=0.5, 0.62" \
  -s "Rigid body/Radius=0.1"
run wall "$prm/punch.prm" "${punch[@]}" -s "Rigid body/Shape=half-space" -s "Rigid body/Point=0.5, 0.55" \
  -s "Rigid body/Normal=0.05, -1"
cube=(-s "Effects=gravity, rigid body" -s "Rigid body/Velocity=0; 0; 0.5" -s "Time/End time=0.02"
  -s "Output/Interval=0.01")
run box_3d "$prm/cube_drop_3d.prm" "${cube[@]}" -s "Rigid body/Lower corner=0.05, 0.1, 0.6" \
  -s "Rigid body/Upper corner=0.25, 0.2, 0.9"
run cylinder_3d "$prm/cube_drop_3d.prm" "${cube[@]}" -s "Rigid body/Shape=cylinder" \
  -s "Rigid body/Center=0.85, 0.85, 0" -s "Rigid body/Radius=0.08"
run wall_3d "$prm/cube_drop_3d.prm" "${cube[@]}" -s "Rigid body/Shape=half-space" \
  -s "Rigid body/Point=0.5, 0.5, 0.8" -s "Rigid body/Normal=0, 0.3, -1"

python3 - <<'PY' || fail "solid files"
import csv, math, sys
from vtk_files import read_vtu, pvd_files, pvtu_pieces, check_series

failures = []
def check(condition, what):
    if not condition:
        failures.append(what)
    return condition

def pieces(folder, series):
    """The last output's pieces of a series (read_vtu dicts)."""
    last = pvd_files("%s/%s.pvd" % (folder, series))[-1][1]
    path = "%s/%s" % (folder, last)
    if path.endswith(".vtu"):
        return [read_vtu(path)]
    base = path.rsplit("/", 1)[0]
    return [read_vtu(base + "/" + p) for p in pvtu_pieces(path)]

def von_mises(t):
    d = [t[0] - t[4], t[4] - t[8], t[8] - t[0]]
    return math.sqrt(0.5 * sum(x * x for x in d) + 3 * (t[1] ** 2 + t[5] ** 2 + t[2] ** 2))

def region(folder, dim, degree, n_cells, lower, upper, cells, nu=None):
    check(not check_series(folder, "fem_region_1.pvd"), "%s: series" % folder)
    particles = pieces(folder, "particles")[0]["arrays"]
    total, ranks = 0, set()
    for v in pieces(folder, "fem_region_1"):
        a, n = v["arrays"], v["n_points"]
        for name in ("mpi_rank", "velocity", "displacement", "stress"):
            if not check(name in a and a[name][:2] == particles[name][:2],
                         "%s: region array %s %s, the particles' %s" % (folder, name, a.get(name, [None])[:2], particles[name][:2])):
                return
        check("stress_xx" not in a and a.get("von_mises", [None])[:2] == ("Float32", 1), "%s: arrays %s" % (folder, sorted(a)))
        per_cell, sub = (degree + 1) ** dim, degree ** dim
        if not check(n % per_cell == 0 and v["n_cells"] == n // per_cell * sub, "%s: %d points, %d cells" % (folder, n, v["n_cells"])):
            return
        total += n // per_cell
        ranks |= set(a["mpi_rank"][2])
        c = v["cells"]
        check(set(c["types"]) == {9 if dim == 2 else 12}, "%s: cell types %s" % (folder, set(c["types"])))
        corners = 2 ** dim
        check(list(c["offsets"]) == [corners * (k + 1) for k in range(v["n_cells"])], "%s: offsets" % folder)
        s, u, x = a["stress"][2], a["displacement"][2], v["points"]
        largest = max(abs(q) for q in s)
        check(largest > 0, "%s: no stress" % folder)
        for i in range(n):
            t = s[9 * i:9 * i + 9]
            first = (i // per_cell) * per_cell
            check(list(t) == list(s[9 * first:9 * first + 9]), "%s: stress not constant in the cell of point %d" % (folder, i))
            check(t[1] == t[3] and t[2] == t[6] and t[5] == t[7], "%s: stress of point %d not symmetric: %r" % (folder, i, t))
            if dim == 2:
                check(t[2] == t[5] == 0 and x[3 * i + 2] == 0, "%s: 2D point %d has z parts" % (folder, i))
            if nu is not None:
                check(abs(t[8] - nu * (t[0] + t[4])) <= 1e-6 * largest, "%s: sigma_zz of point %d: %r" % (folder, i, t))
            # von_mises is the mean of the quadrature points' (a norm's
            # mean is at least the norm of the mean).
            check(a["von_mises"][2][i] >= von_mises(t) - 1e-5 * largest, "%s: von Mises of point %d below the stress's" % (folder, i))
            # Less its displacement, a point is on the cells' lattice.
            for d in range(dim):
                h = (upper[d] - lower[d]) / (cells[d] * degree)
                k = (x[3 * i + d] - u[3 * i + d] - lower[d]) / h
                check(abs(k - round(k)) < 1e-4 and -1e-4 < k < cells[d] * degree + 1e-4,
                      "%s: point %d is not its lattice point plus its displacement" % (folder, i))
            if failures:
                return
        if nu:
            check(max(abs(q) for q in s[8::9]) > 0.1 * largest, "%s: no sigma_zz" % folder)
    check(total == n_cells, "%s: %d cells written, %d in the region" % (folder, total, n_cells))
    return ranks

ranks = region("bar", 2, 1, 20, (0, 0), (0.5, 0.025), (20, 1), nu=0.3)
check(ranks == {0, 1}, "bar: the region's mpi_rank on 2 ranks: %s" % ranks)
region("bar_q2", 2, 2, 20, (0, 0), (0.5, 0.025), (20, 1), nu=0.3)
region("plate", 3, 1, 36, (0.2, 0.2, 0), (0.8, 0.8, 0.1), (6, 6, 1))
region("plate_q2", 3, 2, 36, (0.2, 0.2, 0), (0.8, 0.8, 0.1), (6, 6, 1))

def rows(folder):
    return {float(r["time"]): r for r in csv.DictReader(open(folder + "/statistics.csv"))}

def rigid(folder, dim, n_points, cell_type, n_cells, where, velocity):
    """Every output of rigid_body_1: its outline, moved by the row's
    rigid_displacement; where(points, shift) returns what is wrong."""
    outputs = pvd_files(folder + "/rigid_body_1.pvd")
    check(len(outputs) == len(pvd_files(folder + "/particles.pvd")) > 1, "%s: %d rigid body outputs" % (folder, len(outputs)))
    table = rows(folder)
    axes = "xyz"[:dim]
    for time, name in outputs:
        v = read_vtu(folder + "/" + name)
        if not check(v["n_points"] == n_points and v["n_cells"] == n_cells and set(v["cells"]["types"]) == {cell_type},
                     "%s: %d points, %d cells of types %s" % (folder, v["n_points"], v["n_cells"], set(v["cells"]["types"]))):
            return
        row = table[min(table, key=lambda t: abs(t - time))]  # .pvd times have 12 digits
        shift = [float(row["rigid_displacement_" + a]) for a in axes]
        points = [v["points"][3 * i:3 * i + dim] for i in range(n_points)]
        problem = where(points, shift)
        check(problem is None, "%s at t = %g: %s" % (folder, time, problem))
        vel, expected = v["arrays"]["velocity"][2], velocity(time) + [0] * (3 - dim)
        if None not in expected:  # known (not in a ramp)
            check(all(abs(vel[3 * i + d] - expected[d]) <= 1e-7 for i in range(n_points) for d in range(3)),
                  "%s at t = %g: velocity %r, expected %r" % (folder, time, vel[:3], expected))
    if failures:
        return
    # It moved: the outputs are not all at its start.
    check(any(abs(float(r["rigid_displacement_" + axes[-1]])) > 1e-3 for r in table.values()), "%s: it did not move" % folder)

def near(a, b, tol=1e-9):
    return all(abs(p - q) <= tol for p, q in zip(a, b))

def box(lower, upper):
    def where(points, shift):
        order = [(0, 0), (1, 0), (1, 1), (0, 1)]
        expected = []
        for top in ([0, 1] if len(lower) == 3 else [None]):
            for c in order:
                p = [upper[d] if c[d] else lower[d] for d in range(2)]
                if top is not None:
                    p.append(upper[2] if top else lower[2])
                expected.append([p[d] + shift[d] for d in range(len(p))])
        return None if all(near(p, q) for p, q in zip(points, expected)) else "corners %r, expected %r" % (points, expected)
    return where

def disk(centre, radius, z_range=None):
    def where(points, shift):
        n = 65
        for k, first in enumerate(range(0, len(points), n)):
            c = [centre[d] + shift[d] for d in range(2)]
            if not near(points[first][:2], c):
                return "centre %r, expected %r" % (points[first], c)
            for p in points[first + 1:first + n]:
                if abs(math.dist(p[:2], c) - radius) > 1e-9:
                    return "a rim point %r off the circle" % (p,)
            if z_range and any(abs(p[2] - z_range[k] - shift[2]) > 1e-9 for p in points[first:first + n]):
                return "a cylinder's end not at the grid's z = %g" % z_range[k]
        return None
    return where

def slab(point, normal, diagonal):
    norm = math.sqrt(sum(x * x for x in normal))
    n = [x / norm for x in normal]
    def where(points, shift):
        depths = sorted(round(sum((p[d] - point[d] - shift[d]) * n[d] for d in range(len(n))) / diagonal, 9) for p in points)
        half = len(points) // 2
        expected = [-0.1] * half + [0.0] * half
        return None if near(depths, expected, 1e-9) else "depths behind the face / diagonal %r" % depths
    return where

def ramp(dim):
    def velocity(t):
        if t == 0:
            return [0] * dim
        if t > 0.05:
            return [0] * (dim - 1) + [-0.1]
        return [None] * dim
    return velocity

def constant(v):
    return lambda t: [0, 0, 0] if t == 0 else v

# The punch's velocity ramps up to -0.1 m/s by t = 0.05: checked after it.
for folder, where, n, kind, cells in (
        ("punch", box((0.4, 0.5), (0.6, 1.0)), 4, 9, 1),
        ("disk", disk((0.5, 0.62), 0.1), 65, 5, 64),
        ("wall", slab((0.5, 0.55), (0.05, -1), math.hypot(1, 0.7)), 4, 9, 1)):
    rigid(folder, 2, n, kind, cells, where, ramp(2))
up = constant([0, 0, 0.5])
rigid("box_3d", 3, 8, 12, 1, box((0.05, 0.1, 0.6), (0.25, 0.2, 0.9)), up)
rigid("cylinder_3d", 3, 130, 13, 64, disk((0.85, 0.85), 0.08, (0, 1)), up)
rigid("wall_3d", 3, 8, 12, 1, slab((0.5, 0.5, 0.8), (0, 0.3, -1), math.sqrt(3)), up)

for f in failures[:20]:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY

# The same in .h5/.xdmf as in .vtu, read by ParaView.
if command -v pvpython > /dev/null; then
  run punch_hdf5 "$prm/punch.prm" "${punch[@]}" -s "Output/Format=hdf5"
  run plate_hdf5 "$prm/cube_drop_3d.prm" "${plate[@]}" -s "FEM region 1/Degree=2" -s "Output/Format=hdf5"
  [ -s punch_hdf5/rigid_body_1.xdmf ] || fail "punch_hdf5: no rigid_body_1.xdmf"
  for pair in "punch rigid_body_1" "plate_q2 fem_region_1"; do
    set -- $pair
    timeout 300 pvpython "$here/same_series.py" "$1" "${1%_q2}_hdf5" "$2" > "$1.compare" 2>&1 \
      || fail "$1: $(cat "$1.compare")"
    grep -qi "warning\|error" "$1.compare" && fail "$1: ParaView says: $(grep -i 'warning\|error' "$1.compare" | head -3)"
  done
else
  fail "pvpython missing (./build.sh test installs python3-paraview)"
fi

# A resumed run continues the rigid body's series as the uninterrupted run
# wrote it.
run resumed "$prm/punch.prm" "${punch[@]}" -s "Checkpoint/Steps between checkpoints=20"
cp resumed/rigid_body_1.pvd uninterrupted.pvd
last=$(ls resumed/steps/rigid_body_1_*.vtu | tail -1)
cp "$last" uninterrupted.vtu
older=$(ls -d resumed/checkpoints/checkpoint-* | head -1)
run resumed "$prm/punch.prm" "${punch[@]}" -s "Checkpoint/Steps between checkpoints=20" --resume "$older"
cmp -s uninterrupted.pvd resumed/rigid_body_1.pvd || fail "the resumed run's rigid_body_1.pvd differs"
cmp -s uninterrupted.vtu "$last" || fail "the resumed run's $last differs"
finish "solid output"
