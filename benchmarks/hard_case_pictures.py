"""Pictures of the hard cases for the user guide (doc/guide/scenes.md): each scene as shipped, its
particles coloured by a field at three times, from the program's own
output. Needs ParaView's pvpython (Debian: paraview) and, without a
display, xvfb-run:

    xvfb-run -a pvpython benchmarks/hard_case_pictures.py build/dealmpm [WORK [CASE,CASE]]

writes doc/pictures/<case>_<k>.png (k = 0, 1, 2) and prints the guide
table that shows them (only the rows of the CASEs named, if any).
"""
import os
import subprocess
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, Hide, PVDReader, SaveScreenshot, Show)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PICTURES = os.path.join(ROOT, "doc", "pictures")

# case: (scene, field, component ("Magnitude" or an index: 4 is yy of the
# 3 x 3 stress), three times, what the colour shows)
CASES = {
    "crossing_bodies_2d": ("prm/hard-cases/crossing_bodies_2d.prm", "velocity",
                           "Magnitude", (0, 0.15, 0.3), "speed"),
    "cantilever": ("prm/hard-cases/cantilever.prm", "displacement", "Magnitude",
                   (0, 0.5, 1.1), "displacement"),
    "granular_collapse": ("prm/hard-cases/granular_collapse.prm", "velocity",
                          "Magnitude", (0, 0.2, 1.0), "speed"),
    "dam_break": ("prm/hard-cases/dam_break.prm", "velocity", "Magnitude",
                  (0, 0.1, 0.22), "speed"),
    "resting_column": ("prm/hard-cases/resting_column.prm", "stress", 4,
                       (0, 0.5, 4), "sigma_yy"),
    "stiff_on_soft": ("prm/hard-cases/stiff_on_soft.prm", "stress", 4,
                      (0, 0.5, 6), "sigma_yy"),
    "taylor_bar": ("prm/hard-cases/taylor_bar.prm", "plastic_strain", 0,
                   (0, 2e-5, 8e-5), "plastic strain"),
}
# 3D cases seen from the side (looking along +y, z up) rather than from +z.
SIDE_VIEW = {"taylor_bar"}


def run(dealmpm, scene, folder, times):
    interval = min(b - a for a, b in zip(times, times[1:])) / 2
    subprocess.run([dealmpm, os.path.join(ROOT, scene), "-s", "Output/Directory=" + folder,
                    "-s", "Output/Write particles=true", "-s", "Output/Particle CSV=false",
                    "-s", "Output/Interval=%g" % interval, "-s", "Output/Progress interval=0"],
                   check=True, capture_output=True)


def render(folder, name, field, component, times, label, side):
    reader = PVDReader(FileName=os.path.join(folder, "particles.pvd"))
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [480, 320]
    view.OrientationAxesVisibility = 0
    view.InteractionMode = "2D"
    display = Show(reader, view)
    display.SetRepresentationType("Points")
    display.PointSize = 3
    ColorBy(display, ("POINTS", field))
    lut = GetColorTransferFunction(field)
    if component == "Magnitude":
        lut.VectorMode = "Magnitude"
    else:
        lut.VectorMode = "Component"
        lut.VectorComponent = component
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [1, 1, 1]
    # One camera for the three pictures: the bounds of all three.
    steps = [min(reader.TimestepValues, key=lambda s: abs(s - t)) for t in times]
    low, high = [1e300] * 3, [-1e300] * 3
    for step in steps:
        reader.UpdatePipeline(step)
        b = reader.GetDataInformation().GetBounds()
        for d in range(3):
            low[d], high[d] = min(low[d], b[2 * d]), max(high[d], b[2 * d + 1])
    center = [(a + b) / 2 for a, b in zip(low, high)]
    up = 2 if side else 1
    distance = 10 * max(high[0] - low[0], 1e-9)
    view.CameraFocalPoint = center
    view.CameraPosition = ([center[0], center[1] - distance, center[2]] if side else
                           [center[0], center[1], center[2] + distance])
    view.CameraViewUp = [0, 0, 1] if side else [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.6 * max((high[up] - low[up]), (high[0] - low[0]) * 320 / 480)
    bar = GetScalarBar(lut, view)
    files = []
    for k, step in enumerate(steps):
        view.ViewTime = step
        # The range must be this time's: without the update it is the
        # range of the pipeline's last update (another time).
        reader.UpdatePipeline(step)
        display.RescaleTransferFunctionToDataRange(False, True)
        bar.Title = label
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
        display.SetScalarBarVisibility(view, True)
        path = os.path.join(PICTURES, "%s_%d.png" % (name, k))
        SaveScreenshot(path, view, ImageResolution=[480, 320])
        files.append((view.ViewTime, path))
    display.SetScalarBarVisibility(view, False)
    Hide(reader, view)
    return files


def main():
    dealmpm = os.path.abspath(sys.argv[1])
    work = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "hard-case-pictures")
    os.makedirs(PICTURES, exist_ok=True)
    print("| case | coloured by | three times |\n|---|---|---|")
    only = sys.argv[3].split(",") if len(sys.argv) > 3 else list(CASES)
    for name, (scene, field, component, times, label) in CASES.items():
        if name not in only:
            continue
        folder = os.path.join(work, name)
        run(dealmpm, scene, folder, times)
        files = render(folder, name, field, component, times, label, name in SIDE_VIEW)
        cells = " ".join("![%s at t = %.3g s](../pictures/%s)" % (name, t, os.path.basename(p))
                         for t, p in files)
        print("| %s | %s | %s |" % (name, label, cells))


main()
