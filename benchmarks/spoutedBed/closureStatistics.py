#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Records a spouted bed run of closures.py: plotSpoutedBed.py's profiles,
picture and .result copied into DEST, and the speed statistic measured the
ways a PIV comparison can take it, from the run's particle snapshots after
the 1 s start-up, at the three measured heights:
  statistic  meanSpeed (the mean of |v|, the tutorial's) or speedOfMean
             (|mean v|, the speed of the time-averaged velocity)
  layer      front (within one diameter of the front wall, the tutorial's)
             or depth (every particle)
  bin_mm     10 (the tutorial's) or 8 across the width
into DEST/statistics.csv (statistic,layer,bin_mm,H,x_mm,speed_m_s), and the
run's row in results/closures.csv: the peak speed at each height (the
tutorial's statistic), the mean absolute difference from the PIV, from the
recorded beads (spout and annulus, six heights, as compare.py), the halves'
agreement, the pressure drop over the weight, the fountain and the cost.

usage: closureStatistics.py RUN_DIR DEST CHANGE WALL_S_PER_SIM_S
       closureStatistics.py --reference    the recorded beads' and h = 1.6 rows"""
import csv
import os
import shutil
import subprocess
import sys

import numpy as np

from compare import gaps, profiles, result
from run import ENV, ROOT, START_UP, TUTORIAL

sys.path[:0] = [os.path.join(ROOT, "tutorials"), os.path.join(ROOT, "tutorials", "fluidisedBed")]
import caseProperties  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
H0 = 0.2                       # m, the settled bed (Yue et al. 2020)
HEIGHTS = (0.15, 0.45, 0.75)   # the measured ones
BINS = (0.010, 0.008)          # m
STATISTICS = ("meanSpeed", "speedOfMean")
LAYERS = ("front", "depth")
COLUMNS = ("change", "peak_h015", "peak_h045", "peak_h075", "mad_h015", "mad_h045", "mad_h075",
           "spout_vs_beads_m_s", "annulus_vs_beads_m_s", "halves_spout_m_s", "halves_annulus_m_s",
           "dp_vs_weight", "fountain_mm", "snapshots", "wall_s_per_sim_s")


def measured():
    return {h: np.loadtxt(os.path.join(TUTORIAL, "measured", "particleSpeed_H%03d.csv" % round(100*h)),
                          delimiter=",", skiprows=1) for h in HEIGHTS}


def variant_profiles(case):
    """{(statistic, layer, bin): {H: (x centres, speed)}} over the snapshots."""
    os.chdir(case)  # bedData reads the case it is imported in
    from bedData import read_vtk, snapshots, step
    case = "."
    half = caseProperties.dem_parameters(case)["halfWidth"]
    d = caseProperties.particle_diameter(case)
    dt = caseProperties._entry(os.path.join(case, "system", "controlDict"), "deltaT")
    edges = {b: np.arange(-half, half + 1e-9, b) for b in BINS}
    # per (layer, bin, H): speed sums, velocity sums, counts
    sums = {}
    files = [f for f in snapshots(case) if step(f)*dt > START_UP]
    for f in files:
        x, r, v = read_vtk(f)
        speed = np.linalg.norm(v, axis=1)
        for h in HEIGHTS:
            level = np.abs(x[:, 2] - h*H0) < d
            for layer, pick in (("front", level & (x[:, 1] < r + d)), ("depth", level)):
                for b, e in edges.items():
                    k = np.clip(np.digitize(x[pick, 0], e) - 1, 0, len(e) - 2)
                    s, vec, n = sums.setdefault((layer, b, h), (np.zeros(len(e) - 1), np.zeros((len(e) - 1, 3)),
                                                                np.zeros(len(e) - 1)))
                    np.add.at(s, k, speed[pick])
                    np.add.at(vec, k, v[pick])
                    np.add.at(n, k, 1)
    out = {}
    for (layer, b, h), (s, vec, n) in sums.items():
        centres = 0.5*(edges[b][1:] + edges[b][:-1])
        with np.errstate(invalid="ignore", divide="ignore"):
            out.setdefault(("meanSpeed", layer, b), {})[h] = centres, np.where(n > 0, s/np.maximum(n, 1), np.nan)
            mean_v = vec/np.maximum(n, 1)[:, None]
            out.setdefault(("speedOfMean", layer, b), {})[h] = centres, np.where(n > 0, np.linalg.norm(mean_v, axis=1),
                                                                                  np.nan)
    return out, len(files)


def against_piv(profile, piv):
    """Peak and mean absolute difference from the PIV points of one profile."""
    x, speed = profile
    sim = np.interp(piv[:, 0]/1000, x, speed)
    return float(np.nanmax(speed)), float(np.nanmean(np.abs(sim - piv[:, 1])))


def summary_row(change, folder, snapshots, cost):
    """closures.csv's row of a recorded run folder: its front-wall profiles
    (the tutorial's statistic) against the PIV and the recorded beads."""
    own, front, piv = result(folder), profiles(folder), measured()
    row = dict(change=change, snapshots=snapshots, wall_s_per_sim_s=cost)
    for h in HEIGHTS:
        x_mm, speed = front["%03d" % round(100*h)]
        peak, mad = against_piv((x_mm/1000, speed), piv[h])
        row["peak_h%03d" % round(100*h)] = "%.3f" % peak
        row["mad_h%03d" % round(100*h)] = "%.4f" % mad
    spout, annulus = gaps(front, profiles(os.path.join(RESULTS, "analytical_h1")))
    row.update(spout_vs_beads_m_s="%.4f" % spout, annulus_vs_beads_m_s="%.4f" % annulus,
               halves_spout_m_s="%.4f" % own["halves_spout_m_s"],
               halves_annulus_m_s="%.4f" % own["halves_annulus_m_s"],
               dp_vs_weight="%.4f" % own["dp_vs_weight"], fountain_mm="%.1f" % own["fountain_mm"])
    return row


def reference_rows():
    """The recorded beads and h = 1.6 runs of the tutorial's set-up."""
    summary = {(r["model"], r["h"]): r for r in csv.DictReader(open(os.path.join(RESULTS, "summary.csv")))}
    rows = []
    for change, h in (("none: the beads (h = 1)", "1"), ("none (h = 1.6)", "1.6")):
        folder = os.path.join(RESULTS, "analytical_h%s" % h)
        rows.append(summary_row(change, folder, int(result(folder)["snapshots"]),
                                summary[("analytical", h)]["wall_s_per_sim_s"]))
    return rows


def replace_rows(path, columns, rows, keep):
    old = list(csv.DictReader(open(path))) if os.path.isfile(path) else []
    with open(path, "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        # the tutorial's set-up first, then the changes in the order they ran
        w.writerows(sorted([r for r in old if keep(r)] + rows, key=lambda r: not r["change"].startswith("none")))


def main():
    if sys.argv[1:] == ["--reference"]:
        rows = reference_rows()
        replace_rows(os.path.join(RESULTS, "closures.csv"), COLUMNS, rows, lambda r: not r["change"].startswith("none"))
        return
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    case, dest, change, cost = sys.argv[1:]
    subprocess.run(["/usr/bin/python3", os.path.join(TUTORIAL, "plotSpoutedBed.py"), str(START_UP)], cwd=case,
                   env=ENV, check=True)
    os.makedirs(dest, exist_ok=True)
    for name in ["particleSpeed_H%03d.csv" % round(100*h) for h in (0.15, 0.30, 0.45, 0.60, 0.75, 0.80)] + \
            ["spoutedBed.png", "spoutedBed.result"]:
        shutil.copy(os.path.join(case, name), dest)
    piv = measured()
    variants, count = variant_profiles(case)
    with open(os.path.join(dest, "statistics.csv"), "w") as out:
        out.write("statistic,layer,bin_mm,H,x_mm,speed_m_s\n")
        for (stat, layer, b), by_height in sorted(variants.items()):
            for h, (x, speed) in sorted(by_height.items()):
                for xi, si in zip(x, speed):
                    out.write("%s,%s,%g,%.2f,%.1f,%.5f\n" % (stat, layer, 1000*b, h, 1000*xi, si))
    row = summary_row(change, dest, count, cost)
    front = profiles(dest)
    for h in HEIGHTS:
        x, speed = variants[("meanSpeed", "front", 0.010)][h]
        if not np.allclose(speed, front["%03d" % round(100*h)][1], atol=6e-6, equal_nan=True):
            sys.exit("closureStatistics.py: the front-wall profile at H/H0 = %g differs from plotSpoutedBed.py's" % h)
    replace_rows(os.path.join(RESULTS, "closures.csv"), COLUMNS, [row], lambda r: r["change"] != change)
    stat_columns = ("change", "statistic", "layer", "bin_mm") + tuple(
        "%s_h%03d" % (k, round(100*h)) for k in ("peak", "mad") for h in HEIGHTS)
    stat_rows = []
    for (stat, layer, b), by_height in sorted(variants.items()):
        r = dict(change=change, statistic=stat, layer=layer, bin_mm="%g" % (1000*b))
        for h in HEIGHTS:
            peak, mad = against_piv(by_height[h], piv[h])
            r["peak_h%03d" % round(100*h)], r["mad_h%03d" % round(100*h)] = "%.3f" % peak, "%.4f" % mad
        stat_rows.append(r)
    replace_rows(os.path.join(RESULTS, "closureStatistics.csv"), stat_columns, stat_rows,
                 lambda r: r["change"] != change)
    print("closureStatistics.py: %s recorded in %s, closures.csv and closureStatistics.csv"
          % (change, os.path.relpath(dest, HERE)))


if __name__ == "__main__":
    main()
