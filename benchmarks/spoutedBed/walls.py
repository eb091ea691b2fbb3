#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The spouted bed's parcels with their walls moved out (scaleCase -parcels
-wallVoid c: the side walls out by c (h - 1) d, the part of a parcel beyond
the mesh kept in its cells), against the recorded beads: each run is the
tutorial's Allrun with the wall void given, --end simulated seconds on --ranks
ranks in build/spoutedBed/walls_<model>_h<h>/, its profiles and .result
copied to results/walls/<model>_h<h>/ and its row written to
results/walls.csv:

  model,h,wall_void     the run (c in particle diameters)
  spout_vs_fine_m_s,    as in againstFine.csv: mean |run - beads| of the
  annulus_vs_fine_m_s,  front-wall profiles over the six heights, the two
  noise_spout_m_s,      runs' halves' differences summed, and whether both
  noise_annulus_m_s,    are within it
  within_noise
  walls_kept_spout_vs_fine_m_s   the same run with its walls as they are
                                 (againstFine.csv)
  annulus_solids        the annulus's solids fraction (annulus.py's region
                        and snapshots); the beads' and the run with its walls
                        as they are from annulus.csv
  annulus_solids_beads, annulus_solids_walls_kept
  gas_share_z050,...    the share of the upward gas flux outside the 24 mm
                        over the channel at z = 50, 100, 150 mm (annulus.py),
  gas_share_beads_z050  and the beads' there
  mad_h015,mad_h045,mad_h075   mean |run - PIV| (plotSpoutedBed.py)
  dp_vs_weight          the bed's pressure drop over its weight
  cost_ratio            the beads' wall-clock time per simulated second over
                        the run's

c = 0.166 is the beads' extra void per wall area at a flat wall
(benchmarks/wallPacking.py); nothing here is fitted to the beads' spout. A run
stopped by anything continues from its last written time when this is started
again; a recorded run is not run again unless --rerecord.

usage: walls.py [--runs analytical:4,kernel:4,analytical:3,kernel:3,analytical:2]
                [--wallVoid 0.166] [--end 5] [--ranks 2] [--rerecord]
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys

from annulus import LAYERS, annulus_solids, gas_shares
from carry import latest_time
from compare import default_fine, gaps, profiles, result
from record import wall_seconds
from run import ENV, TUTORIAL, WORK, copy_tutorial, parse_runs, reached, stretch

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
COLUMNS = ("model", "h", "wall_void", "spout_vs_fine_m_s", "annulus_vs_fine_m_s", "noise_spout_m_s",
           "noise_annulus_m_s", "within_noise", "walls_kept_spout_vs_fine_m_s", "annulus_solids",
           "annulus_solids_beads", "annulus_solids_walls_kept", "gas_share_z050", "gas_share_z100",
           "gas_share_z150", "gas_share_beads_z050", "gas_share_beads_z100", "gas_share_beads_z150", "mad_h015", "mad_h045", "mad_h075",
           "dp_vs_weight", "cost_ratio")
KEPT_FILES = ("spoutedBed.result", "spoutedBed.png")


def csv_rows(name):
    path = os.path.join(RESULTS, name)
    return list(csv.DictReader(open(path))) if os.path.isfile(path) else []


def walls_kept(model, h):
    """(spout vs fine, annulus solids) of the recorded run with its walls as they are"""
    fine = next((r for r in csv_rows("againstFine.csv") if r["model"] == model and r["h"] == h), {})
    annulus = next((r for r in csv_rows("annulus.csv") if r["run"] == "%s_h%s/parcels_h%s" % (model, h, h)), {})
    return fine.get("spout_vs_fine_m_s", ""), annulus.get("annulus_solids", "")


def record(case, model, h, wall_void):
    where = os.path.join(RESULTS, "walls", "%s_h%s" % (model, h))
    os.makedirs(where, exist_ok=True)
    for f in os.listdir(case):
        if f.startswith("particleSpeed_H") or f in KEPT_FILES:
            shutil.copy(os.path.join(case, f), where)
    fine_run = default_fine()
    own, fine = result(case), result(fine_run)
    spout, annulus = gaps(profiles(case), profiles(fine_run))
    noise_spout = own["halves_spout_m_s"] + fine["halves_spout_m_s"]
    noise_annulus = own["halves_annulus_m_s"] + fine["halves_annulus_m_s"]
    summary = {r["h"]: r for r in csv_rows("summary.csv") if r["model"] == "analytical"}
    wall, simulated = wall_seconds(case)
    kept_spout, kept_solids = walls_kept(model, h)
    beads = next((r for r in csv_rows("annulus.csv") if r["run"] == "analytical_h1/fine"), {})
    beads_solids = beads.get("annulus_solids", "")
    shares = gas_shares(case)[0]
    row = dict(model=model, h=h, wall_void=wall_void, spout_vs_fine_m_s="%.4f" % spout,
               annulus_vs_fine_m_s="%.4f" % annulus, noise_spout_m_s="%.4f" % noise_spout,
               noise_annulus_m_s="%.4f" % noise_annulus,
               within_noise=int(spout <= noise_spout and annulus <= noise_annulus),
               walls_kept_spout_vs_fine_m_s=kept_spout, annulus_solids="%.3f" % annulus_solids(case)[0],
               annulus_solids_beads=beads_solids, annulus_solids_walls_kept=kept_solids,
               cost_ratio="%.1f" % (float(summary["1"]["wall_s_per_sim_s"])/(wall/simulated)))
    for z, share in zip(LAYERS, shares):
        key = "z%03d" % round(1000*z)
        row["gas_share_" + key] = "%.3f" % share
        row["gas_share_beads_" + key] = beads.get("gas_share_" + key, "")
    for key in ("mad_h015", "mad_h045", "mad_h075", "dp_vs_weight"):
        row[key] = "%.4g" % own[key]
    rows = [r for r in csv_rows("walls.csv") if (r["model"], r["h"], r["wall_void"]) != (model, h, wall_void)]
    rows.append(row)
    order = {(m, "%g" % f): i for i, (m, f) in enumerate(parse_runs(DEFAULT_RUNS))}
    rows.sort(key=lambda r: (order.get((r["model"], r["h"]), len(order)), r["wall_void"]))
    with open(os.path.join(RESULTS, "walls.csv"), "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    print("walls.py: %s h = %s, wall void %s: spout %.3f m/s from the beads' (noise %.3f; walls as they are %s), "
          "annulus solids %s (beads %s, walls as they are %s), %s times cheaper"
          % (model, h, wall_void, spout, noise_spout, kept_spout or "-", row["annulus_solids"], beads_solids or "-",
             kept_solids or "-", row["cost_ratio"]), flush=True)


def run_one(model, h, a):
    name = "%s_h%g" % (model, h)
    top = os.path.join(WORK, "walls_" + name)
    case = os.path.join(top, "parcels_h%g" % h)
    recorded = any((r["model"], r["h"], r["wall_void"]) == (model, "%g" % h, a.wallVoid)
                   for r in csv_rows("walls.csv"))
    if recorded and not a.rerecord:
        print("%s, wall void %s: recorded earlier in walls.csv" % (name, a.wallVoid))
        return
    if latest_time(case) == 0.0:
        copy_tutorial(top)
        print("%s: setting up and running %g s with the walls out by %s (h - 1) d" % (name, a.end, a.wallVoid),
              flush=True)
        subprocess.run(["./Allrun", "%g" % h, model, "%g" % a.end, str(a.ranks), "(z 12 0.2) (x 20) (y 1 0.04)",
                        a.wallVoid], cwd=top, env=ENV, check=True)
    elif not reached(case, a.end):
        print("%s: continuing from t = %g s" % (name, latest_time(case)), flush=True)
        stretch(case, a.ranks)
        subprocess.run(["/usr/bin/python3", os.path.join(TUTORIAL, "plotSpoutedBed.py"), "1.0"], cwd=case,
                       env=ENV, check=True)
    record(case, model, "%g" % h, a.wallVoid)


DEFAULT_RUNS = "analytical:4,kernel:4,analytical:3,kernel:3,analytical:2"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runs", default=DEFAULT_RUNS)
    p.add_argument("--wallVoid", default="0.166")
    p.add_argument("--end", type=float, default=5.0)
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--rerecord", action="store_true")
    a = p.parse_args()
    if not re.fullmatch(r"0?\.\d+", a.wallVoid) or a.end <= 2 or a.ranks < 1:
        sys.exit("walls.py: --wallVoid is a number below 1 such as 0.166; --end must exceed 2 s, --ranks be positive")
    runs = parse_runs(a.runs)
    if any(h <= 1 for _, h in runs):
        sys.exit("walls.py: parcels only (h > 1)")
    os.makedirs(WORK, exist_ok=True)
    for i, (model, h) in enumerate(runs):
        print("== run %d of %d: %s, h = %g" % (i + 1, len(runs), model, h), flush=True)
        run_one(model, h, a)


if __name__ == "__main__":
    main()
