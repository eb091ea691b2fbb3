#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""voidFractionBenchmark: its Eq. 21 error against an independent computation
from the fields demVoidFraction writes, its CSV, and bad input."""
import csv
import os
import sys

import checks
from checks import WORK, check, near, run_model
from foamCase import box_block_mesh, new_case, random_spheres, read_scalar_field, sh, write_dump

L = 0.03


def bench_dict(body, csv_name="bench.csv"):
    return ("FoamFile { version 2.0; format ascii; class dictionary; object voidFractionBenchmarkDict; }\n"
            "reference { voidFractionModel analytical; }\nrepeat 2;\ncsv \"%s\";\n%s" % (csv_name, body))


def test_error_and_csv():
    print("voidFractionBenchmark: Eq. 21 against the fields, CSV rows")
    case = new_case(os.path.join(WORK, "bench"), box_block_mesh((0, 0, 0), (L, L, L), (5, 5, 5)),
                    coupling="voidFractionModel analytical;\nalphaMin 0;\n")
    c, r = random_spheres(600, 0.0005, 0.0012, (0, 0, 0), (L, L, L), seed=31)
    write_dump(os.path.join(case, "p.dump"), c, r)
    fields = {}
    for model in ("analytical", "centroid", "kernel"):
        run_model(case, "p.dump", model, "-name vf_" + model)
        fields[model] = read_scalar_field(os.path.join(case, "0", "vf_" + model))
    with open(os.path.join(case, "system", "voidFractionBenchmarkDict"), "w") as f:
        f.write(bench_dict("runs { pcm { voidFractionModel centroid; } k { voidFractionModel kernel; parameter 0.4; } }\n"))
    if os.path.exists(os.path.join(case, "bench.csv")):
        os.remove(os.path.join(case, "bench.csv"))
    rc, out = sh("voidFractionBenchmark -dump p.dump -sample s1", case, check=False)
    check("voidFractionBenchmark runs", rc == 0, out[-400:] if rc else "")
    rows = list(csv.DictReader(open(os.path.join(case, "bench.csv"))))
    check("one CSV row per run plus the reference", [r["run"] for r in rows] == ["reference", "pcm", "k"],
          str([r["run"] for r in rows]))
    ref = fields["analytical"]
    for run, model in (("pcm", "centroid"), ("k", "kernel")):
        want = 100 * sum(abs(a - b) / b for a, b in zip(fields[model], ref)) / len(ref)
        got = next(float(r["error_percent"]) for r in rows if r["run"] == run)
        near("%s: Eq. 21 error = the fields' (rel)" % model, got / want, 1, 1e-6)
    check("reference error is 0 and all conserve",
          float(rows[0]["error_percent"]) == 0 and all(float(r["conservation"]) < 1e-12 for r in rows))
    check("parameter and sample columns", rows[2]["parameter"] == "0.4" and rows[1]["sample"] == "s1")


def test_bad_input():
    print("voidFractionBenchmark: bad input")
    case = new_case(os.path.join(WORK, "bench-bad"), box_block_mesh((0, 0, 0), (L, L, L), (3, 3, 3)))
    write_dump(os.path.join(case, "p.dump"), [(0.01, 0.01, 0.01)], [0.001])
    cases = [
        ("a run that is not a dictionary", bench_dict("runs { pcm centroid; }\n"), "pcm is not a dictionary"),
        ("an unknown model", bench_dict("runs { x { voidFractionModel nonsense; } }\n"), "nonsense"),
        ("no runs", bench_dict(""), "runs"),
        ("an unwritable CSV", bench_dict("runs { }\n", "/nonexistent/dir/b.csv"), "cannot write the CSV"),
    ]
    for name, text, needle in cases:
        with open(os.path.join(case, "system", "voidFractionBenchmarkDict"), "w") as f:
            f.write(text)
        rc, out = sh("voidFractionBenchmark -dump p.dump", case, check=False)
        check("%s: error says '%s'" % (name, needle), rc != 0 and needle in out and "Segmentation" not in out)


def main():
    checks.run([test_error_and_csv, test_bad_input], sys.argv[1:])
    return checks.summary("benchmark")


if __name__ == "__main__":
    sys.exit(main())
