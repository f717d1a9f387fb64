"""Read the VTK XML files dealmpm writes, for the program checks: .pvd
series, .pvtu records and .vtu pieces, both ours (raw appended binary with
UInt64 headers) and deal.II's (inline base64, zlib-compressed or not)."""

import array
import base64
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

TYPES = {"Int8": "b", "UInt8": "B", "Int32": "i", "UInt32": "I",
         "Int64": "q", "UInt64": "Q", "Float32": "f", "Float64": "d"}


def parse_xml(path):
    """The XML part of a VTK file (everything but raw appended data, which
    is not XML), as an ElementTree root; raises on anything malformed."""
    with open(path, "rb") as f:
        data = f.read()
    cut = data.find(b"<AppendedData")
    if cut >= 0:
        data = data[:cut] + b"</VTKFile>"
    return ET.fromstring(data)


def pvd_files(path):
    """(time, file) of each entry of a .pvd series."""
    root = parse_xml(path)
    assert root.get("type") == "Collection", path
    return [(float(d.get("timestep")), d.get("file"))
            for d in root.iter("DataSet")]


def pvtu_pieces(path):
    root = parse_xml(path)
    return [p.get("Source") for p in root.iter("Piece")]


def declared_arrays(element):
    """{name: (type, components)} of the (P)DataArrays under element."""
    result = {}
    for a in element:
        if a.tag in ("DataArray", "PDataArray"):
            result[a.get("Name")] = (a.get("type"),
                                     int(a.get("NumberOfComponents", "1")))
    return result


def _values(raw, vtk_type):
    values = array.array(TYPES[vtk_type])
    values.frombytes(raw)
    if sys.byteorder != "little":
        values.byteswap()
    return values


def _inline(text, vtk_type, header_type, compressed):
    text = "".join(text.split())
    header_size = struct.calcsize("<" + TYPES[header_type])
    code = "<" + TYPES[header_type]
    if not compressed:
        raw = base64.b64decode(text)
        (n_bytes,) = struct.unpack(code, raw[:header_size])
        return _values(raw[header_size:header_size + n_bytes], vtk_type)
    # zlib: the header (n_blocks, block size, last block size, compressed
    # sizes) is base64 on its own, then the compressed blocks.
    first = base64.b64decode(text[:8])
    (n_blocks,) = struct.unpack(code, first[:header_size])
    header_chars = -(-(3 + n_blocks) * header_size // 3) * 4
    header = base64.b64decode(text[:header_chars])
    sizes = struct.unpack("<" + TYPES[header_type] * (3 + n_blocks),
                          header[:(3 + n_blocks) * header_size])
    blocks = base64.b64decode(text[header_chars:])
    raw, start = b"", 0
    for size in sizes[3:]:
        raw += zlib.decompress(blocks[start:start + size])
        start += size
    return _values(raw, vtk_type)


def read_vtu(path):
    """{'n_points': n, 'points': [x, y, z, ...], 'arrays': {name: (type,
    components, values)}} of an UnstructuredGrid piece."""
    with open(path, "rb") as f:
        data = f.read()
    root = parse_xml(path)
    assert root.get("type") == "UnstructuredGrid", path
    header_type = root.get("header_type", "UInt32")
    compressed = root.get("compressor") is not None
    appended = None
    cut = data.find(b"<AppendedData")
    if cut >= 0:
        appended = data.index(b"_", cut) + 1
    header_size = struct.calcsize("<" + TYPES[header_type])

    def values(a):
        vtk_type = a.get("type")
        if a.get("format") == "appended" and compressed:
            # (n_blocks, block size, last block size, compressed sizes),
            # then the blocks.
            start = appended + int(a.get("offset"))
            code = "<" + TYPES[header_type]
            (n_blocks,) = struct.unpack(code, data[start:start + header_size])
            sizes = struct.unpack("<" + TYPES[header_type] * (3 + n_blocks),
                                  data[start:start + (3 + n_blocks) * header_size])
            start += (3 + n_blocks) * header_size
            raw = b""
            for size in sizes[3:]:
                raw += zlib.decompress(data[start:start + size])
                start += size
            return _values(raw, vtk_type)
        if a.get("format") == "appended":
            start = appended + int(a.get("offset"))
            (n_bytes,) = struct.unpack(
                "<" + TYPES[header_type], data[start:start + header_size])
            start += header_size
            return _values(data[start:start + n_bytes], vtk_type)
        if a.get("format") == "binary":
            return _inline(a.text or "", vtk_type, header_type, compressed)
        return array.array(TYPES[vtk_type], [
            (float if TYPES[vtk_type] in "fd" else int)(v)
            for v in (a.text or "").split()])

    piece = root.find("UnstructuredGrid/Piece")
    result = {"n_points": int(piece.get("NumberOfPoints")),
              "n_cells": int(piece.get("NumberOfCells")), "arrays": {}}
    points = piece.find("Points/DataArray")
    result["points_declared"] = (points is not None and
                                 int(points.get("NumberOfComponents", "1")))
    result["points"] = values(points) if points is not None else []
    for a in piece.find("PointData") or []:
        result["arrays"][a.get("Name")] = (
            a.get("type"), int(a.get("NumberOfComponents", "1")), values(a))
    cells = piece.find("Cells")
    if cells is not None:
        result["cells"] = {a.get("Name"): values(a) for a in cells}
    return result


def check_series(folder, pvd):
    """Problems with a series: entries whose .pvtu or pieces are missing."""
    problems = []
    for _, name in pvd_files(os.path.join(folder, pvd)):
        record = os.path.join(folder, name)
        if not os.path.isfile(record):
            problems.append("missing " + name)
            continue
        if record.endswith(".vtu"):  # one piece (a rigid body)
            continue
        # A .pvtu names its pieces relative to its own folder.
        for piece in pvtu_pieces(record):
            if not os.path.isfile(os.path.join(os.path.dirname(record), piece)):
                problems.append("missing " + piece)
    return problems
