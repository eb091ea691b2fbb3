#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The spouted bed's minimum spouting velocity and spouting pressure drop,
simulated, against the classic spouted-bed results.

The run: the tutorial at h = 1.6 (`analytical`) with the set-up the docs
recommend (Beetstra's drag), spouting at the measured 20.8 m/s in the channel
until --hold s, then the channel's velocity lowered linearly to --low m/s at
--end s, as a minimum spouting velocity is measured: on decreasing flow, the
lowest velocity at which the spout still breaks through the bed's surface.
The criterion: the spout has collapsed from the first particle snapshot
after which the fountain (the height below which 99 % of the particles over
the channel lie) stays less than 8 bead diameters (20 mm) above the packed
bed's surface (the same quantile of all the particles in the first
snapshot); U_ms is the superficial velocity (channel velocity x 24/280) at
that snapshot. (The fountain's particles rain onto the annulus, so the
annulus's own 99 % height is no surface while the bed spouts.) The pressure
drop over the bed's weight is recorded beside it, in windows of 0.1 s.

The references (in results/minimumSpouting.md):
- Mathur and Gishler, "A technique for contacting gases with coarse solid
  particles" (1955): U_ms = (d/D_c) (D_i/D_c)^(1/3) sqrt(2 g H (rho_p -
  rho)/rho), fitted to cylindrical beds. A rectangular bed has no diameter:
  the equivalent diameters of equal area and the hydraulic diameters are
  both evaluated, and the spread between them is the uncertainty of applying
  it here.
- Mamuro and Hattori, "Flow pattern of fluid in spouted beds" (1968): Darcy
  flow in the annulus with U_a/U_mf = 1 - (1 - z/H_m)^3 gives a spouting
  pressure drop of 3/4 of the fluidised bed's at the maximum spoutable
  height H_m, less in shallower beds.
- Lefroy and Davidson, "The mechanics of spouted beds" (1969): a cosine
  pressure profile in the annulus, at minimum fluidisation at the top,
  gives 2/pi of the fluidised bed's.

usage: minimumSpouting.py [--hold 1] [--end 5] [--low 8] [--ranks 2]
       minimumSpouting.py --report    the table and figure from the run
"""
import argparse
import csv
import json
import os
import subprocess
import sys

import numpy as np

from closures import set_entry
from record import wall_seconds
from run import ENV, ROOT, WORK, copy_tutorial, reached, stretch

sys.path[:0] = [os.path.join(ROOT, "tutorials"), os.path.join(ROOT, "tutorials", "fluidisedBed")]
HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
RECORD = os.path.join(RESULTS, "minimumSpouting.json")
FACTOR = 1.6
JET = 20.8                      # m/s in the channel (Yue et al. 2020)
WIDTH, DEPTH, CHANNEL = 0.280, 0.040, 0.024     # m
H0, D, RHO_P = 0.2, 0.0025, 2500.0              # m, m, kg/m3: settled bed, beads
RHO, G = 1.205, 9.81                            # air at 20 C; m/s2
BREAKTHROUGH = 8*D              # the fountain's least height over the packed surface while spouting
CORE = 0.5*CHANNEL              # m from the centre line: over the channel
WINDOW = 0.1                    # s, the pressure drop's averaging window


def superficial(channel):
    return channel*CHANNEL/WIDTH


def channel_velocity(t, a):
    return np.interp(t, (0.0, 0.05, a.hold, a.end), (0.0, JET, JET, a.low))


def mathur_gishler(column, inlet, height=H0):
    return D/column*(inlet/column)**(1/3)*np.sqrt(2*G*height*(RHO_P - RHO)/RHO)


def correlations():
    area = mathur_gishler(np.sqrt(4*WIDTH*DEPTH/np.pi), np.sqrt(4*CHANNEL*DEPTH/np.pi))
    hydraulic = mathur_gishler(2*WIDTH*DEPTH/(WIDTH + DEPTH), 2*CHANNEL*DEPTH/(CHANNEL + DEPTH))
    return {"ums_mathur_gishler_area_m_s": area, "ums_mathur_gishler_hydraulic_m_s": hydraulic,
            "dp_ratio_mamuro_hattori_at_Hm": 0.75, "dp_ratio_lefroy_davidson": 2/np.pi}


def heights(path, read_vtk):
    """the 99 % heights of the particles over the channel and of all of them"""
    x = read_vtk(path)[0]
    return np.quantile(x[np.abs(x[:, 0]) < CORE, 2], 0.99), np.quantile(x[:, 2], 0.99)


def collapse_time(times, excess, hold):
    """the first snapshot after the hold from which the fountain stays below
    the breakthrough height (nan if it spouts to the end)"""
    times, excess = np.asarray(times), np.asarray(excess)
    spouting = np.nonzero((excess >= BREAKTHROUGH) & (times > hold))[0]
    if len(spouting) == 0 or spouting[-1] + 1 >= len(times):
        return float("nan")
    return float(times[spouting[-1] + 1])


def simulate(case, top, a):
    if reached(case, a.end):
        return
    if not os.path.isdir(os.path.join(case, "processor0")):
        copy_tutorial(top)
        set_entry(os.path.join(top, "constant/couplingProperties"), r"drag\s*\{\s*model", "Beetstra")
        u = os.path.join(top, "0.orig", "U")
        text = open(u).read()
        ramp = "table ( (0 (0 0 0)) (0.05 (0 0 %g)) (%g (0 0 %g)) (%g (0 0 %g)) (100 (0 0 %g)) )" % (
            JET, a.hold, JET, a.end, a.low, a.low)
        old = "table ( (0 (0 0 0)) (0.05 (0 0 20.8)) (100 (0 0 20.8)) )"
        if old not in text:
            sys.exit("minimumSpouting.py: %s no longer holds the jet's table %s" % (u, old))
        open(u, "w").write(text.replace(old, ramp))
        print("minimumSpouting: h = %g, the jet held %g s then lowered to %g m/s at %g s"
              % (FACTOR, a.hold, a.low, a.end), flush=True)
        subprocess.run(["./Allrun", "%g" % FACTOR, "analytical", "%g" % a.end, str(a.ranks)], cwd=top, env=ENV,
                       check=True)
    else:
        stretch(case, a.ranks)


def analyse(case, a):
    os.chdir(case)      # bedData reads the case it is imported in
    import caseProperties
    from bedData import bed_weight, pressure_drop, read_vtk, snapshots, step
    dt = caseProperties._entry("system/controlDict", "deltaT")
    files = snapshots(".")
    times = [step(f)*dt for f in files]
    surface = heights(files[0], read_vtk)[1]
    excess = [heights(f, read_vtk)[0] - surface for f in files]
    collapse = collapse_time(times, excess, a.hold)
    t, p = pressure_drop(".")
    weight = bed_weight(".", WIDTH*DEPTH)
    edges = np.arange(0.0, a.end + 1e-9, WINDOW)
    windows = [(lo, hi, float(np.mean(p[(t > lo) & (t <= hi)])/weight)) for lo, hi in zip(edges[:-1], edges[1:])
               if ((t > lo) & (t <= hi)).any()]
    wall, simulated = wall_seconds(".")
    record = dict(correlations(), hold_s=a.hold, end_s=a.end, low_m_s=a.low, h=FACTOR, drag="Beetstra",
                  collapse_s=collapse, ums_channel_m_s=float(channel_velocity(collapse, a)),
                  ums_m_s=float(superficial(channel_velocity(collapse, a))),
                  operating_m_s=superficial(JET), packed_surface_m=float(surface),
                  snapshots=[[float(s), float(e)] for s, e in zip(times, excess)],
                  dp_windows=[[lo, hi, r] for lo, hi, r in windows],
                  wall_s_per_sim_s=wall/max(simulated, 1e-9))
    json.dump(record, open(RECORD, "w"), indent=1)
    return record


def spouting_pressure_drops():
    """the spouting pressure drop over the weight of the recorded runs with
    4 s of averages: Beetstra's drag at h = 1.6 and the beads (Gidaspow)"""
    rows = {r["change"]: r for r in csv.DictReader(open(os.path.join(RESULTS, "closures.csv")))}
    return float(rows["Beetstra"]["dp_vs_weight"]), float(rows["none: the beads (h = 1)"]["dp_vs_weight"])


def table_text(record):
    c = record
    beetstra, beads = spouting_pressure_drops()
    lines = [
        "| quantity | simulated | reference |",
        "|---|---|---|",
        "| minimum spouting velocity, superficial (m/s) | %.3f (h = %g, %s; channel %.1f m/s, at %.2f s) | "
        "Mathur and Gishler: %.3f (equal-area diameters), %.3f (hydraulic diameters) |"
        % (c["ums_m_s"], c["h"], c["drag"], c["ums_channel_m_s"], c["collapse_s"], c["ums_mathur_gishler_area_m_s"],
           c["ums_mathur_gishler_hydraulic_m_s"]),
        "| operating velocity over minimum spouting | %.2f | %.2f, %.2f |"
        % (c["operating_m_s"]/c["ums_m_s"], c["operating_m_s"]/c["ums_mathur_gishler_area_m_s"],
           c["operating_m_s"]/c["ums_mathur_gishler_hydraulic_m_s"]),
        "| spouting pressure drop over the bed's weight | %.3f (h = 1.6, Beetstra), %.3f (the beads, Gidaspow) "
        "| Lefroy and Davidson: %.3f; Mamuro and Hattori: %.2f at the maximum spoutable height, less below it |"
        % (beetstra, beads, c["dp_ratio_lefroy_davidson"], c["dp_ratio_mamuro_hattori_at_Hm"]),
    ]
    return "\n".join(lines) + "\n"


def report(record):
    text = table_text(record)
    open(os.path.join(RESULTS, "minimumSpouting.md"), "w").write(text)
    print(text, end="")
    plot(record)


def plot(c):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    a = argparse.Namespace(hold=c["hold_s"], end=c["end_s"], low=c["low_m_s"])
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    s = np.array(c["snapshots"])
    s = s[s[:, 0] > 0.5]        # after the spout's opening
    top.plot(superficial(channel_velocity(s[:, 0], a)), 1000*s[:, 1], "k.")
    top.axhline(1000*BREAKTHROUGH, color="grey", ls=":")
    top.set_ylabel("fountain over the packed surface (mm)")
    w = np.array(c["dp_windows"])
    mid = 0.5*(w[:, 0] + w[:, 1])
    late = mid > 0.5
    bottom.plot(superficial(channel_velocity(mid[late], a)), w[late, 2], "k-o", ms=3)
    bottom.axhline(c["dp_ratio_lefroy_davidson"], color="C0", ls="--", label="Lefroy and Davidson, 2/pi")
    bottom.axhline(0.75, color="C1", ls="--", label="Mamuro and Hattori at H_m, 3/4")
    bottom.set_ylabel("pressure drop / weight")
    bottom.set_xlabel("superficial gas velocity (m/s), lowered in time")
    for ax in (top, bottom):
        ax.axvline(c["ums_m_s"], color="k", lw=0.8, label="simulated U_ms")
        ax.axvline(c["ums_mathur_gishler_area_m_s"], color="C2", lw=0.8, label="Mathur-Gishler, equal area")
        ax.axvline(c["ums_mathur_gishler_hydraulic_m_s"], color="C3", lw=0.8, label="Mathur-Gishler, hydraulic")
    bottom.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "minimumSpouting.png"), dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--hold", type=float, default=1.0)
    p.add_argument("--end", type=float, default=5.0)
    p.add_argument("--low", type=float, default=8.0)
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--report", action="store_true")
    a = p.parse_args()
    if a.report:
        report(json.load(open(RECORD)))
        return
    if not (0.5 < a.hold < a.end) or not (0 < a.low < JET) or a.ranks < 1:
        sys.exit("minimumSpouting.py: need 0.5 < --hold < --end, 0 < --low < %g, --ranks >= 1" % JET)
    top = os.path.join(WORK, "minimumSpouting")
    case = os.path.join(top, "parcels_h%g" % FACTOR)
    os.makedirs(WORK, exist_ok=True)
    simulate(case, top, a)
    report(analyse(case, a))


if __name__ == "__main__":
    main()
