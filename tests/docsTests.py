#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The documentation against itself and the files it names: every relative
link in README.md and docs/ reaches a file (and, with '#', a heading of
it), and every number README.md states is written in the docs/ section
its sentence links to, where the command that remakes it is given; every result
table in docs/ equals the committed results it is written from, and those
results equal the runs' records they summarise."""
import csv
import glob
import importlib.util
import os
import re
import sys

import numpy as np

import checks
from checks import check, near
from foamCase import ROOT

LINK = re.compile(r"\]\(([^)\s]+)\)")
NUMBER = re.compile(r"[−+]?\d[\d,]*(?:\.\d+)?(?:e[−-]?\d+)?(?: %)?")


def markdown_files():
    return [os.path.join(ROOT, "README.md"), os.path.join(ROOT, "tests", "README.md")] + \
        sorted(glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))


def anchor(heading):
    """the anchor a heading gets: lower case, punctuation dropped, spaces as hyphens"""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(path):
    with open(path) as f:
        return {anchor(m.group(1)) for m in re.finditer(r"^#+\s+(.*)$", f.read(), re.M)}


def test_links():
    print("relative links in README.md and docs/ reach a file and a heading")
    n_links = 0
    for md in markdown_files():
        text = open(md).read()
        # code blocks hold no links
        text = re.sub(r"```.*?```", "", text, flags=re.S)
        for target in LINK.findall(text):
            if re.match(r"[a-z]+:", target):
                continue
            n_links += 1
            path, _, frag = target.partition("#")
            where = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
            name = "%s: %s" % (os.path.relpath(md, ROOT), target)
            if not os.path.exists(where):
                check(name + " exists", False, "(no %s)" % os.path.relpath(where, ROOT))
                continue
            if frag:
                check(name + " names a heading", frag in anchors(where),
                      "" if frag in anchors(where) else "(headings: %s)" % sorted(anchors(where))[:8])
    check("links found (the check sees them)", n_links > 30, "(%d)" % n_links)


# numbers in README that are not results: versions, the papers' years and issue
EXEMPT = re.compile(r"v1912|3\.8\.0|Debian 12|\(20\d\d\)|127\(3\)|\d-core")


def readme_blocks(text):
    """README's paragraphs, list items and table rows, code blocks left out"""
    body = re.sub(r"```.*?```", "", text, flags=re.S)
    blocks = []
    for para in re.split(r"\n\s*\n", body):
        current = []
        for line in para.split("\n"):
            if (line.startswith("|") or line.startswith("- ")) and current:
                blocks.append(" ".join(current))
                current = []
            current.append(line)
        if current:
            blocks.append(" ".join(current))
    return blocks


def section(path, name):
    """The text under the heading whose anchor is name, to the next heading
    of the same or a higher level; the whole file without a name"""
    text = open(path).read()
    if not name:
        return text
    lines = text.split("\n")
    for i, line in enumerate(lines):
        m = re.match(r"^(#+)\s+(.*)$", line)
        if m and anchor(m.group(2)) == name:
            level = len(m.group(1))
            rest = []
            for later in lines[i + 1:]:
                h = re.match(r"^(#+)\s", later)
                if h and len(h.group(1)) <= level:
                    break
                rest.append(later)
            return "\n".join(rest)
    return ""


def untraced(readme):
    """(number, block) for each number of README that is not written in a
    section of docs/ the same block links to (single digits and versions aside)"""
    missing = []
    for block in readme_blocks(readme):
        targets = [t for t in LINK.findall(block) if t.startswith("docs/")]
        plain = EXEMPT.sub("", re.sub(r"\]\([^)]*\)", "]", re.sub(r"`[^`]*`", "", block)))
        numbers = [n for n in NUMBER.findall(plain) if len(n.strip(" %−+,")) > 1 or "." in n]
        if not numbers:
            continue
        text = " ".join(section(os.path.join(ROOT, t.split("#")[0]), t.partition("#")[2])
                        for t in targets)
        text = re.sub(r"\s+", " ", text)
        missing += [(n.rstrip(","), block[:70]) for n in numbers if n.rstrip(",") not in text]
    return missing


def test_readme_numbers_in_linked_sections():
    print("each number README states is written in a section of docs/ its sentence links to")
    readme = open(os.path.join(ROOT, "README.md")).read()
    found = sum(len(NUMBER.findall(b)) for b in readme_blocks(readme))
    check("numbers found in README (the check sees them)", found >= 30, "(%d)" % found)
    for number, block in untraced(readme):
        check("README's %s ('%s...') is in the section it links to" % (number, block), False)
    check("every number of README traced to a linked section", not untraced(readme))
    # a number changed in README, or one whose block links elsewhere, is caught
    first = re.search(r"[−+]\d+\.(\d) %", readme)
    changed = str((int(first.group(1)) + 1) % 10)
    wrong_number = readme[:first.start(1)] + changed + readme[first.end(1):]
    wrong_link = readme.replace("docs/validation.md#coupled-solver", "docs/validation.md#geometry")
    for what, wrong in (("%s changed" % first.group(0), wrong_number), ("a link moved", wrong_link)):
        check("a README number not in its linked section is caught (%s)" % what,
              wrong != readme and len(untraced(wrong)) > 0)


def test_result_tables():
    print("docs/ result tables against their committed sources (docs/tables.py)")
    sys.path.insert(0, os.path.join(ROOT, "docs"))
    import tables
    blocks, problems = tables.process(write=False)
    check("generated tables found (the check sees them)", blocks >= 20, "(%d)" % blocks)
    for p in problems:
        check(p, False)
    check("every generated table equals its source", not problems, "(%d of %d differ)" % (len(problems), blocks))
    # a wrong source must be caught: one changed cell makes a table differ
    source = os.path.join(ROOT, "benchmarks", "spoutedBed", "results", "summary.csv")
    original = open(source, "rb").read()
    try:
        open(source, "wb").write(original.replace(b",", b",9", 1))
        check("a changed results file is caught", len(tables.process(write=False)[1]) == len(problems) + 1)
    finally:
        open(source, "wb").write(original)


def test_coarse_bed_tables_from_runs():
    print("the coarse-grained bed's table.md files written from its runs' records")
    sys.path.insert(0, os.path.join(ROOT, "benchmarks", "coarseGrainedBed"))
    import study
    umf = study.wen_yu_umf()
    for bed in sorted(study.BEDS):
        where, _ = study.bed_dirs(bed, study.RESULTS)
        runs = study.finished(where)
        check("%s bed: runs recorded" % bed, len(runs) >= 10, "(%d)" % len(runs))
        table = open(os.path.join(where, "table.md")).read()
        check("%s bed: table.md is its runs' table" % bed, study.table_text(study.compare(runs, umf), umf) == table)
        shares = study.finished(where, "shares")
        if shares:
            check("%s bed: shares.md is its --shares runs' table" % bed,
                  study.shares_text(shares) == open(os.path.join(where, "shares.md")).read())


def test_study_tables_from_csv():
    print("the void fraction study's tables.md written from its committed CSV files")
    study = os.path.join(ROOT, "benchmarks", "voidFractionStudy")
    # by path: docs/tables.py is also a module named tables
    spec = importlib.util.spec_from_file_location("study_tables", os.path.join(study, "tables.py"))
    study_tables = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(study_tables)
    rows = list(csv.DictReader(open(os.path.join(study, "results", "results.csv"))))
    paper = list(csv.DictReader(open(os.path.join(study, "results", "paperComparison.csv"))))
    parts = [study_tables.l12a(rows), study_tables.samples(rows), study_tables.disks(rows),
             study_tables.comparison(paper)]
    check("tables.md is the CSV files' four tables", "\n".join(parts) ==
          open(os.path.join(study, "results", "tables.md")).read())


def test_compression_tables_from_csv():
    print("the biaxial compression tables written from their committed CSV files")
    here = os.path.join(ROOT, "benchmarks", "coarseGrainingPrecision")
    spec = importlib.util.spec_from_file_location("compression", os.path.join(here, "compression.py"))
    compression = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(compression)
    for dim, name in ((2, "compression2d_size1"), (3, "compression3d_size0.75")):
        rows = compression.load_results(os.path.join(here, "results", name + ".csv"))
        check("%s: the .md is the CSV's table (%d samples)" % (name, len(rows)), len(rows) >= 25 and
              compression.table_text(rows, dim) == open(os.path.join(here, "results", name + ".md")).read())


def test_spouted_bed_summary_from_results():
    print("the spouted bed's summary.csv rows against each run's recorded .result")
    results = os.path.join(ROOT, "benchmarks", "spoutedBed", "results")
    rows = list(csv.DictReader(open(os.path.join(results, "summary.csv"))))
    check("summary rows found", len(rows) >= 1, "(%d)" % len(rows))
    for row in rows:
        path = os.path.join(results, "%s_h%s" % (row["model"], row["h"]), "spoutedBed.result")
        check("%s h = %s has its .result" % (row["model"], row["h"]), os.path.isfile(path))
        if not os.path.isfile(path):
            continue
        result = {k: float(v) for k, v in (l.split() for l in open(path))}
        for key in ("mad_h015", "mad_h045", "mad_h075", "spout_width_mm", "fountain_mm", "dp_vs_weight"):
            check("%s h = %s: %s %s is the .result's %g" % (row["model"], row["h"], key, row[key], result[key]),
                  abs(float(row[key]) - result[key]) <= 5e-4*abs(result[key]))


def test_spouted_bed_against_fine():
    print("the spouted bed's againstFine.csv against the recorded profiles (compare.py)")
    here = os.path.join(ROOT, "benchmarks", "spoutedBed")
    sys.path.insert(0, here)
    import compare
    path = os.path.join(here, "results", "againstFine.csv")
    fine = compare.default_fine()
    check("a fine run to compare with (recorded or carried)", os.path.exists(fine), "(%s)" % os.path.relpath(fine, ROOT))
    if not (os.path.isfile(path) and os.path.exists(fine)):
        return
    runs = compare.recorded()
    rows = [{k: str(v) for k, v in r.items()} for r in compare.against_fine(runs, fine)]
    kept = list(csv.DictReader(open(path)))
    check("againstFine.csv is compare.py's table of the committed results (%d rows)" % len(rows),
          rows == kept and len(rows) == sum(h != "1" for _, h, _, _ in runs))
    # a run set against itself differs by nothing; against another, by the profiles' mean gap
    coarse = [f for _, h, f, _ in runs if h != "1"]
    own = compare.profiles(coarse[0])
    check("a run against itself: no difference", compare.gaps(own, own) == (0.0, 0.0))
    if len(coarse) > 1:
        other = compare.profiles(coarse[1])
        spout = [abs(a - b) for h in compare.HEIGHTS for x, a, b in zip(own[h][0], own[h][1], other[h][1])
                 if abs(x) < 12]
        by_hand = sum(spout)/len(spout)
        check("the spout's difference is the mean over the bins within 12 mm (%.4f)" % by_hand,
              abs(compare.gaps(own, other)[0] - by_hand) < 1e-12)


def test_spouted_bed_walls():
    print("the spouted bed's walls.csv against the recorded profiles and .result files")
    here = os.path.join(ROOT, "benchmarks", "spoutedBed")
    sys.path.insert(0, here)
    import compare
    path = os.path.join(here, "results", "walls.csv")
    rows = list(csv.DictReader(open(path))) if os.path.isfile(path) else []
    check("walls.csv has runs", len(rows) >= 1, "(%d)" % len(rows))
    fine = compare.default_fine()
    if not os.path.exists(fine):
        return
    beads = compare.profiles(fine)
    noise_fine = compare.result(fine)
    kept = {(r["model"], r["h"]): r for r in csv.DictReader(open(os.path.join(here, "results", "againstFine.csv")))}
    for row in rows:
        run = os.path.join(here, "results", "walls", "%s_h%s" % (row["model"], row["h"]))
        label = "%s h = %s, walls out" % (row["model"], row["h"])
        if not os.path.isfile(os.path.join(run, "spoutedBed.result")):
            check("%s: recorded profiles" % label, False)
            continue
        spout, annulus = compare.gaps(compare.profiles(run), beads)
        own = compare.result(run)
        noise = own["halves_spout_m_s"] + noise_fine["halves_spout_m_s"]
        check("%s: spout %s from the beads' is the profiles' (%.4f)" % (label, row["spout_vs_fine_m_s"], spout),
              abs(float(row["spout_vs_fine_m_s"]) - spout) < 6e-5)
        check("%s: annulus %s, noise %s (%.4f, %.4f)" % (label, row["annulus_vs_fine_m_s"], row["noise_spout_m_s"],
                                                       annulus, noise),
              abs(float(row["annulus_vs_fine_m_s"]) - annulus) < 6e-5 and abs(float(row["noise_spout_m_s"]) - noise) < 6e-5)
        for key in ("mad_h015", "mad_h045", "mad_h075", "dp_vs_weight"):
            check("%s: %s is the .result's" % (label, key), abs(float(row[key]) - own[key]) <= 5e-4*abs(own[key]))
        same = kept.get((row["model"], row["h"]), {})
        check("%s: the walls-as-they-are column is againstFine.csv's" % label,
              row["walls_kept_spout_vs_fine_m_s"] == same.get("spout_vs_fine_m_s"))


def test_spouted_bed_closures():
    print("the spouted bed's closure study: closures.csv, closureStatistics.csv and dragRatios.md from their sources")
    here = os.path.join(ROOT, "benchmarks", "spoutedBed")
    sys.path.insert(0, here)
    import closures
    import closureStatistics as stats
    results = os.path.join(here, "results")
    check("dragRatios.md is closures.py --drag-ratios",
          open(os.path.join(results, "dragRatios.md")).read() == closures.drag_ratios() + "\n")
    rows = list(csv.DictReader(open(os.path.join(results, "closures.csv"))))
    references = {r["change"]: r for r in stats.reference_rows()}
    for row in rows:
        if row["change"] in references:
            want = references[row["change"]]
        else:
            want = stats.summary_row(row["change"], os.path.join(results, "closures", row["change"]),
                                     row["snapshots"], row["wall_s_per_sim_s"])
        check("closures.csv '%s' is its recorded profiles' row" % row["change"],
              {k: str(v) for k, v in want.items()} == row)
    changes = [r["change"] for r in rows if r["change"] not in references]
    check("closures.csv holds the references and at least one change", len(references) == 2 and changes,
          "(%s)" % ", ".join(changes))
    kept = list(csv.DictReader(open(os.path.join(results, "closureStatistics.csv"))))
    piv = stats.measured()
    for change in changes:
        table = list(csv.DictReader(open(os.path.join(results, "closures", change, "statistics.csv"))))
        profiles = {}
        for r in table:
            key = (r["statistic"], r["layer"], r["bin_mm"], float(r["H"]))
            profiles.setdefault(key, ([], []))
            profiles[key][0].append(float(r["x_mm"])/1000)
            profiles[key][1].append(float(r["speed_m_s"]))
        mean_speed = [float(r["speed_m_s"]) for r in table if r["statistic"] == "meanSpeed"]
        of_mean = [float(r["speed_m_s"]) for r in table if r["statistic"] == "speedOfMean"]
        check("%s: |mean v| <= mean |v| in every bin (%d bins)" % (change, len(of_mean)),
              len(of_mean) == len(mean_speed) > 0 and
              all(b <= a + 1e-5 for a, b in zip(mean_speed, of_mean) if a == a and b == b))
        for r in [k for k in kept if k["change"] == change]:
            for h in stats.HEIGHTS:
                x, speed = profiles[(r["statistic"], r["layer"], r["bin_mm"], h)]
                peak, mad = stats.against_piv((np.array(x), np.array(speed)), piv[h])
                tag = "%03d" % round(100*h)
                check("%s %s %s %s mm H%s: peak and difference from the PIV" % (change, r["statistic"], r["layer"],
                                                                                r["bin_mm"], tag),
                      abs(peak - float(r["peak_h" + tag])) < 1e-3 and abs(mad - float(r["mad_h" + tag])) < 1e-4)


def heated_bed_lumped(t):
    """the heatedBed tutorial's lumped balance in closed form: 10,000 glass
    beads of 1 mm (2500 kg/m3, c_p 840) at 300 K, air (1.2 kg/m3, Cp 1007)
    at 400 K through 48 x 6 mm, its velocity ramped linearly to 1 m/s over
    0.05 s: T = Tin - (Tin - T0) exp(-rho A Cp int(U dt)/(M c_p))"""
    capacity = 10000*2500*4/3*np.pi*0.0005**3*840
    flow = 1.2*0.048*0.006*1007
    passed = np.where(t < 0.05, t**2/(2*0.05), 0.025 + (t - 0.05))
    return 400 - 100*np.exp(-flow*passed/capacity)


def test_heated_bed_table():
    print("the heated bed's table: the lumped balance in closed form, the rises from the kept run")
    results = os.path.join(ROOT, "benchmarks", "tutorialRuns", "results")
    data = np.genfromtxt(os.path.join(results, "heatedBed.csv"), delimiter=",", names=True)
    t, beads, lumped = data["time_s"], data["beads_mean_K"], data["lumped_K"]
    worst = np.max(np.abs(lumped - heated_bed_lumped(t)))
    check("heatedBed.csv's lumped balance = the closed form (%d rows)" % len(t), len(t) > 100 and worst < 2e-5,
          "(%.1e K apart)" % worst)
    rows = {}
    for line in open(os.path.join(results, "heatedBed.md")):
        m = re.match(r"\| ([\d.]+) \| ([\d.]+) K \| ([\d.]+) K \| ([-+][\d.]+) % \|", line)
        if m:
            rows[float(m.group(1))] = [float(x) for x in m.groups()[1:]]
    wrong = []
    for at, (rise, model, diff) in rows.items():
        i = int(np.argmin(np.abs(t - at)))
        want_rise, want_model = beads[i] - beads[0], heated_bed_lumped(t[i]) - heated_bed_lumped(t[0])
        want_diff = 100*(want_rise/want_model - 1)
        if abs(rise - want_rise) > 6e-4 or abs(model - want_model) > 6e-4 or abs(diff - want_diff) > 0.06:
            wrong.append(at)
    check("heatedBed.md's %d rows recomputed from the CSV's beads and the closed form" % len(rows),
          len(rows) == 4 and not wrong, "(rows at %s differ)" % wrong)


def test_cylinder_parcels_table():
    print("the cylinder bed's parcels: cylinderParcels.md written from its runs' records")
    sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
    import cylinderParcels
    # the slab split: a sphere of radius 1 centred at 0.5 across [0, 2] keeps all but the cap
    # beyond -0.5, pi h^2 (3R - h)/3 with h = 0.5: 1 - 0.15625; [0, 0.5] holds 0.34375
    shares = cylinderParcels.slab_share(0.5, 1.0, np.array([0, 0.5, 1, 1.5, 2]))
    near("slab split: the sphere's share inside [0, 2]", float(shares.sum()), 1 - 0.15625, 1e-12)
    near("slab split: its share in [0, 0.5]", float(shares[0]), 0.34375, 1e-12)
    runs = cylinderParcels.finished()
    check("cylinder runs recorded: the beads and h = 2, 3 with the walls as they are and moved",
          {"beads", "h2_as", "h2_moved", "h3_as", "h3_moved"} <= set(runs), "(%s)" % sorted(runs))
    if "beads" not in runs:
        return
    table = open(os.path.join(ROOT, "benchmarks", "cylinderParcels", "cylinderParcels.md")).read()
    check("cylinderParcels.md is its runs' table", cylinderParcels.table_text(runs) == table)
    runs["beads"]["mean_solids"] += 0.001
    check("a changed record is caught", cylinderParcels.table_text(runs) != table)


def test_spouted_bed_minimum_spouting():
    print("the spouted bed's minimum spouting velocity and pressure drop against the classic results")
    here = os.path.join(ROOT, "benchmarks", "spoutedBed")
    sys.path.insert(0, here)
    import json
    import minimumSpouting as ms
    record = json.load(open(os.path.join(here, "results", "minimumSpouting.json")))
    # Mathur and Gishler (1955) in closed form: 2.5 mm glass (2500 kg/m3) in air (1.205 kg/m3),
    # H = 0.2 m; the 280 x 40 mm bed and its 24 x 40 mm channel as circles of equal area and by
    # their hydraulic diameters (4 A / perimeter)
    lift = np.sqrt(2*9.81*0.2*(2500 - 1.205)/1.205)
    for key, column, inlet in (("area", np.sqrt(0.0112*4/np.pi), np.sqrt(0.00096*4/np.pi)),
                               ("hydraulic", 4*0.0112/0.64, 4*0.00096/0.128)):
        near("Mathur-Gishler U_ms, %s diameters (m/s)" % key, record["ums_mathur_gishler_%s_m_s" % key],
             0.0025/column*(inlet/column)**(1/3)*lift, 1e-9)
    # Mamuro and Hattori: the annulus's gradient follows U_a/U_mf = 1 - (1 - z/H_m)^3, its
    # integral over the height by the trapezoidal rule; Lefroy and Davidson: a cosine profile
    z = np.linspace(0, 1, 100001)
    near("Mamuro-Hattori's ratio at H_m is the integral of 1 - (1 - z)^3",
         record["dp_ratio_mamuro_hattori_at_Hm"], float(np.trapz(1 - (1 - z)**3, z)), 1e-8)
    near("Lefroy-Davidson's ratio is the integral of sin(pi z / 2) over [0, 1]", record["dp_ratio_lefroy_davidson"],
         float(np.trapz(np.sin(np.pi*z/2), z)), 1e-8)
    # the simulated U_ms: the channel's velocity, held at 20.8 m/s to the hold and lowered linearly
    # after it, at the first snapshot after which the fountain stays under 20 mm above the packed bed
    snaps = np.array(record["snapshots"])
    after = np.nonzero((snaps[:, 1] >= 0.02) & (snaps[:, 0] > record["hold_s"]))[0]
    collapse = snaps[after[-1] + 1, 0]
    channel = 20.8 + (record["low_m_s"] - 20.8)*(collapse - record["hold_s"])/(record["end_s"] - record["hold_s"])
    near("the collapse's time (s)", record["collapse_s"], collapse, 1e-12)
    near("U_ms: the channel's velocity then, over the width (m/s)", record["ums_m_s"], channel*24/280, 1e-9)
    table = open(os.path.join(here, "results", "minimumSpouting.md")).read()
    check("minimumSpouting.md is its record's table", ms.table_text(record) == table)
    record["ums_m_s"] += 0.001
    check("a changed record is caught", ms.table_text(record) != table)


def main():
    checks.run([test_links, test_readme_numbers_in_linked_sections, test_result_tables, test_coarse_bed_tables_from_runs,
                test_study_tables_from_csv, test_compression_tables_from_csv,
                test_spouted_bed_summary_from_results, test_spouted_bed_against_fine, test_spouted_bed_walls,
                test_spouted_bed_closures,
                test_spouted_bed_minimum_spouting, test_heated_bed_table, test_cylinder_parcels_table],
               sys.argv[1:])
    return checks.summary("docs")


if __name__ == "__main__":
    sys.exit(main())
