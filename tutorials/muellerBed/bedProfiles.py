#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The time-averaged profiles of a muellerBed run.

    bedProfiles.py --probes NX NZ   the probe locations for system/probeLocations:
                                    the cell centres of the rows either side of
                                    each measured height, on the mesh Allrun makes
    bedProfiles.py [--start T]      after a run: the averages over t > T (default
                                    the first second, or a third of shorter runs)

The void fraction across the width at each height is interpolated linearly in
z between the two rows of cell centres around it, and averaged in time (the
depth is one cell). The particles' vertical velocity is averaged over the
particles in a slice one diameter thick at each height, in 2 mm bins across
the width, weighted by particle (as a magnetic resonance time average is).
Each average is also taken over the two halves of the window: their mean
difference says how converged it is. Writes postProcessing/profiles/*.csv,
muellerBed.result and muellerBed.png; profiles under measured/ with the same
names as the written ones are drawn beside them."""
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("VFM_PROJECT_DIR",
                                               os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")),
                                "tutorials"))
import caseProperties

PARAMETERS = caseProperties.dem_parameters(".")
WIDTH, DEPTH, TOP = PARAMETERS["width"], PARAMETERS["depth"], PARAMETERS["top"]
HEIGHTS = (PARAMETERS["sliceLow"], PARAMETERS["sliceHigh"])
BIN = 0.002


def label(height):
    return "h%.1fmm" % (1000*height)


def probe_locations(nx, nz):
    dz = TOP/nz
    points = []
    for h in HEIGHTS:
        below = min(max(int(np.floor(h/dz - 0.5)), 0), nz - 2)
        for row in (below, below + 1):
            points += [((i + 0.5)*WIDTH/nx, DEPTH/2, (row + 0.5)*dz) for i in range(nx)]
    return "probeLocations\n(\n%s\n);\n" % "\n".join("    (%.9g %.9g %.9g)" % p for p in points)


def read_probes():
    """(times, probe points, values), over every start directory of a restarted run"""
    files = sorted(glob.glob("postProcessing/voidFraction/*/alpha"), key=lambda f: float(f.split("/")[-2]))
    if not files:
        raise SystemExit("bedProfiles: no postProcessing/voidFraction/*/alpha: has the run written probes?")
    points = [tuple(map(float, m)) for m in
              re.findall(r"# Probe \d+ \((\S+) (\S+) (\S+)\)", open(files[0]).read())]
    rows = np.vstack([np.loadtxt(f, comments="#", ndmin=2) for f in files])
    _, first = np.unique(rows[:, 0], return_index=True)
    rows = rows[first]
    return rows[:, 0], np.array(points), rows[:, 1:]


def windows(t, start):
    mid = 0.5*(start + t[-1])
    return {"all": t > start, "first half": (t > start) & (t <= mid), "second half": t > mid}


def void_fraction_profiles(start):
    t, points, values = read_probes()
    profiles = {}
    for h in HEIGHTS:
        levels = np.unique(points[:, 2])
        z0, z1 = levels[levels <= h].max(initial=levels.min()), levels[levels > h].min(initial=levels.max())
        lower, upper = np.isclose(points[:, 2], z0), np.isclose(points[:, 2], z1)
        weight = (h - z0)/(z1 - z0) if z1 > z0 else 0.0
        at_height = (1 - weight)*values[:, lower] + weight*values[:, upper]
        profiles[h] = (points[lower, 0], {k: at_height[w].mean(axis=0) for k, w in windows(t, start).items()})
    return profiles


def read_slices(path):
    """per snapshot: time step, x, vz of the particles in the slice"""
    snapshots, lines, i = [], open(path).read().split("\n"), 0
    while i < len(lines) and lines[i].startswith("ITEM: TIMESTEP"):
        step, n = int(lines[i + 1]), int(lines[i + 3])
        columns = lines[i + 8].split()[2:]
        data = np.array([l.split() for l in lines[i + 9:i + 9 + n]], float).reshape(n, len(columns))
        snapshots.append((step, data[:, columns.index("x")], data[:, columns.index("vz")]))
        i += 9 + n
    return snapshots


def velocity_profiles(start):
    edges = np.linspace(0, WIDTH, int(round(WIDTH/BIN)) + 1)
    dt = PARAMETERS["demStep"]
    profiles = {}
    for h, name in zip(HEIGHTS, ("low", "high")):
        snapshots = read_slices(os.path.join("DEM", "post", "slice_%s.dump" % name))
        t = np.array([s[0]*dt for s in snapshots])
        sums = np.array([np.histogram(s[1], edges, weights=s[2])[0] for s in snapshots])
        counts = np.array([np.histogram(s[1], edges)[0] for s in snapshots])
        profiles[h] = (0.5*(edges[1:] + edges[:-1]),
                       {k: sums[w].sum(axis=0)/np.maximum(counts[w].sum(axis=0), 1)
                        for k, w in windows(t, start).items()})
    return profiles


def write_csv(path, x, values, column):
    np.savetxt(path, np.column_stack([x, values]), fmt="%.6g", delimiter=",",
               header="x_m,%s" % column, comments="")


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--probes":
        sys.stdout.write(probe_locations(int(sys.argv[2]), int(sys.argv[3])))
        return
    t_dp = np.loadtxt("postProcessing/inletPressure/0/surfaceFieldValue.dat", comments="#", ndmin=2)
    end = t_dp[-1, 0]
    start = float(sys.argv[sys.argv.index("--start") + 1]) if "--start" in sys.argv else min(1.0, end/3)
    nu, rho_f, _ = caseProperties.fluid()
    rho_p, g, d = caseProperties.particle_density(), caseProperties.gravity(), caseProperties.particle_diameter()
    weight = PARAMETERS["count"]*np.pi/6*d**3*(rho_p - rho_f)*g/(WIDTH*DEPTH)
    dp = rho_f*t_dp[t_dp[:, 0] > start, 1].mean()
    bed = np.loadtxt("DEM/post/bed.txt", comments="#", ndmin=2)
    height = 2*bed[bed[:, 0] > start, 1].mean()

    os.makedirs("postProcessing/profiles", exist_ok=True)
    result = {"start_s": start, "end_s": end, "dp_Pa": dp, "weight_Pa": weight, "dp_over_weight": dp/weight,
              "bed_height_m": height}
    kinds = (("voidfraction", void_fraction_profiles(start), "voidfraction"),
             ("particleVelocity", velocity_profiles(start), "vz_m_s"))
    print("averages over %.4g to %.4g s:" % (start, end))
    print("    pressure drop %.4g Pa, bed weight per area %.4g Pa (ratio %.4g); bed height (twice the "
          "particles' mean height) %.4g mm" % (dp, weight, dp/weight, 1000*height))
    for kind, profiles, column in kinds:
        for h, (x, averages) in profiles.items():
            name = "%s_%s" % (kind, label(h))
            write_csv("postProcessing/profiles/%s.csv" % name, x, averages["all"], column)
            halves = np.abs(averages["first half"] - averages["second half"]).mean()
            result[name + "_mean"] = averages["all"].mean()
            result[name + "_halves"] = halves
            print("    %s at %.1f mm: mean %.4g, halves differ by %.3g on average"
                  % (kind, 1000*h, averages["all"].mean(), halves))
    with open("muellerBed.result", "w") as f:
        f.writelines("%s %.8g\n" % kv for kv in result.items())
    plot(kinds)
    print("profiles in postProcessing/profiles/, plot muellerBed.png")


def plot(kinds):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    model = re.search(r"(?m)^voidFractionModel\s+(\w+);", open("constant/couplingProperties").read()).group(1)
    fig, axes = plt.subplots(2, 2, figsize=(9, 6.5), sharex=True)
    for col, (kind, profiles, column) in enumerate(kinds):
        for row, (h, (x, averages)) in enumerate(sorted(profiles.items(), reverse=True)):
            ax = axes[row, col]
            for half in ("first half", "second half"):
                ax.plot(1000*x, averages[half], lw=0.8, alpha=0.5, label=half)
            ax.plot(1000*x, averages["all"], "k-", lw=1.6, label=model)
            measured = os.path.join("measured", "%s_%s.csv" % (kind, label(h)))
            if os.path.isfile(measured):
                m = np.loadtxt(measured, delimiter=",", skiprows=1, ndmin=2)
                ax.plot(1000*m[:, 0], m[:, 1], "o", mfc="none", label="measured")
            ax.set_title("%.1f mm above the distributor" % (1000*h), fontsize=10)
            ax.set_ylabel({"voidfraction": "void fraction", "particleVelocity": "particle v_z (m/s)"}[kind])
            ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("x from the left wall (mm)")
    axes[0, 0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("muellerBed.png", dpi=110)


if __name__ == "__main__":
    main()
