#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Tutorial runs whose numbers the docs show, kept as committed results.

  stress    fluidisedBed's numerical-stability stress test (`./Allrun stress
            0.3`: the six models at cells of 1.5, 2, 3 and 5 diameters, 24
            serial runs, about 40 minutes): stress.csv, stress.md
            (docs/validation.md)
  riser     the riser, 0.5 s serial (2 to 3 minutes): riser.result, riser.md
            (docs/solver.md)
  cylinder  cylinderBed, 1 s serial (`analytical`), as it is, with the inlet
            at 0.8 m/s and with slip walls for the gas (about 6 minutes
            each): cylinder.csv, cylinder.md (docs/solver.md)
  heated    heatedBed, 2 s serial (about 14 minutes): heatedBed.csv,
            heatedBed.png, heatedBed.md (docs/solver.md)

Each runs in a copy of its tutorial under build/tutorialRuns/ and writes to
benchmarks/tutorialRuns/results/.

usage: benchmarks/tutorialRuns.py [stress] [riser] [cylinder] [heated]   (default all)
       benchmarks/tutorialRuns.py --heated-table CSV   heatedBed.md from a run's CSV
"""
import os
import re
import shutil
import subprocess
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
WORK = os.path.join(ROOT, "build", "tutorialRuns")
START_UP = 0.3   # s: plotCylinderBed.py's averages begin here
RESULTS = os.path.join(ROOT, "benchmarks", "tutorialRuns", "results")
OUTPUTS = shutil.ignore_patterns("processor*", "log.*", "[1-9]*", "0.[0-9]*", "VTK", "stress",
                                 "parcels_h*", "*.png", "*.result", "*.csv", "stress.md")
# the cylinder bed's runs: name, what, (file, pattern, replacement) edits
CYLINDER = [
    ("noSlip", "1 m/s, no-slip walls", []),
    ("inlet0.8", "0.8 m/s, no-slip walls", [("0.orig/U", r"\(0\.05 \(0 0 1\.0\)\) \(100 \(0 0 1\.0\)\)",
                                                   "(0.05 (0 0 0.8)) (100 (0 0 0.8))")]),
    ("slip", "1 m/s, slip walls for the gas", [("0.orig/U", r"walls\s*\{ type noSlip; \}", "walls   { type slip; }")]),
]


def copy(tutorial, name):
    case = os.path.join(WORK, name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "tutorials", tutorial), case, ignore=OUTPUTS)
    return case


def run(case, args):
    log = os.path.join(case, "log.tutorialRuns")
    print("tutorialRuns: ./Allrun %s in %s (log %s)" % (" ".join(args), case, log), flush=True)
    with open(log, "w") as out:
        rc = subprocess.call(["./Allrun"] + args, cwd=case, stdout=out, stderr=subprocess.STDOUT)
    if rc != 0:
        sys.exit("tutorialRuns: ./Allrun %s failed (exit %d), see %s" % (" ".join(args), rc, log))


def result(path):
    return {k: float(v) for k, v in (line.split() for line in open(path) if line.strip())}


def edit(path, pattern, replacement):
    text, n = re.subn(pattern, replacement, open(path).read())
    if n != 1:
        sys.exit("tutorialRuns: '%s' found %d times in %s, expected once" % (pattern, n, path))
    open(path, "w").write(text)


def stress():
    case = copy("fluidisedBed", "stress")
    run(case, ["stress", "0.3"])
    for name in ("stress.csv", "stress.md"):
        shutil.copy(os.path.join(case, name), RESULTS)


def riser():
    case = copy("riser", "riser")
    run(case, ["0.5", "1"])
    shutil.copy(os.path.join(case, "riser.result"), RESULTS)
    r = result(os.path.join(case, "riser.result"))
    if "slip" not in r:
        sys.exit("tutorialRuns: the riser did not develop (no slip in riser.result)")
    rows = [
        "| | coupled run (serial) | reference |", "|---|---|---|",
        "| slip (gas interstitial − bead) | %.4f m/s | %.4f m/s: terminal velocity × α^(n−1), n = %.2f (%+.1f %%) |"
        % (r["slip"], r["slip_expected"], r["rz_exponent"], 100*r["slip_error"]),
        "| beads leaving the top | {:,.0f} per s | {:,.0f} per s fed ({:+.1f} %) |".format(
            r["outflow_rate"], r["feed_rate"], 100*(r["outflow_ratio"] - 1)),
        "| beads fed − removed − held | %d | 0 |" % r["balance"]]
    open(os.path.join(RESULTS, "riser.md"), "w").write("\n".join(rows) + "\n")


def cylinder():
    rows = []
    for name, what, edits in CYLINDER:
        case = copy("cylinderBed", "cylinder_" + name)
        for path, pattern, replacement in edits:
            edit(os.path.join(case, path), pattern, replacement)
        run(case, ["analytical", "1.0", "1"])
        r = result(os.path.join(case, "cylinderBed.result"))
        rows.append((name, what, r["mean_dp"]/r["weight_per_area"], r["fluid_share"], r["distributor_share"],
                     r["column_share"]))
    with open(os.path.join(RESULTS, "cylinder.csv"), "w") as f:
        f.write("run,dp_vs_weight,fluid_share,distributor_share,column_share\n")
        for row in rows:
            f.write("%s,%.4f,%.4f,%.4f,%.4f\n" % ((row[0],) + row[2:]))
    first = rows[0]
    lines = ["| run (1 s, `analytical`) | pressure drop / bed weight per inlet area | fluid force on the beads / their weight |",
             "|---|---|---|"] + ["| %s | %.3f | %.3f |" % (what, dp, fluid) for _, what, dp, fluid, _, _ in rows]
    lines += ["", "| what holds the beads (%s) | share of their weight |" % first[1], "|---|---|",
              "| the fluid (drag and pressure, the solver's log) | %.3f |" % first[3],
              "| the distributor (contact forces) | %.3f |" % first[4],
              "| the column wall (contact forces, vertical) | %.3f |" % first[5],
              "| sum (Newton: 1 for a bed that does not accelerate on average) | %.3f |" % sum(first[3:6])]
    # how steadily the distributor carries its share (the first run's samples after the start-up)
    walls = np.loadtxt(os.path.join(WORK, "cylinder_" + first[0], "DEM", "post", "wallForces.txt"), ndmin=2)
    walls = walls[walls[:, 0] > START_UP]
    share = walls[:, 1]/walls[:, 3]
    window = np.floor((walls[:, 0] - START_UP)/0.05)
    means = [share[window == k].mean() for k in np.unique(window) if (window == k).sum() > 1]
    lines += ["", "| the distributor's share (%s, t > %g s) | |" % (first[1], START_UP), "|---|---|",
              "| samples in which it carries more than 1 %% of the weight | %.0f %% |" % (100*np.mean(share > 0.01)),
              "| its mean over windows of 0.05 s, lowest and highest | %.1f %% and %.1f %% |"
              % (100*min(means), 100*max(means))]
    open(os.path.join(RESULTS, "cylinder.md"), "w").write("\n".join(lines) + "\n")


def heated_table(csv):
    """the beads' mean temperature rise against the lumped balance's, at
    every half second of heatedBed.csv"""
    data = np.genfromtxt(csv, delimiter=",", names=True)
    t, beads, lumped = data["time_s"], data["beads_mean_K"], data["lumped_K"]
    rows = ["| t [s] | beads' mean temperature rise (DEM) | lumped balance of the bed | difference |",
            "|---|---|---|---|"]
    for at in np.arange(0.5, t[-1] + 1e-9, 0.5):
        i = int(np.argmin(np.abs(t - at)))
        rise, model = beads[i] - beads[0], lumped[i] - lumped[0]
        rows.append("| %.1f | %.3f K | %.3f K | %+.1f %% |" % (t[i], rise, model, 100*(rise/model - 1)))
    open(os.path.join(RESULTS, "heatedBed.md"), "w").write("\n".join(rows) + "\n")


def heated():
    case = copy("heatedBed", "heatedBed")
    run(case, ["2.0", "1"])
    for name in ("heatedBed.csv", "heatedBed.png"):
        shutil.copy(os.path.join(case, name), RESULTS)
    heated_table(os.path.join(RESULTS, "heatedBed.csv"))


def main():
    if sys.argv[1:2] == ["--heated-table"]:
        kept = os.path.join(RESULTS, "heatedBed.csv")
        if os.path.abspath(sys.argv[2]) != kept:
            shutil.copy(sys.argv[2], kept)
        heated_table(kept)
        return
    parts = {"stress": stress, "riser": riser, "cylinder": cylinder, "heated": heated}
    chosen = sys.argv[1:] or list(parts)
    unknown = [p for p in chosen if p not in parts]
    if unknown:
        sys.exit("tutorialRuns: unknown part(s) %s; choose from %s" % (" ".join(unknown), " ".join(parts)))
    os.environ.setdefault("VFM_PROJECT_DIR", ROOT)
    os.makedirs(RESULTS, exist_ok=True)
    for p in chosen:
        parts[p]()
        print("tutorialRuns: %s written to %s" % (p, RESULTS), flush=True)


if __name__ == "__main__":
    main()
