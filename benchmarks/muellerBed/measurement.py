# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Mueller et al.'s measured profiles (measured/, see its README) and the
difference of a simulated profile from them, shared by the muellerBed
tutorial's bedProfiles.py and the study."""
import os

import numpy as np

MEASURED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "measured")
PUBLISHED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "published")


def _read(path):
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2) if os.path.isfile(path) else None


def measured(kind, u, height):
    """(x_m, value) rows of the measured profile of kind ('voidfraction' or
    'particleVelocity') at inlet velocity u and height ('h16.4mm'), or None"""
    return _read(os.path.join(MEASURED, "%s_U%g_%s.csv" % (kind, u, height)))


def published(source, kind, u, height):
    """a published simulation's profile (published/<source>_<kind>_U<u>_<height>.csv), or None"""
    return _read(os.path.join(PUBLISHED, "%s_%s_U%g_%s.csv" % (source, kind, u, height)))


def difference(points, x, values):
    """(mean absolute, mean signed) difference of the profile (x, values),
    interpolated linearly to each measured x, from the measured points"""
    d = np.interp(points[:, 0], x, values) - points[:, 1]
    return float(np.abs(d).mean()), float(d.mean())
