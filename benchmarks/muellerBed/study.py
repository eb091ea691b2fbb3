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
forceScaling cubic) on cells of 2.5 diameters, named <model>_2.5_U<U>_parcels<h>.
--report writes results/table.md (every run's mean absolute and signed
difference from the measured profiles in measured/, and the runs ranked by
their mean over the four void fraction profiles, beside sediFoam's published
simulation in published/), results/profiles_U<U>.png and velocity_U<U>.png.
--refresh derives the finished runs whose cases are still in build/ again
with the tutorial's current bedProfiles.py, then reports. --redo-incomplete
runs again the finished runs of the selection whose record lacks the particle
velocity at the measured heights.

--depth N runs the same plan with N fluid cells across the bed's depth and
no-slip front and back walls, named <run>_depth<N>; --end other than 5 s
adds _<end>s to the name. --bandwidth B (kernel only) gives the kernel a
bandwidth of B metres on every mesh instead of 0.4 of the cell size, named
<run>_b<B in mm>mm: the mesh study at one smoothing length. --wall-friction F
and --wall-restitution E set the seeds' friction and restitution against the
walls and the distributor (DEM/in.parameters; 0.1 and 0.98 by default),
named <run>_wf<F> and <run>_we<E>. --wall-void C (with --parcels) moves the
side walls out by C (h - 1) d (scaleCase -wallVoid), named <run>_wv<C>.

usage: study.py [--models M,..] [--velocities 0.6,0.9] [--cells 2.5,1.5,4]
                [--parcels 1.5,2] [--depth 1] [--end 5] [--bandwidth B]
                [--wall-friction F] [--wall-restitution E] [--wall-void C]
                [--redo-incomplete]
                [--report | --refresh]
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
sys.path.insert(0, os.path.join(ROOT, "tests"))
from foamCase import set_dem, sh, void_fraction_models  # noqa: E402
import measurement  # noqa: E402

MODELS = void_fraction_models()
MESH_MODELS = ("centroid", "analytical", "kernel")


# The variants of the tutorial's case a run can take: record key, default,
# scale of the value in its name, run name suffix, description, and the label
# beside the model in the table (parcels and depth have columns of their own).
VARIANTS = (("parcels", 1, 1, "_parcels%g", ", parcels h = %g", ""),
            ("depth", 1, 1, "_depth%d", ", %d cells deep", ""),
            ("end", 5, 1, "_%gs", ", %g s", " (%g s)"),
            ("bandwidth", 0, 1000, "_b%gmm", ", bandwidth %g mm", " (b %g mm)"),
            ("wall_friction", 0.1, 1, "_wf%g", ", wall friction %g", " (wall friction %g)"),
            ("wall_restitution", 0.98, 1, "_we%g", ", wall restitution %g", " (wall restitution %g)"),
            ("wall_void", 0, 1, "_wv%g", ", walls out by %g (h - 1) d", " (walls out, c %g)"))
DEFAULTS = {v[0]: v[1] for v in VARIANTS}


def variant(r, key):
    return r.get(key, DEFAULTS[key])


def plan(models, velocities, cells, parcels, options):
    """the runs, each a dict of model, U, cells and the variants (options: the same for all)"""
    runs = []
    for c in cells:
        for m in models:
            if c == 2.5 or m in MESH_MODELS:
                runs += [dict(options, model=m, U=u, cells=c, parcels=1) for u in velocities]
    return runs + [dict(options, model=m, U=u, cells=2.5, parcels=h) for h in parcels for m in models for u in velocities]


def record_name(r):
    return "%s_%g_U%g" % (r["model"], r["cells"], r["U"]) + "".join(
        v[3] % (v[2]*variant(r, v[0])) for v in VARIANTS if variant(r, v[0]) != v[1])


def describe(r):
    return "%s, %g d" % (r["model"], r["cells"]) + "".join(
        v[4] % (v[2]*variant(r, v[0])) for v in VARIANTS if variant(r, v[0]) != v[1])


def table_label(r):
    return r["model"] + "".join(v[5] % (v[2]*variant(r, v[0])) for v in VARIANTS if v[5] and variant(r, v[0]) != v[1])


def packing():
    """the tutorial's packed bed, made once and copied into every run (again
    when the tutorial's DEM inputs change)"""
    case = os.path.join(WORK, "packing")
    restart = os.path.join(case, "DEM", "post", "packed.restart")
    inputs = ("in.packing", "in.settings", "in.parameters")
    if not os.path.isfile(restart) or any(
            not os.path.isfile(os.path.join(case, "DEM", f))
            or open(os.path.join(case, "DEM", f)).read() != open(os.path.join(TUTORIAL, "DEM", f)).read()
            for f in inputs):
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(TUTORIAL, "DEM"), os.path.join(case, "DEM"))
        shutil.rmtree(os.path.join(case, "DEM", "post"), ignore_errors=True)
        os.makedirs(os.path.join(case, "DEM", "post"))
        print("packing the bed with LIGGGHTS", flush=True)
        sh("liggghts -in in.packing -log post/log.packing -screen post/screen.packing",
           os.path.join(case, "DEM"))
    return restart


def run(spec):
    name = record_name(spec)
    case = os.path.join(WORK, name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns(
        "[1-9]*", "0.[0-9]*", "0", "postProcessing", "log.*", "processor*", "*.png", "*.result", "post"))
    os.makedirs(os.path.join(case, "DEM", "post"))
    shutil.copy(packing(), os.path.join(case, "DEM", "post"))
    if spec["bandwidth"]:
        with open(os.path.join(case, "constant", "couplingProperties"), "a") as f:
            f.write("kernelCoeffs        { bandwidth %g; }\n" % spec["bandwidth"])
    set_dem(case, wallFriction=spec["wall_friction"], wallRestitution=spec["wall_restitution"])
    began = time.time()
    command = "./Allrun %s %g %g %g 1 %d" % (spec["model"], spec["U"], spec["cells"], spec["end"], spec["depth"])
    if spec["parcels"] != 1:
        command = "WALL_VOID=%g ./Allrun parcels %g %s %g %g %g 1 %d" % (
            variant(spec, "wall_void"), spec["parcels"], spec["model"], spec["U"], spec["cells"], spec["end"],
            spec["depth"])
    rc, out = sh(command, case, check=False)
    wall = time.time() - began
    with open(os.path.join(case, "log.Allrun"), "w") as f:
        f.write(out)
    if rc:
        raise RuntimeError("%s failed: see %s" % (name, os.path.join(case, "log.Allrun")))
    if spec["parcels"] != 1:
        case = os.path.join(case, "parcels_h%g" % spec["parcels"])
    return name, save(name, case, dict(spec, wall_s=wall, wall_per_simulated_s=wall/spec["end"]))


def refresh():
    """the finished runs whose case is still in build/: their profiles and
    record derived again by the tutorial's current bedProfiles.py"""
    for path in sorted(glob.glob(os.path.join(RESULTS, "runs", "*.json"))):
        r = json.load(open(path))
        case = os.path.join(WORK, record_name(r))
        if variant(r, "parcels") != 1:
            case = os.path.join(case, "parcels_h%g" % r["parcels"])
        if not os.path.isfile(os.path.join(case, "muellerBed.result")):
            continue
        sh("VFM_PROJECT_DIR=%s /usr/bin/python3 %s" % (ROOT, os.path.join(TUTORIAL, "bedProfiles.py")), case)
        keep = {k: r[k] for k in ("model", "U", "cells", "wall_s", "wall_per_simulated_s") + tuple(DEFAULTS)
                if k in r}
        save(record_name(r), case, keep)
        print("refreshed %s" % record_name(r), flush=True)


def save(name, case, fields):
    """the run's record (muellerBed.result and fields) and its profiles, into results/"""
    record = {k: float(v) for k, v in (l.split() for l in open(os.path.join(case, "muellerBed.result")))}
    record.update(fields)
    for path in glob.glob(os.path.join(case, "postProcessing", "profiles", "*.csv")):
        kind, height = os.path.basename(path)[:-4].split("_")
        prefix = "" if kind == "voidfraction" else kind + "_"
        shutil.copy(path, os.path.join(RESULTS, "%s%s_%s.csv" % (prefix, name, height)))
    with open(os.path.join(RESULTS, "runs", name + ".json"), "w") as f:
        json.dump(record, f, indent=1)
    return record


HEIGHTS = ("h16.4mm", "h31.2mm")
VELOCITY_HEIGHTS = {0.6: ("h20.0mm",), 0.9: ("h15.0mm", "h25.0mm", "h35.0mm")}


def to_run(name, u, redo_incomplete):
    """no record yet, or (redo_incomplete) one without the particle velocity at the measured heights"""
    path = os.path.join(RESULTS, "runs", name + ".json")
    if not os.path.isfile(path):
        return True
    record = json.load(open(path))
    return redo_incomplete and any("particleVelocity_%s_mean" % h not in record for h in VELOCITY_HEIGHTS[u])


def profile(name, height, kind="voidfraction"):
    path = os.path.join(RESULTS, "%s%s_%s.csv" % ("" if kind == "voidfraction" else kind + "_", name, height))
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2) if os.path.isfile(path) else None


def differences(u, kind, heights, simulated):
    """[(MAD, signed)] from the measurement at each height, None where either is missing"""
    found = []
    for h in heights:
        m, p = measurement.measured(kind, u, h), simulated(h)
        found.append(measurement.difference(m, p[:, 0], p[:, 1]) if m is not None and p is not None else None)
    return found


def cells(found, i, fmt="%.3f"):
    return " / ".join(fmt % f[i] if f else "n/a" for f in found)


def table_rows(records):
    rows = []
    for r in records:
        name = record_name(r)
        void = differences(r["U"], "voidfraction", HEIGHTS, lambda h: profile(name, h))
        velocity = differences(r["U"], "particleVelocity", VELOCITY_HEIGHTS[r["U"]],
                               lambda h: profile(name, h, "particleVelocity"))
        slice_ = differences(r["U"], "voidfraction", HEIGHTS, lambda h: profile(name, h, "voidfractionSlice"))
        r["mad"] = [f[0] if f else None for f in void]
        needed = " / ".join("%.0f" % r["voidfraction_%s_window_for_0.01" % h] if "voidfraction_%s_window_for_0.01" % h in r
                            else "n/a" for h in HEIGHTS)
        rows.append("| %s | %g | %g | %d | %g | %.3f | %.1f | %.3f / %.3f | %s | %s | %s | %s | %s | %.0f |" % (
            table_label(r), r["cells"], variant(r, "parcels"), variant(r, "depth"), r["U"], r["dp_over_weight"],
            1000*r["bed_height_m"],
            r["voidfraction_h16.4mm_halves"], r["voidfraction_h31.2mm_halves"], needed, cells(void, 0),
            cells(void, 1, "%+.3f"), cells(slice_, 0), cells(velocity, 0), r["wall_per_simulated_s"]))
    return rows


def published_rows(velocities):
    rows = []
    for u in velocities:
        void = differences(u, "voidfraction", HEIGHTS,
                           lambda h: measurement.published("sediFoam", "voidfraction", u, h))
        velocity = differences(u, "particleVelocity", VELOCITY_HEIGHTS[u],
                               lambda h: measurement.published("sediFoam", "particleVelocity", u, h))
        rows.append("| sediFoam (published) | %s | 1 | 1 | %g | | | | | %s | %s | | %s | |" % (
            {0.6: "1.7", 0.9: "3.3"}[u], u, cells(void, 0), cells(void, 1, "%+.3f"), cells(velocity, 0)))
    return rows


def ranking(records):
    """mean MAD over the four measured profiles, per run made at both velocities"""
    runs = {}
    for r in records:
        if variant(r, "end") == 5:      # the plan's runs, of one length
            runs.setdefault(describe(r), {})[r["U"]] = r["mad"]
    scored = [(np.mean(m[0.6] + m[0.9]), key, m) for key, m in runs.items()
              if set(m) == {0.6, 0.9} and None not in m[0.6] + m[0.9]]
    sedi = [measurement.difference(measurement.measured("voidfraction", u, h), *measurement.published(
        "sediFoam", "voidfraction", u, h).T)[0] for u in (0.6, 0.9) for h in HEIGHTS]
    scored.append((np.mean(sedi), "sediFoam (published), 1.7 d / 3.3 d", {0.6: sedi[:2], 0.9: sedi[2:]}))
    lines = ["| rank | run | mean MAD | 0.6 m/s: 16.4 / 31.2 mm | 0.9 m/s: 16.4 / 31.2 mm |",
             "|---|---|---|---|---|"]
    for i, (score, name, m) in enumerate(sorted(scored, key=lambda s: s[0])):
        lines.append("| %d | %s | %.3f | %.3f / %.3f | %.3f / %.3f |" % (i + 1, name, score, *m[0.6], *m[0.9]))
    return lines


def report():
    records = [json.load(open(p)) for p in sorted(glob.glob(os.path.join(RESULTS, "runs", "*.json")))]
    records.sort(key=lambda r: (r["U"],) + tuple(variant(r, v[0]) for v in VARIANTS) + (r["cells"], MODELS.index(r["model"])))
    lines = ["| model | cells (d) | parcels h | depth cells | U (m/s) | dp / weight | bed height (mm) | halves differ (16.4 / 31.2 mm)"
             " | halves within 0.01 after (s) | MAD from measured (16.4 / 31.2 mm) | signed (16.4 / 31.2 mm)"
             " | MAD, particles in a 1.2 mm slice | v_z MAD (m/s, at each measured height)"
             " | wall s per simulated s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    lines += table_rows(records) + published_rows(sorted({r["U"] for r in records})) + [""] + ranking(records)
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(records)


def plot(records):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for u in sorted({r["U"] for r in records}):
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
        for ax, h in zip(axes, HEIGHTS):
            for r in (r for r in records if r["U"] == u):
                p = profile(record_name(r), h)
                varied = any(variant(r, v[0]) != v[1] for v in VARIANTS if v[0] != "end")
                style = "--" if varied else {1.5: "-.", 2.5: "-"}.get(r["cells"], ":")
                ax.plot(1000*p[:, 0], p[:, 1], style, lw=1.2,
                        label="%s (MAD %.3f)" % (describe(r), r["mad"][HEIGHTS.index(h)] or float("nan")))
            s = measurement.published("sediFoam", "voidfraction", u, h)
            if s is not None:
                ax.plot(1000*s[:, 0], s[:, 1], color="0.5", lw=2.5, alpha=0.5, label="sediFoam (published)")
            m = measurement.measured("voidfraction", u, h)
            if m is not None:
                ax.plot(1000*m[:, 0], m[:, 1], "ko", mfc="none", label="measured")
            ax.set_title("U = %g m/s, %s above the distributor" % (u, h[1:].replace("mm", " mm")), fontsize=10)
            ax.set_xlabel("x from the left wall (mm)")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=6)
        axes[0].set_ylabel("time-averaged void fraction")
        fig.tight_layout()
        fig.savefig(os.path.join(RESULTS, "profiles_U%g.png" % u), dpi=110)
        plt.close(fig)
        plot_velocity(records, u, plt)


def plot_velocity(records, u, plt):
    heights = VELOCITY_HEIGHTS[u]
    fig, axes = plt.subplots(1, len(heights), figsize=(4.5*len(heights) + 1, 4), sharey=True, squeeze=False)
    for ax, h in zip(axes[0], heights):
        for r in (r for r in records if r["U"] == u):
            p = profile(record_name(r), h, "particleVelocity")
            if p is not None:
                ax.plot(1000*p[:, 0], p[:, 1], lw=1.2, label=describe(r))
        s = measurement.published("sediFoam", "particleVelocity", u, h)
        if s is not None:
            ax.plot(1000*s[:, 0], s[:, 1], color="0.5", lw=2.5, alpha=0.5, label="sediFoam (published)")
        m = measurement.measured("particleVelocity", u, h)
        ax.plot(1000*m[:, 0], m[:, 1], "ko", mfc="none", label="measured")
        ax.set_title("U = %g m/s, %s above the distributor" % (u, h[1:].replace("mm", " mm")), fontsize=10)
        ax.set_xlabel("x from the left wall (mm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6)
    axes[0][0].set_ylabel("time-averaged particle v_z (m/s)")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "velocity_U%g.png" % u), dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--models", default=",".join(MODELS))
    parser.add_argument("--velocities", default="0.6,0.9")
    parser.add_argument("--cells", default="2.5,1.5,4")
    parser.add_argument("--parcels", default="")
    parser.add_argument("--depth", type=int, default=1, help="fluid cells across the depth (no-slip front and back)")
    parser.add_argument("--end", type=float, default=5.0)
    parser.add_argument("--bandwidth", type=float, default=0.0,
                        help="kernel only: the kernel's bandwidth in metres on every mesh")
    parser.add_argument("--wall-friction", type=float, default=DEFAULTS["wall_friction"],
                        help="the seeds' friction against the walls and distributor")
    parser.add_argument("--wall-restitution", type=float, default=DEFAULTS["wall_restitution"],
                        help="the seeds' restitution against the walls and distributor")
    parser.add_argument("--wall-void", type=float, default=DEFAULTS["wall_void"],
                        help="with --parcels: the side walls out by this times (h - 1) d")
    parser.add_argument("--redo-incomplete", action="store_true",
                        help="run again the finished runs without the particle velocity at the measured heights")
    parser.add_argument("--report", action="store_true")
    parser.add_argument("--refresh", action="store_true",
                        help="derive the finished runs still in build/ again with the current bedProfiles.py")
    args = parser.parse_args()
    if args.bandwidth < 0 or (args.bandwidth and set(args.models.split(",")) != {"kernel"}):
        parser.error("--bandwidth is a length in metres > 0 for --models kernel alone (got %g for %s)"
                     % (args.bandwidth, args.models))
    if args.wall_void and not (0 < args.wall_void < 0.5 and args.parcels and not args.cells):
        parser.error("--wall-void is in (0, 0.5) with --parcels and --cells '' (parcels only; got %g)"
                     % args.wall_void)
    if args.wall_friction < 0 or not 0 < args.wall_restitution <= 1:
        parser.error("--wall-friction is >= 0 and --wall-restitution in (0, 1] (got %g and %g)"
                     % (args.wall_friction, args.wall_restitution))
    os.makedirs(os.path.join(RESULTS, "runs"), exist_ok=True)
    if args.refresh:
        refresh()
    elif not args.report:
        options = dict(depth=args.depth, end=args.end, bandwidth=args.bandwidth, wall_friction=args.wall_friction,
                       wall_restitution=args.wall_restitution, wall_void=args.wall_void)
        todo = [r for r in plan(args.models.split(","), [float(u) for u in args.velocities.split(",")],
                                [float(c) for c in args.cells.split(",") if c],
                                [float(h) for h in args.parcels.split(",") if h], options)
                if to_run(record_name(r), r["U"], args.redo_incomplete)]
        for i, spec in enumerate(todo):
            print("[%d/%d] %s, U = %g m/s, %g s" % (i + 1, len(todo), describe(spec), spec["U"], spec["end"]), flush=True)
            name, record = run(spec)
            print("    dp / weight %.4g, bed height %.4g mm, %.4g wall s per simulated s"
                  % (record["dp_over_weight"], 1000*record["bed_height_m"], record["wall_per_simulated_s"]),
                  flush=True)
    report()


if __name__ == "__main__":
    main()
