# pvpython: read the .pvd series of one folder and the series of another
# (its .xdmf if there is one, else its .pvd) and compare them output by
# output (see output_formats.sh). Prints one line per series; exits 1 on
# the first difference.
import os
import sys
import numpy as np
from paraview import servermanager
from paraview.simple import MergeBlocks, PVDReader, XDMFReader
from vtkmodules.numpy_interface import dataset_adapter as dsa

vtu_folder, other_folder, names = sys.argv[1], sys.argv[2], sys.argv[3:]


def outputs(reader):
    """Each output step's points and point arrays (numpy)."""
    merged = MergeBlocks(Input=reader)
    for t in reader.TimestepValues:
        merged.UpdatePipeline(t)
        data = dsa.WrapDataObject(servermanager.Fetch(merged))
        arrays = {k: np.array(data.PointData[k]) for k in data.PointData.keys()}
        yield t, np.array(data.Points), arrays, data.GetNumberOfCells()


def stop(text):
    print(text)
    sys.exit(1)


for name in names:
    pvd = PVDReader(FileName="%s/%s.pvd" % (vtu_folder, name))
    other = "%s/%s" % (other_folder, name)
    if os.path.exists(other + ".xdmf"):
        xdmf = XDMFReader(FileNames=[other + ".xdmf"])
    else:
        xdmf = PVDReader(FileName=other + ".pvd")
    times_v, times_h = list(pvd.TimestepValues), list(xdmf.TimestepValues)
    if len(times_v) != len(times_h) or not np.allclose(times_v, times_h, rtol=1e-12):
        stop("%s: times %s and %s" % (name, times_v, times_h))
    for (t, pv, av, cv), (_, ph, ah, ch) in zip(outputs(pvd), outputs(xdmf)):
        if pv.shape != ph.shape or cv != ch:
            stop("%s at t = %g: %s points and %s, %d cells and %d" % (name, t, pv.shape, ph.shape, cv, ch))
        if name == "particles":
            # The same particles with the same values, bit for bit.
            ov, oh = np.argsort(av["id"]), np.argsort(ah["id"])
            if ah["id"].dtype != np.int64:
                stop("particle ids are %s, not Int64" % ah["id"].dtype)
            if not np.array_equal(pv[ov], ph[oh]):
                stop("particles at t = %g: positions differ" % t)
            for k in av:
                if k not in ah or not np.array_equal(av[k][ov], ah[k][oh]):
                    stop("particles at t = %g: array %s differs or is missing" % (t, k))
        else:
            # The same cells and values (the grid's .vtu, written by
            # deal.II, stores Float32 and its .h5 doubles).
            for k in av:
                if k not in ah:
                    stop("%s: array %s missing" % (name, k))
                scale = max(np.abs(av[k]).max(), 1e-300)
                if np.abs(av[k] - ah[k]).max() > 1e-6 * scale:
                    stop("%s at t = %g: %s differs by %g" % (name, t, k, np.abs(av[k] - ah[k]).max()))
    print("%s: %d outputs of %d points equal in %s and %s" % (name, len(times_v), pv.shape[0], vtu_folder, other_folder))
