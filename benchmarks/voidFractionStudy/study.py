#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Run time against error and smoothness for the six void fraction models,
after Kalderon et al.'s calibration study (its sections 4 and 5).

1. LIGGGHTS makes Kalderon et al.'s samples L1.2a (8,262 frictionless spheres, size
   distribution uniform by number, d60/d10 = 1.2) and L3a (22,600, d60/d10 =
   3; full study only), in periodic cubes compressed to a solid fraction of
   0.62 (lengths x10 Kalderon et al.'s: the void fraction does not depend on scale).
2. For X = 2..6 (cell size X times the largest diameter) a periodic blockMesh
   cube; voidFractionBenchmark runs every model over its parameter (voxel
   sub-division, hybrid resolution, kernel b/ds, diffusion coefficient) and
   measures the error against analytical (Eq. 21), the smoothness (Eq. 22),
   conservation and the median time per call; X = 3 also on 2 MPI ranks
   (the periodic box split across a periodic direction).
2b. 2D: LIGGGHTS (dimension 2) packs 10,000 disks with radii from a Gaussian
   (mean 1.75, sd 0.375, truncated to [1, 2.5] mm, after Kalderon et al.'s sample
   10000gr12p5fb0a) in a periodic square to an area fraction of 0.82; a
   one-cell-thick periodic mesh with empty front and back, twoDimensional
   true, every model over its parameter around Kalderon et al.'s 2D calibrations.
3. Scale: 1,000 spheres of the same grading, then the periodic sample tiled
   k^3 times (8e3 to 1e6 particles), every model at its defaults, X = 3:
   time per particle against particle count.
4. Writes build/study/results.csv and the plots pareto.png, smoothness.png,
   optimalParameter.png, scaling.png; prints the README table for X = 3. A
   partial run (a flag below) starts from the committed results/results.csv
   when build/study has none. Copy results.csv and the plots to results/
   and run tables.py for docs/performance.md's tables.

1b. Friction (Kalderon et al.'s Table 4 b and c samples): L1.2b, L1.2c, L3b, L3c
   with friction 0.1 and 0.3, compressed at a constant strain rate until
   the pressure reaches P_STOP, so the friction sets the solid fraction
   (medium, loose); every model over its parameter at X = 2..6 (full study
   and --friction).

1c. Bimodal (Kalderon et al.'s Table 5): B2a to B2d (size ratio 2, fines 20 to 35 %
   by mass), B6a and B10a (ratio 6 and 10, fines 20 %), frictionless,
   compressed to P_STOP in boxes wide enough for two cells per side at X = 6
   (B2), three at X = 3 (B6), two at X = 2 (B10, Kalderon et al.'s box); every
   model over its parameter (full study and --bimodal).

1d. Cu = 6 (Kalderon et al.'s L6a, b, c): 59,183 spheres whose number fraction is
   linear in log d (sizes uniform by number cannot reach d60/d10 = 6),
   friction 0, 0.1, 0.3, compressed to P_STOP; every model over its
   parameter over X (full study and --cu6).

usage: study.py [--quick] [--l12a] [--2d] [--friction] [--bimodal] [--cu6] [--scale]
       --quick:    3 repeats instead of 10, tiles up to 3^3, no friction,
                   Cu = 6 or bimodal series; about a minute once the
                   packings exist
       --l12a:     only L1.2a over X and on 2 ranks (its rows replaced)
       --2d:       only the 2D disk sample (its rows in results.csv replaced)
       --friction: only the friction series (its rows replaced)
       --bimodal:  only the bimodal samples (their rows replaced)
       --cu6:      only the Cu = 6 samples (their rows replaced)
       --scale:    only the scale series (its rows replaced)
"""
import csv
import math
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests"))
from foamCase import ROOT, box_block_mesh, new_case, sh  # noqa: E402

QUICK = "--quick" in sys.argv
ONLY_2D = "--2d" in sys.argv
ONLY_SCALE = "--scale" in sys.argv
ONLY_L12A = "--l12a" in sys.argv
WORK = os.path.join(ROOT, "build", "study")
CSV = os.path.join(WORK, "results.csv")
COMMITTED = os.path.join(HERE, "results", "results.csv")
REPEAT = 3 if QUICK else 10
TILES = (1, 2, 3) if QUICK else (1, 2, 3, 4, 5)

PERIODIC = {a + b: "type cyclic; neighbourPatch %s%s;" % (a, "max" if b == "min" else "min")
            for a in "xyz" for b in ("min", "max")}

# model, parameter name in its Coeffs, values swept (first: the default)
SWEEPS = [
    ("centroid", None, [None]),
    ("voxel", "voxelsPerSide", [50, 20, 100]),
    ("hybrid", "subGridResolution", [20, 5, 10]),
    ("kernel", "bandwidthOverCellSize", [0.4, 0.2, 0.3, 0.5, 0.6, 0.8]),
    ("diffusion", "coefficient", [0.12, 0.03, 0.06, 0.2, 0.3, 0.5, 0.8, 1.2]),
]


# the sweeps of the 2D sample, from Kalderon et al.'s 2D calibration (first: our 2D default)
SWEEPS_2D = [
    ("centroid", None, [None]),
    ("voxel", "voxelsPerSide", [300, 100, 600]),
    ("hybrid", "subGridResolution", [50, 10, 20]),
    ("kernel", "bandwidthOverCellSize", [0.4, 0.2, 0.3, 0.6, 0.8, 1.0, 1.2, 1.5]),
    ("diffusion", "coefficient", [0.17, 0.06, 0.12, 0.3, 0.5, 0.8]),
]
DISKS = "G2D"

# the friction series: name, spheres, mean radius, d60/d10, friction; packed
# to the pressure P_STOP (Pa): frictionless, that gives the solid fraction
# 0.62 that L1.2a is compressed to
FRICTION_SAMPLES = [("L1.2b", 8262, 1.17e-3, 1.2, 0.1), ("L1.2c", 8262, 1.17e-3, 1.2, 0.3),
                    ("L3b", 22600, 1.48e-3, 3.0, 0.1), ("L3c", 22600, 1.48e-3, 3.0, 0.3)]
P_STOP = 100

# Kalderon et al.'s Cu = 6 samples (L6a, b, c: 59,183 spheres, friction 0, 0.1,
# 0.3): sizes uniform by number cannot reach d60/d10 = 6, a number fraction
# linear in log d can (d_max/d_min 23 with eight classes); smallest radius
# 1.5 mm, so the DEM step is a fifth of its Rayleigh time (at 0.5 mm
# LIGGGHTS lost spheres)
CU6_SAMPLES = [("L6a", 59183, 1.5e-3, 6.0, 0.0), ("L6b", 59183, 1.5e-3, 6.0, 0.1),
               ("L6c", 59183, 1.5e-3, 6.0, 0.3)]

# Kalderon et al.'s Table 5 bimodal samples: name, d_coarse/d_fine, fines content by
# mass, box width in coarse diameters, solid fraction expected. Kalderon et al.'s
# boxes are 4.3 to 4.9 coarse diameters wide (one or two cells at X >= 2);
# ours hold two cells or more at X = 6 (B2) and three at X = 3 (B6: fines
# are 54 per coarse sphere); B10a (250 fines per coarse sphere) keeps the
# Kalderon et al.'s 4.3 and so its two cells per side at X = 2 only. Kalderon et al.'s table
# fits these with d_coarse = 1 mm (its particle counts and mean diameters
# give solid fractions of 0.69 for B2a and 0.84 for B6a with the fines
# counted by mass, 0.55 and 0.31 by number).
BIMODAL_SAMPLES = [("B2a", 2, 0.20, 12, 0.66), ("B2b", 2, 0.25, 12, 0.66), ("B2c", 2, 0.30, 12, 0.66),
                   ("B2d", 2, 0.35, 12, 0.66), ("B6a", 6, 0.20, 9, 0.72), ("B10a", 10, 0.20, 4.3, 0.72)]
R_FINE = 1e-3


def log(msg):
    print("[study] " + msg, flush=True)


def make_packing(name, n, r_mean, cu, mu, phi=0.62, p_stop=0):
    """LIGGGHTS periodic packing, sizes uniform by number with d60/d10 = cu
    (eight equally numerous classes); returns (dump path, box side). With
    p_stop (Pa) the box shrinks until that pressure instead of to the solid
    fraction phi, so the friction sets the density."""
    dmin = 2 * r_mean / (1 + 0.5 * (cu - 1) / (0.6 - 0.1 * cu))
    spread = (cu - 1) / (0.6 - 0.1 * cu) * dmin
    radii = [0.5 * (dmin + (k + 0.5) / 8 * spread) for k in range(8)]
    log_name = "%d spheres, Cu %.1f, friction %.1f" % (n, cu, mu)
    return pack_classes(name, n, radii, [0.125] * 8, mu, phi, p_stop, log_name)


def pack_classes(name, n, radii, weights, mu, phi, p_stop, what, settle=0):
    """LIGGGHTS periodic packing of n spheres in eight size classes (radii,
    number fractions); returns (dump path, box side)."""
    out_dir = os.path.join(WORK, "packings")
    os.makedirs(out_dir, exist_ok=True)
    dump = os.path.join(out_dir, name + ".dump")
    v_mean = sum(w * 4 / 3 * math.pi * r ** 3 for r, w in zip(radii, weights))
    L0 = (n * v_mean / 0.2) ** (1 / 3)
    L1 = (n * v_mean / phi) ** (1 / 3)
    if not os.path.isfile(dump):
        log("LIGGGHTS: packing %s (%s%s)" % (name, what, ", to %g Pa" % p_stop if p_stop else ""))
        var = {"N": n, "L0": L0, "L1": L1, "mu": mu, "seed": 86028157, "out": dump,
               "skin": 0.3 * min(radii), "compressSteps": 20000, "relaxSteps": 10000,
               "pStop": p_stop, "rate": -0.5, "settle": settle}
        var.update({"r%d" % (k + 1): r for k, r in enumerate(radii)})
        var.update({"w%d" % (k + 1): w for k, w in enumerate(weights)})
        args = " ".join("-var %s %r" % (k, v) for k, v in var.items())
        sh("liggghts -in %s/in.periodicPacking %s -log %s.log -screen %s.screen"
           % (HERE, args, dump, dump), out_dir)
        kept = len(read_dump(dump)[1])
        if kept != n:
            os.rename(dump, dump + ".bad")
            sys.exit("%s: LIGGGHTS kept %d of %d spheres (time step too long for the smallest?); "
                     "see %s.screen" % (name, kept, n, dump))
    return dump, box_side(dump) if p_stop else L1


def make_log_packing(name, n, r_min, cu, mu):
    """LIGGGHTS periodic packing whose number fraction is linear in log d
    (eight equally numerous classes, d_max/d_min = cu^(7/4)): d60/d10 = cu
    for any cu, where sizes uniform by number reach 6 only as the smallest
    goes to zero. Compressed to P_STOP; returns (dump path, box side)."""
    radii = [r_min * cu ** (2 * k / 8) for k in range(8)]
    what = "%d spheres, Cu %g, number linear in log d, friction %.1f" % (n, cu, mu)
    # the largest spheres are 23 times the smallest: compressed at the
    # strain rate of the others they build a collisional pressure, so the
    # box is held 1000 steps whenever the pressure passes P_STOP
    return pack_classes(name, n, radii, [0.125] * 8, mu, 0.62, P_STOP, what, settle=1000)


def make_bimodal_packing(name, ratio, fines, width, phi):
    """Kalderon et al.'s Table 5 samples: coarse and fine spheres, size ratio
    d_coarse/d_fine, fines content by mass, frictionless, compressed to
    P_STOP in a box about width coarse diameters wide (phi: the solid
    fraction expected, for the particle count)."""
    fines_per_coarse = fines / (1 - fines) * ratio ** 3
    n_fine = fines_per_coarse / (1 + fines_per_coarse)
    r_coarse = ratio * R_FINE
    v_coarse = 4 / 3 * math.pi * r_coarse ** 3
    n_coarse = phi * (1 - fines) * (width * 2 * r_coarse) ** 3 / v_coarse
    n = round(n_coarse * (1 + fines_per_coarse))
    what = "%d spheres, d ratio %g, fines %d %% by mass" % (n, ratio, round(100 * fines))
    return pack_classes(name, n, [R_FINE] * 4 + [r_coarse] * 4,
                        [n_fine / 4] * 4 + [(1 - n_fine) / 4] * 4, 0.0, phi, P_STOP, what)


def box_side(dump):
    """Side of the (cubic) box of a LIGGGHTS text dump."""
    with open(dump) as f:
        lines = f.read(4096).splitlines()
    k = lines.index(next(l for l in lines if l.startswith("ITEM: BOX BOUNDS")))
    lo, hi = (float(v) for v in lines[k + 1].split()[:2])
    return hi - lo


def make_disk_packing(n=10000, phi=0.82, seed=5):
    """LIGGGHTS 2D periodic packing of Gaussian disks; returns (dump, side)."""
    import random
    out_dir = os.path.join(WORK, "packings")
    os.makedirs(out_dir, exist_ok=True)
    dump = os.path.join(out_dir, DISKS + ".dump")
    rng = random.Random(seed)
    radii = []
    while len(radii) < n:
        r = rng.gauss(1.75, 0.375)
        if 1 <= r <= 2.5:
            radii.append(r * 1e-3)
    area = sum(math.pi * r * r for r in radii)
    L0, L1 = math.sqrt(area / 0.3), math.sqrt(area / phi)
    if os.path.isfile(dump):
        return dump, L1
    log("LIGGGHTS: packing %s (%d disks, Gaussian radii)" % (DISKS, n))
    # loose start on a jittered grid whose pitch exceeds the largest diameter
    m = math.ceil(math.sqrt(n))
    pitch = L0 / m
    data = os.path.join(out_dir, DISKS + ".data")
    with open(data, "w") as f:
        f.write("disks\n\n%d atoms\n1 atom types\n\n0 %.17g xlo xhi\n0 %.17g ylo yhi\n"
                "-0.003 0.003 zlo zhi\n\nAtoms\n\n" % (n, L0, L0))
        for i, r in enumerate(radii):
            j = 0.45 * (pitch - 2 * r)
            x = ((i % m) + 0.5) * pitch + rng.uniform(-j, j)
            y = ((i // m) + 0.5) * pitch + rng.uniform(-j, j)
            f.write("%d 1 %.17g 2500 %.17g %.17g 0\n" % (i + 1, 2 * r, x, y))
    var = {"data": data, "L1": L1, "mu": 0.0, "skin": 3e-4, "compressSteps": 20000,
           "relaxSteps": 10000, "out": dump}
    args = " ".join("-var %s %s" % (k, v) for k, v in var.items())
    sh("liggghts -in %s/in.diskPacking %s -log %s.log -screen %s.screen" % (HERE, args, dump, dump), out_dir)
    return dump, L1


def read_dump(path):
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[start].split()[2:]
    rows = [[float(v) for v in l.split()] for l in lines[start + 1:] if l.strip()]
    ix, iy, iz, ir = (cols.index(c) for c in ("x", "y", "z", "radius"))
    return [(r[ix], r[iy], r[iz]) for r in rows], [r[ir] for r in rows]


def tile(dump, L, k):
    """The periodic sample repeated k times in each direction."""
    path = os.path.join(WORK, "packings", "tile%d.dump" % k)
    if os.path.isfile(path):
        return path
    centres, radii = read_dump(dump)
    with open(path, "w") as f:
        f.write("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\n" % (len(radii) * k ** 3))
        f.write("ITEM: BOX BOUNDS pp pp pp\n" + ("0 %.17g\n" % (k * L)) * 3)
        f.write("ITEM: ATOMS id x y z radius\n")
        n = 0
        for a in range(k):
            for b in range(k):
                for c in range(k):
                    for (x, y, z), r in zip(centres, radii):
                        n += 1
                        f.write("%d %.17g %.17g %.17g %.17g\n" % (n, x % L + a * L, y % L + b * L, z % L + c * L, r))
    return path


def bench_dict(runs, csv=None, repeat=None):
    body = "FoamFile { version 2.0; format ascii; class dictionary; object voidFractionBenchmarkDict; }\n"
    body += "reference { voidFractionModel analytical; }\nrepeat %d;\ncsv \"%s\";\nruns\n{\n" % (
        repeat or REPEAT, csv or CSV)
    for label, model, key, value in runs:
        coeffs = "%sCoeffs { %s %s; }" % (model, key, value) if key else ""
        body += "    %s { voidFractionModel %s; %s parameter %s; }\n" % (label, model, coeffs, value or 0)
    return body + "}\n"


def run_case(name, dump, L, X, r_max, runs, nprocs=1, sample=None, two_d=False, csv=None, repeat=None):
    """Run voidFractionBenchmark on a periodic box of cells X diameters wide;
    rows are appended to csv (default: the study's), each time the median of
    repeat calls (default: the study's)."""
    n = max(1, round(L / (X * 2 * r_max)))
    if two_d:
        # one cell thick, the disks on its mid-plane z = 0
        patches = {k: v for k, v in PERIODIC.items() if k[0] != "z"}
        patches.update(zmin="type empty;", zmax="type empty;")
        mesh = box_block_mesh((0, 0, -r_max), (L, L, r_max), (n, n, 1), patches=patches)
    else:
        mesh = box_block_mesh((0, 0, 0), (L, L, L), (n, n, n), patches=PERIODIC)
    case = new_case(os.path.join(WORK, name), mesh, coupling="voidFractionModel analytical;\nalphaMin 0;\n"
                    + ("twoDimensional true;\n" if two_d else ""))
    with open(os.path.join(case, "system", "voidFractionBenchmarkDict"), "w") as f:
        f.write(bench_dict(runs, csv, repeat))
    sample = sample or os.path.basename(dump)[:-5]
    if nprocs == 1:
        sh("voidFractionBenchmark -dump %s -sample %s" % (dump, sample), case)
    else:
        sh("decomposePar -force && mpirun -np %d voidFractionBenchmark -parallel -dump %s -sample %s"
           % (nprocs, dump, sample), case)


def sweep_runs(sweeps=SWEEPS):
    runs = []
    for model, key, values in sweeps:
        for v in values:
            runs.append(("%s_%s" % (model, v) if key else model, model, key, v))
    return runs


def disk_study():
    dump, L = make_disk_packing()
    centres, radii = read_dump(dump)
    r_max = max(radii)
    phi = sum(math.pi * r * r for r in radii) / L ** 2
    log("%s: %d disks, area fraction %.3f" % (DISKS, len(radii), phi))
    sweep_X(DISKS, dump, L, r_max, SWEEPS_2D, two_d=True)


def sweep_X(name, dump, L, r_max, sweeps, two_d=False):
    """Every model over its parameter at X = 2..6 as Kalderon et al.; a sample is
    only so many diameters wide, so cells per side are whole numbers and X
    lands near the target."""
    done = set()
    for X in (2, 2.5, 3, 4, 5, 6):
        n = round(L / (X * 2 * r_max))
        if n in done or n < 2:
            continue
        done.add(n)
        log("%s, X = %.2f (%d^%d cells): every model over its parameter"
            % (name, L / n / (2 * r_max), n, 2 if two_d else 3))
        run_case("%s-X%g" % (name, X), dump, L, X, r_max, sweep_runs(sweeps), two_d=two_d)


def sphere_study(name, dump, L):
    """Log a 3D sample's solid fraction and grading, sweep every model over
    X; returns (dump, side, largest radius, count)."""
    centres, radii = read_dump(dump)
    phi = sum(4 / 3 * math.pi * r ** 3 for r in radii) / L ** 3
    ds = sorted(2 * r for r in radii)
    if ds[-1] > 1.5 * ds[0] and sum(d < 1.01 * ds[0] for d in ds) + sum(d > 0.99 * ds[-1] for d in ds) == len(ds):
        fines = sum(d ** 3 for d in ds if d < 1.01 * ds[0]) / sum(d ** 3 for d in ds)
        grading = "d ratio %.2f, fines %.3f by mass" % (ds[-1] / ds[0], fines)
    else:
        grading = "d60/d10 %.3f" % (ds[int(0.6 * len(ds))] / ds[int(0.1 * len(ds))])
    log("%s: %d spheres, solid fraction %.3f, %s" % (name, len(radii), phi, grading))
    sweep_X(name, dump, L, max(radii), SWEEPS)
    return dump, L, max(radii), len(radii)


def friction_study():
    """Kalderon et al.'s b and c samples: the friction sets the solid fraction."""
    for name, count, r_mean, cu, mu in FRICTION_SAMPLES:
        sphere_study(name, *make_packing(name, count, r_mean, cu, mu, p_stop=P_STOP))


def scale_study(dump, L, r_max, count):
    """Time per particle against particle count, X = 3, defaults: 1,000
    spheres of L1.2a's grading packed on their own (a tile cannot be smaller
    than the sample), then L1.2a tiled k^3 times."""
    small, L_small = make_packing("L1.2-1k", 1000, 1.17e-3, 1.2, 0.0)
    log("scale: 1000 particles")
    run_case("tile1k", small, L_small, 3, r_max, default_runs(), sample="tile1k")
    for k in TILES:
        path = tile(dump, L, k)
        log("scale: %d particles" % (count * k ** 3))
        run_case("tile%d" % k, path, k * L, 3, r_max, default_runs(), sample="tile%d" % k)


def cu6_study():
    """Kalderon et al.'s Cu = 6 samples, every model over its parameter over X."""
    for name, count, r_min, cu, mu in CU6_SAMPLES:
        sphere_study(name, *make_log_packing(name, count, r_min, cu, mu))


def bimodal_study():
    """Kalderon et al.'s bimodal samples, every model over its parameter at the X
    that leave two cells per side or more."""
    for name, ratio, fines, width, phi in BIMODAL_SAMPLES:
        sphere_study(name, *make_bimodal_packing(name, ratio, fines, width, phi))


def series_table(rows, names):
    """Error (%) of each model at its default against analytical, X near 3,
    for the given samples."""
    names = [n for n in names if any(r["sample"] == n for r in rows)]
    out = ["| model | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
    for model, key, values in SWEEPS:
        run = model if key is None else "%s_%s" % (model, values[0])
        cells = []
        for n in names:
            X = nearest_X(rows, n, 3)
            r = next((r for r in rows if r["sample"] == n and r["run"] == run and r["nProcs"] == "1"
                      and round(float(r["X"]), 2) == X), None)
            cells.append("%.3g (X %.2f)" % (float(r["error_percent"]), X) if r else "-")
        out.append("| %s | %s |" % (model, " | ".join(cells)))
    return "\n".join(out)


def replace_rows(samples):
    """Drop the CSV rows of the given samples (they are about to be rerun);
    a partial run starts from the committed results."""
    if not os.path.exists(CSV) and os.path.exists(COMMITTED):
        shutil.copyfile(COMMITTED, CSV)
    kept = [r for r in load() if r["sample"] not in samples] if os.path.exists(CSV) else []
    if kept:
        with open(CSV, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(kept[0].keys()), lineterminator="\n")
            w.writeheader()
            w.writerows(kept)
    elif os.path.exists(CSV):
        os.remove(CSV)


def series():
    """The sample series the full study runs after the scale series, each
    also alone with its flag: flag, samples (their rows are replaced), the
    function that runs them, the samples of its table."""
    return [("--friction", FRICTION_SAMPLES, friction_study,
             ("L1.2a", "L1.2b", "L1.2c", "L3a", "L3b", "L3c")),
            ("--cu6", CU6_SAMPLES, cu6_study, [n for n, *_ in CU6_SAMPLES]),
            ("--bimodal", BIMODAL_SAMPLES, bimodal_study, [n for n, *_ in BIMODAL_SAMPLES])]


def default_runs():
    return [("%s_%s" % (m, vals[0]) if k else m, m, k, vals[0]) for m, k, vals in SWEEPS]


def load():
    with open(CSV) as f:
        return list(csv.DictReader(f))


def plots(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    markers = {"analytical": "k*", "centroid": "s", "voxel": "^", "hybrid": "v", "kernel": "o", "diffusion": "d"}
    serial = [r for r in rows if r["nProcs"] == "1"]

    # Pareto at X about 3
    l12 = [r for r in serial if r["sample"] == "L1.2a"]
    Xs = sorted({round(float(r["X"]), 2) for r in l12})
    X3 = min(Xs, key=lambda x: abs(x - 3))
    fig, ax = plt.subplots(figsize=(7, 5))
    for model, mk in markers.items():
        pts = [r for r in l12 if r["model"] == model and round(float(r["X"]), 2) == X3]
        if model == "analytical":
            pts = pts[:1]
        if pts:
            ax.plot([float(r["median_s"]) for r in pts], [max(float(r["error_percent"]), 1e-3) for r in pts],
                    mk, ls="none", ms=8, label=model)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("median time per call (s), one core")
    ax.set_ylabel("error against analytical, Eq. 21 (%)  (analytical drawn at 1e-3)")
    ax.set_title("L1.2a, X = %.2f: every model over its parameter" % X3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(WORK, "pareto.png"), dpi=110)

    # smoothness at each X for the defaults
    fig, ax = plt.subplots(figsize=(7, 5))
    for model, key, values in [("analytical", None, [None])] + SWEEPS:
        run = model if key is None else "%s_%s" % (model, values[0])
        pts = sorted((float(r["X"]), float(r["smoothness"])) for r in l12
                     if (r["run"] == run or (model == "analytical" and r["run"] == "reference")))
        if pts:
            ax.plot(*zip(*pts), markers[model][-1] + "-", label=model)
    ax.set_xlabel("X = cell size / largest diameter")
    ax.set_ylabel("smoothness, Eq. 22: mean |grad n| (1/m)")
    ax.set_title("L1.2a, defaults")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(WORK, "smoothness.png"), dpi=110)

    # optimal (least error) kernel b/ds and diffusion coefficient against X
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for k, (model, seed_value, seed_2d) in enumerate((("kernel", 0.4, 1.0), ("diffusion", 0.12, 0.17))):
        for sample in sorted({r["sample"] for r in serial if r["sample"] in ("L1.2a", "L3a", DISKS)}):
            sel = [r for r in serial if r["sample"] == sample and r["model"] == model]
            best = []
            for X in sorted({round(float(r["X"]), 2) for r in sel}):
                pts = [r for r in sel if round(float(r["X"]), 2) == X]
                b = min(pts, key=lambda r: float(r["error_percent"]))
                best.append((X, float(b["parameter"])))
            if best:
                ax[k].plot(*zip(*best), "o-", label="least error, %s" % sample)
        ax[k].axhline(seed_value, color="k", ls=":", label="Kalderon et al.'s calibration, 3D")
        ax[k].axhline(seed_2d, color="k", ls="--", label="Kalderon et al.'s calibration, 2D")
        ax[k].set_xlabel("X")
        ax[k].set_ylabel("b/ds" if model == "kernel" else "coefficient a")
        ax[k].set_title(model)
        ax[k].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(WORK, "optimalParameter.png"), dpi=110)

    # time per particle against particle count
    tiles = [r for r in serial if r["sample"].startswith("tile")]
    fig, ax = plt.subplots(figsize=(7, 5))
    for model, mk in markers.items():
        run = "reference" if model == "analytical" else None
        pts = sorted((int(r["nParticles"]), float(r["median_s"]) / int(r["nParticles"])) for r in tiles
                     if (r["run"] == run if run else (r["model"] == model and r["run"] != "reference")))
        if len(pts) >= 2:
            slope = math.log(pts[-1][1] / pts[0][1]) / math.log(pts[-1][0] / pts[0][0])
            ax.plot(*zip(*pts), mk[-1] + "-", label="%s (slope %.2f)" % (model, slope))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("particles")
    ax.set_ylabel("time per particle per call (s)")
    ax.set_title("1,000 spheres, then L1.2a tiled k^3 times; X = 3, defaults: flat = linear cost", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(WORK, "scaling.png"), dpi=110)
    return X3


def nearest_X(rows, sample, X):
    Xs = {round(float(r["X"]), 2) for r in rows if r["sample"] == sample}
    return min(Xs, key=lambda x: abs(x - X))


def table(rows, X3, sample_name="L1.2a", sweeps=SWEEPS):
    out = []
    for sample, nprocs in ((sample_name, "1"), (sample_name, "2")):
        sel = [r for r in rows if r["sample"] == sample and round(float(r["X"]), 2) == X3
               and r["nProcs"] == nprocs]
        pcm = next((float(r["median_s"]) for r in sel if r["run"] == "centroid"), None)
        if not sel or not pcm:
            continue
        out.append("| %s, %s rank%s | error (%%) | smoothness (1/m) | conservation | time (s) | time / PCM |"
                   % (sample, nprocs, "" if nprocs == "1" else "s"))
        out.append("|---|---|---|---|---|---|")
        for model, key, values in [("analytical", None, [None])] + sweeps:
            run = "reference" if model == "analytical" else (model if key is None else "%s_%s" % (model, values[0]))
            r = next((r for r in sel if r["run"] == run), None)
            if r:
                out.append("| %s | %.3g | %.4g | %.0e | %.3g | %.1f |" % (
                    model, float(r["error_percent"]), float(r["smoothness"]), float(r["conservation"]),
                    float(r["median_s"]), float(r["median_s"]) / pcm))
        out.append("")
    return "\n".join(out)


def main():
    os.makedirs(WORK, exist_ok=True)
    if ONLY_2D:
        replace_rows({DISKS})
        disk_study()
        rows = load()
        print(table(rows, nearest_X(rows, DISKS, 3), DISKS, SWEEPS_2D))
        return
    if ONLY_L12A:
        replace_rows({"L1.2a"})
        dump, L, r_max, count = sphere_study("L1.2a", *make_packing("L1.2a", 8262, 1.17e-3, 1.2, 0.0))
        log("X = 3 on 2 MPI ranks")
        run_case("L1.2a-X3-np2", dump, L, 3, r_max, default_runs(), nprocs=2)
        rows = load()
        print(table(rows, plots(rows)))
        return
    if ONLY_SCALE:
        replace_rows({r["sample"] for r in load() if r["sample"].startswith("tile")})
        dump, L = make_packing("L1.2a", 8262, 1.17e-3, 1.2, 0.0)
        centres, radii = read_dump(dump)
        scale_study(dump, L, max(radii), len(radii))
        return
    for flag, samples, run_series, names in series():
        if flag in sys.argv:
            replace_rows({n for n, *_ in samples})
            run_series()
            print(series_table(load(), names))
            return
    if os.path.exists(CSV):
        os.remove(CSV)
    # Kalderon et al.'s Table 4 samples L1.2a and (full study) L3a, frictionless
    samples = [("L1.2a", 8262, 1.17e-3, 1.2)] + ([] if QUICK else [("L3a", 22600, 1.48e-3, 3.0)])
    packed = {}
    for name, count, r_mean, cu in samples:
        packed[name] = sphere_study(name, *make_packing(name, count, r_mean, cu, 0.0))
    dump, L, r_max, count = packed["L1.2a"]
    log("X = 3 on 2 MPI ranks")
    run_case("L1.2a-X3-np2", dump, L, 3, r_max, default_runs(), nprocs=2)
    scale_study(dump, L, r_max, count)
    if not QUICK:
        for _, _, run_series, _ in series():
            run_series()
    disk_study()
    rows = load()
    X3 = plots(rows)
    print(table(rows, X3))
    print(table(rows, nearest_X(rows, DISKS, 3), DISKS, SWEEPS_2D))
    if "L3a" in packed:
        print(table(rows, nearest_X(rows, "L3a", 3), "L3a"))
        for _, _, _, names in series():
            print(series_table(rows, names))
    # peak memory of a whole benchmark process (dump, mesh, every model in
    # turn) against particle count: the slope is the memory per particle
    peaks = sorted({(int(r["nParticles"]), max(float(q["peak_memory_MB"]) for q in rows if q["sample"] == r["sample"]))
                    for r in rows if r["sample"].startswith("tile")})
    if len(peaks) >= 2:
        (n0, m0), (n1, m1) = peaks[0], peaks[-1]
        log("peak memory %s MB at %s particles: %.0f bytes per particle" %
            (" ".join("%.0f" % m for _, m in peaks), " ".join(str(n) for n, _ in peaks),
             (m1 - m0) * 1048576 / (n1 - n0)))
    log("results in %s; plots pareto.png smoothness.png optimalParameter.png scaling.png" % WORK)


if __name__ == "__main__":
    main()
