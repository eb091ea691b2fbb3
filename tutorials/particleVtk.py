# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The particle files pimpleDEMFoam writes, VTK/particles_<step>.vtp (VTK XML
polydata, inline ASCII or base64: the centres as points, point data radius,
id and velocity), and legacy VTK/particles_<step>.vtk files."""
import base64
import glob
import os
import re
import xml.etree.ElementTree as ElementTree

import numpy as np

TYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "Int64": "<i8", "UInt8": "u1"}


def files(case):
    """The case's particle files, sorted by time step"""
    found = glob.glob(os.path.join(case, "VTK", "particles_*.vt[kp]"))
    return sorted(found, key=step)


def step(path):
    """The time step a particle file was written at"""
    return int(re.search(r"_(\d+)\.vt[kp]$", path).group(1))


def read(path):
    """(positions n x 3, radii n, velocities n x 3 or None where the file has none)"""
    if path.endswith(".vtk"):
        return read_legacy(path)
    piece = ElementTree.parse(path).getroot().find("PolyData/Piece")
    if piece is None:
        raise SystemExit("particleVtk: no PolyData Piece in %s" % path)
    n = int(piece.get("NumberOfPoints"))
    x = data_array(piece.find("Points/DataArray"), n, 3, path)
    arrays = {a.get("Name"): a for a in piece.findall("PointData/DataArray")}
    if "radius" not in arrays:
        raise SystemExit("particleVtk: no radius in %s" % path)
    r = data_array(arrays["radius"], n, 1, path)
    v = data_array(arrays["velocity"], n, 3, path) if "velocity" in arrays else None
    return x.astype(float), r.astype(float), None if v is None else v.astype(float)


def data_array(element, n, components, path):
    dtype = np.dtype(TYPES[element.get("type")])
    text = element.text or ""
    if element.get("format") == "ascii":
        values = np.array(text.split(), dtype)
    else:
        raw = base64.b64decode("".join(text.split()))
        # a UInt64 byte count precedes the values
        values = np.frombuffer(raw[8:8 + int(np.frombuffer(raw[:8], "<u8")[0])], dtype)
    if values.size != n*components:
        raise SystemExit("particleVtk: %s in %s has %d values, not %d" %
                         (element.get("Name"), path, values.size, n*components))
    return values.reshape(n, components) if components > 1 else values


def read_legacy(path):
    lines = open(path).read().split("\n")
    at = next((i for i, line in enumerate(lines) if line.startswith("POINTS")), None)
    if at is None:
        raise SystemExit("particleVtk: no POINTS in %s" % path)
    n = int(lines[at].split()[1])
    x = np.array([line.split() for line in lines[at + 1:at + 1 + n]], float).reshape(n, 3)

    def block(header, skip):
        i = next((k for k, line in enumerate(lines) if line.startswith(header)), None)
        return None if i is None else lines[i + skip:i + skip + n]
    radius = block("SCALARS radius", 2)
    if radius is None:
        raise SystemExit("particleVtk: no radius in %s" % path)
    velocity = block("VECTORS velocity", 1)
    r = np.array(radius, float)
    v = None if velocity is None else np.array([line.split() for line in velocity], float).reshape(n, 3)
    return x, r, v
