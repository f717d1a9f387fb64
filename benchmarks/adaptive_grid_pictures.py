"""Pictures of prm/disk_drop_adaptive.prm for the user guide
(doc/guide/adaptivity.md): the adaptive grid (grey edges) and the
particles coloured by speed before, at and after the impact, from the
program's own output. Needs ParaView's pvbatch (Debian: paraview), which
renders without a display:

    xvfb-run -a pvbatch benchmarks/adaptive_grid_pictures.py build/dealmpm [WORK]

writes doc/pictures/disk_drop_adaptive_<k>.png (k = 0, 1, 2).
"""
import os
import subprocess
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, PVDReader, SaveScreenshot, Show)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SCENE = os.path.join(ROOT, "prm", "disk_drop_adaptive.prm")
PICTURES = os.path.join(ROOT, "doc", "pictures")
TIMES = (0.0, 0.26, 0.5)


def run(dealmpm, folder):
    subprocess.run([dealmpm, SCENE, "-s", "Output/Directory=" + folder,
                    "-s", "Output/Interval=0.01", "-s", "Output/Progress interval=0"],
                   check=True, capture_output=True)


def show(folder, view):
    """The grid as grey edges, the particles as points coloured by speed."""
    grid = PVDReader(FileName=os.path.join(folder, "grid.pvd"))
    edges = Show(grid, view)
    edges.SetRepresentationType("Wireframe")
    edges.ColorArrayName = ["POINTS", ""]
    edges.AmbientColor = edges.DiffuseColor = [0.55, 0.55, 0.55]
    particles = PVDReader(FileName=os.path.join(folder, "particles.pvd"))
    points = Show(particles, view)
    points.SetRepresentationType("Points")
    points.PointSize = 3
    ColorBy(points, ("POINTS", "velocity"))
    lut = GetColorTransferFunction("velocity")
    lut.VectorMode = "Magnitude"
    lut.RescaleTransferFunction(0.0, 2.5)
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "speed (m/s)", ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    points.SetScalarBarVisibility(view, True)
    return particles


def main():
    dealmpm = os.path.abspath(sys.argv[1])
    folder = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "adaptive-grid-pictures")
    run(dealmpm, folder)
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [480, 480]
    view.OrientationAxesVisibility = 0
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [1, 1, 1]
    particles = show(folder, view)
    # The lower half of the box, where the disk falls and bounces.
    view.CameraFocalPoint = [2, 1, 0]
    view.CameraPosition = [2, 1, 10]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 1.05
    for k, t in enumerate(TIMES):
        view.ViewTime = min(particles.TimestepValues, key=lambda s: abs(s - t))
        path = os.path.join(PICTURES, "disk_drop_adaptive_%d.png" % k)
        SaveScreenshot(path, view, ImageResolution=[480, 480])
        print("t = %.3g s: %s" % (view.ViewTime, os.path.relpath(path, ROOT)))


main()
