#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Precision of exactly scaled coarse-grained DEM: the biaxial study of
Zhang, Huang and Zhao, "Comparison of coarse graining DEM models based on
exact scaling laws" (CMES 2021, section 4), with LIGGGHTS.

2D (the paper's study): a periodic 6 x 12 sample of disks with radii from a
Gaussian (mean 0.03, standard deviation 0.005, truncated to [0.02, 0.04]),
porosity 0.2, 20,371 disks at h = 1 and the paper's Table 2 counts at
h = 2 ... 4. 3D (not in the paper): a periodic 1.2 x 2.4 x 1.2 sample of
spheres of the same radii at porosity 0.4 (18,335 spheres at h = 1).
At scale factor h every length (radii, box, skin) is multiplied by h, every
time (time step, 1/rates, 1/damping) by h, the density and the confining
pressure by 1, the stiffness by h^(d-2) (force/length: 1 per unit depth in
2D, h in 3D), so the average contact force scales by h^(d-1) (the paper's
Eqs. 34 and 35). Each sample is a new random packing.

Each sample: random sequential placement at solid fraction PHI_LOOSE,
frictionless compaction to the paper's porosity, frictionless
servo-controlled isotropic consolidation to P0 (a dense sample: porosity
about 0.16 in 2D), then compression along y to 1 % strain at a constant
rate with friction MU and the lateral stress held at P0 (in.biaxial). G is
the gradient of the average normal contact force (kn x mean overlap)
against the axial strain, the least-squares line over the whole loading
(as the paper's Fig. 4); G_0 is the same over the first 0.1 % (the initial
stiffness). The theoretical value at h is h^(d-1) G_1 with G_1 the mean
over the h = 1 samples; err (Eq. 36) = |G_theory - mean G_h| / G_theory,
and var the variance of the samples' relative deviations
|G_theory - G| / G_theory (the paper's Fig. 6).

usage: compression.py [--dim 2|3] [--factors 1,2,4] [--samples N] [--size s]
                      [--jobs J] [--results DIR] [--plot]
  --size s scales the sample's sides by s (s = 1: the paper's sample); each
  finished sample is appended to DIR/compression<dim>d_size<s>.csv and is not
  run again, so an interrupted study resumes where it stopped.
"""
import argparse
import csv
import itertools
import math
import os
import random
import statistics
import subprocess
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

PAPER_FACTORS = [1, 2, 2.2, 2.42, 2.662, 2.9282, 3.2210, 3.5430, 4]
TABLE2_COUNTS = {1: 20371, 2: 5092, 2.2: 4209, 2.42: 3478, 2.662: 2875, 2.9282: 2375,
                 3.2210: 1964, 3.5430: 1622, 4: 1273}
SAMPLE = {2: dict(box=(6.0, 12.0), porosity=0.2, count=20371),
          3: dict(box=(1.2, 2.4, 1.2), porosity=0.4, count=18335)}
R_MEAN, R_SD, R_MIN, R_MAX = 0.03, 0.005, 0.02, 0.04
RHO = 2650.0           # kg/m3, quartz
P0 = 1.0e5             # Pa, confining pressure
KN = {2: 1.0e8, 3: 6.0e6}  # N/m per unit depth (2D), N/m (3D) at h = 1: overlap ~ 0.2 % of r at P0
KT_KN = 0.5
MU = 0.5
MU_CONSOLIDATE = 0.0
DAMPING_RATIO = 0.3
PHI_LOOSE = {2: 0.5, 3: 0.3}
RATE_COMPACT = 3.0     # 1/s per axis at h = 1
RATE_LOAD = 0.05       # 1/s at h = 1: inertial number about 5e-4
GAIN, RATE_MAX, TOL = 1.0, 1.0, 0.01
KI = 0.3              # integral gain while loading: rate change per chunk per relative error
CHUNK, SETTLE_CHUNKS, MAX_CHUNKS = 20, 10, 10000
LOAD_STRAIN = 0.01
INITIAL_STRAIN = 0.001


def particle_count(dim, h, size):
    base = SAMPLE[dim]["count"] * size ** dim
    if dim == 2 and size == 1 and h in TABLE2_COUNTS:
        return TABLE2_COUNTS[h]
    return int(base / h ** dim)


def make_packing(dim, h, size, seed):
    """Radii (scaled to the sample's porosity exactly) and loose positions."""
    rng = random.Random(seed)
    n = particle_count(dim, h, size)
    radii = []
    while len(radii) < n:
        r = rng.gauss(R_MEAN, R_SD)
        if R_MIN <= r <= R_MAX:
            radii.append(r * h)
    box = [b * size for b in SAMPLE[dim]["box"]]
    measure = math.pi * sum(r ** 2 for r in radii) if dim == 2 \
        else 4 / 3 * math.pi * sum(r ** 3 for r in radii)
    target = (1 - SAMPLE[dim]["porosity"]) * math.prod(box)
    scale = (target / measure) ** (1 / dim)
    radii = sorted((r * scale for r in radii), reverse=True)
    stretch = ((1 - SAMPLE[dim]["porosity"]) / PHI_LOOSE[dim]) ** (1 / dim)
    loose = [b * stretch for b in box]
    return radii, place(radii, loose, rng), box, loose


def place(radii, box, rng):
    """Random sequential placement without overlap in a periodic box."""
    dim = len(box)
    cell = 2 * radii[0]
    ncell = [max(1, int(b / cell)) for b in box]
    size = [b / n for b, n in zip(box, ncell)]
    reach = [int(math.ceil(2 * radii[0] / s)) for s in size]
    grid = {}
    centres = []
    for i, r in enumerate(radii):
        for _ in range(100000):
            p = [rng.uniform(0, b) for b in box]
            key = [int(p[a] / size[a]) % ncell[a] for a in range(dim)]
            if not overlaps(p, r, key, reach, ncell, box, grid, centres, radii):
                grid.setdefault(tuple(key), []).append(i)
                centres.append(p)
                break
        else:
            sys.exit("compression.py: cannot place particle %d of %d at the loose solid fraction"
                     % (i + 1, len(radii)))
    return centres


def overlaps(p, r, key, reach, ncell, box, grid, centres, radii):
    dim = len(box)
    ranges = [range(key[a] - reach[a], key[a] + reach[a] + 1) for a in range(dim)]
    seen = set()
    for idx in itertools.product(*ranges):
        k = tuple(idx[a] % ncell[a] for a in range(dim))
        if k in seen:
            continue
        seen.add(k)
        for j in grid.get(k, ()):
            d2 = 0.0
            for a in range(dim):
                d = p[a] - centres[j][a]
                d -= box[a] * round(d / box[a])
                d2 += d * d
            if d2 < (r + radii[j]) ** 2:
                return True
    return False


def write_data(path, radii, centres, loose, dim):
    depth = 2 * max(radii)
    with open(path, "w") as f:
        f.write("LIGGGHTS data: loose sample for compression.py\n\n%d atoms\n1 atom types\n\n"
                % len(radii))
        f.write("0 %.12g xlo xhi\n0 %.12g ylo yhi\n" % (loose[0], loose[1]))
        zhi = loose[2] if dim == 3 else depth
        zlo = 0 if dim == 3 else -depth
        f.write("%.12g %.12g zlo zhi\n\nAtoms\n\n" % (zlo, zhi))
        for i, (r, c) in enumerate(zip(radii, centres)):
            z = c[2] if dim == 3 else 0.0
            f.write("%d 1 %.12g %.12g %.12g %.12g %.12g\n" % (i + 1, 2 * r, RHO, c[0], c[1], z))


def contact_parameters(dim, h):
    """Stiffness, damping and time step at scale h (see the module doc), from
    the nominal radii so that they scale exactly."""
    kn = KN[dim] * h ** (dim - 2)
    def mass(r):
        return (math.pi * r ** 2 if dim == 2 else 4 / 3 * math.pi * r ** 3) * RHO
    gamma = 2 * DAMPING_RATIO * math.sqrt(kn / (mass(R_MEAN * h) / 2))
    dt = math.pi * math.sqrt((mass(R_MIN * h) / 2) / kn) / 20
    return kn, gamma, dt


def run_sample(dim, h, size, seed, work):
    os.makedirs(work, exist_ok=True)
    radii, centres, box, loose = make_packing(dim, h, size, seed)
    data = os.path.join(work, "loose.data")
    write_data(data, radii, centres, loose, dim)
    kn, gamma, dt = contact_parameters(dim, h)
    rate_compact = RATE_COMPACT / h
    compact_time = math.log(max(l / b for l, b in zip(loose, box))) / rate_compact
    load_rate = RATE_LOAD / h
    load_chunks = int(math.ceil(LOAD_STRAIN / (load_rate * dt * CHUNK)))
    var = dict(dim=dim, data=data, kn=kn, kt=KT_KN * kn, gn=gamma, gt=gamma, muCompact=MU_CONSOLIDATE, mu=MU,
               dt=dt, skin=0.1 * R_MIN * h, lx=box[0], ly=box[1], lz=box[2] if dim == 3 else 0,
               compactSteps=int(compact_time / dt), chunk=CHUNK, p0=P0, gain=GAIN / h,
               rmax=RATE_MAX / h, tol=TOL, settleChunks=SETTLE_CHUNKS, maxChunks=MAX_CHUNKS,
               erate=load_rate, loadChunks=load_chunks, ki=KI / h)
    args = " ".join("-var %s %.12g" % (k, v) if isinstance(v, float) else "-var %s %s" % (k, v)
                    for k, v in var.items())
    log = os.path.join(work, "log.liggghts")
    start = time.time()
    rc = subprocess.run("liggghts -in %s/in.biaxial %s -echo none -log %s -screen %s/screen.txt"
                        % (HERE, args, log, work), shell=True, cwd=work).returncode
    wall = time.time() - start
    if rc != 0:
        raise RuntimeError("LIGGGHTS failed (rc %d) for h %g sample %d: see %s" % (rc, h, seed, log))
    stages = read_stages(log)
    consolidated = stages["consolidation"][-1]
    stress_error = max(abs(consolidated[4 + a] / P0 - 1) for a in range(dim))
    if stress_error > TOL:
        raise RuntimeError("h %g sample %d did not consolidate to p0 (stress error %.3g): see %s"
                           % (h, seed, stress_error, log))
    load = stages["loading"]
    ly0 = load[0][2]
    strain = [1 - row[2] / ly0 for row in load]
    force = [kn * row[7] for row in load]
    gradient = slope(list(zip(strain, force)))
    initial = slope([(e, f) for e, f in zip(strain, force) if e <= INITIAL_STRAIN * (1 + 1e-9)])
    lateral = max(abs(row[4] / P0 - 1) for row in load)
    solid = math.pi * sum(r ** 2 for r in radii) if dim == 2 \
        else 4 / 3 * math.pi * sum(r ** 3 for r in radii)
    volume = math.prod(consolidated[1:1 + dim])
    return dict(dim=dim, h=h, size=size, sample=seed, particles=len(radii),
                porosity=1 - solid / volume, force0=force[0], gradient=gradient, initial=initial,
                lateral_error=lateral, steps=int(load[-1][0]), wall_s=wall)


def read_stages(log):
    """Thermo rows (step lx ly lz pxx pyy pzz overlap ke) of each stage."""
    stages, name = {}, None
    with open(log) as f:
        for line in f:
            if line.startswith("STAGE "):
                name = line.split()[1]
                stages[name] = []
                continue
            parts = line.split()
            if name and len(parts) == 9:
                try:
                    row = [float(p) for p in parts]
                except ValueError:
                    continue
                if not stages[name] or stages[name][-1][0] != row[0]:
                    stages[name].append(row)
    return stages


def slope(points):
    n = len(points)
    mx = sum(p[0] for p in points) / n
    my = sum(p[1] for p in points) / n
    return sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)


FIELDS = ["dim", "h", "size", "sample", "particles", "porosity", "force0", "gradient", "initial",
          "lateral_error", "steps", "wall_s"]


def load_results(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def append_result(path, row):
    new = not os.path.exists(path)
    with open(path, "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        if new:
            w.writeheader()
        w.writerow({k: row[k] for k in FIELDS})


# Zhang et al.'s Table 3 (theory, average of 20 samples): their error by Eq. 36
PAPER_TABLE3 = {2: (1.6733e8, 1.6223e8), 2.2: (1.8406e8, 1.7646e8), 2.42: (2.0247e8, 1.9754e8),
                2.662: (2.2272e8, 2.1523e8), 2.9282: (2.4499e8, 2.3780e8),
                3.2210: (2.6949e8, 2.5923e8), 3.5430: (2.9644e8, 2.8682e8), 4: (3.3466e8, 3.2160e8)}


def paper_error(h):
    if h not in PAPER_TABLE3:
        return None
    theory, mean = PAPER_TABLE3[h]
    return abs(theory - mean) / theory


def summary(rows, dim, key="gradient"):
    """Per h: samples, particles, mean G, theory, err (Eq. 36), variance of
    the samples' relative deviations; key: gradient or initial."""
    by_h = {}
    for r in rows:
        by_h.setdefault(r["h"], []).append(r)
    if 1.0 not in by_h:
        return []
    g1 = statistics.fmean(r[key] for r in by_h[1.0])
    table = []
    for h in sorted(by_h):
        g = [r[key] for r in by_h[h]]
        theory = h ** (dim - 1) * g1
        dev = [abs(theory - x) / theory for x in g]
        table.append(dict(h=h, samples=len(g), particles=int(by_h[h][0]["particles"]),
                          porosity=statistics.fmean(r["porosity"] for r in by_h[h]),
                          mean=statistics.fmean(g), theory=theory,
                          err=abs(theory - statistics.fmean(g)) / theory,
                          var=statistics.pvariance(dev) if len(g) > 1 else 0.0,
                          sem=statistics.stdev(g) / math.sqrt(len(g)) / theory if len(g) > 1 else 0.0))
    return table


def print_summary(rows, dim):
    table = summary(rows, dim)
    initial = {t["h"]: t for t in summary(rows, dim, "initial")}
    print("| h | particles | samples | porosity | mean G (N%s) | h^%d G_1 | err (Eq. 36) "
          "| standard error | variance | err of G_0 |%s"
          % ("/m" if dim == 2 else "", dim - 1, " paper (Table 3) |" if dim == 2 else ""))
    print("|---" * (11 if dim == 2 else 10) + "|")
    for t in table:
        paper = paper_error(t["h"])
        print("| %g | %d | %d | %.3f | %.4e | %.4e | %.2f %% | %.2f %% | %.2e | %.2f %% |%s"
              % (t["h"], t["particles"], t["samples"], t["porosity"], t["mean"], t["theory"],
                 100 * t["err"], 100 * t["sem"], t["var"], 100 * initial[t["h"]]["err"],
                 (" %.2f %% |" % (100 * paper) if paper is not None else " |") if dim == 2 else ""))
    return table


def short_e(x, digits):
    """5.325e5 rather than 5.325e+05"""
    mantissa, exponent = ("%.*e" % (digits - 1, x)).split("e")
    return "%se%d" % (mantissa, int(exponent))


def table_text(rows, dim):
    """The docs' table of a results CSV's rows (docs/coarseGraining.md)"""
    table = summary(rows, dim)
    initial = {t["h"]: t for t in summary(rows, dim, "initial")}
    unit, power = ("N/m", "") if dim == 2 else ("N", "\u00b2")
    header = ["h", "disks" if dim == 2 else "spheres", "porosity", "mean G (%s)" % unit, "h%s G\u2081" % power,
              "err", "standard error of the mean", "variance", "err of G\u2080"] + (["paper"] if dim == 2 else [])
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for t in table:
        first = t["h"] == 1.0
        paper = paper_error(t["h"])
        cells = ["%g" % t["h"], "{:,}".format(t["particles"]), "%.3f" % t["porosity"], short_e(t["mean"], 4),
                 "\u2014" if first else short_e(t["theory"], 4), "\u2014" if first else "%.2f %%" % (100 * t["err"]),
                 "%.2f %%" % (100 * t["sem"]), short_e(t["var"], 2),
                 "\u2014" if first else "%.2f %%" % (100 * initial[t["h"]]["err"])]
        if dim == 2:
            cells.append("\u2014" if paper is None else "%.2f %%" % (100 * paper))
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def plot(table, dim, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [t for t in table if t["h"] != 1.0]
    h = [t["h"] for t in rows]
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
    ax[0].errorbar(h, [100 * t["err"] for t in rows], yerr=[100 * t["sem"] for t in rows], fmt="o-",
                   capsize=3, label="LIGGGHTS, periodic sample (bars: standard error of the mean)")
    if dim == 2:
        ph = sorted(PAPER_TABLE3)
        ax[0].plot(ph, [100 * paper_error(x) for x in ph], "s--", label="Zhang et al., Table 3")
    ax[0].set_xlabel("scale factor h")
    ax[0].set_ylabel("relative error of G (%)")
    ax[0].legend(fontsize=7)
    ax[1].plot(h, [t["var"] for t in rows], "o-")
    ax[1].set_xlabel("scale factor h")
    ax[1].set_ylabel("variance of the relative deviation")
    fig.suptitle("%dD: gradient of the average contact force against axial strain" % dim)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--dim", type=int, choices=(2, 3), default=2)
    p.add_argument("--factors", default=",".join("%g" % h for h in PAPER_FACTORS))
    p.add_argument("--samples", type=int, default=10)
    p.add_argument("--size", type=float, default=1.0)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--results", default=os.path.join(HERE, "results"))
    p.add_argument("--work", default=os.path.join(ROOT, "build", "coarseGrainingPrecision"))
    p.add_argument("--plot", action="store_true")
    a = p.parse_args()
    factors = [float(x) for x in a.factors.split(",")]
    if any(h < 1 for h in factors) or a.samples < 1 or a.size <= 0:
        sys.exit("compression.py: factors must be >= 1, samples >= 1, size > 0")
    os.makedirs(a.results, exist_ok=True)
    out = os.path.join(a.results, "compression%dd_size%g.csv" % (a.dim, a.size))
    done = {(r["h"], int(r["sample"])) for r in load_results(out)}
    todo = [(h, s) for s in range(1, a.samples + 1) for h in factors if (h, s) not in done]
    print("compression %dD size %g: %d samples to run, %d already in %s"
          % (a.dim, a.size, len(todo), len(done), out), flush=True)
    start = time.time()
    with ProcessPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_sample, a.dim, h, a.size, s,
                               os.path.join(a.work, "%dd_size%g_h%g_s%d" % (a.dim, a.size, h, s))):
                   (h, s) for h, s in todo}
        for n, fut in enumerate(as_completed(futures), 1):
            row = fut.result()
            append_result(out, row)
            elapsed = time.time() - start
            print("  [%d/%d] h %g sample %d: %d particles, G %.4e, porosity %.3f, %.0f s "
                  "(elapsed %.0f s, about %.0f s left)"
                  % (n, len(todo), row["h"], row["sample"], row["particles"], row["gradient"],
                     row["porosity"], row["wall_s"], elapsed, elapsed / n * (len(todo) - n)),
                  flush=True)
    table = print_summary(load_results(out), a.dim)
    with open(out[:-len(".csv")] + ".md", "w") as f:
        f.write(table_text(load_results(out), a.dim))
    print("wrote", out[:-len(".csv")] + ".md")
    if a.plot and table:
        path = os.path.join(a.results, "compression%dd_size%g.png" % (a.dim, a.size))
        plot(table, a.dim, path)
        print("wrote", path)


if __name__ == "__main__":
    main()
