#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The study's tables for docs/performance.md, from its committed results
(results/results.csv, results/paperComparison.csv) with Kalderon et al.'s
(2021) values in brackets: writes results/tables.md, whose parts
docs/tables.py copies into the docs.

  part 1: L1.2a at X near 2.8, each model at its default, 1 and 2 ranks
  part 2: the error at each model's default over the other 3D samples
  part 3: the 2D disks at X near 3
  part 4: each model at the paper's settings beside ours (paperComparison)

usage: tables.py
"""
import csv
import os

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")

# Kalderon et al. (2021): errors (%) at X = 3, its Figs. 17 (2D) and 18 (3D),
# and the time of its MATLAB implementations relative to PCM
PAPER_ERROR = {"3D": {"voxel": "8", "hybrid": "1.4", "kernel": "1.7", "diffusion": "2.5"},
               "2D": {"centroid": "17", "voxel": "8.8", "hybrid": "0.3", "kernel": "3.8", "diffusion": "6.1"}}
PAPER_TIME = {"3D": {"voxel": "7,000"},
              "2D": {"voxel": "3,000", "hybrid": "26", "kernel": "26", "diffusion": "3"}}

# each model's default run in the study, and how the tables name it
DEFAULTS = {"3D": [("reference", "analytical"), ("centroid", "centroid"), ("voxel_50", "voxel (50 per side)"),
                   ("hybrid_20", "hybrid (20 per diameter)"), ("kernel_0.4", "kernel (b/ds 0.4)"),
                   ("diffusion_0.12", "diffusion (a 0.12)")],
            "2D": [("reference", "analytical"), ("centroid", "centroid"), ("voxel_300", "voxel (300 per side)"),
                   ("hybrid_50", "hybrid (50 per diameter)"), ("kernel_0.4", "kernel (b/ds 0.4)"),
                   ("diffusion_0.17", "diffusion (a 0.17)")]}
SAMPLES = ["L1.2a", "L1.2b", "L1.2c", "L3a", "L3b", "L3c", "L6a", "L6b", "L6c", "B2a", "B6a", "B10a"]


def g(value, digits=3):
    return "%.*g" % (digits, float(value))


def ratio(value):
    return "%.1f" % value if value < 10 else "%.0f" % value


def bracket(value, paper):
    return "%s [%s]" % (value, paper) if paper else value


def nearest(rows, sample, x, ranks=1):
    """The rows of sample at the X nearest x, by run name"""
    mine = [r for r in rows if r["sample"] == sample and int(r["nProcs"]) == ranks]
    best = min((abs(float(r["X"]) - x), float(r["X"])) for r in mine)[1]
    return {r["run"]: r for r in mine if float(r["X"]) == best}, best


def table(header, rows):
    return "\n".join(["| " + " | ".join(header) + " |", "|" + "---|"*len(header)] +
                     ["| " + " | ".join(r) + " |" for r in rows]) + "\n"


def default_cells(found, dim):
    """Per default run: its name, (row, [error, smoothness, time / PCM]) with the paper's in brackets"""
    pcm = float(found["centroid"]["median_s"])
    for run, name in DEFAULTS[dim]:
        r, model = found[run], found[run]["model"]
        error = "0 (reference)" if run == "reference" else bracket(g(r["error_percent"]),
                                                                    PAPER_ERROR[dim].get(model))
        yield run, name, r, [error, g(r["smoothness"], 4),
                             bracket(ratio(float(r["median_s"])/pcm), PAPER_TIME[dim].get(model))]


def l12a(rows):
    one, x = nearest(rows, "L1.2a", 2.8)
    two, _ = nearest(rows, "L1.2a", x, 2)
    out = []
    for run, name, r, (error, smooth, relative) in default_cells(one, "3D"):
        out.append([name, error, smooth, "%.0e" % float(r["conservation"]), g(r["median_s"]), relative,
                    g(two[run]["median_s"]) if run in two else "-"])
    return table(["model", "error (%)", "smoothness (1/m)", "conservation", "time (s)", "time / PCM",
                  "2 ranks: time (s)"], out)


def samples(rows):
    found = {s: nearest(rows, s, 3.0)[0] for s in SAMPLES}
    out = []
    for run, name in DEFAULTS["3D"][1:]:
        out.append([name.split(" (")[0]] + [g(found[s][run]["error_percent"]) for s in SAMPLES])
    return table(["model"] + SAMPLES, out)


def disks(rows):
    one, _ = nearest(rows, "G2D", 3.0)
    out = [[name] + cells for _, name, _, cells in default_cells(one, "2D")]
    return table(["model", "error (%)", "smoothness (1/m)", "time / PCM"], out)


SETTINGS = [  # (name in the table, 3D setting, 2D setting, bold: a recommended setting)
    ("centroid", "centroid", "centroid", False),
    ("voxel, 50 per side (300 in 2D; default)", "voxel default", "voxel default", False),
    ("voxel, `voxelsPerCell` 10 (25 in 2D)", "voxel 10 per cell", "voxel 25 per cell", True),
    ("hybrid (default)", "hybrid default", "hybrid default", True),
    ("kernel (default)", "kernel default", "kernel default", True),
    ("diffusion, implicit, a 0.12 (0.17; default)", "diffusion default", "diffusion default", False),
    ("diffusion, explicit, a 0.12 (0.17)", "diffusion explicit a 0.12", "diffusion explicit a 0.17", False),
    ("diffusion, explicit, a from Eq. 34 (33): %s (%s)", "diffusion explicit a * (Eq. 34)",
     "diffusion explicit a * (Eq. 33)", False),
    ("diffusion, explicit from `initial analytical`, a 0.12 (0.17)", "diffusion explicit from analytical a 0.12",
     "diffusion explicit from analytical a 0.17", True),
]


def comparison(rows):
    def find(dim, setting):
        head, _, tail = setting.partition("*")
        return next(r for r in rows if r["dim"] == dim and r["setting"].startswith(head)
                    and r["setting"].endswith(tail))
    x3 = float(find("3D", "centroid")["X"])
    x2 = float(find("2D", "centroid")["X"])
    out = []
    for name, s3, s2, bold in SETTINGS:
        r3, r2 = find("3D", s3), find("2D", s2)
        if "%s" in name:
            name = name % (r3["setting"].split()[3], r2["setting"].split()[3])
        cells = []
        for r, dim in ((r3, "3D"), (r2, "2D")):
            error = g(r["error_percent"])
            paper = PAPER_ERROR[dim].get(r["model"])
            cells += [bracket("**%s**" % error if bold else error, paper), g(r["smoothness"], 4)]
        out.append([name] + cells)
    return table(["setting", "L1.2a, X = %.2f: error" % x3, "smoothness", "2D disks, X = %.2f: error" % x2,
                  "smoothness"], out)


def main():
    rows = list(csv.DictReader(open(os.path.join(RESULTS, "results.csv"))))
    paper = list(csv.DictReader(open(os.path.join(RESULTS, "paperComparison.csv"))))
    parts = [l12a(rows), samples(rows), disks(rows), comparison(paper)]
    with open(os.path.join(RESULTS, "tables.md"), "w") as f:
        f.write("\n".join(parts))
    print("wrote %s (%d tables)" % (os.path.join(RESULTS, "tables.md"), len(parts)))


if __name__ == "__main__":
    main()
