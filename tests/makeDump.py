#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Writes a LIGGGHTS-style text dump of random polydisperse spheres.

usage: makeDump.py OUT N rmin rmax xmin xmax ymin ymax zmin zmax [seed] [--wall-gap]
With --wall-gap every sphere lies wholly inside the box, so the exact solid
volume in the mesh is the sum of the sphere volumes. Columns come in a
shuffled order on purpose (the reader must find them by name).
"""
import random
import sys

args = [a for a in sys.argv[1:] if not a.startswith("--")]
out, n = args[0], int(args[1])
rmin, rmax = float(args[2]), float(args[3])
lo = [float(args[4]), float(args[6]), float(args[8])]
hi = [float(args[5]), float(args[7]), float(args[9])]
seed = int(args[10]) if len(args) > 10 else 1
gap = "--wall-gap" in sys.argv
rng = random.Random(seed)
with open(out, "w") as f:
    f.write("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\n" % n)
    f.write("ITEM: BOX BOUNDS ff ff ff\n")
    for a, b in zip(lo, hi):
        f.write("%.17g %.17g\n" % (a, b))
    f.write("ITEM: ATOMS id type x y z vx vy vz radius\n")
    for i in range(n):
        r = rng.uniform(rmin, rmax)
        m = r if gap else 0.0
        x = [rng.uniform(a + m, b - m) for a, b in zip(lo, hi)]
        f.write("%d 1 %.17g %.17g %.17g 0 0 0 %.17g\n" % (i + 1, x[0], x[1], x[2], r))
