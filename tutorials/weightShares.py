# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Where a bed's weight rests: the fluid's vertical force on the particles (the
solver's coupling lines) and the walls' contact forces (a LIGGGHTS fix print of
the wall fixes' stored forces), each over the particles' weight."""
import glob
import os
import re

import numpy as np


def weight_shares(case, after, until=float("inf")):
    """(fluid, distributor, column wall) vertical force over the beads' weight, each
    time-averaged over after < t <= until: the fluid's from the solver's log (every log of
    a continued run), the walls' from DEM/post/wallForces.txt (t, distributor, column, weight
    as a LIGGGHTS fix print writes them); None without those"""
    if not os.path.isfile(os.path.join(case, "DEM/post/wallForces.txt")):
        return None
    walls = np.loadtxt(os.path.join(case, "DEM/post/wallForces.txt"), ndmin=2)
    late = (walls[:, 0] > after) & (walls[:, 0] <= until)
    # each coupling line after the time step it ends (every log of a continued run)
    coupled, fz = [], []
    for log in sorted(glob.glob(os.path.join(case, "log.pimpleDEMFoam*"))):
        now = None
        for line in open(log):
            if line.startswith("Time = "):
                now = float(line.split()[2])
            m = re.search(r"total fluid force on the particles \(\S+ \S+ (\S+)\)", line)
            if m and now is not None:
                coupled.append(now)
                fz.append(float(m.group(1)))
    coupled, fz = np.array(coupled), np.array(fz)
    window = (coupled > after) & (coupled <= until)
    if not late.any() or not window.any():
        return None
    weight = walls[late, 3].mean()
    return (fz[window].mean()/weight, walls[late, 1].mean()/weight, walls[late, 2].mean()/weight)
