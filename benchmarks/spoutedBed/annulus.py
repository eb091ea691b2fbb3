#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The annulus of spouted bed runs: how densely its particles pack and what
share of the gas passes through it rather than the spout. The bed is 40 mm
deep between its front and back walls: 16 beads, but 8, 5.3 and 4 parcels at
h = 2, 3 and 4, and spheres pack looser within a diameter of a wall, so the
coarse annulus is the more permeable one. Writes results/annulus.csv, one row
per run:

  run               the run's case, under build/spoutedBed/
  spout_m_s         its front-wall particle speed over the channel (the
                    24 mm over it, the six heights' profiles averaged)
  parcel_mm         its particles' diameter
  depth_in_parcels  the bed's 40 mm depth over it
  cells             the fluid's cells
  annulus_solids    solids volume fraction of the annulus (|x| > 40 mm,
                    30 mm < z < 150 mm), averaged over the snapshots after 1 s
  gas_share_z050    the share of the gas's upward volume flux that passes
  gas_share_z100    outside the 24 mm over the channel, in the layer of cells
  gas_share_z150    nearest z = 50, 100 and 150 mm, averaged over the fields
                    written after 1 s (reconstructed where they are not)
  times             the snapshots and fields averaged

usage: annulus.py CASE...   CASE: a run's case folder, for example
                            build/spoutedBed/analytical_h4/parcels_h4"""
import csv
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RUNS = os.path.join(ROOT, "build", "spoutedBed")
sys.path[:0] = [os.path.join(ROOT, "tests"), os.path.join(ROOT, "tutorials")]
import caseProperties  # noqa: E402
import particleVtk  # noqa: E402
from foamCase import read_scalar_field, read_vector_field, sh  # noqa: E402
from compare import CHANNEL_HALF_WIDTH_MM, profiles  # noqa: E402

START_UP = 1.0                  # s, as plotSpoutedBed.py
SPOUT_HALF_WIDTH = CHANNEL_HALF_WIDTH_MM/1000
ANNULUS_X, ANNULUS_Z = 0.04, (0.03, 0.15)   # m, clear of the spout's edge and the bed's surface
LAYERS = (0.05, 0.10, 0.15)     # m


def annulus_solids(case):
    """(solids fraction of the annulus averaged over the snapshots after the
    start-up, their number)"""
    box = caseProperties.dem_parameters(case)
    half, depth = box["halfWidth"], box["depth"]
    volume = 2*(half - ANNULUS_X)*depth*(ANNULUS_Z[1] - ANNULUS_Z[0])
    dt = caseProperties._entry(os.path.join(case, "system", "controlDict"), "deltaT")
    fractions = []
    for f in particleVtk.files(case):
        if particleVtk.step(f)*dt <= START_UP:
            continue
        x, r, _ = particleVtk.read(f)
        inside = (np.abs(x[:, 0]) > ANNULUS_X) & (x[:, 2] > ANNULUS_Z[0]) & (x[:, 2] < ANNULUS_Z[1])
        fractions.append(np.sum(4/3*np.pi*r[inside]**3)/volume)
    return (float(np.mean(fractions)) if fractions else float("nan")), len(fractions)


def written_times(case, where=""):
    """The times after the start-up with the fluid's fields (in where)"""
    folder = os.path.join(case, where)
    if not os.path.isdir(folder):
        return []
    return sorted((d for d in os.listdir(folder) if re.fullmatch(r"\d+(\.\d+)?", d) and float(d) > START_UP
                   and os.path.isfile(os.path.join(folder, d, "alpha"))), key=float)


def gas_shares(case):
    """([annulus share of the upward gas flux at each of LAYERS], fields
    averaged, cells)"""
    # the time folders hold the DEM's files, so reconstructPar -newTimes would skip them
    missing = sorted(set(written_times(case, "processor0")) - set(written_times(case)), key=float)
    if missing:
        sh("reconstructPar -time '%s' -fields '(U alpha)' > log.reconstructPar.annulus 2>&1"
           % ",".join(missing), case)
    sh("postProcess -func writeCellCentres -time 0 > /dev/null && "
       "postProcess -func writeCellVolumes -time 0 > /dev/null", case)
    centres = np.array(read_vector_field(os.path.join(case, "0", "C")))
    volumes = np.array(read_scalar_field(os.path.join(case, "0", "V")))
    levels = np.unique(np.round(centres[:, 2], 7))
    layers = [np.abs(centres[:, 2] - levels[np.argmin(np.abs(levels - z))]) < 1e-6 for z in LAYERS]
    outside = np.abs(centres[:, 0]) > SPOUT_HALF_WIDTH
    shares = []
    times = written_times(case)
    for t in times:
        alpha = np.array(read_scalar_field(os.path.join(case, t, "alpha")))
        uz = np.array(read_vector_field(os.path.join(case, t, "U")))[:, 2]
        flux = alpha*uz*volumes        # a layer's cells share its thickness
        shares.append([np.sum(flux[layer & outside])/np.sum(flux[layer]) for layer in layers])
    return (np.mean(shares, axis=0) if shares else [float("nan")]*len(LAYERS)), len(times), len(volumes)


def spout_speed(case):
    """Mean front-wall speed over the channel's bins at the six heights"""
    return float(np.nanmean(np.concatenate([speed[np.abs(x) < CHANNEL_HALF_WIDTH_MM]
                                            for x, speed in profiles(case).values()])))


def row(case):
    diameter = caseProperties.particle_diameter(case)
    depth = caseProperties.dem_parameters(case)["depth"]
    solids, snapshots = annulus_solids(case)
    shares, fields, cells = gas_shares(case)
    out = dict(run=os.path.relpath(case, RUNS), spout_m_s="%.3f" % spout_speed(case),
               parcel_mm="%.2f" % (1000*diameter),
               depth_in_parcels="%.1f" % (depth/diameter), cells=cells, annulus_solids="%.3f" % solids)
    out.update(("gas_share_z%03d" % round(1000*z), "%.3f" % s) for z, s in zip(LAYERS, shares))
    out["times"] = "%d snapshots, %d fields" % (snapshots, fields)
    return out


def main():
    cases = [os.path.abspath(c) for c in sys.argv[1:]]
    if not cases:
        raise SystemExit("usage: " + __doc__.split("usage: ")[1])
    for c in cases:
        if not os.path.isfile(os.path.join(c, "particleSpeed_H015.csv")):
            raise SystemExit("annulus.py: %s is not a spouted bed run with its profiles (no "
                             "particleSpeed_H015.csv: run plotSpoutedBed.py there)" % c)
    rows = []
    for case in cases:
        rows.append(row(case))
        print("    %(run)s: spout %(spout_m_s)s m/s, annulus solids %(annulus_solids)s, gas outside the spout %(gas_share_z050)s, "
              "%(gas_share_z100)s, %(gas_share_z150)s at z = 50, 100, 150 mm (%(times)s)" % rows[-1])
    with open(os.path.join(HERE, "results", "annulus.csv"), "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
