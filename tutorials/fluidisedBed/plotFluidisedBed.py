#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Bubbling bed: pressure drop against time next to the bed weight per area,
and particle snapshots; prints the time-averaged pressure drop after the
start-up (t > 0.4 s) and writes fluidisedBed.png and fluidisedBed.result."""
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from bedData import bed_weight, pressure_drop, pressure_panel, read_vtk, snapshots, step as step_of
from weightShares import weight_shares  # on the path bedData sets

weight = bed_weight(".")
t, dp = pressure_drop(".")
settled = t > 0.4
mean = dp[settled].mean()
fluctuation = dp[settled].std()/mean
model = re.search(r"^voidFractionModel\s+(\w+);", open("constant/couplingProperties").read(), re.M).group(1)
print(f"{model}: time-averaged pressure drop (t > 0.4 s) {mean:.1f} Pa, bed weight per area {weight:.1f} Pa "
      f"({100*(mean/weight - 1):+.1f} %), fluctuation {100*fluctuation:.1f} %")
with open("fluidisedBed.result", "w") as f:
    f.write(f"dp_error {abs(mean/weight - 1)}\nfluctuation {fluctuation}\n")
    # where the weight rests (runs that wrote the distributor's contact force)
    shares = weight_shares(".", 0.4)
    if shares:
        f.write(f"fluid_share {shares[0]}\ndistributor_share {shares[1]}\n")
        print(f"    the beads' weight carried by the gas {shares[0]:.3f}, the distributor {shares[1]:.3f} (t > 0.4 s)")

files = snapshots(".")[-4:]   # none in a run shorter than a write interval
fig = plt.figure(figsize=(10, 4.6))
ax = fig.add_subplot(1, len(files) + 2, (1, 2))
pressure_panel(ax, t, dp, weight, mean, 0.4)
couplingText = open("constant/couplingProperties").read()
n = int(re.search(r"particleFluidCoupling: formulation \w+, (\d+) particles", open("log.pimpleDEMFoam").read()).group(1))
parcels = re.search(r"coarseGraining\s*\{\s*factor\s+([0-9.]+);", couplingText)
what = f"{n:,} parcels (h = {parcels.group(1)})" if parcels else f"{n:,} beads"
ax.set_title(f"{model}: {what} in air", fontsize=9)
dt = float(re.search(r"^deltaT\s+(\S+);", open("system/controlDict").read(), re.M).group(1))
points = None
for k, path in enumerate(files):
    x, r, v = read_vtk(path)
    a = fig.add_subplot(1, len(files) + 2, k + 3)
    points = a.scatter(1e3*x[:, 0], 1e3*x[:, 2], s=0.3, c=v[:, 2], cmap="coolwarm", vmin=-0.3, vmax=0.3)
    a.set_xlim(0, 48)
    a.set_ylim(0, 120)
    a.set_aspect("equal")
    a.set_xticks([])
    a.set_yticks([] if k else [0, 40, 80, 120])
    step = step_of(path)
    a.set_title(f"t = {step*dt:.1f} s", fontsize=8)
plt.tight_layout()
if points is not None:
    fig.colorbar(points, ax=fig.axes[1:], shrink=0.8, label="bead vertical velocity [m/s]")
plt.savefig("fluidisedBed.png", dpi=120)
