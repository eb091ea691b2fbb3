#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Records a finished tutorials/spoutedBed run (its folder, after Allrun and
plotSpoutedBed.py) in results/: the profiles, the picture and the .result
file in results/<model>_h<h>/, and its row in results/summary.csv
(model,h,cells,particles,mad_h015,mad_h045,mad_h075,spout_width_mm,
fountain_mm,dp_vs_weight,wall_s_per_sim_s), replacing an earlier row of the
same model and h. The wall-clock time is the solver's own (ExecutionTime at
the last step of each log.pimpleDEMFoam*, one per stretch of a continued
run) over the simulated time those stretches covered.

usage: record.py RUN_DIR"""
import csv
import glob
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
COLUMNS = ("model", "h", "cells", "particles", "mad_h015", "mad_h045", "mad_h075", "spout_width_mm",
           "fountain_mm", "dp_vs_weight", "wall_s_per_sim_s")


def wall_seconds(run):
    """Wall-clock seconds and simulated seconds over every stretch's log."""
    wall = simulated = 0.0
    for log in glob.glob(os.path.join(run, "log.pimpleDEMFoam*")):
        text = open(log).read()
        times = [float(t) for t in re.findall(r"(?m)^Time = (\S+)", text)]
        execution = re.findall(r"ExecutionTime = (\S+) s", text)
        if times and execution:
            wall += float(execution[-1])
            simulated += times[-1] - times[0]
    return wall, simulated


def main():
    if len(sys.argv) != 2 or not os.path.isfile(os.path.join(sys.argv[1], "spoutedBed.result")):
        sys.exit("record.py: give a spoutedBed run folder holding spoutedBed.result (run plotSpoutedBed.py first)")
    run = sys.argv[1]
    result = {k: float(v) for k, v in (l.split() for l in open(os.path.join(run, "spoutedBed.result")))}
    coupling = open(os.path.join(run, "constant", "couplingProperties")).read()
    model = re.search(r"(?m)^voidFractionModel\s+(\w+);", coupling).group(1)
    factor = re.search(r"coarseGraining\s*\{\s*factor\s+(\S+);", coupling)
    h = float(factor.group(1)) if factor else 1.0
    # a carried run's first log keeps only its time and timing lines: the count is in a later stretch's
    logs = "".join(open(f).read() for f in sorted(glob.glob(os.path.join(run, "log.pimpleDEMFoam*"))))
    wall, simulated = wall_seconds(run)
    cells = int(re.search(r"nCells: (\d+)", open(os.path.join(run, "log.blockMesh")).read()).group(1))
    particles = int(re.search(r"particleFluidCoupling: formulation \w+, (\d+) particles", logs).group(1))
    row = dict(model=model, h="%g" % h, cells=cells, particles=particles,
               wall_s_per_sim_s="%.1f" % (wall/simulated))
    for key in COLUMNS[4:-1]:
        row[key] = "%.4g" % result[key]
    where = os.path.join(RESULTS, "%s_h%g" % (model, h))
    os.makedirs(where, exist_ok=True)
    for f in glob.glob(os.path.join(run, "particleSpeed_H*.csv")) + [os.path.join(run, "spoutedBed.png"),
                                                                     os.path.join(run, "spoutedBed.result")]:
        shutil.copy(f, where)
    summary = os.path.join(RESULTS, "summary.csv")
    rows = list(csv.DictReader(open(summary))) if os.path.isfile(summary) else []
    rows = [r for r in rows if (r["model"], r["h"]) != (row["model"], row["h"])] + [row]
    rows.sort(key=lambda r: (float(r["h"]), r["model"]))
    with open(summary, "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    print("record.py: %s h = %g in %s and summary.csv" % (model, h, os.path.relpath(where, HERE)))


if __name__ == "__main__":
    main()
