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
                    the run's (an unrecorded fine run's from its logs)
  fine_snapshots    the snapshots the fine run's averages hold

The halves' difference of a run is about 1.6 standard deviations of its
window's average (two independent halves of a stationary signal), so the sum
of two runs' is about twice the standard deviation of the difference of their
averages: a coarse run within it cannot be told from the fine run by these
windows.

usage: compare.py [--fine RUN]   RUN: a run folder holding particleSpeed_H*.csv
                                 and spoutedBed.result, or a carried run's
                                 archive (default: the recorded
                                 results/analytical_h1, else the carried
                                 carried/analytical_h1.tar.xz as it stands)"""
import argparse
import csv
import glob
import io
import os
import tarfile
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from record import wall_seconds

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
MEASURED = os.path.join(HERE, "..", "..", "tutorials", "spoutedBed", "measured")
HEIGHTS = ("015", "030", "045", "060", "075", "080")
CHANNEL_HALF_WIDTH_MM = 12.0   # the inlet channel is 24 mm wide (Yue et al. 2020)


_ARCHIVED = {}


def archived(run):
    """{name: text} of a carried run's profiles, .result and logs (one pass
    through the archive)."""
    if run not in _ARCHIVED:
        with tarfile.open(run) as archive:
            _ARCHIVED[run] = {m.name: archive.extractfile(m).read().decode() for m in archive
                              if m.isfile() and "/" not in m.name and
                              m.name.startswith(("particleSpeed_H", "spoutedBed.result", "log.pimpleDEMFoam"))}
    return _ARCHIVED[run]


def read(run, name):
    """A file's text from a run folder or a carried run's archive."""
    return archived(run)[name] if run.endswith(".tar.xz") else open(os.path.join(run, name)).read()


def profiles(run):
    """{height: (x_mm, front-wall speed)} of a run."""
    out = {}
    for h in HEIGHTS:
        data = np.loadtxt(io.StringIO(read(run, "particleSpeed_H%s.csv" % h)), delimiter=",", skiprows=1, ndmin=2)
        out[h] = data[:, 0], data[:, 1]
    return out


def result(run):
    return {k: float(v) for k, v in (l.split() for l in read(run, "spoutedBed.result").splitlines())}


def cost(run, row):
    """Wall-clock seconds per simulated second: the recorded row's, else the
    run's logs' (a folder's or an archive's)."""
    if row:
        return float(row["wall_s_per_sim_s"])
    if run.endswith(".tar.xz"):
        with tempfile.TemporaryDirectory() as where:
            for name, text in archived(run).items():
                if name.startswith("log."):
                    open(os.path.join(where, name), "w").write(text)
            wall, simulated = wall_seconds(where)
    else:
        wall, simulated = wall_seconds(run)
    return wall/simulated if simulated > 0 else float("nan")


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
    """[(model, h, folder, summary row)] of results/summary.csv, in its order."""
    rows = list(csv.DictReader(open(os.path.join(RESULTS, "summary.csv"))))
    return [(r["model"], r["h"], os.path.join(RESULTS, "%s_h%s" % (r["model"], r["h"])), r) for r in rows]


def default_fine():
    """The recorded fine run, else the carried one as it stands."""
    recorded_fine = os.path.join(RESULTS, "analytical_h1")
    return recorded_fine if os.path.isdir(recorded_fine) else os.path.join(HERE, "carried", "analytical_h1.tar.xz")


def against_fine(runs, fine_run):
    """againstFine.csv's rows: each coarse-grained run against the fine run."""
    fine_row = next((r for m, h, f, r in runs if h == "1"), None)
    fine, fine_result = profiles(fine_run), result(fine_run)
    fine_cost = cost(fine_run, fine_row)
    rows = []
    for model, h, folder, row in runs:
        if h == "1":
            continue
        own = result(folder)
        spout, annulus = gaps(profiles(folder), fine)
        noise_spout = own["halves_spout_m_s"] + fine_result["halves_spout_m_s"]
        noise_annulus = own["halves_annulus_m_s"] + fine_result["halves_annulus_m_s"]
        rows.append(dict(model=model, h=h, spout_vs_fine_m_s="%.4f" % spout, annulus_vs_fine_m_s="%.4f" % annulus,
                         noise_spout_m_s="%.4f" % noise_spout, noise_annulus_m_s="%.4f" % noise_annulus,
                         within_noise=int(spout <= noise_spout and annulus <= noise_annulus),
                         cost_ratio="%.1f" % (fine_cost/float(row["wall_s_per_sim_s"])),
                         fine_snapshots=int(fine_result["snapshots"])))
    return rows


def plot(runs, fine_run):
    """profiles.png: every run's front-wall profiles at the measured heights."""
    recorded_fine = any(h == "1" for _, h, _, _ in runs)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5), sharey=True)
    for ax, h in zip(axes, ("015", "045", "075")):
        for model, factor, folder, _ in runs:
            x, speed = profiles(folder)[h]
            if factor == "1":
                ax.plot(x, speed, "k-", lw=2, label="beads (h = 1)")
            else:
                ax.plot(x, speed, lw=1.0, ls="-" if model == "analytical" else "--",
                        label="%s, h = %s" % (model, factor))
        if fine_run and not recorded_fine:
            x, speed = profiles(fine_run)[h]
            ax.plot(x, speed, "k-", lw=2, label="beads (h = 1), %d snapshots so far" % result(fine_run)["snapshots"])
        m = np.loadtxt(os.path.join(MEASURED, "particleSpeed_H%s.csv" % h), delimiter=",", skiprows=1)
        ax.plot(m[:, 0], m[:, 1], "ko", ms=3, label="Yue et al. 2020 (PIV)")
        ax.set_title("H/H0 = %.2f, particles within one diameter of the front wall" % (int(h)/100), fontsize=9)
        ax.set_xlabel("x [mm]")
        ax.set_xlim(-140, 140)
    axes[0].set_ylabel("time-averaged particle speed [m/s]")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "profiles.png"), dpi=100)


def main():
    parser = argparse.ArgumentParser(usage=__doc__.split("usage: ")[1])
    parser.add_argument("--fine", default=default_fine())
    fine_run = parser.parse_args().fine
    runs = recorded()
    if not runs:
        raise SystemExit("compare.py: results/summary.csv has no run")
    if not (os.path.isfile(fine_run) or os.path.isfile(os.path.join(fine_run, "spoutedBed.result"))):
        print("    no fine run at %s: profiles.png only" % fine_run)
        fine_run = None
    else:
        rows = against_fine(runs, fine_run)
        for r in rows:
            print("    %(model)s h = %(h)s: against the fine run %(spout_vs_fine_m_s)s m/s (spout), "
                  "%(annulus_vs_fine_m_s)s m/s (annulus); noise %(noise_spout_m_s)s, %(noise_annulus_m_s)s; "
                  "%(cost_ratio)s times cheaper" % r)
        with open(os.path.join(RESULTS, "againstFine.csv"), "w", newline="") as out:
            w = csv.DictWriter(out, fieldnames=list(rows[0]) if rows else ["model"], lineterminator="\n")
            w.writeheader()
            w.writerows(rows)
    plot(runs, fine_run)
    print("    %s%s" % ("againstFine.csv, " if fine_run else "", "profiles.png in results/"))


if __name__ == "__main__":
    main()
