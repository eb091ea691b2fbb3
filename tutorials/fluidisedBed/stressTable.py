#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The stress test's table: for every model and cell size, whether the run
finished, the smallest void fraction, the largest continuity error and
Courant number, the time-averaged pressure drop against the bed weight and
its fluctuation. Writes stress.csv and stress.md."""
import os
import sys

import numpy as np

from bedData import bed_weight, log_extremes, pressure_drop

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests"))
from foamCase import void_fraction_models  # noqa: E402

MODELS = list(void_fraction_models())
rows = []
for cells in ["1.5", "2", "3", "5"]:
    for model in MODELS:
        case = os.path.join("stress", f"{model}_{cells}")
        finished, amin, cont, co = log_extremes(case)
        mean = fluct = np.nan
        try:
            t, dp = pressure_drop(case)
            settled = t > 0.15
            w = bed_weight(case)
            mean, fluct = dp[settled].mean()/w - 1, dp[settled].std()/dp[settled].mean()
        except (OSError, IndexError, ValueError):
            pass
        rows.append((model, cells, finished, amin, cont, co, mean, fluct))

with open("stress.csv", "w") as f:
    f.write("model,cell_size_d,finished,min_void_fraction,max_continuity_error,max_courant,"
            "dp_minus_weight_rel,dp_fluctuation_rel\n")
    for r in rows:
        f.write("%s,%s,%s,%.4f,%.3e,%.3f,%.4f,%.4f\n" % r)
with open("stress.md", "w") as f:
    f.write("| model | cell / d | finished | min alpha | max continuity error | max Co | "
            "mean dp / weight - 1 | dp fluctuation |\n|---|---|---|---|---|---|---|---|\n")
    for m, c, fin, a, ce, co, mean, fl in rows:
        f.write(f"| {m} | {c} | {'yes' if fin else 'NO'} | {a:.3f} | {ce:.1e} | {co:.2f} | "
                f"{100*mean:+.1f} % | {100*fl:.1f} % |\n")
print(open("stress.md").read())
