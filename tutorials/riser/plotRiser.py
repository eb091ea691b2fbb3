#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Riser: the beads' speed along the riser and, where the flow is developed,
their slip against the single bead's terminal velocity with the
Richardson-Zaki correction (Schiller-Naumann drag and Rowe's exponent,
computed here, independent of the solver); the beads fed, removed and held.
Writes riser.png, riser.csv and riser.result; prints the comparison."""
import math
import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.join(os.environ.get("VFM_PROJECT_DIR",
                                               os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")),
                                "tutorials"))
import caseProperties  # noqa: E402
import particleVtk  # noqa: E402

nu, rho_f, mu = caseProperties.fluid()
rho_p, d = caseProperties.particle_density(), caseProperties.particle_diameter()
g = caseProperties.gravity()
dem = caseProperties.dem_parameters()
width, feed_rate = dem["width"], dem["feedRate"]
u0 = float(re.search(r"inlet\s*\{\s*type fixedValue; value uniform \(0 0 (\S+)\)",
                     open("0.orig/U").read()).group(1))
height = 0.2
dt = float(re.search(r"^deltaT\s+(\S+);", open("system/controlDict").read(), re.M).group(1))
DEVELOPED = (0.1, 0.19)      # m: from half way up to just below the top


v_t = caseProperties.terminal_velocity()
re_t = v_t*d/nu
# Rowe (1987), "A convenient empirical equation for estimation of the Richardson-Zaki exponent"
n_rz = (4.7 + 0.41*re_t**0.75)/(1 + 0.175*re_t**0.75)

# the beads of the written times in the second half of the run
snapshots = []
for path in particleVtk.files("."):
    snapshots.append((particleVtk.step(path)*dt, path))
end = snapshots[-1][0] if snapshots else 0
late = [(t, p) for t, p in snapshots if t >= max(0.3, 0.6*end)]
bins = np.linspace(0, height, 21)
speed_sum, count = np.zeros(len(bins) - 1), np.zeros(len(bins) - 1)
vz_dev, n_dev = [], []
for t, path in late:
    x, r, v = particleVtk.read(path)
    if len(x) == 0:
        continue
    k = np.clip(np.digitize(x[:, 2], bins) - 1, 0, len(bins) - 2)
    np.add.at(speed_sum, k, v[:, 2])
    np.add.at(count, k, 1)
    inside = (x[:, 2] > DEVELOPED[0]) & (x[:, 2] < DEVELOPED[1])
    vz_dev.extend(v[inside, 2])
    n_dev.append(inside.sum())

# fed (LIGGGHTS's screen), removed (the solver's log, with the time), held
fed_steps = [(int(s)*dem["demStep"], int(n)) for n, s in
             re.findall(r"inserted (\d+) particle templates .* at step (\d+)", open("DEM/log.liggghtsScreen").read())]
# a coupling line counts the beads mapped, before those outside are removed
removed, held, now, leaving = [], [], 0.0, 0
for line in open("log.pimpleDEMFoam"):
    m = re.match(r"^Time = (\S+)", line)
    if m:
        now, leaving = float(m.group(1)), 0
    m = re.match(r"^particleFluidCoupling: removing (\d+) particles", line)
    if m:
        leaving = int(m.group(1))
        removed.append((now, leaving))
    m = re.match(r"^coupling \d+: (\d+) particles", line)
    if m:
        held.append((now, int(m.group(1)) - leaving))
fed_total = sum(n for _, n in fed_steps)
removed_total = sum(n for _, n in removed)
held_end = held[-1][1] if held else 0
balance = fed_total - removed_total - held_end
print(f"beads fed {fed_total}, removed at the top {removed_total}, held {held_end}: "
      f"fed - removed - held = {balance}")

result = {"balance": balance, "fed": fed_total, "removed": removed_total, "held": held_end}
if late and vz_dev:
    t0 = late[0][0]
    out_rate = sum(n for t, n in removed if t > t0)/max(end - t0, 1e-12)
    v_p = float(np.mean(vz_dev))
    solid = float(np.mean(n_dev))*math.pi*d**3/6/(width*width*(DEVELOPED[1] - DEVELOPED[0]))
    alpha = 1 - solid
    u_gas = (u0 - solid*v_p)/alpha            # the gas's interstitial velocity (continuity)
    slip = u_gas - v_p
    expected = v_t*alpha**(n_rz - 1)
    slip_error = slip/expected - 1
    print(f"developed flow ({DEVELOPED[0]*1000:.0f} to {DEVELOPED[1]*1000:.0f} mm, t >= {t0:.2f} s, "
          f"{len(late)} snapshots): beads {v_p:.4f} m/s, gas {u_gas:.4f} m/s, solid fraction {solid:.5f}")
    print(f"slip {slip:.4f} m/s against terminal velocity x Richardson-Zaki {expected:.4f} m/s "
          f"(v_t {v_t:.4f} m/s, Re_t {re_t:.1f}, n {n_rz:.2f}): {100*slip_error:+.2f} %")
    print(f"beads leaving the top {out_rate:.0f} per s against {feed_rate:.0f} per s fed "
          f"({100*(out_rate/feed_rate - 1):+.1f} %)")
    result.update(slip=slip, slip_expected=expected, slip_error=slip_error, bead_speed=v_p,
                  gas_speed=u_gas, solid_fraction=solid, outflow_ratio=out_rate/feed_rate,
                  outflow_rate=out_rate, feed_rate=feed_rate, terminal_velocity=v_t, rz_exponent=n_rz)
else:
    print("short run: the riser is not yet developed (written times from 0.3 s are averaged)")
with open("riser.result", "w") as f:
    for k, v in result.items():
        f.write(f"{k} {v}\n")

z_mid = 0.5*(bins[1:] + bins[:-1])
mean_speed = np.where(count > 0, speed_sum/np.maximum(count, 1), np.nan)
np.savetxt("riser.csv", np.column_stack([z_mid, mean_speed, count]), delimiter=",",
           header="z_m,bead_speed_m_s,samples", comments="")
fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
a.plot(mean_speed, z_mid*1000, "o-", ms=3, label="beads (time-averaged)")
if "slip" in result:
    a.axvline(result["gas_speed"] - result["slip_expected"], color="k", ls="--",
              label="gas - terminal x Richardson-Zaki")
    a.axvline(result["gas_speed"], color="grey", ls=":", label="gas (interstitial)")
a.axhspan(DEVELOPED[0]*1000, DEVELOPED[1]*1000, color="0.9", zorder=0)
a.set_xlabel("upward speed [m/s]")
a.set_ylabel("height [mm]")
a.legend(fontsize=8, loc="lower right")
a.set_title("bead speed along the riser")
for series, label in ((fed_steps, "fed"), (removed, "removed at the top")):
    if series:
        t, n = zip(*series)
        b.plot(t, np.cumsum(n), label=label)
if held:
    t, n = zip(*held)
    b.plot(t, n, label="held")
b.set_xlabel("t [s]")
b.set_ylabel("beads")
b.legend(fontsize=8)
b.set_title(f"fed - removed - held = {balance}")
fig.tight_layout()
fig.savefig("riser.png", dpi=110)
