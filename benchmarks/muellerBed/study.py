#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The void fraction models in Mueller et al.'s bubbling bed (tutorials/muellerBed).

Each run is the tutorial's ./Allrun MODEL U CELLS END in its own copy under
build/muellerBed/ (one packing, shared), and records in results/runs/<run>.json
the time-averaged pressure drop against the bed weight, the bed height, the
mean difference between the averages over the two halves of the window (the
profiles' own statistical spread), the wall-clock time per simulated second,
and copies the profiles to results/<model>_<cells>_U<U>_<height>.csv. A run
with a .json is not run again (the study resumes: interrupt it at will).

The plan: every model at both velocities on cells of 2.5 diameters, and
centroid, analytical and kernel on cells of 1.5 and 4 diameters. --models,
--velocities and --cells select a subset. --parcels 1.5,2 adds the same
models as coarse-grained parcels of h^3 seeds (./Allrun parcels h ...,
forceScaling cubic) on cells of 2.5 diameters, named <model>_2.5_U<U>_parcels<h>. --report writes results/table.md and
results/profiles_U<U>.png; measured profiles placed in measured/ as
voidfraction_U<U>_<height>.csv (x_m, voidfraction) add their mean absolute
difference to the table and their points to the figures.

usage: study.py [--models M,..] [--velocities 0.6,0.9] [--cells 2.5,1.5,4]
                [--parcels 1.5,2] [--end 5] [--report]
"""
import argparse
import glob
import json
import os
import shutil
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TUTORIAL = os.path.join(ROOT, "tutorials", "muellerBed")
WORK = os.path.join(ROOT, "build", "muellerBed")
RESULTS = os.path.join(HERE, "results")
MEASURED = os.path.join(HERE, "measured")
sys.path.insert(0, os.path.join(ROOT, "tests"))
from foamCase import sh  # noqa: E402

MODELS = ("centroid", "analytical", "voxel", "hybrid", "kernel", "diffusion")
MESH_MODELS = ("centroid", "analytical", "kernel")


def plan(models, velocities, cells, parcels):
    runs = []
    for c in cells:
        for m in models:
            if c == 2.5 or m in MESH_MODELS:
                runs += [(m, u, c, 1) for u in velocities]
    return runs + [(m, u, 2.5, h) for h in parcels for m in models for u in velocities]


def run_name(model, u, cells, h=1):
    return "%s_%g_U%g%s" % (model, cells, u, "" if h == 1 else "_parcels%g" % h)


def packing():
    """the tutorial's packed bed, made once and copied into every run"""
    restart = os.path.join(WORK, "packing", "DEM", "post", "packed.restart")
    if not os.path.isfile(restart):
        case = os.path.join(WORK, "packing")
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(TUTORIAL, "DEM"), os.path.join(case, "DEM"))
        shutil.rmtree(os.path.join(case, "DEM", "post"), ignore_errors=True)
        os.makedirs(os.path.join(case, "DEM", "post"))
        print("packing the bed with LIGGGHTS", flush=True)
        sh("liggghts -in in.packing -log post/log.packing -screen post/screen.packing",
           os.path.join(case, "DEM"))
    return restart


def run(model, u, cells, h, end):
    name = run_name(model, u, cells, h)
    case = os.path.join(WORK, name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns(
        "[1-9]*", "0.[0-9]*", "0", "postProcessing", "log.*", "processor*", "*.png", "*.result", "post"))
    os.makedirs(os.path.join(case, "DEM", "post"))
    shutil.copy(packing(), os.path.join(case, "DEM", "post"))
    began = time.time()
    command = "./Allrun %s %g %g %g" % (model, u, cells, end)
    if h != 1:
        command = "./Allrun parcels %g %s %g %g %g" % (h, model, u, cells, end)
    rc, out = sh(command, case, check=False)
    wall = time.time() - began
    with open(os.path.join(case, "log.Allrun"), "w") as f:
        f.write(out)
    if rc:
        raise RuntimeError("%s failed: see %s" % (name, os.path.join(case, "log.Allrun")))
    if h != 1:
        case = os.path.join(case, "parcels_h%g" % h)
    record = {k: float(v) for k, v in (l.split() for l in open(os.path.join(case, "muellerBed.result")))}
    record.update(model=model, U=u, cells=cells, parcels=h, wall_s=wall, wall_per_simulated_s=wall/end)
    for path in glob.glob(os.path.join(case, "postProcessing", "profiles", "*.csv")):
        kind, height = os.path.basename(path)[:-4].split("_")
        prefix = "" if kind == "voidfraction" else kind + "_"
        shutil.copy(path, os.path.join(RESULTS, "%s%s_%s.csv" % (prefix, name, height)))
    with open(os.path.join(RESULTS, "runs", name + ".json"), "w") as f:
        json.dump(record, f, indent=1)
    return name, record


def measured(u, height):
    path = os.path.join(MEASURED, "voidfraction_U%g_%s.csv" % (u, height))
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2) if os.path.isfile(path) else None


def profile(model, u, cells, height, h=1):
    path = os.path.join(RESULTS, "%s_%s.csv" % (run_name(model, u, cells, h), height))
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2) if os.path.isfile(path) else None


def report():
    records = [json.load(open(p)) for p in sorted(glob.glob(os.path.join(RESULTS, "runs", "*.json")))]
    records.sort(key=lambda r: (r["U"], r.get("parcels", 1), r["cells"], MODELS.index(r["model"])))
    heights = ("h16.4mm", "h31.2mm")
    lines = ["| model | cells (d) | parcels h | U (m/s) | dp / weight | bed height (mm) | halves differ (16.4 / 31.2 mm)"
             " | MAD from measured (16.4 / 31.2 mm) | wall s per simulated s |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in records:
        mads = []
        for h in heights:
            m, p = measured(r["U"], h), profile(r["model"], r["U"], r["cells"], h, r.get("parcels", 1))
            mads.append("%.3f" % np.abs(np.interp(m[:, 0], p[:, 0], p[:, 1]) - m[:, 1]).mean()
                        if m is not None and p is not None else "n/a")
        lines.append("| %s | %g | %g | %g | %.3f | %.1f | %.3f / %.3f | %s | %.0f |" % (
            r["model"], r["cells"], r.get("parcels", 1), r["U"], r["dp_over_weight"], 1000*r["bed_height_m"],
            r["voidfraction_h16.4mm_halves"], r["voidfraction_h31.2mm_halves"], " / ".join(mads),
            r["wall_per_simulated_s"]))
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for u in sorted({r["U"] for r in records}):
        fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
        for ax, h in zip(axes, heights):
            for r in (r for r in records if r["U"] == u):
                h_p = r.get("parcels", 1)
                p = profile(r["model"], u, r["cells"], h, h_p)
                ax.plot(1000*p[:, 0], p[:, 1], "--" if h_p != 1 else "-" if r["cells"] == 2.5 else ":", lw=1.2,
                        label="%s, %g d%s" % (r["model"], r["cells"], "" if h_p == 1 else ", parcels h = %g" % h_p))
            m = measured(u, h)
            if m is not None:
                ax.plot(1000*m[:, 0], m[:, 1], "ko", mfc="none", label="measured")
            ax.set_title("U = %g m/s, %s above the distributor" % (u, h[1:].replace("mm", " mm")), fontsize=10)
            ax.set_xlabel("x from the left wall (mm)")
            ax.grid(alpha=0.3)
        axes[0].set_ylabel("time-averaged void fraction")
        axes[1].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(RESULTS, "profiles_U%g.png" % u), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--models", default=",".join(MODELS))
    parser.add_argument("--velocities", default="0.6,0.9")
    parser.add_argument("--cells", default="2.5,1.5,4")
    parser.add_argument("--parcels", default="")
    parser.add_argument("--end", type=float, default=5.0)
    parser.add_argument("--report", action="store_true")
    args = parser.parse_args()
    os.makedirs(os.path.join(RESULTS, "runs"), exist_ok=True)
    if not args.report:
        todo = [r for r in plan(args.models.split(","), [float(u) for u in args.velocities.split(",")],
                                [float(c) for c in args.cells.split(",") if c],
                                [float(h) for h in args.parcels.split(",") if h])
                if not os.path.isfile(os.path.join(RESULTS, "runs", run_name(*r) + ".json"))]
        for i, (model, u, cells, h) in enumerate(todo):
            print("[%d/%d] %s, U = %g m/s, cells of %g d%s, %g s" % (
                i + 1, len(todo), model, u, cells, "" if h == 1 else ", parcels h = %g" % h, args.end), flush=True)
            name, record = run(model, u, cells, h, args.end)
            print("    dp / weight %.4g, bed height %.4g mm, %.4g wall s per simulated s"
                  % (record["dp_over_weight"], 1000*record["bed_height_m"], record["wall_per_simulated_s"]),
                  flush=True)
    report()


if __name__ == "__main__":
    main()
