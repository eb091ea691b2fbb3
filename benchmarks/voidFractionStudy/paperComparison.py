#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Each model at Kalderon et al.'s own settings beside ours, on the study's
samples near X = 3 (L1.2a in 3D at X = 2.79, the 2D disks at X = 3.02), against
the paper's errors for the same methods (its Figs. 17 and 18 at X = 3).

Besides each model's default, the settings of the paper's implementations:
  - diffusion with integration explicit: the paper's Eq. 20 step, with the
    coefficient of its Tables 6 and 7 (0.17 in 2D, 0.12 in 3D) and that of
    its Eq. 33 (2D) or Eq. 34 (3D) at the sample's X, from the centroid
    split, and from the analytical one;
  - voxel with voxelsPerCell: voxels dividing each cell evenly, as the
    paper's grids did (50^3 voxels over 5^3 cells in 3D, 300^2 over 12^2 in
    2D: 10 and 25 per cell edge), for 4 to 16 voxels per cell edge (2D: 8
    to 64).
Writes results/paperComparison.csv and prints the table for docs/performance.md.
Uses the study's packings (build/study/packings; made when missing).

usage: paperComparison.py
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import study  # noqa: E402

RESULTS = os.path.join(HERE, "results", "paperComparison.csv")

# the paper's errors (%) at X = 3, its Figs. 17 (2D) and 18 (3D)
PAPER = {"3D": {"voxel": 8, "hybrid": 1.4, "kernel": 1.7, "diffusion": 2.5},
         "2D": {"centroid": 17, "voxel": 8.8, "hybrid": 0.3, "kernel": 3.8, "diffusion": 6.1}}


def coefficient(dim, X):
    """The paper's calibration of a against X: Eq. 33 (2D), Eq. 34 (3D)"""
    return -0.0042*X + 0.211 if dim == "2D" else -0.003*X + 0.1327


def runs(dim, X):
    a, table = coefficient(dim, X), (0.17 if dim == "2D" else 0.12)
    per_cell = (4, 6, 8, 10, 12, 16) if dim == "3D" else (8, 16, 25, 32, 48, 64)
    out = [("centroid", "centroid", None, None),
           ("voxel default", "voxel", None, None),
           ("hybrid default", "hybrid", None, None),
           ("kernel default", "kernel", None, None),
           ("diffusion default", "diffusion", None, None),
           ("diffusion explicit a %g" % table, "diffusion", "integration explicit; coefficient", table),
           ("diffusion explicit a %.4f (Eq. %s)" % (a, "33" if dim == "2D" else "34"), "diffusion",
            "integration explicit; coefficient", a),
           ("diffusion explicit from analytical a %g" % table, "diffusion",
            "initial analytical; integration explicit; coefficient", table)]
    out += [("voxel %d per cell" % n, "voxel", "voxelsPerCell", n) for n in per_cell]
    return out


def run_sample(dim, name, dump, L, r_max, X_target):
    n = max(1, round(L/(X_target*2*r_max)))
    X = L/n/(2*r_max)
    table = runs(dim, X)
    labelled = [("run%d" % i, model, key, value) for i, (_, model, key, value) in enumerate(table)]
    csv_path = os.path.join(study.WORK, "paperComparison-%s.csv" % dim)
    if os.path.exists(csv_path):
        os.remove(csv_path)
    study.run_case("paperComparison-%s" % dim, dump, L, X_target, r_max, labelled, two_d=(dim == "2D"),
                   csv=csv_path, repeat=3)
    with open(csv_path) as f:
        rows = {r["run"]: r for r in csv.DictReader(f)}
    return [(dim, name, X, label, model, float(rows[run]["error_percent"]), float(rows[run]["smoothness"]),
             float(rows[run]["median_s"]))
            for (label, model, _, _), (run, *_) in zip(table, labelled)]


def main():
    os.makedirs(study.WORK, exist_ok=True)
    dump, L = study.make_packing("L1.2a", 8262, 1.17e-3, 1.2, 0.0)
    _, radii = study.read_dump(dump)
    rows = run_sample("3D", "L1.2a", dump, L, max(radii), 3)
    dump, L = study.make_disk_packing()
    _, radii = study.read_dump(dump)
    rows += run_sample("2D", study.DISKS, dump, L, max(radii), 3)
    with open(RESULTS, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["dim", "sample", "X", "setting", "model", "error_percent", "smoothness", "median_s"])
        w.writerows(rows)
    print("| sample | setting | error (%) | the paper's (%) | smoothness (1/m) | time / centroid |")
    print("|---|---|---|---|---|---|")
    for dim in ("3D", "2D"):
        sel = [r for r in rows if r[0] == dim]
        pcm = next(r[7] for r in sel if r[3] == "centroid")
        for r in sel:
            paper = PAPER[dim].get(r[4])
            print("| %s, X %.2f | %s | %.3g | %s | %.4g | %.1f |" % (
                r[1], r[2], r[3], r[5], "%g" % paper if paper is not None else "-", r[6], r[7]/pcm))


if __name__ == "__main__":
    main()
