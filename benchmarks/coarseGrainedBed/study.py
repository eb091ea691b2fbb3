#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The coarse-grained bubbling bed against the fine one.

The fine system is tutorials/fluidisedBed (10,000 glass beads of 1 mm in
air, a 48 x 6 mm slice periodic in x and y, cells of 3 mm, inlet 1 m/s);
--bed wide makes it 96 x 24 mm with 80,000 beads (the same beads, air,
inlet and cells), wide and deep enough that the mesh coarsened by h = 4
still has 8 cells across and 2 through the depth.
Each coarse system is `scaleCase -factor h -parcels <law>` of it: parcels of
h^3 beads, the drag scaled by h^3 (cubic) or h^2 (exact), with --mesh fine
(-keepMesh: the fine bed's mesh and steps), --mesh coarsened (cells,
fluid and coupling steps coarsened by h, the smoothing relative to the
cells: -relativeSmoothing), --mesh bed (coarsened by at most h, at least
12 cells across the settled bed's height, the smoothing in metres:
-minCells) or --mesh bedCo (as bed, the fluid and coupling steps by the
coarse bed's needs: -courant, --courant Co; the runs' mesh is named bedCo<Co>).
Each run packs its bed with LIGGGHTS, runs pimpleDEMFoam on --ranks ranks
and records:
  - bubbling (inlet 1 m/s, END s): the pressure drop averaged over
    t > SETTLE s against the bed weight per area, its fluctuation, the bed
    height (the height below which 95 % of the particles' volume lies,
    averaged over the snapshots after SETTLE), the time-averaged fluid
    fraction against height (each written time after SETTLE, averaged over
    x and y), and the wall-clock time per simulated second;
  - ramp (--ramp): the inlet held at 1 m/s to RAMP_HOLD s, then lowered
    linearly to 0 at RAMP_END s (a defluidisation curve); Umf is where the
    fixed bed's pressure drop, a least-squares a U + b U^2 over
    U < FIXED_BED_U, reaches the bed weight. Reference: Wen and Yu's
    correlation, Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7.
Each finished run writes <name>.json in results/runs/ (results/wide/runs/
for the wide bed) and is not run again (the study resumes); --report writes
the table (table.md), the plots (profiles.png, ramp.png) of each bed and
results/summary.csv, one row per coarse run of every bed: the pressure
drop, Umf, bed height and fluid fraction profile against the fine bed's
(same bed, same model; the coarse profile interpolated to the fine bed's
cell layers) and the speed-up in wall-clock time per simulated second.
--shares makes bubbling runs of their own (results/<bed>/shares/, not in the
table) for where the bed's weight rests over t > SETTLE s: the gas's
vertical force on the particles (the solver's log), the distributor's and
the side walls' contact forces (DEM/post/wallForces.txt); --report writes
them to shares.md. --profile makes bubbling runs of their own
(results/<bed>/profile/) that record where the wall-clock time goes (the
solver's stage timings); --report writes them to profile.md.

usage: study.py [--bed tutorial|wide] [--mesh fine|coarsened|bed|bedCo] [--courant 0.5] [--ranks 1]
                [--models analytical,kernel,centroid] [--factors 1,1.5,2,3]
                [--laws cubic,exact] [--end 2.0] [--ramp | --shares | --profile] [--jobs 2]
                [--report] [--results DIR]
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np
from concurrent.futures import ProcessPoolExecutor, as_completed

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TUTORIAL = os.path.join(ROOT, "tutorials", "fluidisedBed")
sys.path.insert(0, os.path.join(ROOT, "tests"))
sys.path.insert(0, TUTORIAL)
from foamCase import cell_centres, read_scalar_field, sh  # noqa: E402
from couplingTests import edit  # noqa: E402
_cwd = os.getcwd()
os.chdir(TUTORIAL)      # bedData reads the fluid and the beads' density where it is imported:
import bedData  # noqa: E402,I100   the same in every run (parcels keep the beads' density)
from weightShares import weight_shares  # noqa: E402
os.chdir(_cwd)

WORK = os.path.join(ROOT, "build", "coarseGrainedBed")
RESULTS = os.path.join(HERE, "results")
SETTLE = 0.4
U_BUBBLING = 1.0
RAMP_HOLD, RAMP_END = 0.3, 1.8
FIXED_BED_U = 0.35
# mm across x and y, beads, and cells of 3 mm (the tutorial's default) across x and y
BEDS = {"tutorial": dict(width=48, depth=6, count=10000, NX=16, NY=2),
        "wide": dict(width=96, depth=24, count=80000, NX=32, NY=8)}
MESH_Z = dict(NZ=40, NZP=2)
# --mesh bed: at least 12 cells across the settled bed's 42 mm (both beds' fine height)
BED_MIN_CELLS = "(z 12 0.042)"
# --mesh bedCo: scaleCase's Courant number on the coarse cells (the gas's speed bounded by the
# inlet's through the densest packing), by default
COURANT = 0.5
OUTPUTS = shutil.ignore_patterns("[1-9]*", "0.[0-9]*", "0", "postProcessing", "VTK", "log.*", "parcels_h*",
                                 "stress", "processor*", "*.png", "*.result", "post")


def shell(cmd, cwd, log=None):
    """foamCase.sh with the output kept in log"""
    rc, out = sh(cmd, cwd, check=False)
    if log:
        with open(log, "w") as f:
            f.write(out)
    if rc:
        raise RuntimeError("'%s' failed in %s%s" % (cmd, cwd, " (see %s)" % log if log else ""))


def run_name(model, h, law, ramp, mesh="fine"):
    return "%s_%s_h%g%s%s" % ("ramp" if ramp else "bubbling", model, h, "" if h == 1 else "_" + law,
                              "_" + mesh if h != 1 and mesh != "fine" else "")


def bed_dirs(bed, results):
    """(results, work) directories of a bed"""
    if bed == "tutorial":
        return results, WORK
    return os.path.join(results, bed), os.path.join(WORK, bed)


def vertices_of(template, width, depth):
    """the blockMeshDict template's vertices with x = 48 mm moved to width and y = 6 mm to depth"""
    head, rest = template.split("vertices", 1)
    body, tail = rest.split("blocks", 1)
    def move(m):
        x, y, z = m.groups()
        return "(%s %s %s)" % ("%g" % width if x == "48" else x, "%g" % depth if y == "6" else y, z)
    return head + "vertices" + re.sub(r"\((\S+) (\S+) (\S+)\)", move, body) + "blocks" + tail


def source_case(bed, work):
    """The fine system of a bed, meshed for cells of 3 mm: the tutorial, or
    the tutorial widened (box, beads, mesh) for the wide bed."""
    spec = BEDS[bed]
    src = os.path.join(work, "source")
    if os.path.isfile(os.path.join(src, "system", "blockMeshDict")):
        return src
    shutil.rmtree(src, ignore_errors=True)
    shutil.copytree(TUTORIAL, src, ignore=OUTPUTS)
    params = os.path.join(src, "DEM", "in.parameters")
    for name, value in (("width", spec["width"]*1e-3), ("depth", spec["depth"]*1e-3), ("count", spec["count"])):
        edit(params, r"^(variable\s+%s\s+equal\s+)\S+" % name, r"\g<1>%.12g" % value)
    template = vertices_of(open(os.path.join(src, "system", "blockMeshDict.template")).read(),
                           spec["width"], spec["depth"]).replace("48 x 6 mm", "%g x %g mm" % (spec["width"], spec["depth"]))
    counts = dict(MESH_Z, NX=spec["NX"], NY=spec["NY"])
    for key in sorted(counts, key=len, reverse=True):       # NZP before NZ
        template = template.replace(key, str(counts[key]))
    with open(os.path.join(src, "system", "blockMeshDict"), "w") as f:
        f.write(template)
    return src


def make_case(case, source, model, h, law, ramp, end, mesh, ranks):
    shutil.rmtree(case, ignore_errors=True)
    if h == 1:
        shutil.copytree(source, case, ignore=OUTPUTS)
    else:
        mesh_options = {"fine": " -keepMesh", "coarsened": " -relativeSmoothing",
                        "bed": " -minCells '%s'" % BED_MIN_CELLS}.get(mesh)
        if mesh.startswith("bedCo"):
            mesh_options = " -minCells '%s' -courant %s" % (BED_MIN_CELLS, mesh[len("bedCo"):])
        shell("scaleCase -factor %g -parcels %s%s -output %s -overwrite"
              % (h, law, mesh_options, case), source,
              os.path.join(os.path.dirname(case), "log.scaleCase." + os.path.basename(case)))
    os.makedirs(os.path.join(case, "DEM", "post"), exist_ok=True)
    edit(os.path.join(case, "constant", "couplingProperties"),
         r"^voidFractionModel(\s+)\w+;", r"voidFractionModel\g<1>%s;" % model)
    edit(os.path.join(case, "system", "controlDict"), r"^endTime(\s+)\S+;", r"endTime\g<1>%g;" % end)
    if ranks > 1:
        decompose = os.path.join(case, "system", "decomposeParDict")
        edit(decompose, r"^numberOfSubdomains .*;", "numberOfSubdomains %d;" % ranks)
        edit(decompose, r"n\s*\(\s*\d+ 1 1\s*\)", "n (%d 1 1)" % ranks)
    shell("rm -rf 0 && cp -r 0.orig 0 && blockMesh", case, os.path.join(case, "log.blockMesh"))
    if ramp:
        table = "table ( (0 (0 0 0)) (0.05 (0 0 %g)) (%g (0 0 %g)) (%g (0 0 0)) (100 (0 0 0)) )" \
            % (U_BUBBLING, RAMP_HOLD, U_BUBBLING, RAMP_END)
        edit(os.path.join(case, "0", "U"), r"uniformValue\s+table\s*\(.*\);", "uniformValue    %s;" % table)


def inlet_velocity(t):
    if t <= RAMP_HOLD:
        return U_BUBBLING
    return max(0.0, U_BUBBLING * (RAMP_END - t) / (RAMP_END - RAMP_HOLD))


def pack(case, ranks):
    mpi = "mpirun -np %d " % ranks if ranks > 1 else ""
    shell("cd DEM && %sliggghts -in in.packing -log post/log.packing -screen post/screen.packing" % mpi, case)


def solve(case, ranks):
    """pimpleDEMFoam with its progress printed; the fluid fraction reconstructed after a parallel run"""
    command = ["mpirun", "-np", str(ranks), "pimpleDEMFoam", "-parallel"] if ranks > 1 else ["pimpleDEMFoam"]
    if ranks > 1:
        shell("decomposePar -force", case, os.path.join(case, "log.decomposePar"))
    rc = subprocess.call([os.path.join(ROOT, "etc", "runWithProgress"), "log.pimpleDEMFoam"] + command, cwd=case)
    if rc:
        raise RuntimeError("pimpleDEMFoam failed in %s (see log.pimpleDEMFoam)" % case)
    if ranks > 1:
        shell("reconstructPar -fields '(alpha)'", case, os.path.join(case, "log.reconstructPar"))


def run_one(model, h, law, ramp, end, results, bed="tutorial", mesh="fine", ranks=1, store="runs"):
    results, work = bed_dirs(bed, results)
    name = run_name(model, h, law, ramp, mesh)
    case = os.path.join(work, name if store == "runs" else store + "_" + name)
    source = source_case(bed, work)
    make_case(case, source, model, h, law, ramp, end, mesh, ranks)
    if h == 1:
        # the fine bed packed once, in the source, and reused by every model
        if not os.path.isfile(os.path.join(source, "DEM", "post", "packed.restart")):
            os.makedirs(os.path.join(source, "DEM", "post"), exist_ok=True)
            pack(source, ranks)
        shutil.copy(os.path.join(source, "DEM", "post", "packed.restart"), os.path.join(case, "DEM", "post"))
    else:
        pack(case, ranks)
    print("  %s (%s bed, %d rank%s): %g s" % (name, bed, ranks, "s" if ranks > 1 else "", end), flush=True)
    start = time.time()
    solve(case, ranks)
    wall = time.time() - start
    result = dict(name=name, model=model, h=h, law=law if h != 1 else "fine", ramp=ramp, bed=bed,
                  mesh=mesh if h != 1 else "fine", ranks=ranks, end=end, wall_per_s=wall / end)
    result.update(analyse_ramp(case) if ramp else analyse_bubbling(case))
    result["stages"] = stage_seconds(case, end)
    result["deltaT"] = float(re.search(r"(?m)^deltaT\s+(\S+);",
                                       open(os.path.join(case, "system", "controlDict")).read()).group(1))
    os.makedirs(os.path.join(results, store), exist_ok=True)
    with open(os.path.join(results, store, name + ".json"), "w") as f:
        json.dump(result, f, indent=1)
    return result


STAGES = ("DEM", "exchange", "voidFraction", "forces", "fluid")


def stage_seconds(case, end):
    """wall seconds per simulated second of each stage the solver's coupling
    lines time, and of the coupling loop as a whole ("coupling")"""
    pattern = re.compile(r"seconds " + " ".join(r"%s (\S+)" % s for s in STAGES)
                         + r";.*wall seconds since the last coupling (\S+)")
    sums = [0.0] * (len(STAGES) + 1)
    with open(os.path.join(case, "log.pimpleDEMFoam"), errors="replace") as f:
        for line in f:
            m = pattern.search(line)
            if m:
                sums = [a + float(b) for a, b in zip(sums, m.groups())]
    return dict(zip(STAGES + ("coupling",), (x / end for x in sums)))


def analyse_bubbling(case):
    weight = bedData.bed_weight(case)
    t, dp = bedData.pressure_drop(case)
    settled = [p for s, p in zip(t, dp) if s > SETTLE]
    mean = sum(settled) / len(settled)
    fluct = math.sqrt(sum((p - mean) ** 2 for p in settled) / len(settled)) / mean
    heights = []
    dt = float(re.search(r"(?m)^deltaT\s+(\S+);", open(os.path.join(case, "system", "controlDict")).read()).group(1))
    for path in bedData.snapshots(case):
        step = bedData.step(path)
        if step * dt > SETTLE:
            x, r, _ = bedData.read_vtk(path)
            heights.append(volume_quantile(x[:, 2], r ** 3, 0.95))
    z, alpha = alpha_profile(case)
    half = len(settled) // 2
    shares = weight_shares(case, SETTLE)
    if shares:
        extra = dict(fluid_share=shares[0], distributor_share=shares[1], walls_share=shares[2])
    else:
        extra = {}
    return dict(extra, weight=weight, dp_mean=mean, dp_error=mean / weight - 1, dp_fluctuation=fluct,
                dp_halves=[sum(settled[:half]) / half / weight - 1,
                           sum(settled[half:]) / (len(settled) - half) / weight - 1],
                bed_height=sum(heights) / len(heights) if heights else float("nan"),
                profile_z=z, profile_alpha=alpha)


def volume_quantile(z, volume, q):
    order = sorted(range(len(z)), key=lambda i: z[i])
    total, acc = float(sum(volume)), 0.0
    for i in order:
        acc += volume[i]
        if acc >= q * total:
            return float(z[i])
    return float(z[order[-1]])


def alpha_profile(case):
    """z of each cell layer (bed region) and the fluid fraction averaged over
    x, y and the written times after SETTLE"""
    centres = cell_centres(case)
    layers = sorted({round(c[2], 9) for c in centres if c[2] > 0})
    index = {z: k for k, z in enumerate(layers)}
    sums, count = [0.0] * len(layers), [0] * len(layers)
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.]+", d) and float(d) > SETTLE
             and os.path.isfile(os.path.join(case, d, "alpha"))]
    for d in times:
        for c, a in zip(centres, read_scalar_field(os.path.join(case, d, "alpha"))):
            k = index.get(round(c[2], 9))
            if k is not None:
                sums[k] += a
                count[k] += 1
    return layers, [s / n if n else float("nan") for s, n in zip(sums, count)]


def analyse_ramp(case):
    weight = bedData.bed_weight(case)
    t, dp = bedData.pressure_drop(case)
    fixed = [(inlet_velocity(s), p) for s, p in zip(t, dp)
             if s > RAMP_HOLD and 0.02 < inlet_velocity(s) < FIXED_BED_U]
    # least squares dp = a U + b U^2 (Ergun's form through the origin)
    s11 = sum(u ** 2 for u, _ in fixed)
    s12 = sum(u ** 3 for u, _ in fixed)
    s22 = sum(u ** 4 for u, _ in fixed)
    r1 = sum(u * p for u, p in fixed)
    r2 = sum(u ** 2 * p for u, p in fixed)
    det = s11 * s22 - s12 ** 2
    a, b = (r1 * s22 - r2 * s12) / det, (s11 * r2 - s12 * r1) / det
    umf = (-a + math.sqrt(a * a + 4 * b * weight)) / (2 * b) if b > 0 else weight / a
    return dict(weight=weight, umf=umf, ergun_a=a, ergun_b=b,
                curve=[(inlet_velocity(s), p) for s, p in zip(t, dp) if s > RAMP_HOLD][::10])


def wen_yu_umf():
    import caseProperties
    _, rho, mu = caseProperties.fluid(TUTORIAL)
    d = caseProperties.particle_diameter(TUTORIAL)
    rho_p, g = caseProperties.particle_density(TUTORIAL), caseProperties.gravity(TUTORIAL)
    ar = d ** 3 * rho * (rho_p - rho) * g / mu ** 2
    re_mf = math.sqrt(33.7 ** 2 + 0.0408 * ar) - 33.7
    return re_mf * mu / (rho * d)


def finished(results, store="runs"):
    runs = os.path.join(results, store)
    if not os.path.isdir(runs):
        return {}
    return {f[:-5]: json.load(open(os.path.join(runs, f))) for f in sorted(os.listdir(runs))
            if f.endswith(".json")}


def profile_difference(run, fine):
    """mean |alpha - alpha_fine| over the fine bed's layers below 1.2 x its
    bed height, the run's profile interpolated linearly to them"""
    top = 1.2 * fine["bed_height"]
    pairs = [(float(np.interp(z, run["profile_z"], run["profile_alpha"])), b)
             for z, b in zip(fine["profile_z"], fine["profile_alpha"]) if z < top]
    return sum(abs(a - b) for a, b in pairs) / len(pairs)


def compare(runs, umf_ref):
    """a row per run with its differences from the fine run of its model"""
    rows = []
    nan = float("nan")
    for r in runs.values():
        fine = runs.get(run_name(r["model"], 1, "", r["ramp"]))
        row = dict(model=r["model"], h=r["h"], law=r["law"], mesh=r.get("mesh", "fine"),
                   test="ramp" if r["ramp"] else "bubbling", wall_per_s=r["wall_per_s"],
                   speedup=fine["wall_per_s"] / r["wall_per_s"] if fine else nan)
        if r["ramp"]:
            row.update(umf=r["umf"], umf_vs_fine=r["umf"] / fine["umf"] - 1 if fine else nan,
                       umf_vs_wen_yu=r["umf"] / umf_ref - 1)
        else:
            row.update(dp_error=r["dp_error"], dp_halves=r.get("dp_halves"), dp_vs_fine=r["dp_mean"] / fine["dp_mean"] - 1 if fine else nan,
                       dp_fluctuation=r["dp_fluctuation"], bed_height=r["bed_height"],
                       bed_height_vs_fine=r["bed_height"] / fine["bed_height"] - 1 if fine else nan,
                       alpha_difference=profile_difference(r, fine) if fine else nan)
        rows.append(row)
    rows.sort(key=lambda x: (x["test"], x["model"], x["h"], x["law"], x["mesh"]))
    return rows


SUMMARY = ("model", "h", "law", "mesh", "dp_vs_fine", "umf_vs_fine", "bed_height_vs_fine", "profile_mad_vs_fine",
           "speedup", "bed")


def summary_rows(rows, bed):
    """results/summary.csv's rows of a bed: each coarse bubbling run with the
    Umf of the ramp run of the same model, h, law and mesh"""
    key = lambda r: (r["model"], r["h"], r["law"], r["mesh"])
    umf = {key(r): r["umf_vs_fine"] for r in rows if r["test"] == "ramp"}
    out = []
    for r in rows:
        if r["test"] == "bubbling" and r["h"] != 1:
            out.append((r["model"], "%g" % r["h"], r["law"], r["mesh"], "%.4f" % r["dp_vs_fine"],
                        "%.4f" % umf.get(key(r), float("nan")), "%.4f" % r["bed_height_vs_fine"],
                        "%.4f" % r["alpha_difference"], "%.2f" % r["speedup"], bed))
    return out


def report(results):
    umf_ref = wen_yu_umf()
    summary = []
    for bed in BEDS:
        where, _ = bed_dirs(bed, results)
        runs = finished(where)
        if not runs:
            continue
        rows = compare(runs, umf_ref)
        write_table(rows, umf_ref, where)
        plot(runs, umf_ref, where)
        summary += summary_rows(rows, bed)
        write_shares(finished(where, "shares"), where)
        write_profile(finished(where, "profile"), where)
    if not summary:
        sys.exit("study.py: no finished runs in %s" % os.path.join(results, "runs"))
    with open(os.path.join(results, "summary.csv"), "w") as f:
        f.write(",".join(SUMMARY) + "\n")
        for row in summary:
            f.write(",".join(row) + "\n")


def table_text(rows, umf_ref):
    """table.md of a bed: its bubbling runs, then its ramp runs"""
    lines = ["| model | h | law | mesh | dp / bed weight - 1 (halves) | dp vs fine | fluctuation | bed height (mm) "
             "| mean abs. alpha vs fine | s per simulated s | speed-up |", "|---" * 11 + "|"]
    for r in (x for x in rows if x["test"] == "bubbling"):
        halves = " (%+.1f, %+.1f)" % tuple(100 * x for x in r["dp_halves"]) if r["dp_halves"] else ""
        lines.append("| %s | %g | %s | %s | %+.1f %%%s | %+.1f %% | %.1f %% | %.1f | %.4f | %.0f | %.1f |"
                     % (r["model"], r["h"], r["law"], r["mesh"], 100 * r["dp_error"], halves, 100 * r["dp_vs_fine"],
                        100 * r["dp_fluctuation"], 1e3 * r["bed_height"], r["alpha_difference"],
                        r["wall_per_s"], r["speedup"]))
    ramp = [x for x in rows if x["test"] == "ramp"]
    if ramp:
        lines += ["", "Wen-Yu: Umf = %.3f m/s" % umf_ref, "",
                  "| model | h | law | mesh | Umf (m/s) | vs fine | vs Wen-Yu | s per simulated s | speed-up |",
                  "|---" * 9 + "|"]
        for r in ramp:
            vs_fine = "%+.1f %%" % (100 * r["umf_vs_fine"]) if r["umf_vs_fine"] == r["umf_vs_fine"] else "no fine run"
            speedup = "%.1f" % r["speedup"] if r["speedup"] == r["speedup"] else "no fine run"
            lines.append("| %s | %g | %s | %s | %.3f | %s | %+.1f %% | %.0f | %s |"
                         % (r["model"], r["h"], r["law"], r["mesh"], r["umf"], vs_fine,
                            100 * r["umf_vs_wen_yu"], r["wall_per_s"], speedup))
    return "\n".join(lines + verdict_lines(rows)) + "\n"


AIM_DP, AIM_UMF = 0.05, 0.10    # the pressure drop and Umf against the fine bed's


def verdict_lines(rows):
    """Which h holds, per model and coarse mesh: the cubic parcels' bubbling
    speed-up and pressure drop and their ramp's Umf, each against the fine
    bed's, and whether both are within AIM_DP and AIM_UMF."""
    key = lambda r: (r["model"], r["mesh"], r["h"])
    cubic = [r for r in rows if r["law"] == "cubic" and r["mesh"] != "fine"]
    bubbling = {key(r): r for r in cubic if r["test"] == "bubbling"}
    umf = {key(r): r["umf_vs_fine"] for r in cubic if r["test"] == "ramp"}
    factors = sorted({k[2] for k in bubbling if k in umf})
    if not factors:
        return []
    lines = ["", "Against the aim of the pressure drop within %g %% and Umf within %g %% of the fine bed's "
             "(speed-ups from the bubbling runs):" % (100 * AIM_DP, 100 * AIM_UMF), "",
             "| model | mesh | " + " | ".join("h = %g" % h for h in factors) + " |", "|---" * (2 + len(factors)) + "|"]
    for model, mesh in sorted({k[:2] for k in bubbling}, key=lambda k: (k[1] != "coarsened", k)):
        cells = []
        for h in factors:
            r, u = bubbling.get((model, mesh, h)), umf.get((model, mesh, h))
            if r is None or u is None:
                cells.append("")
                continue
            dp_ok, umf_ok = abs(r["dp_vs_fine"]) <= AIM_DP, abs(u) <= AIM_UMF
            word = "holds" if dp_ok and umf_ok else "dp misses" if umf_ok else "Umf misses" if dp_ok else "no"
            cells.append("%s: %s×, dp %+.1f %%, Umf %+.1f %%" % (word, ("%.0f" if r["speedup"] >= 10 else "%.1f")
                                                              % r["speedup"], 100 * r["dp_vs_fine"], 100 * u))
        lines.append("| `%s` | %s | %s |" % (model, mesh, " | ".join(cells)))
    return lines


def write_shares(runs, where):
    """shares.md of a bed: where its weight rests in the runs made for it (--shares)"""
    if runs:
        with open(os.path.join(where, "shares.md"), "w") as f:
            f.write(shares_text(runs))


def write_profile(runs, where):
    """profile.md of a bed: where the time of its --profile runs goes"""
    if runs:
        with open(os.path.join(where, "profile.md"), "w") as f:
            f.write(profile_text(runs))


def profile_text(runs):
    """per run: the fluid step, the wall seconds per simulated second and the
    share of each stage in them (the rest: start-up, output, Info)"""
    lines = ["| model | h | mesh | fluid step (s) | s per simulated s | " + " | ".join(STAGES)
             + " | rest | speed-up vs bed |", "|---" * (6 + len(STAGES)) + "|"]
    base = {(r["model"], r["h"]): r["wall_per_s"] for r in runs.values() if r["mesh"] == "bed"}
    for r in sorted(runs.values(), key=lambda r: (r["model"], r["h"], r["deltaT"])):
        st = r["stages"]
        shares = ["%.0f %%" % (100 * st[s] / r["wall_per_s"]) for s in STAGES]
        rest = 1 - sum(st[s] for s in STAGES) / r["wall_per_s"]
        ref = base.get((r["model"], r["h"]))
        lines.append("| %s | %g | %s | %g | %.1f | %s | %.0f %% | %s |"
                     % (r["model"], r["h"], r["mesh"], r["deltaT"], r["wall_per_s"], " | ".join(shares),
                        100 * rest, "%.2f" % (ref / r["wall_per_s"]) if ref else ""))
    return "\n".join(lines) + "\n"


def shares_text(runs):
    lines = ["| model | h | mesh | gas (solver's force) | distributor (contacts) | side walls (contacts) | sum "
             "| dp / bed weight |", "|---" * 8 + "|"]
    for r in sorted(runs.values(), key=lambda r: (r["model"], r["h"], r["mesh"])):
        total = r["fluid_share"] + r["distributor_share"] + r["walls_share"]
        lines.append("| %s | %g | %s | %.3f | %.3f | %.3f | %.3f | %.3f |"
                     % (r["model"], r["h"], r["mesh"], r["fluid_share"], r["distributor_share"],
                        r["walls_share"], total, 1 + r["dp_error"]))
    return "\n".join(lines) + "\n"


def write_table(rows, umf_ref, where):
    text = table_text(rows, umf_ref)
    with open(os.path.join(where, "table.md"), "w") as f:
        f.write(text)
    print(text)


def label(r):
    if r["h"] == 1:
        return "fine"
    mesh = {"coarsened": "coarsened", "bed": "bed's cells"}.get(r.get("mesh"), "fine mesh")
    if r.get("mesh", "").startswith("bedCo"):
        mesh = "bed's cells, Co %s" % r["mesh"][len("bedCo"):]
    return "h = %g %s, %s" % (r["h"], r["law"], mesh)


def plot_per_model(runs, draw):
    """One panel per model, its runs in the order of h; draw(ax, run, style) adds one curve."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    models = sorted({r["model"] for r in runs})
    if not models:
        return None
    fig, axes = plt.subplots(1, len(models), figsize=(4 * len(models), 4), squeeze=False)
    for ax, m in zip(axes[0], models):
        for r in sorted((r for r in runs if r["model"] == m),
                        key=lambda r: (r["h"], r["law"], r.get("mesh", "fine"))):
            fine = r["h"] == 1
            draw(ax, r, dict(color="k" if fine else None, lw=2 if fine else 1, label=label(r)))
        ax.set_title(m)
    return fig, axes[0]


def plot(runs, umf_ref, where):
    def profile(ax, r, style):
        ax.plot(r["profile_alpha"], [1e3 * z for z in r["profile_z"]], **style)
        ax.set_xlabel("time-averaged fluid fraction")
        ax.set_ylabel("height (mm)")

    def ramp(ax, r, style):
        u, p = zip(*r["curve"])
        ax.plot(u, [x / r["weight"] for x in p], **dict(style, lw=0.6 * style["lw"]))
        ax.set_xlabel("inlet velocity (m/s)")
        ax.set_ylabel("pressure drop / bed weight per area")

    for ramps, draw, name in ((False, profile, "profiles.png"), (True, ramp, "ramp.png")):
        made = plot_per_model([r for r in runs.values() if r["ramp"] == ramps], draw)
        if made is None:
            continue
        fig, axes = made
        for ax in axes:
            if ramps:
                ax.axvline(umf_ref, color="k", ls="--", lw=1, label="Wen-Yu Umf")
            ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(where, name), dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bed", choices=sorted(BEDS), default="tutorial")
    p.add_argument("--mesh", choices=("fine", "coarsened", "bed", "bedCo"), default="fine",
                   help="the coarse runs on the fine bed's mesh (-keepMesh), on the mesh coarsened by h with "
                   "the smoothing relative to the cells, or (bed) coarsened by at most h keeping "
                   + BED_MIN_CELLS + " and the smoothing in metres, bedCo: as bed with the steps by -courant (--courant)")
    p.add_argument("--courant", type=float, default=COURANT, help="the Courant number of --mesh bedCo")
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--models", default="analytical,kernel,centroid")
    p.add_argument("--factors", default="1,1.5,2,3")
    p.add_argument("--laws", default="cubic,exact")
    p.add_argument("--end", type=float, default=2.0)
    p.add_argument("--ramp", action="store_true")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--profile", action="store_true",
                   help="bubbling runs apart from the table's (results/<bed>/profile/), one after another, for "
                   "where the time goes (profile.md)")
    p.add_argument("--shares", action="store_true",
                   help="bubbling runs apart from the table's (results/<bed>/shares/) for where the weight rests: "
                   "the gas, the distributor and the side walls (shares.md)")
    p.add_argument("--report", action="store_true")
    p.add_argument("--results", default=RESULTS)
    a = p.parse_args()
    if a.report:
        report(a.results)
        return
    factors = [float(x) for x in a.factors.split(",")]
    if any(not h >= 1 for h in factors):
        sys.exit("study.py: factors must be >= 1")
    if a.ranks < 1 or a.jobs < 1:
        sys.exit("study.py: --ranks and --jobs must be at least 1")
    end = RAMP_END if a.ramp else a.end
    if not end > SETTLE:
        sys.exit("study.py: --end must exceed the start-up of %g s that the averages leave out" % SETTLE)
    if a.mesh == "bedCo":
        if not 0 < a.courant <= 1:
            sys.exit("study.py: --courant must lie in (0, 1]")
        a.mesh = "bedCo%g" % a.courant
    where, work = bed_dirs(a.bed, a.results)
    store = "shares" if a.shares else "profile" if a.profile else "runs"
    if (a.shares or a.profile) and a.ramp:
        sys.exit("study.py: --shares and --profile record bubbling runs, not a ramp")
    if a.shares and a.profile:
        sys.exit("study.py: --shares or --profile, not both")
    done = finished(where, store)
    todo = []
    for model in a.models.split(","):
        for h in factors:
            for law in (a.laws.split(",") if h != 1 else ["fine"]):
                if run_name(model, h, law, a.ramp, a.mesh) not in done:
                    todo.append((model, h, law))
    os.makedirs(work, exist_ok=True)
    print("coarse-grained bed (%s, %s mesh, %d rank%s): %d runs to do (%s s each)"
          % (a.bed, a.mesh, a.ranks, "s" if a.ranks > 1 else "", len(todo), end), flush=True)
    start = time.time()
    with ProcessPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_one, m, h, law, a.ramp, end, a.results, a.bed, a.mesh, a.ranks, store): (m, h, law)
                   for m, h, law in todo}
        for n, fut in enumerate(as_completed(futures), 1):
            m, h, law = futures[fut]
            try:
                r = fut.result()
                what = ("Umf %.3f m/s" % r["umf"]) if a.ramp else \
                    ("dp %+.1f %% of the bed weight" % (100 * r["dp_error"]))
            except RuntimeError as e:
                what = "failed: %s" % e
            elapsed = time.time() - start
            print("  [%d/%d] %s h %g %s: %s (elapsed %.0f s, about %.0f s left)"
                  % (n, len(todo), m, h, law, what, elapsed, elapsed / n * (len(todo) - n)),
                  flush=True)
    report(a.results)


if __name__ == "__main__":
    main()
