#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Bubbling bed in the cylindrical column: the inlet pressure drop against
time beside the bed weight per area of the mesh's inlet, and side views of
the beads; prints the time-averaged pressure drop after the start-up
(t > 0.3 s) and where the beads' weight rests over the same time: the
fluid's vertical force on them (the solver's log), the distributor's and
the column wall's contact forces (DEM/post/wallForces.txt), each over the
beads' weight, and their sum (Newton: 1 for a bed that does not accelerate
on average). Writes cylinderBed.png and cylinderBed.result."""
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

# the fluidisedBed tutorial's readers, also from a copy of the case elsewhere
PROJECT = os.environ.get("VFM_PROJECT_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "../.."))
sys.path[:0] = [os.path.join(PROJECT, "tutorials"), os.path.join(PROJECT, "tutorials", "fluidisedBed")]
from bedData import bed_weight, inlet_area, pressure_drop, pressure_panel, read_vtk, snapshots, step as step_of  # noqa: E402
from weightShares import weight_shares  # noqa: E402

START_UP = 0.3


weight = bed_weight(".", inlet_area("."))
t, dp = pressure_drop(".")
settled = t > START_UP
if not settled.any():
    print(f"plotCylinderBed: the run ends before t = {START_UP} s: no average, no plot")
    if os.path.exists("cylinderBed.result"):
        os.remove("cylinderBed.result")
    sys.exit(0)
mean = dp[settled].mean()
model = re.search(r"^voidFractionModel\s+(\w+);", open("constant/couplingProperties").read(), re.M).group(1)
n = int(re.search(r"particleFluidCoupling: formulation \w+, (\d+) particles",
                  open("log.pimpleDEMFoam").read()).group(1))
print(f"{model}: time-averaged pressure drop (t > {START_UP} s) {mean:.1f} Pa, bed weight per inlet area "
      f"{weight:.1f} Pa ({100*(mean/weight - 1):+.1f} %)")
with open("cylinderBed.result", "w") as f:
    f.write(f"dp_error {abs(mean/weight - 1)}\nweight_per_area {weight}\nmean_dp {mean}\n")
    shares = weight_shares(".", START_UP)
    if shares:
        print("    where the beads' weight rests (t > %g s): fluid %.3f, distributor %.3f, column wall %.3f; "
              "sum %.3f" % ((START_UP,) + shares + (sum(shares),)))
        f.write("fluid_share %.6g\ndistributor_share %.6g\ncolumn_share %.6g\n" % shares)

files = snapshots(".")[-3:]
fig = plt.figure(figsize=(10, 4.6))
ax = fig.add_subplot(1, len(files) + 2, (1, 2))
pressure_panel(ax, t, dp, weight, mean, START_UP, per="inlet area")
ax.set_title(f"{model}: {n:,} beads, 30 mm column (O-grid)", fontsize=9)
dt = float(re.search(r"^deltaT\s+(\S+);", open("system/controlDict").read(), re.M).group(1))
points = None
for k, path in enumerate(files):
    x, _, v = read_vtk(path)
    a = fig.add_subplot(1, len(files) + 2, k + 3)
    # the beads of the central slab |y| < 3 mm, seen from the side
    slab = np.abs(x[:, 1]) < 3e-3
    points = a.scatter(1e3*x[slab, 0], 1e3*x[slab, 2], s=1.5, c=v[slab, 2], cmap="coolwarm",
                       vmin=-0.3, vmax=0.3)
    a.set_xlim(-15, 15)
    a.set_ylim(0, 60)
    a.set_aspect("equal")
    a.set_xticks([-15, 0, 15])
    a.set_yticks([] if k else [0, 20, 40, 60])
    step = step_of(path)
    a.set_title(f"t = {step*dt:.2f} s\n|y| < 3 mm" + ("\nz [mm]" if not k else ""), fontsize=8)
fig.subplots_adjust(wspace=0.35)
if points is not None:
    fig.colorbar(points, ax=fig.axes[1:], shrink=0.8, label="bead vertical velocity [m/s]")
fig.savefig("cylinderBed.png", dpi=120)
