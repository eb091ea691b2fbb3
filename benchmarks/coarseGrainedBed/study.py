#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The coarse-grained bubbling bed against the fine one.

The fine system is tutorials/fluidisedBed (10,000 glass beads of 1 mm in
air, a 48 x 6 mm slice periodic in x and y, cells of 3 mm, inlet 1 m/s).
Each coarse system is `scaleCase -factor h -parcels <law> -keepMesh` of it: parcels of
h^3 beads on the same mesh, the drag scaled by h^3 (cubic) or h^2 (exact).
Each run packs its bed with LIGGGHTS, runs pimpleDEMFoam serially and
records:
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
Each finished run writes <name>.json in results/runs/ and is not run again
(the study resumes); --report writes the table (results/table.md) and the plots (profiles.png, ramp.png).

usage: study.py [--models analytical,kernel,centroid] [--factors 1,1.5,2,3]
                [--laws cubic,exact] [--end 2.0] [--ramp] [--jobs 2]
                [--report] [--results DIR]
"""
import argparse
import json
import math
import os
import re
import shutil
import sys
import time
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
os.chdir(_cwd)

WORK = os.path.join(ROOT, "build", "coarseGrainedBed")
RESULTS = os.path.join(HERE, "results")
SETTLE = 0.4
U_BUBBLING = 1.0
RAMP_HOLD, RAMP_END = 0.3, 1.8
FIXED_BED_U = 0.35
MESH = dict(NX=16, NY=2, NZ=40, NZP=2)      # cells of 3 mm, as the tutorial's default


def shell(cmd, cwd, log=None):
    """foamCase.sh with the output kept in log"""
    rc, out = sh(cmd, cwd, check=False)
    if log:
        with open(log, "w") as f:
            f.write(out)
    if rc:
        raise RuntimeError("'%s' failed in %s%s" % (cmd, cwd, " (see %s)" % log if log else ""))


def run_name(model, h, law, ramp):
    return "%s_%s_h%g%s" % ("ramp" if ramp else "bubbling", model, h, "" if h == 1 else "_" + law)


def make_case(case, model, h, law, ramp, end):
    shutil.rmtree(case, ignore_errors=True)
    if h == 1:
        shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns(
            "[1-9]*", "0.[0-9]*", "0", "postProcessing", "VTK", "log.*", "parcels_h*", "stress",
            "processor*", "*.png", "*.result", "post"))
    else:
        shell("scaleCase -factor %g -parcels %s -keepMesh -output %s -overwrite" % (h, law, case), TUTORIAL,
              os.path.join(WORK, "log.scaleCase." + os.path.basename(case)))
    os.makedirs(os.path.join(case, "DEM", "post"), exist_ok=True)
    sed = "; ".join("s/%s/%d/g" % (k, v) for k, v in sorted(MESH.items(), key=lambda kv: -len(kv[0])))
    shell("sed -e '%s' system/blockMeshDict.template > system/blockMeshDict" % sed, case)
    edit(os.path.join(case, "constant", "couplingProperties"),
         r"^voidFractionModel(\s+)\w+;", r"voidFractionModel\g<1>%s;" % model)
    edit(os.path.join(case, "system", "controlDict"), r"^endTime(\s+)\S+;", r"endTime\g<1>%g;" % end)
    shell("rm -rf 0 && cp -r 0.orig 0 && blockMesh", case, os.path.join(case, "log.blockMesh"))
    if ramp:
        table = "table ( (0 (0 0 0)) (0.05 (0 0 %g)) (%g (0 0 %g)) (%g (0 0 0)) (100 (0 0 0)) )" \
            % (U_BUBBLING, RAMP_HOLD, U_BUBBLING, RAMP_END)
        edit(os.path.join(case, "0", "U"), r"uniformValue\s+table\s*\(.*\);", "uniformValue    %s;" % table)


def inlet_velocity(t):
    if t <= RAMP_HOLD:
        return U_BUBBLING
    return max(0.0, U_BUBBLING * (RAMP_END - t) / (RAMP_END - RAMP_HOLD))


def run_one(model, h, law, ramp, end, results):
    global RESULTS
    RESULTS = results
    name = run_name(model, h, law, ramp)
    case = os.path.join(WORK, name)
    make_case(case, model, h, law, ramp, end)
    shell("cd DEM && liggghts -in in.packing -log post/log.packing -screen post/screen.packing", case)
    start = time.time()
    shell("pimpleDEMFoam", case, os.path.join(case, "log.pimpleDEMFoam"))
    wall = time.time() - start
    result = dict(name=name, model=model, h=h, law=law if h != 1 else "fine", ramp=ramp,
                  end=end, wall_per_s=wall / end)
    result.update(analyse_ramp(case) if ramp else analyse_bubbling(case))
    os.makedirs(os.path.join(RESULTS, "runs"), exist_ok=True)
    with open(os.path.join(RESULTS, "runs", name + ".json"), "w") as f:
        json.dump(result, f, indent=1)
    return result


def analyse_bubbling(case):
    weight = bedData.bed_weight(case)
    t, dp = bedData.pressure_drop(case)
    settled = [p for s, p in zip(t, dp) if s > SETTLE]
    mean = sum(settled) / len(settled)
    fluct = math.sqrt(sum((p - mean) ** 2 for p in settled) / len(settled)) / mean
    heights = []
    for path in bedData.snapshots(case):
        step = int(re.findall(r"_(\d+)\.vtk", path)[0])
        if step * 1e-4 > SETTLE:
            x, r, _ = bedData.read_vtk(path)
            heights.append(volume_quantile(x[:, 2], r ** 3, 0.95))
    z, alpha = alpha_profile(case)
    return dict(weight=weight, dp_mean=mean, dp_error=mean / weight - 1, dp_fluctuation=fluct,
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


def finished():
    runs = os.path.join(RESULTS, "runs")
    if not os.path.isdir(runs):
        return {}
    return {f[:-5]: json.load(open(os.path.join(runs, f))) for f in sorted(os.listdir(runs))
            if f.endswith(".json")}


def profile_difference(run, fine):
    """mean |alpha - alpha_fine| over the layers below 1.2 x the fine bed height"""
    top = 1.2 * fine["bed_height"]
    pairs = [(a, b) for z, a, b in zip(run["profile_z"], run["profile_alpha"], fine["profile_alpha"])
             if z < top]
    return sum(abs(a - b) for a, b in pairs) / len(pairs)


def report():
    runs = finished()
    if not runs:
        sys.exit("study.py: no finished runs in %s" % os.path.join(RESULTS, "runs"))
    umf_ref = wen_yu_umf()
    rows = []
    for r in runs.values():
        fine = runs.get(run_name(r["model"], 1, "", r["ramp"]))
        row = dict(model=r["model"], h=r["h"], law=r["law"], test="ramp" if r["ramp"] else "bubbling",
                   wall_per_s=r["wall_per_s"],
                   speedup=fine["wall_per_s"] / r["wall_per_s"] if fine else float("nan"))
        if r["ramp"]:
            row.update(umf=r["umf"], umf_vs_fine=r["umf"] / fine["umf"] - 1 if fine else float("nan"),
                       umf_vs_wen_yu=r["umf"] / umf_ref - 1)
        else:
            row.update(dp_error=r["dp_error"], dp_vs_fine=r["dp_mean"] / fine["dp_mean"] - 1 if fine
                       else float("nan"), dp_fluctuation=r["dp_fluctuation"], bed_height=r["bed_height"],
                       alpha_difference=profile_difference(r, fine) if fine else float("nan"))
        rows.append(row)
    rows.sort(key=lambda x: (x["test"], x["model"], x["h"], x["law"]))
    write_table(rows, umf_ref)
    plot(runs, umf_ref)


def write_table(rows, umf_ref):
    lines = ["| model | h | law | dp / bed weight - 1 | dp vs fine | fluctuation | bed height (mm) "
             "| mean abs. alpha vs fine | s per simulated s | speed-up |", "|---" * 10 + "|"]
    for r in (x for x in rows if x["test"] == "bubbling"):
        lines.append("| %s | %g | %s | %+.1f %% | %+.1f %% | %.1f %% | %.1f | %.4f | %.0f | %.1f |"
                     % (r["model"], r["h"], r["law"], 100 * r["dp_error"], 100 * r["dp_vs_fine"],
                        100 * r["dp_fluctuation"], 1e3 * r["bed_height"], r["alpha_difference"],
                        r["wall_per_s"], r["speedup"]))
    ramp = [x for x in rows if x["test"] == "ramp"]
    if ramp:
        lines += ["", "Wen-Yu: Umf = %.3f m/s" % umf_ref, "",
                  "| model | h | law | Umf (m/s) | vs fine | vs Wen-Yu | s per simulated s | speed-up |",
                  "|---" * 8 + "|"]
        for r in ramp:
            lines.append("| %s | %g | %s | %.3f | %+.1f %% | %+.1f %% | %.0f | %.1f |"
                         % (r["model"], r["h"], r["law"], r["umf"], 100 * r["umf_vs_fine"],
                            100 * r["umf_vs_wen_yu"], r["wall_per_s"], r["speedup"]))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write(text)
    print(text)


def plot(runs, umf_ref):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    bubbling = [r for r in runs.values() if not r["ramp"]]
    models = sorted({r["model"] for r in bubbling})
    if models:
        fig, axes = plt.subplots(1, len(models), figsize=(4 * len(models), 4), squeeze=False)
        for ax, m in zip(axes[0], models):
            for r in sorted((r for r in bubbling if r["model"] == m), key=lambda r: (r["h"], r["law"])):
                label = "fine" if r["h"] == 1 else "h = %g %s" % (r["h"], r["law"])
                ax.plot(r["profile_alpha"], [1e3 * z for z in r["profile_z"]],
                        "k-" if r["h"] == 1 else "-", lw=2 if r["h"] == 1 else 1, label=label)
            ax.set_title(m)
            ax.set_xlabel("time-averaged fluid fraction")
            ax.set_ylabel("height (mm)")
            ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(RESULTS, "profiles.png"), dpi=110)
    ramp = [r for r in runs.values() if r["ramp"]]
    if ramp:
        fig, ax = plt.subplots(figsize=(5, 4))
        for r in sorted(ramp, key=lambda r: (r["model"], r["h"], r["law"])):
            u, p = zip(*r["curve"])
            label = "%s %s" % (r["model"], "fine" if r["h"] == 1 else "h = %g %s" % (r["h"], r["law"]))
            ax.plot(u, [x / r["weight"] for x in p], lw=0.8, label=label)
        ax.axvline(umf_ref, color="k", ls="--", lw=1, label="Wen-Yu Umf")
        ax.set_xlabel("inlet velocity (m/s)")
        ax.set_ylabel("pressure drop / bed weight per area")
        ax.legend(fontsize=6)
        fig.tight_layout()
        fig.savefig(os.path.join(RESULTS, "ramp.png"), dpi=110)


def main():
    global RESULTS
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--models", default="analytical,kernel,centroid")
    p.add_argument("--factors", default="1,1.5,2,3")
    p.add_argument("--laws", default="cubic,exact")
    p.add_argument("--end", type=float, default=2.0)
    p.add_argument("--ramp", action="store_true")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--report", action="store_true")
    p.add_argument("--results", default=RESULTS)
    a = p.parse_args()
    RESULTS = a.results
    if a.report:
        report()
        return
    factors = [float(x) for x in a.factors.split(",")]
    if any(h < 1 for h in factors):
        sys.exit("study.py: factors must be >= 1")
    end = RAMP_END if a.ramp else a.end
    if end <= SETTLE:
        sys.exit("study.py: --end must exceed the start-up of %g s that the averages leave out" % SETTLE)
    todo = []
    for model in a.models.split(","):
        for h in factors:
            for law in (a.laws.split(",") if h != 1 else ["fine"]):
                if run_name(model, h, law, a.ramp) not in finished():
                    todo.append((model, h, law))
    os.makedirs(WORK, exist_ok=True)
    print("coarse-grained bed: %d runs to do (%s s each)" % (len(todo), end), flush=True)
    start = time.time()
    with ProcessPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_one, m, h, law, a.ramp, end, RESULTS): (m, h, law) for m, h, law in todo}
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
    report()


if __name__ == "__main__":
    main()
