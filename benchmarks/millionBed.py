#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The million-bead bed of benchmarks/couplingScale.py (998,280 glass beads
of 1 mm, 239.7 x 120.4 mm, cells of 3 mm, inlet 1 m/s) as coarse-grained
parcels.

For each factor h, `scaleCase -factor h -parcels cubic` of the fine case:
parcels of h^3 beads, the fluid coarsened with them (cells of about 3 h mm,
fluid and coupling steps h times longer, as scaleCase prints). Each run packs
its parcels at random (a lattice with gaps of a quarter diameter, moved by up
to 0.12 diameters, settled for 0.25 s as the tutorial's pour), runs END
simulated seconds on 2 ranks and records: the pressure drop averaged over
t > SETTLE against the bed weight per area, the bed height (below which 95 %
of the parcels' volume lies, averaged over the snapshots after SETTLE) and
the wall-clock seconds per simulated second (the couplings after SETTLE).
The fine bed's cost per simulated second is the median time per coupling of
couplingScale's 10^6 run on 2 ranks (series.csv), so the saving is measured
on the same bed.

Resumable: each finished run's result is kept in build/millionBed/<run>/
result.json and in benchmarks/millionBed/results/runs/<run>.json; the table
holds every run kept there, so a run on a fresh machine adds its row to the
others. Writes benchmarks/millionBed/results/summary.csv, table.md and
beds.png (a slice of each bed at the end, of the runs whose particles are
still in build/).

--z-factor N multiplies the coarse mesh's cells in z by N after scaleCase
(runs named h<h>_<model>_z<N>): how many cells tall the bed must be.

usage: benchmarks/millionBed.py [--factors 4,3,2] [--models analytical,kernel]
                                [--end 2.0] [--z-factor 1] [--report]
"""
import argparse
import glob
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tutorials"))
import couplingScale  # noqa: E402
import particleVtk  # noqa: E402

WORK = os.path.join(ROOT, "build", "millionBed")
RESULTS = os.path.join(HERE, "millionBed", "results")
KEPT = os.path.join(RESULTS, "runs")
SETTLE = 0.4
PACK_GAP, PACK_JITTER, PACK_SETTLE = 1.25, 0.12, 0.25     # diameters, diameters, s (the tutorial's)
RANKS = 2
LAW = "cubic"
COUPLING = re.compile(r"^coupling (\d+): .*; wall seconds since the last coupling (\S+)$")
TIME = re.compile(r"^Time = (\S+)$")


def entry(path, name):
    m = re.search(r"^\s*%s\s+(\S+?);" % name, open(path).read(), re.M)
    if not m:
        sys.exit("millionBed: no %s in %s" % (name, path))
    return m.group(1)


def dem_variable(case, name):
    m = re.search(r"^variable\s+%s\s+equal\s+(\S+)" % name,
                  open(os.path.join(case, "DEM", "in.parameters")).read(), re.M)
    if not m:
        sys.exit("millionBed: no variable %s in %s/DEM/in.parameters" % (name, case))
    return float(m.group(1))


def fine_case(end):
    """The fine 10^6 bed's case (not run: scaleCase's source)."""
    case = os.path.join(WORK, "fine")
    couplingScale.prepare(case, "1e6")
    couplingScale.edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+\S+;", "endTime         %g;" % end)
    decompose = os.path.join(case, "system", "decomposeParDict")
    couplingScale.edit(decompose, r"^numberOfSubdomains .*;", "numberOfSubdomains %d;" % RANKS)
    couplingScale.edit(decompose, r"n\s*\(\s*\d+ 1 1\s*\)", "n (%d 1 1)" % RANKS)
    return case


def refine_height(case, factor):
    """Multiply the coarse mesh's cell counts in z by factor (the check of
    how many cells tall the bed must be)."""
    path = os.path.join(case, "system", "blockMeshDict")
    text = re.sub(r"\((\d+) (\d+) (\d+)\) simpleGrading",
                  lambda m: "(%s %s %d) simpleGrading" % (m.group(1), m.group(2), factor*int(m.group(3))),
                  open(path).read())
    open(path, "w").write(text)
    print("    cells in z multiplied by %d: the bed %d times as many cells tall" % (factor, factor), flush=True)


def coarse_run(fine, h, model, end, z_factor=1):
    name = "h%g_%s%s" % (h, model, "" if z_factor == 1 else "_z%d" % z_factor)
    case = os.path.join(WORK, name)
    keep = os.path.join(case, "result.json")
    if os.path.exists(keep):
        result = json.load(open(keep))
        if result.get("end") == end:
            print("  %s: kept" % name, flush=True)
            return result
    print("  %s: scaleCase -factor %g -parcels %s -relativeSmoothing (the fluid coarsened by h)" % (name, h, LAW),
          flush=True)
    couplingScale.sh("scaleCase -factor %g -parcels %s -relativeSmoothing -output %s -overwrite" % (h, LAW, case), fine, "log.scaleCase." + name)
    text = open(os.path.join(fine, "log.scaleCase." + name)).read()
    for line in text.split("\n"):
        if re.search(r"cells|deltaT|couplingInterval|count|radius", line) and "->" in line:
            print("    " + line.strip(), flush=True)
    couplingScale.edit(os.path.join(case, "constant", "couplingProperties"), r"^voidFractionModel\s+\w+;",
                       "voidFractionModel   %s;" % model)
    if z_factor != 1:
        refine_height(case, z_factor)
    os.makedirs(os.path.join(case, "DEM", "post"), exist_ok=True)
    # a random packing: the lattice of the scale series (2 % gaps) settles
    # into columns, a simple cubic stack (solid fraction 0.52) that 1 m/s
    # does not fluidise; from gaps of a quarter diameter and a jitter of
    # up to 0.12 diameters the parcels fall past each other
    with open(os.path.join(case, "DEM", "in.lattice"), "w") as f:
        f.write(couplingScale.lattice_script(gap=PACK_GAP, jitter=PACK_JITTER, settle=PACK_SETTLE))
    start = time.time()
    couplingScale.sh("mpirun -np 2 liggghts -in in.lattice -log post/log.packing -screen post/screen.packing",
          os.path.join(case, "DEM"), "post/log.mpirun")
    packing = time.time() - start
    for d in glob.glob(os.path.join(case, "processor*")) + [os.path.join(case, "0")]:
        shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    couplingScale.sh("blockMesh", case, "log.blockMesh")
    couplingScale.sh("decomposePar -force", case, "log.decomposePar")
    print("    packed in %.0f s; %g s on %d ranks (progress below)" % (packing, end, RANKS), flush=True)
    start = time.time()
    rc = subprocess.call([os.path.join(ROOT, "etc", "runWithProgress"), "log.pimpleDEMFoam", "mpirun", "-np",
                          str(RANKS), "pimpleDEMFoam", "-parallel"], cwd=case)
    if rc != 0:
        sys.exit("millionBed: the run failed, see %s/log.pimpleDEMFoam" % case)
    result = analyse(case)
    result.update({"name": name, "h": h, "model": model, "law": LAW, "end": end, "packing_s": packing,
                   "z_factor": z_factor,
                   "wall_s": time.time() - start})
    json.dump(result, open(keep, "w"), indent=1)
    print("    pressure drop / bed weight %.3f, bed height %.1f mm, %.0f s per simulated second" % (
        result["dp_over_weight"], 1e3*result["bed_height_m"], result["wall_per_simulated_s"]), flush=True)
    return result


def bed_height(x, r):
    """Below which 95 % of the particles' volume lies."""
    pairs = sorted((p[2], q**3) for p, q in zip(x, r))
    total, acc = sum(v for _, v in pairs), 0
    for z, v in pairs:
        acc += v
        if acc >= 0.95*total:
            return z
    return pairs[-1][0]


def snapshots(case, dt):
    """The VTK particle files written after SETTLE, in time order."""
    return [p for p in particleVtk.files(case) if particleVtk.step(p)*dt > SETTLE + 1e-9]


def bed_measures(case):
    """Over the snapshots after SETTLE, the mean bed height and the mean
    fraction of the parcels touching the distributor (lowest point within
    5 % of a radius of z = 0: weight that can rest on it rather than on the
    gas), each snapshot read once."""
    dt = float(entry(os.path.join(case, "system", "controlDict"), "deltaT"))
    heights, touching = [], []
    for path in snapshots(case, dt):
        x, r, _ = particleVtk.read(path)
        heights.append(bed_height(x, r))
        touching.append(sum(1 for p, q in zip(x, r) if p[2] - q < 0.05*q)/len(x))
    mean = lambda v: statistics.mean(v) if v else float("nan")
    return mean(heights), mean(touching)


def analyse(case):
    log = open(os.path.join(case, "log.pimpleDEMFoam")).read().split("\n")
    n = int(re.search(r"particleFluidCoupling: formulation \w+, (\d+) particles", "\n".join(log)).group(1))
    radius = dem_variable(case, "radius")
    rho_p = dem_variable(case, "density")
    g = dem_variable(case, "gravity")
    transport = os.path.join(case, "constant", "transportProperties")
    rho_f = float(re.search(r"rho\s+(?:\[[^]]*\]\s+)?(\S+?);", open(transport).read()).group(1))
    area = dem_variable(case, "width")*dem_variable(case, "depth")
    weight = n*4.0/3*math.pi*radius**3*(rho_p - rho_f)*g/area
    dat = os.path.join(case, "postProcessing", "inletPressure", "0", "surfaceFieldValue.dat")
    rows = [l.split() for l in open(dat) if l.strip() and not l.startswith("#")]
    dp = [rho_f*float(p) for t, p in rows if float(t) > SETTLE]
    half = len(dp)//2
    # the couplings after SETTLE: wall seconds per simulated second
    now, walls = 0.0, []
    for line in log:
        m = TIME.match(line)
        if m:
            now = float(m.group(1))
        m = COUPLING.match(line)
        if m and now > SETTLE:
            walls.append(float(m.group(2)))
    control = os.path.join(case, "system", "controlDict")
    end, dt = float(entry(control, "endTime")), float(entry(control, "deltaT"))
    interval = int(entry(os.path.join(case, "constant", "couplingProperties"), "couplingInterval"))
    dem_dt = dem_variable(case, "demStep")
    coupling_time = max(dt, interval*dem_dt)
    height, touching = bed_measures(case)
    return {"particles": n, "radius_m": radius, "weight_pa": weight, "dp_pa": statistics.mean(dp),
            "dp_over_weight": statistics.mean(dp)/weight,
            "dp_halves": [statistics.mean(dp[:half])/weight, statistics.mean(dp[half:])/weight],
            "bed_height_m": height,
            "wall_per_simulated_s": sum(walls)/(len(walls)*coupling_time) if walls else float("nan"),
            "on_distributor": touching,
            "cells": int(re.search(r"nCells: (\d+)", open(os.path.join(case, "log.blockMesh")).read()).group(1)),
            "end_time": end}


def fine_cost():
    """The fine bed's seconds per simulated second on 2 ranks, from the scale series."""
    path = os.path.join(HERE, "couplingScale", "results", "series.csv")
    import csv
    for row in csv.DictReader(open(path)):
        if int(row["ranks"]) == RANKS and int(row["particles"]) > 500000:
            return float(row["total_ms"])*1e-3/1e-4, int(row["particles"]), int(row["cells"])
    sys.exit("millionBed: no 10^6 row on %d ranks in %s (run benchmarks/couplingScale.py)" % (RANKS, path))


def order(r):
    return (r["model"], -r["h"], r.get("z_factor", 1))


def with_kept(new):
    """The runs of results/runs/ with the new ones (kept there too) in place of theirs."""
    os.makedirs(KEPT, exist_ok=True)
    for r in new:
        json.dump(r, open(os.path.join(KEPT, r["name"] + ".json"), "w"), indent=1)
    runs = {}
    for path in sorted(glob.glob(os.path.join(KEPT, "*.json"))):
        r = json.load(open(path))
        runs[r["name"]] = r
    return list(runs.values())


def report(new):
    results = with_kept(new)
    fine_s, fine_n, fine_cells = fine_cost()
    columns = ("model", "h", "law", "z_factor", "particles", "cells", "end_s", "dp_over_weight",
               "on_distributor", "bed_height_mm", "wall_per_simulated_s", "speedup")
    lines = ["| model | h | cells in z | parcels | cells | simulated s | pressure drop / bed weight (halves) "
             "| on the distributor | bed height mm | wall s per simulated s | saving |",
             "|---|---|---|---|---|---|---|---|---|---|---|",
             "| fine | 1 | | %d | %d | 30 couplings | | | | %.0f | 1 |" % (fine_n, fine_cells, fine_s)]
    with open(os.path.join(RESULTS, "summary.csv"), "w") as f:
        f.write(",".join(columns) + "\n")
        for r in sorted(results, key=order):
            speedup = fine_s/r["wall_per_simulated_s"]
            z = r.get("z_factor", 1)
            f.write("%s,%g,%s,%d,%d,%d,%g,%.4f,%.4f,%.2f,%.1f,%.1f\n" % (
                r["model"], r["h"], r["law"], z, r["particles"], r["cells"], r["end"], r["dp_over_weight"],
                r["on_distributor"], 1e3*r["bed_height_m"], r["wall_per_simulated_s"], speedup))
            lines.append("| %s | %g | %s | %d | %d | %g | %.3f (%.3f, %.3f) | %.3f | %.1f | %.0f | %.0f |" % (
                r["model"], r["h"], "coarsened" if z == 1 else "coarsened, then x %d" % z, r["particles"],
                r["cells"], r["end"], r["dp_over_weight"], r["dp_halves"][0],
                r["dp_halves"][1], r["on_distributor"], 1e3*r["bed_height_m"], r["wall_per_simulated_s"], speedup))
    open(os.path.join(RESULTS, "table.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(results)


def plot(results):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    runs = [r for r in sorted(results, key=order) if particleVtk.files(os.path.join(WORK, r["name"]))]
    if not runs:
        return
    fig, axes = plt.subplots(1, len(runs), figsize=(3.2*len(runs), 3.6), squeeze=False)
    for ax, r in zip(axes[0], runs):
        case = os.path.join(WORK, r["name"])
        x, rad, _ = particleVtk.read(particleVtk.files(case)[-1])
        depth = dem_variable(case, "depth")
        # a slice of 3 parcel diameters about the middle of the depth
        keep = [(p[0], p[2]) for p, q in zip(x, rad) if abs(p[1] - depth/2) < 3*q]
        ax.scatter([1e3*a for a, _ in keep], [1e3*b for _, b in keep], s=0.4, c="C0")
        ax.set_xlim(0, 1e3*dem_variable(case, "width"))
        ax.set_ylim(0, 120)
        ax.set_aspect("equal")
        ax.set_title("%s, h = %g%s\n%d parcels, t = %g s" % (
            r["model"], r["h"], "" if r.get("z_factor", 1) == 1 else ", cells in z x %d" % r["z_factor"],
            r["particles"], r["end"]),
                     fontsize=8)
        ax.set_xlabel("x mm")
    axes[0][0].set_ylabel("z mm")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "beds.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--factors", default="4,3,2")
    parser.add_argument("--models", default="analytical,kernel")
    parser.add_argument("--end", type=float, default=2.0)
    parser.add_argument("--z-factor", type=int, default=1,
                        help="cells in z times this on the coarse mesh (how many cells tall the bed must be)")
    parser.add_argument("--report", action="store_true", help="only the table and plot of the kept runs")
    args = parser.parse_args()
    os.environ.setdefault("VFM_PROJECT_DIR", ROOT)
    os.makedirs(WORK, exist_ok=True)
    results = []
    if args.report:
        for keep in glob.glob(os.path.join(WORK, "*", "result.json")):
            result = json.load(open(keep))
            if "on_distributor" not in result:
                result["on_distributor"] = bed_measures(os.path.dirname(keep))[1]
                json.dump(result, open(keep, "w"), indent=1)
            results.append(result)
    else:
        fine = fine_case(args.end)
        for h in [float(f) for f in args.factors.split(",")]:
            for model in args.models.split(","):
                results.append(coarse_run(fine, h, model, args.end, args.z_factor))
    report(results)


if __name__ == "__main__":
    main()
