"""A picture of one time of a run's output series (a .pvd file), for the
tutorials (doc/tutorials/) and for a first look without opening ParaView:

    pvpython scripts/render_series.py SERIES.pvd FIELD OUT.png [--time T]
        [--component C] [--also OTHER.pvd] [--axes xz] [--range LOW,HIGH]

ParaView's reader (the one File > Open uses) loads the series and picks
the time (the output nearest --time T; without it, the last); the points
or cells are drawn coloured by FIELD: its magnitude for a vector or tensor,
or one component with --component (0, 1, 2 for x, y, z; 4 is yy of the
3 x 3 stress), the range of the picture's time or --range. --also draws a
second series (an FEM region's fem_region_N.pvd beside the particles) at
the same time, coloured alike where it has the field, grey where not. A 3D
series is seen along z (--axes xy) or from the side (--axes xz, yz).

Why it draws with matplotlib and not with ParaView's renderer: Debian's
pvpython renders only into an X display, which CI, a remote shell and the
documentation test (tests/house/doc_commands.py) do not have; matplotlib
(python3-matplotlib, which build.sh installs) writes the picture with no
display at all, so every command of the tutorials runs anywhere the tests
run. The particles are drawn as squares as wide as their volume's side.
"""
import argparse
import math
import sys

import matplotlib
matplotlib.use("Agg")  # no display: write files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import MergeBlocks, PVDReader  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

AXES = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
POLYGONS = {5: [0, 1, 2], 9: [0, 1, 2, 3], 12: [0, 1, 2, 3]}  # VTK tri, quad, hexahedron's face
VERTEX_TYPES = {1, 2}  # VTK_VERTEX, VTK_POLY_VERTEX


def arguments():
    """The command line (see the module's docstring)."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("series", help="a run's .pvd file (particles.pvd, fem_region_N.pvd)")
    p.add_argument("field", help="a point field of the series: velocity, stress, plastic_strain, ...")
    p.add_argument("output", help="the picture (.png)")
    p.add_argument("--time", type=float, help="the time to draw (the nearest output; default: the last)")
    p.add_argument("--component", type=int, help="one component of the field (default: its magnitude)")
    p.add_argument("--also", help="a second .pvd series drawn at the same time")
    p.add_argument("--axes", choices=sorted(AXES), default="xy", help="the plane a 3D series is seen in")
    p.add_argument("--range", help="the colour range LOW,HIGH (default: the picture's)")
    return p.parse_args()


def times_of(reader):
    """The series' output times as a list (ParaView gives a bare number for one)."""
    values = reader.TimestepValues
    if values is None:
        return [0.0]
    return list(values) if hasattr(values, "__len__") else [values]


def fetch(path, time):
    """The series' data set at the output nearest @p time (None: the last), and that time."""
    reader = PVDReader(FileName=path)
    times = times_of(reader)
    chosen = times[-1] if time is None else min(times, key=lambda s: abs(s - time))
    merged = MergeBlocks(Input=reader)
    merged.UpdatePipeline(chosen)
    return servermanager.Fetch(merged), chosen


def values_of(data, field, component):
    """The field's value at each point (magnitude or one component); None if it has none."""
    array = data.GetPointData().GetArray(field)
    if array is None:
        return None
    values = vtk_to_numpy(array).astype(float)
    if values.ndim == 1:
        return values
    if component is not None:
        if component >= values.shape[1]:
            sys.exit(f"'{field}' has {values.shape[1]} components: no component {component}")
        return values[:, component]
    return numpy.linalg.norm(values, axis=1)


def polygons_of(data, plane):
    """The cells that are polygons (an FEM region's elements) as lists of 2D corners, with their point ids."""
    points = vtk_to_numpy(data.GetPoints().GetData())[:, plane]
    corners, ids = [], []
    for c in range(data.GetNumberOfCells()):
        order = POLYGONS.get(data.GetCellType(c))
        if order is None:
            continue
        cell = data.GetCell(c).GetPointIds()
        point_ids = [cell.GetId(k) for k in order]
        corners.append(points[point_ids])
        ids.append(point_ids)
    return corners, ids


def is_particles(data):
    """True when the data set is points only (the particles), not a mesh."""
    n = data.GetNumberOfCells()
    return n == 0 or data.GetCellType(0) in VERTEX_TYPES


def particle_width(data, points, dimension):
    """The side of a particle's volume (median), for the marker size."""
    volume = data.GetPointData().GetArray("volume")
    if volume is not None and volume.GetNumberOfTuples() > 0:
        return float(numpy.median(vtk_to_numpy(volume))) ** (1.0 / dimension)
    extent = numpy.ptp(points, axis=0)
    return math.sqrt(max(extent[0] * extent[1], 1e-30) / max(len(points), 1))


def draw(axis, data, values, plane, dimension, colours):
    """Draw one data set on @p axis: particles as squares, cells as polygons."""
    points = vtk_to_numpy(data.GetPoints().GetData())[:, plane]
    if is_particles(data):
        if values is None:
            drawn = axis.scatter(points[:, 0], points[:, 1], marker="s", linewidths=0, c="0.6")
        else:
            drawn = axis.scatter(points[:, 0], points[:, 1], c=values, marker="s", linewidths=0,
                                 **colours)
        drawn.particle_width = particle_width(data, points, dimension)
        return drawn
    corners, ids = polygons_of(data, plane)
    if values is None:
        cells = PolyCollection(corners, facecolors="0.7", edgecolors="0.4", linewidths=0.2)
    else:
        cells = PolyCollection(corners, array=numpy.array([values[i].mean() for i in ids]),
                               edgecolors="0.3", linewidths=0.2, cmap=colours["cmap"])
        cells.set_clim(colours["vmin"], colours["vmax"])
    axis.add_collection(cells)
    return cells


def size_markers(figure, axis, drawn):
    """Make each particle's square as wide as its volume's side, once the layout is final."""
    figure.canvas.draw()
    x0, x1 = axis.transData.transform([[0, 0], [1, 0]])[:, 0]
    points_per_unit = (x1 - x0) * 72.0 / figure.dpi
    for collection in drawn:
        width = getattr(collection, "particle_width", None)
        if width is not None:
            collection.set_sizes([max((1.1 * width * points_per_unit) ** 2, 0.5)])


def bounds(sets, plane):
    """The lower and upper corner, in the picture's plane, of all data sets."""
    points = numpy.vstack([vtk_to_numpy(d.GetPoints().GetData())[:, plane] for d in sets])
    low, high = points.min(axis=0), points.max(axis=0)
    pad = 0.04 * max(high - low)
    return low - pad, high + pad


def colour_range(all_values, text):
    """The colour range: --range, or the values' own (a flat field gets a unit wide range)."""
    if text:
        low, high = (float(v) for v in text.split(","))
        return low, high
    joined = numpy.concatenate([v for v in all_values if v is not None and len(v)] or [numpy.zeros(1)])
    low, high = float(joined.min()), float(joined.max())
    return (low, high) if high > low else (low - 0.5, low + 0.5)


def load(args):
    """The series (and --also) at the chosen time, each with its field's values."""
    main_data, time = fetch(args.series, args.time)
    if main_data.GetNumberOfPoints() == 0:
        sys.exit(f"{args.series}: no points at t = {time:g}")
    sets = [main_data] + ([fetch(args.also, time)[0]] if args.also else [])
    values = [values_of(d, args.field, args.component) for d in sets]
    if values[0] is None:
        data = main_data.GetPointData()
        names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())]
        sys.exit(f"{args.series}: no point field '{args.field}' (the fields: {', '.join(names)})")
    return sets, values, time


def field_label(data, args):
    """The colour bar's title: the field, |field| for a magnitude, field [k] for a component."""
    if data.GetPointData().GetArray(args.field).GetNumberOfComponents() == 1:
        return args.field
    return f"|{args.field}|" if args.component is None else f"{args.field} [{args.component}]"


def empty_axis(sets, plane):
    """A figure whose axis fits every data set, one length unit the same along both."""
    low, high = bounds([d for d in sets if d.GetNumberOfPoints()], plane)
    figure, axis = plt.subplots(figsize=(6.4, 4.0), dpi=100)
    axis.set_xlim(low[0], high[0])
    axis.set_ylim(low[1], high[1])
    axis.set_aspect("equal")
    axis.set_xlabel("xyz"[plane[0]])
    axis.set_ylabel("xyz"[plane[1]])
    return figure, axis


def main():
    """Load, draw (the --also series first, underneath) and save the picture."""
    args = arguments()
    plane = AXES[args.axes]
    sets, values, time = load(args)
    dimension = 3 if numpy.ptp(vtk_to_numpy(sets[0].GetPoints().GetData())[:, 2]) > 0 else 2
    figure, axis = empty_axis(sets, plane)
    vmin, vmax = colour_range(values, args.range)
    colours = {"cmap": "coolwarm", "vmin": vmin, "vmax": vmax}
    mappable, drawn = None, []
    for data, v in reversed(list(zip(sets, values))):
        if data.GetNumberOfPoints():
            drawn.append(draw(axis, data, v, plane, dimension, colours))
            mappable = drawn[-1] if v is not None else mappable
    label = field_label(sets[0], args)
    figure.colorbar(mappable, ax=axis, shrink=0.8, label=label)
    axis.set_title(f"{args.series}, t = {time:.4g}")
    size_markers(figure, axis, drawn)
    figure.savefig(args.output, bbox_inches="tight")
    print(f"{args.output}: {label} at t = {time:.4g} ({sets[0].GetNumberOfPoints()} points)")


main()
