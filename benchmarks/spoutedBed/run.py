#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The spouted bed of Yue et al. (2020), fine and coarse-grained, against the
PIV measurement: runs tutorials/spoutedBed for each model and factor given,
then averages until the two halves of the averaging window agree.

Each run (a copy of the tutorial in build/spoutedBed/<model>_h<h>/) runs
--end simulated seconds on --ranks ranks; its averages start after the 1 s
start-up. After each stretch plotSpoutedBed.py compares the front-wall speed
profiles of the window's first and second halves (mean absolute difference
over the six heights, inside the 24 mm over the channel and outside it): the
run is done when they agree within --spout and --annulus m/s, or when it has
used --budget hours of wall-clock time (then it is recorded as it stands and
the .result says how far the halves are apart); otherwise it runs --extend
seconds more. A run stopped by anything continues from its last written time
when this is started again; --save keeps the runs' last written times in
carried/ (carry.py), and a machine without a run's folder continues it from
there (to be committed while a run outlives the machine); finished runs are recorded by record.py in
results/ (profiles, picture, .result, summary.csv) and not run again.

usage: run.py [--runs analytical:4,kernel:4,analytical:3,...] [--ranks 2]
              [--end 5] [--extend 2.5] [--budget 8] [--spout 0.05]
              [--annulus 0.02] [--rerecord] [--save]
       h = 1 runs the 175,800 beads themselves.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import time

from carry import latest_time, restore, save
from record import wall_seconds

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TUTORIAL = os.path.join(ROOT, "tutorials", "spoutedBed")
WORK = os.path.join(ROOT, "build", "spoutedBed")
CARRIED = os.path.join(HERE, "carried")  # runs saved to continue on another machine
START_UP = 1.0      # s, before the averages start (the jet's ramp and the spout's opening)
ENV = dict(os.environ, VFM_PROJECT_DIR=ROOT)


def parse_runs(text):
    runs = []
    for item in text.split(","):
        model, _, h = item.partition(":")
        if not model or not re.fullmatch(r"[0-9.]+", h):
            sys.exit("run.py: --runs wants model:h items such as analytical:4, not '%s'" % item)
        runs.append((model, float(h)))
    return runs


def case_dir(model, h):
    top = os.path.join(WORK, "%s_h%g" % (model, h))
    return top, os.path.join(top, "fine" if h == 1 else "parcels_h%g" % h)


def set_end(case, end):
    path = os.path.join(case, "system", "controlDict")
    text = re.sub(r"(?m)^(endTime\s+)[0-9.eE+-]+;", r"\g<1>%g;" % end, open(path).read())
    open(path, "w").write(text)


def read_result(case):
    path = os.path.join(case, "spoutedBed.result")
    return {k: float(v) for k, v in (l.split() for l in open(path))} if os.path.isfile(path) else {}


def reached(case, end):
    """A stretch of the run ended normally at end (its last time need not be written)."""
    for log in glob.glob(os.path.join(case, "log.pimpleDEMFoam*")):
        text = open(log).read()
        times = re.findall(r"(?m)^Time = (\S+)", text)
        # the solver stops within half a step of its end
        if times and re.search(r"(?m)^End$", text) and float(times[-1]) >= end - 1e-3:
            return True
    return False


def copy_tutorial(top):
    """A fresh copy of the tutorial in top, without the tutorial's own runs"""
    shutil.rmtree(top, ignore_errors=True)
    outputs = shutil.ignore_patterns("parcels_h*", "fine", "log.*", "*.png", "*.csv", "*.result", "0")
    shutil.copytree(TUTORIAL, top, ignore=lambda d, names: outputs(d, names) if d == TUTORIAL else set())


def stretch(case, ranks):
    """Continue the run from its last written time to its endTime."""
    n = len(glob.glob(os.path.join(case, "log.pimpleDEMFoam*")))
    command = "mpirun -np %d pimpleDEMFoam -parallel" % ranks if ranks > 1 else "pimpleDEMFoam"
    subprocess.run(["bash", "-c", ". '%s/etc/bashrc' && '%s/etc/runWithProgress' log.pimpleDEMFoam.%d %s"
                    % (ROOT, ROOT, n, command)], cwd=case, env=ENV, check=True)


def analyse(case):
    subprocess.run(["/usr/bin/python3", os.path.join(TUTORIAL, "plotSpoutedBed.py"), str(START_UP)],
                   cwd=case, env=ENV, check=True)
    return read_result(case)


def carried_archive(model, h):
    return os.path.join(CARRIED, "%s_h%g.tar.xz" % (model, h))


def run_one(model, h, a):
    top, case = case_dir(model, h)
    done = os.path.join(top, "recorded")
    if os.path.isfile(done) and not a.rerecord:
        print("%s h = %g: recorded earlier (remove %s to run it again)" % (model, h, done))
        return
    carried = carried_archive(model, h)
    if latest_time(case) == 0.0:
        copy_tutorial(top)
        if os.path.isfile(carried):
            print("%s h = %g: continuing the run saved in %s" % (model, h, carried))
            restore(carried, case)
        else:
            print("%s h = %g: setting up and running the first %g s" % (model, h, a.end))
            subprocess.run(["./Allrun", "%g" % h, model, "%g" % a.end, str(a.ranks)], cwd=top, env=ENV,
                           check=True)
    while True:
        end = float(re.search(r"(?m)^endTime\s+(\S+);", open(os.path.join(case, "system", "controlDict")).read())
                    .group(1))
        if not reached(case, end):
            print("%s h = %g: continuing from t = %g s to %g s" % (model, h, latest_time(case), end))
            stretch(case, a.ranks)
        result = analyse(case)
        wall, simulated = wall_seconds(case)
        agreed = (result.get("halves_spout_m_s", 1e9) <= a.spout and
                  result.get("halves_annulus_m_s", 1e9) <= a.annulus)
        if agreed or wall + a.extend*wall/max(simulated, 1e-9) > 3600*a.budget:
            print("%s h = %g: %s after %g s simulated (%.0f s of wall-clock time): halves differ by %.3f m/s "
                  "(spout), %.3f m/s (annulus)" % (model, h, "averages agree" if agreed else "budget reached",
                                                   end, wall, result.get("halves_spout_m_s", float("nan")),
                                                   result.get("halves_annulus_m_s", float("nan"))))
            break
        set_end(case, end + a.extend)
    subprocess.run(["/usr/bin/python3", os.path.join(HERE, "record.py"), case], env=ENV, check=True)
    open(done, "w").write("%s\n" % time.strftime("%Y-%m-%d %H:%M"))
    if os.path.isfile(carried):
        # recorded: nothing is left to continue
        os.remove(carried)
        print("%s h = %g: recorded; removed %s (git rm it)" % (model, h, carried))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runs", default="analytical:4,kernel:4,analytical:3,kernel:3,analytical:2,kernel:2,"
                   "centroid:2,analytical:1")
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--end", type=float, default=5.0, help="first stretch's end, s")
    p.add_argument("--extend", type=float, default=2.5, help="s added while the halves disagree")
    p.add_argument("--budget", type=float, default=8.0, help="wall-clock hours per run")
    p.add_argument("--spout", type=float, default=0.05, help="m/s, halves' agreement in the spout")
    p.add_argument("--annulus", type=float, default=0.02, help="m/s, halves' agreement in the annulus")
    p.add_argument("--rerecord", action="store_true", help="run and record runs recorded earlier again")
    p.add_argument("--save", action="store_true", help="save the runs' last written times in carried/, "
                   "from where a run continues on a machine that does not have it")
    a = p.parse_args()
    if a.end <= START_UP or a.extend <= 0 or a.ranks < 1 or a.budget <= 0:
        sys.exit("run.py: --end must exceed the %g s start-up; --extend, --ranks and --budget must be positive"
                 % START_UP)
    runs = parse_runs(a.runs)
    if a.save:
        os.makedirs(CARRIED, exist_ok=True)
        for model, h in runs:
            save(case_dir(model, h)[1], carried_archive(model, h))
        return
    os.makedirs(WORK, exist_ok=True)
    for i, (model, h) in enumerate(runs):
        print("== run %d of %d: %s, h = %g" % (i + 1, len(runs), model, h), flush=True)
        run_one(model, h, a)


if __name__ == "__main__":
    main()
