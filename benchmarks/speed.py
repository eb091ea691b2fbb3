#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Speed of the six void fraction models per core.

A dense polydisperse packing (jittered FCC lattice, radii uniform in
[0.8, 1] r_max, solid fraction about 0.45) in a box meshed with cells
3 x the largest diameter: Cartesian (blockMesh) and tetrahedral (each
hexahedron of the same size split into 6 tetrahedra). demVoidFraction
times repeated calls after a warm-up; the median is reported, and each
model's time relative to centroid on the same mesh in the same run. Every
model runs with its defaults; voxel also at Kalderon et al.'s 50 voxels per sample
side and at 10 voxels per particle diameter. Five rounds over all models;
the median over the rounds is reported.

Writes benchmarks/speed/results/table.md (docs/performance.md shows it).

usage: benchmarks/speed.py [N]   (N particles, default 200000)
"""
import math
import os
import random
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))
from foamCase import ROOT, box_block_mesh, new_case, parse_report, set_coupling, sh, write_dump  # noqa: E402

N = int(sys.argv[1]) if len(sys.argv) > 1 else 200000
rmax = 0.001
nn = 2.1 * rmax                       # FCC nearest-neighbour distance
a = nn * math.sqrt(2)                 # FCC cube edge
n = max(2, round((N / 4) ** (1 / 3)))
L = n * a
rng = random.Random(11)
centres, radii = [], []
jit = (nn - 2 * rmax) / 2 * 0.99
for i in range(n):
    for j in range(n):
        for k in range(n):
            for b in ((0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)):
                c = [(i + b[0] + 0.25) * a, (j + b[1] + 0.25) * a, (k + b[2] + 0.25) * a]
                centres.append([x + rng.uniform(-jit, jit) / math.sqrt(3) for x in c])
                radii.append(rng.uniform(0.8, 1.0) * rmax)
ncell = max(1, round(L / (3 * 2 * rmax)))
work = os.path.join(ROOT, "build", "benchmarks")
os.makedirs(work, exist_ok=True)
dump = os.path.join(work, "packing_%d.dump" % len(radii))
write_dump(dump, centres, radii)
N_PARTICLES = len(radii)
solid = sum(4 / 3 * math.pi * r ** 3 for r in radii) / L ** 3
print("%d particles, solid fraction %.3f, box %.4f m, %d^3 cells of %.2f d_max"
      % (len(radii), solid, L, ncell, L / ncell / (2 * rmax)))

CONFIGS = [
    ("centroid", "centroid", ""),
    ("analytical", "analytical", ""),
    ("voxel 50/side", "voxel", "voxelsPerSide 50;"),
    ("voxel 10/diam", "voxel", "voxelsPerDiameter 10;"),
    ("hybrid", "hybrid", ""),
    ("kernel", "kernel", ""),
    ("diffusion", "diffusion", ""),
]


def run(case, label, model, coeffs, repeat):
    set_coupling(case, "voidFractionModel %s;\n%sCoeffs { %s }\n" % (model, model, coeffs))
    _, out = sh("demVoidFraction -dump %s -repeat %d" % (dump, repeat), case)
    rep = parse_report(out)
    return rep


# Other work on a shared machine slows whole stretches of a run: every model
# is timed in each of ROUNDS rounds, and the table gives the median over the
# rounds of its median time and of its ratio to centroid in the same round
# (one round for the sub-grid models on tetrahedra, which take seconds a call).
ROUNDS = 5
cart = new_case(os.path.join(work, "cartesian"), box_block_mesh((0, 0, 0), (L, L, L), (ncell,) * 3))
tet = new_case(os.path.join(work, "tetrahedral"))
sh("rm -rf constant/polyMesh && /usr/bin/python3 %s/tests/makeTetMesh.py . %d %r 0.0" % (ROOT, ncell, L), tet)
runs = {}   # (mesh, label) -> one report per round
for rnd in range(ROUNDS):
    for label, model, coeffs in CONFIGS:
        runs.setdefault(("cartesian", label), []).append(run(cart, label, model, coeffs, 20))
    for label, model, coeffs in CONFIGS:
        slow = model in ("voxel", "hybrid")
        if label == "voxel 50/side" or (slow and rnd > 0):
            continue
        runs.setdefault(("tetrahedral", label), []).append(run(tet, label, model, coeffs, 3 if slow else 9))
    print("round %d of %d done" % (rnd + 1, ROUNDS), flush=True)

lines = ["| mesh | model | median time per call (s) | particles/s | time / centroid | conservation |",
         "|---|---|---|---|---|---|"]
for (mesh, label), reps in runs.items():
    base = runs[(mesh, "centroid")]
    t = statistics.median(r["median"] for r in reps)
    ratio = statistics.median(r["median"] / b["median"] for r, b in zip(reps, base))
    lines.append("| %s | %s | %.5f | %.3e | %.2f | %.0e |" % (mesh, label, t, N_PARTICLES / t, ratio,
                                                             max(r["conservation"] for r in reps)))
print("\n".join(lines))
results = os.path.join(ROOT, "benchmarks", "speed", "results")
os.makedirs(results, exist_ok=True)
with open(os.path.join(results, "table.md"), "w") as f:
    f.write("%d particles, solid fraction %.3f, %d^3 cells of %.2f d_max\n\n%s\n"
            % (N_PARTICLES, solid, ncell, L / ncell / (2 * rmax), "\n".join(lines)))
print("wrote %s" % os.path.join(results, "table.md"))
