#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Plots the void fraction of the demo and checks the layer averages.

The mesh is 5 x 5 x 10 box cells inside the DEM walls, so each horizontal
layer of cells holds the slices of the spheres between its two planes: that
slab volume has a closed form (sphere minus two caps), independent of the
library. The analytical model matches it up to the volume the DEM presses
into the side walls (contact overlap, a few 1e-6 of the particle volume,
reported by demVoidFraction as 'volume outside'); the other models show
their error against it (the smoothing ones blur the layers by design)."""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests"))
from foamCase import read_scalar_field, void_fraction_models  # noqa: E402

nx, ny, nz, H, W = 5, 5, 10, 0.04, 0.02
MODELS = void_fraction_models()
fields = {m: np.array(read_scalar_field("0/voidfraction_%s" % m)).reshape(nz, ny, nx)
          for m in MODELS}

# particles from the dump
rows, cols = [], None
with open("DEM/post/packing.dump") as f:
    lines = f.read().splitlines()
start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
cols = lines[start].split()[2:]
data = np.array([[float(v) for v in l.split()] for l in lines[start + 1:] if l.strip()])
z, r = data[:, cols.index("z")], data[:, cols.index("radius")]


def cap(R, d):   # volume of the ball beyond a plane at signed distance d
    d = np.clip(d, -R, R)
    h = R - d
    return math.pi * h * h * (3 * R - h) / 3


planes = np.linspace(0, H, nz + 1)
solid = np.array([np.sum(4 / 3 * math.pi * r ** 3 - cap(r, z - z0) - cap(r, z1 - z))
                  for z0, z1 in zip(planes[:-1], planes[1:])])
exact = 1 - solid / (W * W * H / nz)
zc = 0.5 * (planes[:-1] + planes[1:])

fig = plt.figure(figsize=(15, 6.5))
ax0 = fig.add_subplot(1, 4, 1)
styles = ("s--", "o-", "^-.", "v-", "d:", "x--")
for m, style in zip(MODELS, styles):
    layer = fields[m].mean(axis=(1, 2))
    ax0.plot(layer, zc * 1000, style, label=m)
    print("layer-averaged void fraction, %-10s max |error| against the slab closed form: %.3e"
          % (m, np.max(np.abs(layer - exact))))
ax0.plot(exact, zc * 1000, "k:", lw=2, label="exact slabs")
ax0.set_xlabel("layer-averaged void fraction")
ax0.set_ylabel("height (mm)")
ax0.legend(fontsize=8)
for k, m in enumerate(MODELS):
    ax = fig.add_subplot(2, 4, 2 + k + (k // 3))
    im = ax.imshow(fields[m][:, ny // 2, :], origin="lower", extent=(0, 20, 0, 40),
                   vmin=0.3, vmax=1.0, cmap="viridis")
    ax.set_title("%s (y = 10 mm)" % m, fontsize=9)
    ax.set_xticks([])
    ax.set_yticks([])
fig.colorbar(im, ax=fig.axes[1:], label="void fraction", shrink=0.8)
fig.savefig("voidFraction.png", dpi=110)
err = np.max(np.abs(fields["analytical"].mean(axis=(1, 2)) - exact))
sys.exit(0 if err < 1e-5 else 1)
