#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The numerical-stability stress test, kept: the six models at cells of 1.5,
2, 3 and 5 bead diameters in the fluidisedBed tutorial (`./Allrun stress`),
run in build/stability/fluidisedBed; its stress.csv and stress.md (the table
docs/validation.md shows) are copied to benchmarks/stability/results.

About 40 minutes on 2 cores (24 serial runs of END simulated seconds).

usage: benchmarks/stability.py [END]      (default 0.3)
"""
import os
import shutil
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def main():
    end = sys.argv[1] if len(sys.argv) > 1 else "0.3"
    try:
        if float(end) <= 0:
            raise ValueError
    except ValueError:
        sys.exit("stability.py: END must be a positive number of seconds, not '%s'" % end)
    case = os.path.join(ROOT, "build", "stability", "fluidisedBed")
    if os.path.isdir(case):
        shutil.rmtree(case)
    shutil.copytree(os.path.join(ROOT, "tutorials", "fluidisedBed"), case,
                    ignore=shutil.ignore_patterns("processor*", "log.*", "[1-9]*", "VTK", "stress"))
    os.environ.setdefault("VFM_PROJECT_DIR", ROOT)
    log = os.path.join(case, "log.stress")
    print("stability.py: ./Allrun stress %s in %s (log %s)" % (end, case, log), flush=True)
    with open(log, "w") as out:
        rc = subprocess.call(["./Allrun", "stress", end], cwd=case, stdout=out,
                             stderr=subprocess.STDOUT)
    if rc != 0:
        sys.exit("stability.py: ./Allrun stress failed (exit %d), see %s" % (rc, log))
    results = os.path.join(ROOT, "benchmarks", "stability", "results")
    os.makedirs(results, exist_ok=True)
    for name in ("stress.csv", "stress.md"):
        shutil.copy(os.path.join(case, name), results)
    print(open(os.path.join(results, "stress.md")).read())
    print("written to %s" % results)


if __name__ == "__main__":
    main()
