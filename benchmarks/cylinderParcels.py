#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The cylinder bed's parcels against its beads.

tutorials/cylinderBed (18,000 glass beads of 1 mm in a column of 30 mm,
air at 1 m/s, `analytical`) for END s on 2 ranks, and the same case as
parcels of h = 2 and 3 (`scaleCase -parcels cubic -keepMesh`: the fine
mesh and steps, 15 and 10 parcels across the column), each with the
column wall as it is and moved out by -wallVoid 0.166 (parcelWalls:
0.083 and 0.166 mm). Every run writes its particles every 0.02 s and
records the solver's wall-clock time per simulated second and, over
t > START_UP s:
  - the pressure drop over the bed weight per inlet area, and the gas's
    share of the weight (plotCylinderBed.py's cylinderBed.result);
  - the bed height: below it lies 95 % of the particles' volume, averaged
    over the snapshots;
  - the radial solids profile: the particles' volume per annulus of
    BIN m over the annulus's volume between z = Z_LOW and Z_HIGH (the dense
    bottom of the bed), each particle centred there split across the
    annuli as a slab of its sphere normal to the radius, averaged over the
    snapshots; and its mean over the column.
Each run writes results/cylinderParcels/<name>.json and is not run again;
--report writes cylinderParcels.csv, cylinderParcels.md and
cylinderParcels.png from them.

usage: benchmarks/cylinderParcels.py [--factors 1,2,3] [--walls as,moved] [--end 1.0] [--report]
"""
import argparse
import json
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tutorials"))
sys.path.insert(0, HERE)
import particleVtk  # noqa: E402
import tutorialRuns  # noqa: E402

WORK = os.path.join(ROOT, "build", "cylinderParcels")
RESULTS = os.path.join(HERE, "cylinderParcels", "results")
START_UP = 0.3
COLUMN_RADIUS = 0.015
BIN = 0.0015
Z_LOW, Z_HIGH = 0.002, 0.014
WALL_VOID = 0.166
WRITE_STEPS = 200          # particles every 0.02 s (deltaT 1e-4 s)


def run_name(h, walls):
    return "beads" if h == 1 else "h%g_%s" % (h, walls)


def make_case(h, walls):
    case = os.path.join(WORK, run_name(h, walls))
    source = tutorialRuns.copy("cylinderBed", "cylinderParcels_source")
    tutorialRuns.edit(os.path.join(source, "system", "controlDict"), r"(?m)^writeInterval\s+1000;",
                      "writeInterval   %d;" % WRITE_STEPS)
    if h == 1:
        subprocess.check_call(["rm", "-rf", case])
        os.rename(source, case)
        return case
    options = ["-factor", "%g" % h, "-parcels", "cubic", "-keepMesh", "-output", case, "-overwrite"]
    if walls == "moved":
        options += ["-wallVoid", "%g" % WALL_VOID]
    with open(os.path.join(WORK, "log.scaleCase." + run_name(h, walls)), "w") as log:
        subprocess.check_call(["scaleCase"] + options, cwd=source, stdout=log, stderr=subprocess.STDOUT)
    return case


def slab_share(centre, radius, edges):
    """the share of a sphere's volume between each pair of edges along one
    axis, the sphere centred at centre"""
    lo = np.clip(edges[:-1], centre - radius, centre + radius) - centre
    hi = np.clip(edges[1:], centre - radius, centre + radius) - centre
    # integral of (R^2 - s^2) ds over [lo, hi], over 4/3 R^3
    return (radius**2*(hi - lo) - (hi**3 - lo**3)/3)/(4/3*radius**3)


def radial_profile(files):
    """(annulus centres, the solids fraction of each, the height of 95 % of
    the volume), averaged over the snapshots"""
    edges = np.arange(0, COLUMN_RADIUS + BIN/2, BIN)
    area = np.pi*(edges[1:]**2 - edges[:-1]**2)
    solids, heights = np.zeros(len(edges) - 1), []
    for path in files:
        x, r, _ = particleVtk.read(path)
        volume = 4/3*np.pi*r**3
        order = np.argsort(x[:, 2])
        cumulative = np.cumsum(volume[order])
        heights.append(x[order, 2][np.searchsorted(cumulative, 0.95*cumulative[-1])])
        inside = (x[:, 2] >= Z_LOW) & (x[:, 2] < Z_HIGH)
        rc = np.hypot(x[inside, 0], x[inside, 1])
        for c, R, v in zip(rc, r[inside], volume[inside]):
            solids += v*slab_share(c, R, edges)
    solids /= len(files)*area*(Z_HIGH - Z_LOW)
    return 0.5*(edges[1:] + edges[:-1]), solids, float(np.mean(heights))


def clock_time(case):
    """the solver's last ClockTime, s"""
    times = re.findall(r"ClockTime = (\S+) s", open(os.path.join(case, "log.pimpleDEMFoam")).read())
    return float(times[-1])


def run_one(h, walls, end):
    name = run_name(h, walls)
    case = make_case(h, walls)
    tutorialRuns.run(case, ["analytical", "%g" % end, "2"])
    result = tutorialRuns.result(os.path.join(case, "cylinderBed.result"))
    dt = 1e-4
    files = [f for f in particleVtk.files(case) if particleVtk.step(f)*dt > START_UP + 1e-9]
    centres, solids, height = radial_profile(files)
    area = np.pi*((centres + BIN/2)**2 - (centres - BIN/2)**2)
    record = dict(name=name, h=h, walls=walls if h != 1 else "", end=end, snapshots=len(files),
                  wall_per_s=clock_time(case)/end,
                  dp_vs_weight=result["mean_dp"]/result["weight_per_area"], fluid_share=result["fluid_share"],
                  bed_height=height, radius=centres.tolist(), solids=solids.tolist(),
                  mean_solids=float(np.sum(solids*area)/np.sum(area)))
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, name + ".json"), "w") as f:
        json.dump(record, f, indent=1)
    return record


def finished():
    return {f[:-5]: json.load(open(os.path.join(RESULTS, f)))
            for f in sorted(os.listdir(RESULTS)) if f.endswith(".json")} if os.path.isdir(RESULTS) else {}


def table_text(runs):
    """cylinderParcels.md: each run against the beads'"""
    beads = runs["beads"]
    rows = sorted(runs.values(), key=lambda r: (r["h"], r["walls"]))
    lines = ["| run | dp / bed weight | gas's share | bed height (mm) | solids, z %g-%g mm | from the beads' "
             "| solids, outer %g mm | from the beads' | profile: mean abs. from the beads' | s per simulated s "
             "| speed-up |" % (1e3*Z_LOW, 1e3*Z_HIGH, 1e3*BIN), "|---" * 11 + "|"]
    for r in rows:
        what = "beads" if r["h"] == 1 else "h = %g, walls %s" % (r["h"], "as they are" if r["walls"] == "as"
                                                                 else "moved out")
        lines.append("| %s | %.3f | %.3f | %.1f | %.3f | %+.3f | %.3f | %+.3f | %.3f | %.0f | %.1f |"
                     % (what, r["dp_vs_weight"], r["fluid_share"], 1e3*r["bed_height"], r["mean_solids"],
                        r["mean_solids"] - beads["mean_solids"], r["solids"][-1],
                        r["solids"][-1] - beads["solids"][-1],
                        float(np.mean(np.abs(np.subtract(r["solids"], beads["solids"])))),
                        r["wall_per_s"], beads["wall_per_s"]/r["wall_per_s"]))
    return "\n".join(lines) + "\n"


def report():
    runs = finished()
    if "beads" not in runs:
        sys.exit("cylinderParcels: no beads run in %s" % RESULTS)
    rows = sorted(runs.values(), key=lambda r: (r["h"], r["walls"]))
    with open(os.path.join(HERE, "cylinderParcels", "cylinderParcels.csv"), "w") as f:
        f.write("run,h,walls,dp_vs_weight,fluid_share,bed_height,mean_solids,wall_annulus_solids\n")
        for r in rows:
            f.write("%s,%g,%s,%.4f,%.4f,%.5f,%.4f,%.4f\n" % (r["name"], r["h"], r["walls"], r["dp_vs_weight"],
                                                             r["fluid_share"], r["bed_height"], r["mean_solids"],
                                                             r["solids"][-1]))
    text = table_text(runs)
    open(os.path.join(HERE, "cylinderParcels", "cylinderParcels.md"), "w").write(text)
    print(text)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for r in rows:
        style = "k-" if r["h"] == 1 else ("-" if r["walls"] == "moved" else "--")
        ax.plot(1e3*np.array(r["radius"]), r["solids"], style, marker="o", ms=3,
                label="beads" if r["h"] == 1 else "h = %g, walls %s" % (r["h"], r["walls"]))
    ax.set_xlabel("radius (mm)")
    ax.set_ylabel("solids fraction, z %g-%g mm" % (1e3*Z_LOW, 1e3*Z_HIGH))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "cylinderParcels", "cylinderParcels.png"), dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--factors", default="1,2,3")
    p.add_argument("--walls", default="as,moved")
    p.add_argument("--end", type=float, default=1.0)
    p.add_argument("--report", action="store_true")
    a = p.parse_args()
    if a.report:
        report()
        return
    if not a.end > START_UP:
        sys.exit("cylinderParcels: --end must exceed the start-up of %g s" % START_UP)
    os.makedirs(WORK, exist_ok=True)
    tutorialRuns.WORK = WORK
    for h in (float(x) for x in a.factors.split(",")):
        for walls in (["as"] if h == 1 else a.walls.split(",")):
            if os.path.isfile(os.path.join(RESULTS, run_name(h, walls) + ".json")):
                continue
            r = run_one(h, walls, a.end)
            print("  %s: dp/weight %.3f, bed %.1f mm, solids %.3f" % (r["name"], r["dp_vs_weight"],
                                                                     1e3*r["bed_height"], r["mean_solids"]),
                  flush=True)
    report()


if __name__ == "__main__":
    main()
