#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Which choices move the spouted bed's spout: the tutorial at h = 1.6
(`analytical`, the run that follows the beads within their noise) with one
change at a time from its set-up, each run --end simulated seconds on
--ranks ranks in build/spoutedBed/closure_<change>/ and analysed by
closureStatistics.py (the speed statistic, the bin width and the layer sampled)
into results/closures/<change>/ and a row of results/closures.csv.

Changes (one each, everything else the tutorial's):
  DiFelice   Di Felice's (1994) drag instead of Gidaspow's
  Beetstra   Beetstra, van der Hoef and Kuipers' (2007) drag
  gasLethe   air of density 1.0 kg/m3 and viscosity 1.81e-5 Pa s (the
             published Lethe example's) instead of 1.205 kg/m3, 1.5e-5 m2/s
--factor 1 runs the beads themselves with a change (recorded as
<change>_h1, about 3,000 s of wall-clock time per simulated second on 2
ranks). A run stopped by anything continues from its last written time when
this is started again; a recorded change (results/closures/<change>/) is not
run again unless --rerecord. --save keeps the runs' last written times in
carried/closure_<change>.tar.xz (carry.py), from where a machine without the
run's folder continues it.

usage: closures.py [--changes DiFelice,Beetstra,gasLethe] [--end 5] [--ranks 2]
                   [--factor 1.6] [--rerecord] [--save]
       closures.py --drag-ratios    Di Felice's and Beetstra's drag over
                   Gidaspow's at the bed's void fractions and Reynolds numbers
                   (results/dragRatios.md)
"""
import argparse
import os
import re
import subprocess
import sys

from carry import latest_time, restore, save
from record import wall_seconds
from run import CARRIED, ENV, WORK, copy_tutorial, reached, stretch

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tests"))
from dragLaws import LAWS  # noqa: E402
RESULTS = os.path.join(HERE, "results", "closures")
FACTOR = 1.6
MODEL = "analytical"


def set_entry(path, key, value):
    """key: a regular expression for what precedes the value on its line"""
    text = open(path).read()
    changed, n = re.subn(r"(?m)^(\s*%s\s+)[^;]+;" % key, r"\g<1>%s;" % value, text)
    if n != 1:
        sys.exit("closures.py: %s holds no single '%s' entry to change" % (path, key))
    open(path, "w").write(changed)


CHANGES = {
    "DiFelice": [("constant/couplingProperties", r"drag\s*\{\s*model", "DiFelice")],
    "Beetstra": [("constant/couplingProperties", r"drag\s*\{\s*model", "Beetstra")],
    "gasLethe": [("constant/transportProperties", "rho", "1.0"),
                 ("constant/transportProperties", "nu", "1.81e-05")],
}


def places(change, a):
    """the change's name, run folder, results folder and carried archive"""
    name = change if a.factor == FACTOR else "%s_h%g" % (change, a.factor)
    top = os.path.join(WORK, "closure_%s" % name)
    case = os.path.join(top, "fine" if a.factor == 1 else "parcels_h%g" % a.factor)
    return name, top, case, os.path.join(RESULTS, name), os.path.join(CARRIED, "closure_%s.tar.xz" % name)


def run_change(change, a):
    name, top, case, where, carried = places(change, a)
    if os.path.isdir(where) and not a.rerecord:
        print("%s: recorded earlier in %s" % (change, os.path.relpath(where, HERE)))
        return
    if latest_time(case) == 0.0 and os.path.isfile(carried):
        copy_tutorial(top)
        print("%s: continuing the run saved in %s" % (name, os.path.relpath(carried, HERE)), flush=True)
        restore(carried, case)
    if latest_time(case) == 0.0:
        copy_tutorial(top)
        for path, key, value in CHANGES[change]:
            set_entry(os.path.join(top, path), key, value)
        print("%s: setting up and running %g s at h = %g" % (change, a.end, a.factor), flush=True)
        subprocess.run(["./Allrun", "%g" % a.factor, MODEL, "%g" % a.end, str(a.ranks)], cwd=top, env=ENV,
                       check=True)
    elif not reached(case, a.end):
        print("%s: continuing from t = %g s" % (change, latest_time(case)), flush=True)
        stretch(case, a.ranks)
    wall, simulated = wall_seconds(case)
    subprocess.run(["/usr/bin/python3", os.path.join(HERE, "closureStatistics.py"), case, where, name,
                    "%.1f" % (wall/max(simulated, 1e-9))], env=ENV, check=True)
    if os.path.isfile(carried):
        os.remove(carried)
        print("%s: recorded; removed %s (git rm it)" % (name, os.path.relpath(carried, HERE)))


def drag_ratios():
    """A markdown table: each law's force over Gidaspow's on a bead in the
    tutorial's air, by void fraction and superficial particle Reynolds number."""
    rho, mu, d = 1.205, 1.81e-5, 0.0025
    res = (100, 300, 1000, 3000)
    lines = ["| void fraction | " + " | ".join("Re %d: Di Felice, Beetstra" % r for r in res) + " |",
             "|---|" + "---|"*len(res)]
    for a in (0.41, 0.5, 0.6, 0.7, 0.79, 0.81, 0.9, 0.95):
        cells = []
        for reynolds in res:
            u = reynolds*mu/(a*rho*d)
            g = LAWS["Gidaspow"](d, a, u, rho, mu)
            cells.append("%.2f, %.2f" % (LAWS["DiFelice"](d, a, u, rho, mu)/g, LAWS["Beetstra"](d, a, u, rho, mu)/g))
        lines.append("| %.2f | %s |" % (a, " | ".join(cells)))
    return "\n".join(lines)


def main():
    if sys.argv[1:] == ["--drag-ratios"]:
        open(os.path.join(HERE, "results", "dragRatios.md"), "w").write(drag_ratios() + "\n")
        print(drag_ratios())
        return
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--changes", default=",".join(CHANGES))
    p.add_argument("--end", type=float, default=5.0)
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--factor", type=float, default=FACTOR)
    p.add_argument("--rerecord", action="store_true")
    p.add_argument("--save", action="store_true")
    a = p.parse_args()
    changes = a.changes.split(",")
    unknown = [c for c in changes if c not in CHANGES]
    if unknown or a.end <= 2 or a.ranks < 1 or a.factor < 1:
        sys.exit("closures.py: changes are %s (not %s); --end must exceed 2 s, --ranks be positive, --factor >= 1"
                 % (", ".join(CHANGES), ", ".join(unknown) or "-"))
    if a.save:
        os.makedirs(CARRIED, exist_ok=True)
        for change in changes:
            name, _, case, _, carried = places(change, a)
            if latest_time(case) > 0.0:
                save(case, carried)
                print("%s: saved t = %g s in %s" % (name, latest_time(case), os.path.relpath(carried, HERE)))
        return
    os.makedirs(WORK, exist_ok=True)
    for i, change in enumerate(changes):
        print("== change %d of %d: %s" % (i + 1, len(changes), change), flush=True)
        run_change(change, a)


if __name__ == "__main__":
    main()
