#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""A spouted bed run (run in its folder): the pressure drop at the inlet
against the bed weight per area of the bed's cross-section, and the
time-averaged particle speed across the width at H/H0 = 0.15 to 0.80, of
the particles within one diameter of the front wall (y = 0, where the
measurement looks) and of all particles (depth-averaged), after the
start-up. Writes particleSpeed_H<NNN>.csv (x_mm,speed_m_s: the front wall;
depth_averaged_m_s beside it), spoutedBed.result (the mean absolute
difference from each measured profile, the spout's width, the fountain's
height, the pressure drop over the weight, the particle count, and the
shares of the weight the gas, the floor and the walls carry) and
spoutedBed.png (a snapshot coloured by speed, the profiles with the
measured points)."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

PROJECT = os.environ.get("VFM_PROJECT_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "../.."))
sys.path[:0] = [os.path.join(PROJECT, "tutorials"), os.path.join(PROJECT, "tutorials", "fluidisedBed")]
import caseProperties  # noqa: E402
from bedData import bed_weight, pressure_drop, read_vtk, snapshots, step  # noqa: E402
from weightShares import weight_shares  # noqa: E402

START_UP = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
H0 = 0.2                    # m, the settled bed (Yue et al. 2020)
HEIGHTS = (0.15, 0.30, 0.45, 0.60, 0.75, 0.80)
BIN = 0.01                  # m, across the width
MEASURED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "measured")

box = caseProperties.dem_parameters(".")
half, depth = box["halfWidth"], box["depth"]
d = caseProperties.particle_diameter(".")
dt = caseProperties._entry("system/controlDict", "deltaT")
weight = bed_weight(".", 2*half*depth)
t, dp = pressure_drop(".")
late = t > START_UP
result = {"dp_vs_weight": float(np.mean(dp[late])/weight) if late.any() else float("nan")}
# where the weight rests (runs that wrote the walls' contact forces)
shares = weight_shares(".", START_UP)
if shares:
    result.update(fluid_share=shares[0], floor_share=shares[1], walls_share=shares[2])
    print("    the beads' weight carried by the gas %.3f, the floor %.3f, the walls %.3f (t > %g s)"
          % (shares + (START_UP,)))

edges = np.arange(-half, half + 1e-9, BIN)
centres = 0.5*(edges[1:] + edges[:-1])
WHERE = ("front", "depth")
CACHE = "snapshotProfiles.npz"


def snapshot_sums(path):
    """One snapshot's speed sums and particle counts [height, front or depth,
    bin], and its fountain: the height below which 99 % of the particles over
    the inlet lie."""
    x, r, v = read_vtk(path)
    speed = np.linalg.norm(v, axis=1)
    sums = np.zeros((len(HEIGHTS), len(WHERE), len(centres)))
    counts = np.zeros_like(sums)
    for i, h in enumerate(HEIGHTS):
        layer = np.abs(x[:, 2] - h*H0) < d
        for j, pick in enumerate((layer & (x[:, 1] < r + d), layer)):
            k = np.clip(np.digitize(x[pick, 0], edges) - 1, 0, len(centres) - 1)
            np.add.at(sums[i, j], k, speed[pick])
            np.add.at(counts[i, j], k, 1)
    core = np.abs(x[:, 0]) < 0.012
    return sums, counts, np.quantile(x[core, 2], 0.99) if core.any() else np.nan


def snapshot_table():
    """{time step: (sums, counts, fountain)} of every snapshot after the
    start-up. Kept in snapshotProfiles.npz, so that a run continued elsewhere
    without its earlier snapshots still averages over them."""
    table = {}
    if os.path.isfile(CACHE):
        kept = np.load(CACHE)
        if kept["edges"].shape == edges.shape and np.allclose(kept["edges"], edges) and kept["diameter"] == d:
            table = {int(s): (a, c, f) for s, a, c, f in zip(kept["steps"], kept["sums"], kept["counts"],
                                                             kept["fountain"])}
    added = False
    for f in snapshots("."):
        if step(f)*dt > START_UP and step(f) not in table:
            table[step(f)] = snapshot_sums(f)
            added = True
    if added and table:
        steps = sorted(table)
        np.savez_compressed(CACHE, edges=edges, diameter=d, steps=np.array(steps),
                            sums=np.array([table[s][0] for s in steps]),
                            counts=np.array([table[s][1] for s in steps]),
                            fountain=np.array([table[s][2] for s in steps]))
    return {s: table[s] for s in sorted(table) if s*dt > START_UP}


def averaged(steps):
    """Time-averaged speed profiles {(H/H0, 'front' or 'depth'): per bin} of
    the snapshots, and the fountain height of each."""
    sums = sum(table[s][0] for s in steps)
    counts = sum(table[s][1] for s in steps)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.where(counts > 0, sums/np.maximum(counts, 1), np.nan)
    return ({(h, where): mean[i, j] for i, h in enumerate(HEIGHTS) for j, where in enumerate(WHERE)},
            [table[s][2] for s in steps])


files = [(step(f)*dt, f) for f in snapshots(".")]
table = snapshot_table()
used = list(table)
if not used:
    sys.exit("    no particle snapshot after the %g s start-up to average" % START_UP)
profiles, fountain = averaged(used)
for h in HEIGHTS:
    with open("particleSpeed_H%03d.csv" % round(100*h), "w") as out:
        out.write("x_mm,speed_m_s,depth_averaged_m_s\n")
        for c, front, deep in zip(centres, profiles[(h, "front")], profiles[(h, "depth")]):
            out.write("%.1f,%.5f,%.5f\n" % (1000*c, front, deep))
measured = {}
for h in (0.15, 0.45, 0.75):
    m = np.loadtxt(os.path.join(MEASURED, "particleSpeed_H%03d.csv" % round(100*h)), delimiter=",", skiprows=1)
    measured[h] = m
    sim = np.interp(m[:, 0]/1000, centres, profiles[(h, "front")])
    result["mad_h%03d" % round(100*h)] = float(np.nanmean(np.abs(sim - m[:, 1])))
# the spout: where the front-wall speed at H/H0 = 0.45 exceeds half its peak
mid = profiles[(0.45, "front")]
if np.isfinite(mid).any():
    fast = centres[mid > 0.5*np.nanmax(mid)]
    result["spout_width_mm"] = float(1000*(fast.max() - fast.min() + BIN))
result["fountain_mm"] = float(1000*np.nanmean(fountain)) if fountain else float("nan")
# statistics: the front-wall profiles of the averaging window's two halves, their mean
# absolute difference over the six heights in the spout (the channel's 24 mm) and the annulus
if len(used) >= 4:
    first, _ = averaged(used[:len(used)//2])
    second, _ = averaged(used[len(used)//2:])
    spout = np.abs(centres) < 0.012
    for name, where in (("spout", spout), ("annulus", ~spout)):
        gap = np.concatenate([np.abs(first[(h, "front")] - second[(h, "front")])[where] for h in HEIGHTS])
        result["halves_%s_m_s" % name] = float(np.nanmean(gap))
result["snapshots"] = len(used)
with open("spoutedBed.result", "w") as out:
    for k, v in result.items():
        out.write("%s %.6g\n" % (k, v))
print("    after t = %g s (%d snapshots): pressure drop / bed weight %.3f; mean |front-wall speed - measured| "
      "%.3f, %.3f, %.3f m/s at H/H0 = 0.15, 0.45, 0.75; spout %.0f mm wide, fountain %.0f mm; halves differ by %.3f m/s (spout), %.3f m/s (annulus)"
      % (START_UP, len(used), result["dp_vs_weight"], result.get("mad_h015", np.nan), result.get("mad_h045", np.nan),
         result.get("mad_h075", np.nan), result.get("spout_width_mm", np.nan), result["fountain_mm"],
         result.get("halves_spout_m_s", np.nan), result.get("halves_annulus_m_s", np.nan)))

fig, axes = plt.subplots(1, 4, figsize=(15, 5), gridspec_kw=dict(width_ratios=[1.1, 1, 1, 1]))
if files:
    x, r, v = read_vtk(files[-1][1])
    speed = np.linalg.norm(v, axis=1)
    sc = axes[0].scatter(1000*x[:, 0], 1000*x[:, 2], s=2, c=speed, cmap="viridis", vmin=0, vmax=2)
    fig.colorbar(sc, ax=axes[0], label="particle speed [m/s]")
    axes[0].set_title("t = %.2f s, side view" % files[-1][0], fontsize=9)
axes[0].set_xlim(-140, 140)
axes[0].set_ylim(-40, 600)
axes[0].set_aspect("equal")
axes[0].set_xlabel("x [mm]")
axes[0].set_ylabel("z [mm]")
for ax, h in zip(axes[1:], (0.15, 0.45, 0.75)):
    ax.plot(1000*centres, profiles[(h, "front")], label="front wall (within one diameter)")
    ax.plot(1000*centres, profiles[(h, "depth")], ls="--", label="depth-averaged")
    ax.plot(measured[h][:, 0], measured[h][:, 1], "ko", ms=3, label="Yue et al. 2020 (PIV)")
    ax.set_title("H/H0 = %.2f: mean abs. difference %.3f m/s" % (h, result["mad_h%03d" % round(100*h)]), fontsize=9)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("time-averaged particle speed [m/s]")
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig("spoutedBed.png", dpi=110)
print("    plot spoutedBed.png, profiles particleSpeed_H*.csv")
