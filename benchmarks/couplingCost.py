#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Time split of a coupling step of the fluidisedBed tutorial, on 1 and 2 ranks.

Runs tutorials/fluidisedBed (10,000 beads, cells 3 d, couplingInterval 10
DEM steps) with the given void fraction model for END simulated seconds at
each rank count, reads the solver's per-coupling log line (seconds in DEM,
exchange, void fraction, forces, fluid solve; the master's clock) and
reports the median of each over the couplings after the first tenth (and
over the first and last fifth of those: the DEM's cost falls as the bed
expands), the coupling overhead (exchange + void fraction + forces) relative
to the DEM,
and the most particles one rank held. Writes cost.csv and cost.md (the table
docs/performance.md shows) to build/couplingCost and
benchmarks/couplingCost/results.

usage: benchmarks/couplingCost.py [model] [END] [ranks...]
       (default: analytical 0.1 1 2)
"""
import os
import re
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
STAGES = ("DEM", "exchange", "voidFraction", "forces", "fluid")
LINE = re.compile(r"^coupling \d+: (\d+) particles \(at most (\d+) on a rank\), seconds "
                  r"DEM (\S+) exchange (\S+) voidFraction (\S+) forces (\S+) fluid (\S+);")


def run(case, model, end, ranks):
    log = os.path.join(case, "log.couplingCost.%d" % ranks)
    with open(log, "w") as out:
        rc = subprocess.call(["./Allrun", model, "3", str(end), str(ranks)], cwd=case,
                             stdout=out, stderr=subprocess.STDOUT)
    if rc != 0:
        sys.exit("couplingCost: the %d-rank run failed, see %s" % (ranks, log))
    rows = []
    for line in open(os.path.join(case, "log.pimpleDEMFoam")):
        m = LINE.match(line)
        if m:
            rows.append([int(m.group(1)), int(m.group(2))] + [float(m.group(i)) for i in range(3, 8)])
    if len(rows) < 20:
        sys.exit("couplingCost: only %d coupling lines in the %d-rank log" % (len(rows), ranks))
    rows = rows[len(rows)//10:]

    def median(part):
        return {s: statistics.median(r[2 + i] for r in part) for i, s in enumerate(STAGES)}
    # the DEM's cost falls as the bed expands (fewer contacts): the first and
    # last fifths show the packed start and the bubbling bed apart
    fifth = max(1, len(rows)//5)
    return (rows[0][0], max(r[1] for r in rows), len(rows), median(rows),
            median(rows[:fifth]), median(rows[-fifth:]))


def main():
    model = sys.argv[1] if len(sys.argv) > 1 else "analytical"
    end = float(sys.argv[2]) if len(sys.argv) > 2 else 0.1
    ranks = [int(a) for a in sys.argv[3:]] or [1, 2]
    work = os.path.join(ROOT, "build", "couplingCost")
    case = os.path.join(work, "fluidisedBed")
    tutorial = os.path.join(ROOT, "tutorials", "fluidisedBed")
    if os.path.isdir(case):
        shutil.rmtree(case)
    shutil.copytree(tutorial, case, ignore=shutil.ignore_patterns("processor*", "log.*", "[1-9]*", "VTK"))
    os.environ.setdefault("VFM_PROJECT_DIR", ROOT)

    results = []
    for n in ranks:
        print("couplingCost: %s, %g s on %d rank(s)" % (model, end, n), flush=True)
        results.append((n,) + run(case, model, end, n))

    def overhead(med):
        return (med["exchange"] + med["voidFraction"] + med["forces"])/med["DEM"]

    lines = ["| ranks | most particles on a rank | DEM | exchange | void fraction | forces | fluid | overhead / DEM "
             "| DEM first / last fifth | overhead first / last fifth |", "|" + "---|" * 10]
    with open(os.path.join(work, "cost.csv"), "w") as csv:
        csv.write("ranks,particles,maxHeld,couplings," + ",".join(STAGES)
                  + ",overhead,demFirst,demLast,overheadFirst,overheadLast\n")
        for n, total, held, count, med, first, last in results:
            csv.write("%d,%d,%d,%d,%s,%.4f,%.6g,%.6g,%.4f,%.4f\n" % (
                n, total, held, count, ",".join("%.6g" % med[s] for s in STAGES),
                overhead(med), first["DEM"], last["DEM"], overhead(first), overhead(last)))
            lines.append("| %d | {:,} | %s | %.1f %% | %.2f / %.2f | %.1f / %.1f %% |".format(held) % (
                n, " | ".join("%.2f" % (1e3*med[s]) for s in STAGES),
                100*overhead(med), 1e3*first["DEM"], 1e3*last["DEM"],
                100*overhead(first), 100*overhead(last)))
    results_dir = os.path.join(ROOT, "benchmarks", "couplingCost", "results")
    os.makedirs(results_dir, exist_ok=True)
    with open(os.path.join(work, "cost.md"), "w") as md:
        md.write("%s, %g s, milliseconds per coupling (medians)\n\n%s\n" % (model, end, "\n".join(lines)))
    for name in ("cost.csv", "cost.md"):
        shutil.copy(os.path.join(work, name), results_dir)
    print("\n".join(lines))
    print("median milliseconds per coupling after the first tenth; written to %s" % results_dir)


if __name__ == "__main__":
    main()
