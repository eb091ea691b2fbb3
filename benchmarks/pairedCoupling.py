#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Paired comparison of two builds on the fluidisedBed coupling step.

A change to the coupling is often worth a few per cent of a stage, less
than the machine's own drift between runs: this runs the case that
couplingCost.py prepared (build/couplingCost/fluidisedBed) alternately with
build A and build B, PAIRS times each, and reports per stage the median
over all couplings of the runs of each build and the ratio B/A. It also
checks that the two builds' coupling log lines, without their timings,
are identical (the same void fraction range, momentum balance and total
force every coupling): a speed change must not change the results.

A build is a directory with lib/ (libvoidFractionModels.so,
libdemCoupling.so) and bin/pimpleDEMFoam, e.g. a copy of platforms/ made
before and after the change.

usage: benchmarks/pairedCoupling.py A B [ranks] [pairs] [endTime]
       (default: 1 rank, 4 pairs, 0.05 s = 500 couplings)
"""
import os
import re
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CASE = os.path.join(ROOT, "build", "couplingCost", "fluidisedBed")
STAGES = ("DEM", "exchange", "voidFraction", "forces", "fluid")
LINE = re.compile(r"^coupling \d+: .* seconds DEM (\S+) exchange (\S+) voidFraction (\S+)"
                  r" forces (\S+) fluid (\S+);")


def prepare(end, ranks):
    if not os.path.isdir(CASE):
        sys.exit("pairedCoupling: no %s; run benchmarks/couplingCost.py once first" % CASE)
    control = os.path.join(CASE, "system", "controlDict")
    text = re.sub(r"(?m)^endTime\s+\S+;", "endTime         %g;" % end, open(control).read())
    open(control, "w").write(text)
    if ranks > 1:
        subprocess.check_call("decomposePar -force > log.pairedDecompose", shell=True, cwd=CASE)


def clean():
    # written times would turn the next run into a restart
    for d in [CASE] + [os.path.join(CASE, p) for p in os.listdir(CASE) if p.startswith("processor")]:
        for t in os.listdir(d):
            if re.match(r"^\d+\.\d+$", t) or (re.match(r"^\d+$", t) and t != "0"):
                shutil.rmtree(os.path.join(d, t))


def run(build, ranks):
    clean()
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = os.path.join(build, "lib") + ":" + env.get("LD_LIBRARY_PATH", "")
    solver = os.path.join(build, "bin", "pimpleDEMFoam")
    cmd = [solver] if ranks == 1 else \
        ["mpirun", "-np", str(ranks), "-x", "LD_LIBRARY_PATH", solver, "-parallel"]
    log = os.path.join(CASE, "log.paired")
    with open(log, "w") as out:
        if subprocess.call(cmd, cwd=CASE, env=env, stdout=out, stderr=subprocess.STDOUT):
            sys.exit("pairedCoupling: the run of %s failed, see %s" % (build, log))
    times, results = [], []
    for line in open(log):
        m = LINE.match(line)
        if m:
            times.append([float(m.group(i)) for i in range(1, 6)])
            # the results without the timings (the stages' and the wall clock's)
            results.append(re.sub(r"; wall seconds since the last coupling \S+", "",
                                  re.sub(r"seconds.*?; alpha", "alpha", line)))
    if len(times) < 20:
        sys.exit("pairedCoupling: only %d coupling lines in %s" % (len(times), log))
    return times[len(times)//10:], results


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    builds = [os.path.abspath(b) for b in sys.argv[1:3]]
    ranks = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    pairs = int(sys.argv[4]) if len(sys.argv) > 4 else 4
    end = float(sys.argv[5]) if len(sys.argv) > 5 else 0.05
    prepare(end, ranks)
    rows = {0: [], 1: []}
    runs = {0: [], 1: []}
    reference = {}
    for k in range(pairs):
        for b in (0, 1) if k % 2 == 0 else (1, 0):
            times, results = run(builds[b], ranks)
            rows[b] += times
            runs[b].append([statistics.median(r[i] for r in times) for i in range(5)])
            if b not in reference:
                reference[b] = results
            elif results != reference[b]:
                print("pairedCoupling: build %s gave different results in two runs" % "AB"[b])
        print("pair %d of %d done" % (k + 1, pairs), flush=True)
    same = reference[0] == reference[1]
    med = {b: [statistics.median(r[i] for r in rows[b]) for i in range(5)] for b in rows}
    # the machine drifts between runs: the ratio of each pair's two
    # neighbouring runs, and its median over the pairs, is the robust one
    def pairRatio(value):
        return statistics.median(value(runs[1][k])/max(value(runs[0][k]), 1e-12)
                                 for k in range(pairs))
    print("| stage | A ms | B ms | B/A of the medians | median B/A of the pairs |")
    print("|---|---|---|---|---|")
    for i, s in enumerate(STAGES):
        print("| %s | %.3f | %.3f | %.3f | %.3f |" % (
            s, 1e3*med[0][i], 1e3*med[1][i], med[1][i]/max(med[0][i], 1e-12),
            pairRatio(lambda m: m[i])))
    over = [sum(med[b][1:4]) for b in (0, 1)]
    print("| overhead | %.3f | %.3f | %.3f | %.3f |" % (
        1e3*over[0], 1e3*over[1], over[1]/over[0], pairRatio(lambda m: sum(m[1:4]))))
    print("overhead / DEM: A %.1f %%, B %.1f %% (medians of the runs)" % tuple(
        100*statistics.median(sum(m[1:4])/m[0] for m in runs[b]) for b in (0, 1)))
    print("%d rank(s), %d pairs; coupling results %s" % (ranks, pairs,
          "identical" if same else "DIFFER between A and B"))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
