#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The recorded spouted bed runs against the fine run (the beads themselves)
and the measurement: results/profiles.png (every run's front-wall speed at
H/H0 = 0.15, 0.45 and 0.75 with the PIV points) and results/againstFine.csv,
one row per coarse-grained run:

  model,h           the run
  spout_vs_fine_m_s   mean |run - fine| of the front-wall profiles over the
  annulus_vs_fine_m_s six heights, in the 24 mm over the channel and outside
  noise_spout_m_s     the two runs' own statistics there: the sum of their
  noise_annulus_m_s   halves' differences (the .result files)
  within_noise      1 when both differences are within the noise
  cost_ratio        the fine run's wall-clock time per simulated second over
                    the run's

The halves' difference of a run is about 1.6 standard deviations of its
window's average (two independent halves of a stationary signal), so the sum
of two runs' is about twice the standard deviation of the difference of their
averages: a coarse run within it cannot be told from the fine run by these
windows.

usage: compare.py [--fine RUN_DIR]   RUN_DIR: a run folder holding
                                     particleSpeed_H*.csv and spoutedBed.result
                                     (default: the recorded results/analytical_h1)"""
import argparse
import csv
import glob
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
MEASURED = os.path.join(HERE, "..", "..", "tutorials", "spoutedBed", "measured")
HEIGHTS = ("015", "030", "045", "060", "075", "080")
CHANNEL_HALF_WIDTH_MM = 12.0   # the inlet channel is 24 mm wide (Yue et al. 2020)


def profiles(run):
    """{height: (x_mm, front-wall speed)} of a run folder."""
    out = {}
    for h in HEIGHTS:
        data = np.loadtxt(os.path.join(run, "particleSpeed_H%s.csv" % h), delimiter=",", skiprows=1, ndmin=2)
        out[h] = data[:, 0], data[:, 1]
    return out


def result(run):
    return {k: float(v) for k, v in (l.split() for l in open(os.path.join(run, "spoutedBed.result")))}


def gaps(run, fine):
    """Mean |run - fine| over the six heights, in the spout and in the annulus."""
    spout, annulus = [], []
    for h in HEIGHTS:
        x, speed = run[h]
        xf, fine_speed = fine[h]
        if x.shape != xf.shape or not np.allclose(x, xf):
            raise SystemExit("compare.py: the runs' profiles at H%s use different bins" % h)
        diff = np.abs(speed - fine_speed)
        core = np.abs(x) < CHANNEL_HALF_WIDTH_MM
        spout.append(diff[core])
        annulus.append(diff[~core])
    return float(np.nanmean(np.concatenate(spout))), float(np.nanmean(np.concatenate(annulus)))


def recorded():
    """[(model, h, folder, summary row)] of results/summary.csv, coarse first."""
    rows = list(csv.DictReader(open(os.path.join(RESULTS, "summary.csv"))))
    return [(r["model"], r["h"], os.path.join(RESULTS, "%s_h%s" % (r["model"], r["h"])), r) for r in rows]


def main():
    parser = argparse.ArgumentParser(usage=__doc__.split("usage: ")[1])
    parser.add_argument("--fine", default=os.path.join(RESULTS, "analytical_h1"))
    args = parser.parse_args()
    runs = recorded()
    if not runs:
        raise SystemExit("compare.py: results/summary.csv has no run")
    fine_row = next((r for m, h, f, r in runs if h == "1"), None)
    have_fine = os.path.isfile(os.path.join(args.fine, "spoutedBed.result"))
    rows = []
    if have_fine:
        fine, fine_result = profiles(args.fine), result(args.fine)
        for model, h, folder, row in runs:
            if h == "1":
                continue
            own = result(folder)
            spout, annulus = gaps(profiles(folder), fine)
            noise_spout = own["halves_spout_m_s"] + fine_result["halves_spout_m_s"]
            noise_annulus = own["halves_annulus_m_s"] + fine_result["halves_annulus_m_s"]
            cost = float(fine_row["wall_s_per_sim_s"])/float(row["wall_s_per_sim_s"]) if fine_row else float("nan")
            rows.append(dict(model=model, h=h, spout_vs_fine_m_s="%.4f" % spout, annulus_vs_fine_m_s="%.4f" % annulus,
                             noise_spout_m_s="%.4f" % noise_spout, noise_annulus_m_s="%.4f" % noise_annulus,
                             within_noise=int(spout <= noise_spout and annulus <= noise_annulus),
                             cost_ratio="%.1f" % cost))
            print("    %s h = %s: against the fine run %.3f m/s (spout), %.3f m/s (annulus); noise %.3f, %.3f%s"
                  % (model, h, spout, annulus, noise_spout, noise_annulus,
                     "; %.0f times cheaper" % cost if fine_row else ""))
        with open(os.path.join(RESULTS, "againstFine.csv"), "w", newline="") as out:
            w = csv.DictWriter(out, fieldnames=list(rows[0]) if rows else ["model"], lineterminator="\n")
            w.writeheader()
            w.writerows(rows)
    else:
        print("    no fine run at %s: profiles.png only" % args.fine)

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5), sharey=True)
    for ax, h in zip(axes, ("015", "045", "075")):
        for model, factor, folder, _ in runs:
            x, speed = profiles(folder)[h]
            if factor == "1":
                ax.plot(x, speed, "k-", lw=2, label="beads (h = 1)")
            else:
                ax.plot(x, speed, lw=1.0, ls="-" if model == "analytical" else "--",
                        label="%s, h = %s" % (model, factor))
        if have_fine and fine_row is None:
            x, speed = fine[h]
            ax.plot(x, speed, "k-", lw=2, label="beads (h = 1), so far")
        m = np.loadtxt(os.path.join(MEASURED, "particleSpeed_H%s.csv" % h), delimiter=",", skiprows=1)
        ax.plot(m[:, 0], m[:, 1], "ko", ms=3, label="Yue et al. 2020 (PIV)")
        ax.set_title("H/H0 = %.2f, particles within one diameter of the front wall" % (int(h)/100), fontsize=9)
        ax.set_xlabel("x [mm]")
        ax.set_xlim(-140, 140)
    axes[0].set_ylabel("time-averaged particle speed [m/s]")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "profiles.png"), dpi=100)
    print("    %s%s" % ("againstFine.csv, " if have_fine else "", "profiles.png in results/"))


if __name__ == "__main__":
    main()
