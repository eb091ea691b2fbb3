#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""How coarse-grained parcels pack against walls, the DEM alone (no gas):
the spouted bed's glass beads (d = 2.5 mm, its contact parameters) and
parcels of h = 2, 3 and 4 poured into a slot 40 mm deep (walls at y = 0 and
40 mm, periodic in x) and, as the reference without walls, into the same
box periodic in y. Parcels follow the project's scaling (radius x h, count
/ h^3, Hertz modulus unchanged, step x h). Each run packs a bed about 120 mm
tall and writes every particle; the analysis takes the particles whose
centres lie 2.5 diameters above the floor and 2.5 below the surface and
gives, per run, the solids fraction averaged over the gap and its profile
across it (the exact volume of each sphere between two planes), and per
slot the void the walls add per unit wall area, in the particles' diameters.
Then the parcels again with their walls moved out by s = c (h - 1) d, c the
beads' wall void in diameters: a parcel packing leaves c h d per wall area
from its walls, so with every parcel's whole volume kept inside the fluid
the slot holds the beads' solids; that solids fraction is the last column.
The same for a cylinder of 30 mm (the wall moved out by the slot's rule).

usage: wallPacking.py [--factors 1,2,3,4] [--jobs 2]     runs what is missing
       wallPacking.py --analyse                          results/ from the runs
Runs go to build/wallPacking/<geometry>_h<h>/, results to
benchmarks/wallPacking/results/ (wallPacking.csv, profiles.csv, .md, .png).
"""
import argparse
import concurrent.futures
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
WORK = os.path.join(ROOT, "build", "wallPacking")
RESULTS = os.path.join(HERE, "wallPacking", "results")
DEPTH = 0.04
CYLINDER = 0.015        # the cylinder's radius
HEIGHT = 0.12           # the settled bed's height aimed at
RADIUS = 1.25e-3
SOLIDS = 0.6            # to size the count

SCRIPT = """# {label}: poured and settled, every particle written
atom_style      granular
atom_modify     map array
boundary        {boundary}
newton          off
communicate     single vel yes
units           si
region          domain block {box} 0 {top} units box
create_box      1 domain
neighbor        {skin} bin
neigh_modify    delay 0
fix m1 all property/global youngsModulus peratomtype 1.e7
fix m2 all property/global poissonsRatio peratomtype 0.25
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.3
pair_style      gran model hertz tangential history
pair_coeff      * *
timestep        {step}
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix floor all wall/gran model hertz tangential history primitive type 1 zplane 0.0
{walls}
fix integr all nve/sphere
fix pts all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant {radius}
fix pdd all particledistribution/discrete 32452843 1 pts 1.0
region          insreg {insert} {radius} {fillHigh} units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once &
    overlapcheck yes all_in yes particles_in_region {count} region insreg
thermo          10000
thermo_style    custom step atoms ke
run             {steps}
reset_timestep  0
dump final all custom 1 final.txt id x y z radius
run             0
"""


def case(geometry, h):
    return os.path.join(WORK, "%s_h%g" % (geometry, h))


def write_case(geometry, h, shift=0.0):
    """shift: the walls moved out by it (geometries "shifted" and "cylinderShifted")"""
    radius = RADIUS*h
    step = 1e-5*h
    wall = "fix %s all wall/gran model hertz tangential history primitive type 1 %s"
    if geometry.startswith("cylinder"):
        big = CYLINDER + shift
        count = int(round(SOLIDS*math.pi*CYLINDER**2*HEIGHT/(4/3*math.pi*radius**3)))
        boundary, box = "f f f", "%g %g %g %g" % (-big, big, -big, big)
        insert = "cylinder z 0 0 %g" % big
        walls = wall % ("side", "zcylinder %g 0 0" % big)
    else:
        width = max(0.04, 24*radius)          # periodic in x: 12 diameters at least
        count = int(round(SOLIDS*width*DEPTH*HEIGHT/(4/3*math.pi*radius**3)))
        boundary = "p p f" if geometry == "bulk" else "p f f"
        box = "0 %g %g %g" % (width, -shift, DEPTH + shift)
        insert = "block %s" % box
        walls = "" if geometry == "bulk" else \
            wall % ("front", "yplane %g" % -shift) + "\n" + wall % ("back", "yplane %g" % (DEPTH + shift))
    text = SCRIPT.format(label="%s, h = %g" % (geometry, h), boundary=boundary, box=box, insert=insert,
                         top=0.3, skin=0.6e-3*h, step=step, walls=walls, radius=radius, fillHigh=0.29,
                         count=count, steps=int(round(0.8/step)))
    path = case(geometry, h)
    os.makedirs(path, exist_ok=True)
    open(os.path.join(path, "in.packing"), "w").write(text)
    return path


def run(geometry, h, shift=0.0):
    path = case(geometry, h)
    if os.path.isfile(os.path.join(path, "final.txt")):
        return "%s h = %g: packed earlier" % (geometry, h)
    write_case(geometry, h, shift)
    subprocess.run(["liggghts", "-in", "in.packing", "-log", "log.packing", "-screen", "screen.packing"],
                   cwd=path, check=True)
    return "%s h = %g: packed" % (geometry, h)


def slab_volume(y, r, lo, hi):
    """the volume of spheres (centres y, radius r) between the planes lo and hi"""
    def below(t):
        # volume of the sphere under the plane y = t
        s = np.clip(t - (y - r), 0, 2*r)
        return math.pi*s*s*(3*r - s)/3
    return below(hi) - below(lo)


def analyse_run(geometry, h, bins):
    data = np.loadtxt(os.path.join(case(geometry, h), "final.txt"), skiprows=9)
    x, y, z, r = data[:, 1], data[:, 2], data[:, 3], data[:, 4][0]
    d = 2*r
    surface = np.percentile(z, 99) + r
    keep = (z > 2.5*d) & (z < surface - 2.5*d)
    if geometry.startswith("cylinder"):
        # every sphere's whole volume in the fluid: inside the wall, or kept when it reaches past
        return keep.sum()*4/3*math.pi*r**3/(math.pi*CYLINDER**2*(surface - 5*d)), None, d, surface, keep.sum()
    text = open(os.path.join(case(geometry, h), "in.packing")).read()
    width = float(text.split("region          domain block 0 ")[1].split()[0])
    box = width*DEPTH*((surface - 2.5*d) - 2.5*d)
    edges = np.linspace(0, DEPTH, bins + 1)
    profile = np.array([slab_volume(y[keep], r, lo, hi).sum() for lo, hi in zip(edges[:-1], edges[1:])])
    profile /= box/bins
    if geometry == "bulk":
        # periodic in y: the images across y = 0 and y = depth
        for shift in (-DEPTH, DEPTH):
            profile += np.array([slab_volume(y[keep] + shift, r, lo, hi).sum()
                                 for lo, hi in zip(edges[:-1], edges[1:])])/(box/bins)
    if geometry == "shifted":
        # what the fluid between y = 0 and the depth holds when the void fraction keeps every
        # parcel's whole volume: all of it, wherever the sphere reaches
        return keep.sum()*4/3*math.pi*r**3/box, profile, d, surface, keep.sum()
    return profile.mean(), profile, d, surface, keep.sum()


def wall_void(h):
    """the void the walls add per unit wall area, in diameters, from the slot and bulk runs"""
    bulk, _, d, _, _ = analyse_run("bulk", h, 160)
    slot = analyse_run("slot", h, 160)[0]
    return (bulk - slot)*DEPTH/2/(bulk*d)


def shift(h):
    """the parcels' walls moved out so that, their whole volume kept, they leave the beads'
    void per wall area: c h d - s = c d, with c the beads' (a property of the packing)"""
    return wall_void(1)*(h - 1)*2*RADIUS


def analyse(factors):
    os.makedirs(RESULTS, exist_ok=True)
    rows, profiles = [], {}
    bins = 160
    shifted, cylinder, cylinderVoid, cylinderShifted = {}, {}, {}, {}
    for h in factors:
        bulk, _, d, _, _ = analyse_run("bulk", h, bins)
        mean, profile, d, surface, n = analyse_run("slot", h, bins)
        rows.append((h, d*1e3, n, surface*1e3, bulk, mean, wall_void(h)))
        profiles[h] = profile
        if h > 1 and os.path.isfile(os.path.join(case("shifted", h), "final.txt")):
            shifted[h] = analyse_run("shifted", h, bins)[0]
        if os.path.isfile(os.path.join(case("cylinder", h), "final.txt")):
            cylinder[h] = analyse_run("cylinder", h, bins)[0]
            # the void per wall area over the cylinder's wall, R/2 of its cross-section per wall area
            cylinderVoid[h] = (bulk - cylinder[h])*CYLINDER/2/(bulk*d)
        if h > 1 and os.path.isfile(os.path.join(case("cylinderShifted", h), "final.txt")):
            cylinderShifted[h] = analyse_run("cylinderShifted", h, bins)[0]
    with open(os.path.join(RESULTS, "wallPacking.csv"), "w") as f:
        f.write("h,diameter_mm,particles_counted,surface_mm,bulk_solids,slot_solids,wall_void_diameters,"
                "wall_shift_mm,shifted_solids\n")
        for h, dmm, n, s, b, m, e in rows:
            f.write("%g,%.2f,%d,%.1f,%.4f,%.4f,%.3f,%.3f,%s\n" % (h, dmm, n, s, b, m, e, shift(h)*1e3,
                    "%.4f" % shifted[h] if h in shifted else ""))
    centres = (np.arange(bins) + 0.5)*DEPTH/bins
    with open(os.path.join(RESULTS, "profiles.csv"), "w") as f:
        f.write("y_mm," + ",".join("solids_h%g" % h for h in factors) + "\n")
        for i, yc in enumerate(centres):
            f.write("%.3f," % (yc*1e3) + ",".join("%.4f" % profiles[h][i] for h in factors) + "\n")
    for row in rows:
        print("h = %g: bulk %.4f, slot %.4f, wall void %.3f diameters" % (row[0], row[4], row[5], row[6]))
    with open(os.path.join(RESULTS, "wallPacking.md"), "w") as f:
        f.write("| h | diameter | particles counted | solids fraction, no walls | solids fraction, slot "
                "| from the beads' slot | wall void per wall area | walls moved out by | solids fraction, "
                "walls moved | from the beads' slot |\n|---|---|---|---|---|---|---|---|---|---|\n")
        for h, dmm, n, s, b, m, e in rows:
            moved = ("%.3f | %+.3f" % (shifted[h], shifted[h] - rows[0][5])) if h in shifted else "| "
            f.write("| %g | %.1f mm | %d | %.3f | %.3f | %+.3f | %.3f d | %.2f mm | %s |\n"
                    % (h, dmm, n, b, m, m - rows[0][5], e, shift(h)*1e3, moved))
    if cylinder:
        with open(os.path.join(RESULTS, "cylinder.csv"), "w") as f:
            f.write("h,cylinder_solids,wall_void_diameters,wall_shift_mm,shifted_solids\n")
            for h in sorted(cylinder):
                f.write("%g,%.4f,%.3f,%.3f,%s\n" % (h, cylinder[h], cylinderVoid[h], shift(h)*1e3,
                        "%.4f" % cylinderShifted[h] if h in cylinderShifted else ""))
        with open(os.path.join(RESULTS, "cylinder.md"), "w") as f:
            f.write("| h | solids fraction, cylinder | from the beads' | wall void per wall area | wall moved out "
                    "by | solids fraction, wall moved | from the beads' |\n|---|---|---|---|---|---|---|\n")
            for h in sorted(cylinder):
                moved = ("%.3f | %+.3f" % (cylinderShifted[h], cylinderShifted[h] - cylinder[1])
                         if h in cylinderShifted else "| ")
                f.write("| %g | %.3f | %+.3f | %.3f d | %.2f mm | %s |\n" % (h, cylinder[h], cylinder[h] - cylinder[1],
                        cylinderVoid[h], shift(h)*1e3, moved))
        for h in sorted(cylinder):
            print("cylinder h = %g: %.4f, wall void %.3f diameters%s" % (h, cylinder[h], cylinderVoid[h],
                  ", walls moved: %.4f" % cylinderShifted[h] if h in cylinderShifted else ""))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    for h in factors:
        ax.plot(centres*1e3, profiles[h], label="h = %g" % h, lw=1)
    ax.set_xlabel("y across the slot [mm]")
    ax.set_ylabel("solids fraction")
    ax.set_xlim(0, DEPTH*1e3)
    ax.set_title("poured into a slot 40 mm deep: beads (h = 1) and parcels")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "profiles.png"), dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--factors", default="1,2,3,4")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--analyse", action="store_true")
    a = p.parse_args()
    factors = [float(f) for f in a.factors.split(",")]
    if a.analyse:
        analyse(factors)
        return 0
    jobs = [(g, h) for h in factors for g in ("slot", "bulk")]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for message in pool.map(lambda j: run(*j), jobs):
            print(message, flush=True)
        # the walls moved by the rule, the beads' wall void measured above
        for message in pool.map(lambda h: run("shifted", h, shift(h)), [h for h in factors if h > 1]):
            print(message, flush=True)
        # a cylinder of 30 mm, and the parcels' wall moved out by the slot's rule
        jobs = [("cylinder", h, 0.0) for h in factors] + \
            [("cylinderShifted", h, shift(h)) for h in factors if h > 1]
        for message in pool.map(lambda j: run(*j), jobs):
            print(message, flush=True)
    analyse(factors)
    return 0


if __name__ == "__main__":
    sys.exit(main())
