#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""How the coupled run's cost grows with the particles: the fluidised bed
tutorial's beads, air, inlet, cells (3 d) and steps on beds made wider and
deeper so that they hold about 10^4, 10^5 and 10^6 beads.

Each bed is packed once (beads on a lattice with a small random jitter, then
settled under gravity: insert/pack and a pour do not reach 10^6 beads in
reasonable time) and its restart reused. Each run couples a fixed number of
intervals after the packing and reports, from the solver's per-coupling log
line, the median milliseconds per coupling of each stage (DEM, exchange,
void fraction, forces, fluid), their sum against the wall time between the
log lines, the peak resident memory of the largest rank and the most
particles any rank holds.

The exchange runs put one bed on 2, 4, 8 ... ranks (more than the cores: they
count what moves, they are not timed) with reportExchange on, and record per
rank the particles and bytes it sends and receives per coupling, the ranks it
talks to, its own particles and its processor faces.

Each (bed, ranks) runs --repeats times, and the table takes the median over
the repeats of each stage's median. Resumable: each run's result is kept in
build/couplingScale/<bed>_<ranks>/ and reused unless --refresh. Writes benchmarks/couplingScale/results/
series.csv, exchange.csv, series.md and scale.png (--short writes to
build/couplingScale/short/ instead).

usage: benchmarks/couplingScale.py [--beds 1e4,1e5,1e6] [--ranks 1,2]
           [--couplings 30] [--exchange-bed 1e5] [--exchange-ranks 2,4,8]
           [--model analytical] [--repeats 3] [--refresh] [--short]
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
TUTORIAL = os.path.join(ROOT, "tutorials", "fluidisedBed")
STAGES = ("dem", "exchange", "voidfraction", "forces", "fluid")
D = 0.001                      # the tutorial's beads, m
CELL = 3*D                     # its cells
DEM_STEPS = 10                 # DEM steps per coupling, as the tutorial
# the beds: name -> beads across x and y of a lattice of LAYERS layers
# with 2 % gaps (the packing's start); the domain is the lattice's extent
# (the tutorial's is 48 x 6 mm)
GAP = 1.02
SETTLE_STEPS = 3000            # 0.03 s: the top layer falls its gaps in about 0.012 s
LAYERS = 36
BEDS = {"1e4": (47, 6), "1e5": (94, 30), "1e6": (235, 118)}
LINE = re.compile(r"^coupling (\d+): (\d+) particles \(at most (\d+) on a rank\), seconds "
                  r"DEM (\S+) exchange (\S+) voidFraction (\S+) forces (\S+) fluid (\S+);"
                  r".*; wall seconds since the last coupling (\S+)$")
EXCHANGE = re.compile(r"^exchange rank (\d+): owns (\d+) holds (\d+) sends (\d+) particles (\d+) bytes "
                      r"to (\d+) ranks receives (\d+) particles (\d+) bytes from (\d+) ranks; "
                      r"cells (\d+) processor faces (\d+) area (\S+) m2$")


def lattice_script(gap=GAP, jitter=0.005, settle=SETTLE_STEPS*1e-5):
    """The packing, from in.parameters alone (so that scaleCase -parcels
    makes the parcels' packing of it): count beads of the radius on a lattice
    of spacing gap diameters filling the width and depth, whole layers then
    the rows of a last one, moved at random by up to jitter diameters, and
    settled under gravity for settle seconds."""
    return """# The bed on a lattice with gaps and a random jitter, settled under
# gravity; writes post/packed.restart.
atom_style      granular
atom_modify     map array
boundary        p p f
newton          off
communicate     single vel yes
units           si
processors      * 1 1
include         in.parameters
variable        diameter equal 2*${radius}
variable        spacing equal %(gap)g*${diameter}
variable        nx equal floor(${width}/${spacing}+1e-6)
variable        ny equal floor(${depth}/${spacing}+1e-6)
variable        ax equal ${width}/${nx}
variable        ay equal ${depth}/${ny}
variable        layers equal floor(${count}/(${nx}*${ny})+1e-6)
variable        rows equal floor((${count}-${layers}*${nx}*${ny})/${nx}+1e-6)
variable        full equal ${layers}*${spacing}
variable        partial equal ${full}+${spacing}
variable        rowsEnd equal ${rows}*${ay}
variable        jitter equal %(jitter)g*${diameter}
variable        settleSteps equal round(%(settle)g/${demStep})
region          domain block 0 ${width} 0 ${depth} ${bottom} ${top} units box
create_box      1 domain
lattice         custom 1.0 a1 ${ax} 0 0 a2 0 ${ay} 0 a3 0 0 ${spacing} basis 0.5 0.5 0.5
region          bed block 0 ${width} 0 ${depth} 0 ${full} units box
create_atoms    1 region bed
if              "${rows} > 0" then &
                "region top block 0 ${width} 0 ${rowsEnd} ${full} ${partial} units box" &
                "create_atoms 1 region top"
set             group all diameter ${diameter} density ${density}
displace_atoms  all random ${jitter} ${jitter} ${jitter} 49979687 units box
include         in.settings
thermo          500
thermo_style    custom step atoms ke
run             ${settleSteps}
reset_timestep  0
write_restart   post/packed.restart
""" % {"gap": gap, "jitter": jitter, "settle": settle}


def edit(path, pattern, replacement):
    text = open(path).read()
    new, n = re.subn(pattern, replacement, text, flags=re.M)
    if n == 0:
        sys.exit("couplingScale: '%s' not found in %s" % (pattern, path))
    open(path, "w").write(new)


def prepare(case, bed):
    """The tutorial's case widened to the bed; returns the bead count."""
    nx, ny = BEDS[bed]
    layers = LAYERS
    width, depth = nx*GAP*D, ny*GAP*D
    count = nx*ny*layers
    if not os.path.isdir(case):
        runs = shutil.ignore_patterns("processor*", "log.*", "VTK", "post", "parcels_*", "stress", "*.png")
        shutil.copytree(TUTORIAL, case, ignore=lambda d, names: set(runs(d, names)) | {
            n for n in names if re.match(r"^[0-9.e-]+$", n)})
    params = os.path.join(case, "DEM", "in.parameters")
    # the values only: the comments carry the dimensions and marks scaleCase reads
    edit(params, r"^(variable width\s+equal\s+)\S+", r"\g<1>%.9g" % width)
    edit(params, r"^(variable depth\s+equal\s+)\S+", r"\g<1>%.9g" % depth)
    edit(params, r"^(variable count\s+equal\s+)\S+", r"\g<1>%d" % count)
    with open(os.path.join(case, "DEM", "in.lattice"), "w") as f:
        f.write(lattice_script())
    cells = [max(1, int(round(v/CELL))) for v in (width, depth, 0.120, 0.006)]
    w, d = 1e3*width, 1e3*depth
    template = open(os.path.join(case, "system", "blockMeshDict.template")).read()
    vertices = ("    (0 0 -6) ({w:.9g} 0 -6) ({w:.9g} {d:.9g} -6) (0 {d:.9g} -6)\n"
                "    (0 0 0) ({w:.9g} 0 0) ({w:.9g} {d:.9g} 0) (0 {d:.9g} 0)\n"
                "    (0 0 120) ({w:.9g} 0 120) ({w:.9g} {d:.9g} 120) (0 {d:.9g} 120)\n").format(w=w, d=d)
    template, n = re.subn(r"vertices\s*\(.*?\n\);", "vertices\n(\n" + vertices + ");", template, flags=re.S)
    if n != 1:
        sys.exit("couplingScale: no vertices in the tutorial's blockMeshDict.template")
    for key, value in (("NX", cells[0]), ("NY", cells[1]), ("NZP", cells[3]), ("NZ", cells[2])):
        template = template.replace(key, str(value))
    open(os.path.join(case, "system", "blockMeshDict"), "w").write(template)
    return count, cells[0]*cells[1]*(cells[2] + cells[3])


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as out:
        rc = subprocess.call(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, shell=True)
    if rc != 0:
        sys.exit("couplingScale: '%s' failed in %s, see %s" % (cmd, cwd, log))


def pack(work, bed):
    """Packs the bed once, in work/packed_<bed>; returns the restart's
    path and the packing's wall seconds."""
    case = os.path.join(work, "packed_" + bed)
    count, _ = prepare(case, bed)
    post = os.path.join(case, "DEM", "post")
    restart, stamp = os.path.join(post, "packed.restart"), os.path.join(post, "packing.seconds")
    if os.path.exists(restart) and os.path.exists(stamp):
        return restart, float(open(stamp).read())
    os.makedirs(post, exist_ok=True)
    print("  packing %d beads (%d settling steps on 2 ranks)" % (count, SETTLE_STEPS), flush=True)
    start = time.time()
    sh("mpirun -np 2 liggghts -in in.lattice -log post/log.packing -screen post/screen.packing",
       os.path.join(case, "DEM"), "post/log.mpirun")
    seconds = time.time() - start
    open(stamp, "w").write("%.1f\n" % seconds)
    return restart, seconds


def prepare_packed(work, case, bed):
    """A case of the bed with the packed restart; returns the bead count,
    cells and packing seconds."""
    restart, seconds = pack(work, bed)
    count, cells = prepare(case, bed)
    os.makedirs(os.path.join(case, "DEM", "post"), exist_ok=True)
    shutil.copy(restart, os.path.join(case, "DEM", "post", "packed.restart"))
    return count, cells, seconds


# each rank's peak resident memory, written by a wrapper around it
RSS_WRAPPER = ("import os, resource, subprocess, sys; rc = subprocess.call(sys.argv[1:]); "
               "open('rss.%s' % os.environ.get('OMPI_COMM_WORLD_RANK', '0'), 'w').write("
               "str(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)); sys.exit(rc)")


def couple(case, ranks, couplings, model, report_exchange=False, write_at_end=False):
    """Runs the coupled solver for couplings intervals; returns its log."""
    for entry in os.listdir(case):
        path = os.path.join(case, entry)
        if entry.startswith("processor") or entry in ("0", "VTK", "postProcessing") or \
           re.match(r"^[0-9.e-]+$", entry):
            shutil.rmtree(path)
        elif entry.startswith("rss."):
            os.remove(path)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    props = os.path.join(case, "constant", "couplingProperties")
    edit(props, r"^voidFractionModel\s+\w+;", "voidFractionModel   %s;" % model)
    text = re.sub(r"^reportExchange.*\n", "", open(props).read(), flags=re.M)
    open(props, "w").write(text + ("reportExchange      true;\n" if report_exchange else ""))
    control = os.path.join(case, "system", "controlDict")
    end = couplings*1e-4
    edit(control, r"^endTime\s+\S+;", "endTime         %g;" % end)
    edit(control, r"^writeInterval\s+\S+;", "writeInterval   %d;" % (couplings if write_at_end else 1000000))
    decompose = os.path.join(case, "system", "decomposeParDict")
    edit(decompose, r"^numberOfSubdomains .*;", "numberOfSubdomains %d;" % ranks)
    edit(decompose, r"n\s*\(\s*\d+ 1 1\s*\)", "n (%d 1 1)" % ranks)
    sh("blockMesh", case, "log.blockMesh")
    solver = "%s -c \"%s\" pimpleDEMFoam" % (sys.executable, RSS_WRAPPER)
    if ranks > 1:
        sh("decomposePar -force", case, "log.decomposePar")
        # the exchange counts run more ranks than cores (not timed)
        sh("mpirun --oversubscribe -np %d %s -parallel" % (ranks, solver), case, "log.pimpleDEMFoam")
    else:
        sh(solver, case, "log.pimpleDEMFoam")
    return os.path.join(case, "log.pimpleDEMFoam")


def measure(log, skip):
    rows = []
    for line in open(log):
        m = LINE.match(line.strip())
        if m:
            rows.append([int(m.group(i)) for i in (1, 2, 3)] + [float(m.group(i)) for i in range(4, 10)])
    if len(rows) <= skip + 2:
        sys.exit("couplingScale: only %d coupling lines in %s" % (len(rows), log))
    kept = rows[skip:]
    result = {s: 1e3*statistics.median(r[3 + i] for r in kept) for i, s in enumerate(STAGES)}
    result["stage_sum_ms"] = 1e3*statistics.median(sum(r[3:8]) for r in kept)
    result["total_ms"] = 1e3*statistics.median(r[8] for r in kept)
    # the timed stages' share of the wall time over all kept couplings (medians need not add up)
    result["stage_share"] = sum(sum(r[3:8]) for r in kept)/max(sum(r[8] for r in kept), 1e-300)
    result["particles"] = kept[-1][1]
    result["max_held"] = max(r[2] for r in kept)
    result["measured"] = len(kept)
    return result


def peak_rss_mb(case, ranks):
    values = []
    for rank in range(ranks):
        path = os.path.join(case, "rss.%d" % rank)
        if os.path.exists(path):
            values.append(int(open(path).read())/1024.0)
    if len(values) != ranks:
        sys.exit("couplingScale: the peak memory of %d of %d ranks in %s" % (len(values), ranks, case))
    return max(values)


def series_run(work, bed, ranks, couplings, model, refresh, estimate, repeats):
    """The bed on ranks, repeats times (kept as result_<k>.json); each
    stage's median per coupling, the median over the repeats."""
    case = os.path.join(work, "%s_%d" % (bed, ranks))
    kept = []
    for k in range(1, repeats + 1):
        keep = os.path.join(case, "result_%d.json" % k)
        if os.path.exists(keep) and not refresh:
            result = json.load(open(keep))
            if result.get("couplings") == couplings and result.get("model") == model:
                print("  %s beads on %d rank(s), repeat %d: kept from %s" % (bed, ranks, k, keep), flush=True)
                kept.append(result)
                continue
        count, cells, packing = prepare_packed(work, case, bed)
        guess = estimate(count, ranks, couplings)
        print("  %s beads (%d) on %d rank(s), %d couplings, repeat %d of %d%s" % (
            bed, count, ranks, couplings, k, repeats, " (about %.0f s)" % guess if guess else ""), flush=True)
        start = time.time()
        log = couple(case, ranks, couplings, model)
        result = measure(log, skip=max(2, couplings//6))
        result.update({"bed": bed, "ranks": ranks, "cells": cells, "couplings": couplings, "model": model,
                       "packing_s": packing, "peak_rss_mb": peak_rss_mb(case, ranks),
                       "wall_s": time.time() - start})
        json.dump(result, open(keep, "w"), indent=1)
        print("    %.0f ms per coupling (%s), peak %.0f MB" % (result["total_ms"], ", ".join(
            "%s %.1f" % (s, result[s]) for s in STAGES), result["peak_rss_mb"]), flush=True)
        kept.append(result)
    median = dict(kept[0])
    for key, value in kept[0].items():
        if isinstance(value, float) and key not in ("packing_s",):
            median[key] = statistics.median(r[key] for r in kept)
    median["max_held"] = max(r["max_held"] for r in kept)
    median["repeats"] = len(kept)
    return median


def exchange_runs(work, bed, ranks_list, model, refresh):
    rows = []
    for ranks in ranks_list:
        case = os.path.join(work, "exchange_%s_%d" % (bed, ranks))
        keep = os.path.join(case, "exchange.json")
        if os.path.exists(keep) and not refresh:
            rows += json.load(open(keep))
            print("  exchange, %s beads on %d ranks: kept" % (bed, ranks), flush=True)
            continue
        count, _, _ = prepare_packed(work, case, bed)
        print("  exchange, %s beads on %d ranks (oversubscribed, not timed)" % (bed, ranks), flush=True)
        log = couple(case, ranks, 3, model, report_exchange=True, write_at_end=True)
        lines = [EXCHANGE.match(l.strip()) for l in open(log)]
        lines = [m for m in lines if m][-ranks:]
        if len(lines) != ranks:
            sys.exit("couplingScale: %d exchange lines for %d ranks in %s" % (len(lines), ranks, log))
        names = ("rank", "owns", "holds", "sent", "sent_bytes", "sent_to", "received", "received_bytes",
                 "received_from", "cells", "processor_faces")
        result = []
        for m in lines:
            row = {"ranks": ranks, "particles": count}
            row.update({n: int(m.group(i + 1)) for i, n in enumerate(names)})
            row["processor_area_m2"] = float(m.group(12))
            result.append(row)
        json.dump(result, open(keep, "w"), indent=1)
        rows += result
    return rows


SERIES_COLUMNS = ("particles", "ranks", "cells", "couplings", "dem_ms", "exchange_ms", "voidfraction_ms",
                  "forces_ms", "fluid_ms", "stage_sum_ms", "total_ms", "peak_rss_mb", "max_held",
                  "packing_s")


def write_series(out, results):
    with open(os.path.join(out, "series.csv"), "w") as f:
        f.write(",".join(SERIES_COLUMNS) + "\n")
        for r in results:
            values = {c: r.get(c[:-3] if c.endswith("_ms") and c[:-3] in STAGES else c) for c in SERIES_COLUMNS}
            f.write(",".join(("%.6g" % v) if isinstance(v, float) else str(v) for v in
                             (values[c] for c in SERIES_COLUMNS)) + "\n")


def write_exchange(out, rows):
    columns = ("particles", "ranks", "rank", "owns", "holds", "sent", "sent_bytes", "sent_to", "received",
               "received_bytes", "received_from", "cells", "processor_faces", "processor_area_m2")
    with open(os.path.join(out, "exchange.csv"), "w") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(str(r[c]) for c in columns) + "\n")


def write_table(out, results, rows):
    lines = ["| particles | ranks | cells | " + " | ".join("%s ms" % s for s in STAGES)
             + " | sum / wall ms | µs per particle: DEM step, exchange, void fraction, forces "
             "| fluid µs per cell | peak MB (per 10^6 particles) | most held | packing s |",
             "|" + "---|" * 13]
    for r in results:
        n, ranks = r["particles"], r["ranks"]
        per = lambda s: 1e3*r[s]/(n/ranks)
        lines.append("| %d | %d | %d | %s | %.0f / %.0f | %.3f, %.3f, %.3f, %.3f | %.2f | %.0f (%.0f) | %d | %.0f |" % (
            n, ranks, r["cells"], " | ".join("%.1f" % r[s] for s in STAGES), r["stage_sum_ms"], r["total_ms"],
            per("dem")/DEM_STEPS, per("exchange"), per("voidfraction"), per("forces"),
            1e3*r["fluid"]/(r["cells"]/ranks), r["peak_rss_mb"], r["peak_rss_mb"]*1e6*ranks/n,
            r["max_held"], r["packing_s"]))
    lines += ["", "Per coupling, the median after the first sixth of the couplings, median over %d "
              "repeats; µs per particle " % min(r.get("repeats", 1) for r in results) +
              "of a rank's share (particles / ranks). The exchange:", "",
              "| ranks | rank | owns | holds | sends (bytes) to ranks | receives (bytes) from ranks "
              "| cells | processor faces |", "|" + "---|" * 8]
    for r in rows:
        lines.append("| %d | %d | %d | %d | %d (%d) to %d | %d (%d) from %d | %d | %d |" % (
            r["ranks"], r["rank"], r["owns"], r["holds"], r["sent"], r["sent_bytes"], r["sent_to"],
            r["received"], r["received_bytes"], r["received_from"], r["cells"], r["processor_faces"]))
    lines += projection(rows)[0]
    open(os.path.join(out, "series.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def projection(rows):
    """From the measured exchange: particles sent per m2 of processor
    interface, bytes per particle sent, and what columns of a bed (the full
    height, a square grid of ranks across the width and depth) would send on
    hundreds of ranks."""
    if not rows:
        return [], None
    sigma = statistics.median(r["sent"]/r["processor_area_m2"] for r in rows if r["processor_area_m2"] > 0)
    per_particle = statistics.median(r["sent_bytes"]/r["sent"] for r in rows if r["sent"])
    lines = ["", "Measured: %.3g particles sent per m2 of processor interface, %.0f bytes per particle "
             "sent (positions out; the forces come back for the same particles). Projected for the "
             "10^6 bed split into columns of the full height:" % (sigma, per_particle), "",
             "| ranks | columns | owned per rank | sent per rank | share of owned | bytes per rank "
             "| ranks talked to |", "|---|---|---|---|---|---|---|"]
    nx, ny = BEDS["1e6"]
    width, depth, height = nx*GAP*D, ny*GAP*D, 0.126
    count = nx*ny*LAYERS
    for px, py in ((8, 4), (16, 8), (16, 16), (32, 32)):
        ranks = px*py
        area = 2*(width/px + depth/py)*height
        sent = sigma*area
        lines.append("| %d | %d x %d | %d | %.0f | %.0f %% | %.0f kB | 8 |" % (
            ranks, px, py, count/ranks, sent, 100*sent/(count/ranks), sent*per_particle/1e3))
    return lines, sigma


def plot(out, results):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("couplingScale: no matplotlib, no plot")
        return
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for ranks, style in ((1, "-o"), (2, "--s")):
        rs = sorted((r for r in results if r["ranks"] == ranks), key=lambda r: r["particles"])
        if not rs:
            continue
        for i, s in enumerate(STAGES + ("total",)):
            key = "total_ms" if s == "total" else s
            ax.loglog([r["particles"] for r in rs], [r[key] for r in rs], style, color="C%d" % i,
                      label="%s" % s if ranks == 1 else None)
    ax.set_xlabel("particles")
    ax.set_ylabel("ms per coupling (%d DEM steps)" % DEM_STEPS)
    ax.set_title("coupled run, cells of 3 d: 1 rank (solid), 2 ranks (dashed)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "scale.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--beds", default="1e4,1e5,1e6")
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--couplings", type=int, default=30)
    parser.add_argument("--exchange-bed", default="1e5")
    parser.add_argument("--exchange-ranks", default="2,4,8")
    parser.add_argument("--model", default="analytical")
    parser.add_argument("--repeats", type=int, default=3, help="runs of each (bed, ranks); medians over them")
    parser.add_argument("--refresh", action="store_true")
    parser.add_argument("--short", action="store_true", help="the 10^4 bed, a few couplings, into build/")
    args = parser.parse_args()
    if args.short:
        args.beds, args.couplings, args.exchange_bed, args.exchange_ranks = "1e4", 30, "1e4", "2,3"
    beds = args.beds.split(",")
    for bed in beds + [args.exchange_bed]:
        if bed not in BEDS:
            sys.exit("couplingScale: unknown bed '%s' (known: %s)" % (bed, ", ".join(BEDS)))
    ranks_list = [int(r) for r in args.ranks.split(",")]
    work = os.path.join(ROOT, "build", "couplingScale") + ("/short" if args.short else "")
    out = work if args.short else os.path.join(ROOT, "benchmarks", "couplingScale", "results")
    os.makedirs(work, exist_ok=True)
    os.makedirs(out, exist_ok=True)
    os.environ.setdefault("VFM_PROJECT_DIR", ROOT)

    results = []

    def estimate(count, ranks, couplings):
        # from the last run: time per particle and coupling, plus start-up
        if not results:
            return 0
        last = results[-1]
        return 20 + couplings*last["total_ms"]*1e-3*(count/last["particles"])*(last["ranks"]/ranks)

    print("couplingScale: beds %s on %s rank(s), %d couplings each, %s" % (
        ", ".join(beds), args.ranks, args.couplings, args.model), flush=True)
    for bed in beds:
        for ranks in ranks_list:
            results.append(series_run(work, bed, ranks, args.couplings, args.model, args.refresh, estimate,
                                      1 if args.short else args.repeats))
    rows = exchange_runs(work, args.exchange_bed, [int(r) for r in args.exchange_ranks.split(",")],
                         args.model, args.refresh)
    write_series(out, results)
    write_exchange(out, rows)
    write_table(out, results, rows)
    plot(out, results)
    print("couplingScale: written to %s" % out)


if __name__ == "__main__":
    main()
