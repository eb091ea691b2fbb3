# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The particles of a VTK/particles_<step>.vtk file that pimpleDEMFoam writes
(legacy ASCII polydata: the centres as POINTS, then point data with the
radius as a scalar and the velocity as a vector)."""
import numpy as np


def read(path):
    """(positions n x 3, radii n, velocities n x 3 or None where the file has none)"""
    lines = open(path).read().split("\n")
    at = next((i for i, l in enumerate(lines) if l.startswith("POINTS")), None)
    if at is None:
        raise SystemExit("particleVtk: no POINTS in %s" % path)
    n = int(lines[at].split()[1])
    x = np.array([l.split() for l in lines[at + 1:at + 1 + n]], float).reshape(n, 3)

    def block(header, skip):
        i = next((k for k, l in enumerate(lines) if l.startswith(header)), None)
        return None if i is None else lines[i + skip:i + skip + n]
    radius = block("SCALARS radius", 2)
    if radius is None:
        raise SystemExit("particleVtk: no radius in %s" % path)
    velocity = block("VECTORS velocity", 1)
    r = np.array(radius, float)
    v = None if velocity is None else np.array([l.split() for l in velocity], float).reshape(n, 3)
    return x, r, v
