#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The time-averaged profiles of a muellerBed run.

    bedProfiles.py --probes NX NY NZ   the probe locations for system/probeLocations:
                                    the cell centres of the rows either side of
                                    each measured height, on the mesh Allrun makes
    bedProfiles.py [--start T] [--end E]
                                    after a run: the averages over T < t <= E
                                    (default: from the first second, or a third of
                                    shorter runs, to the end)

The void fraction across the width at each measured height (sliceLow and
sliceHigh in DEM/in.parameters) is interpolated linearly in z between the two
rows of cell centres around it, averaged over the cells across the depth (as
the magnetic resonance signal is) and in time.
The particles' vertical velocity at each height where it was measured
(velocity1, velocity2, ...) is averaged over the particles in a slice one
diameter thick, in 2 mm bins across the width, weighted by particle (as a
magnetic resonance time average is). Each average is also taken over the two
halves of the window: their mean difference says how converged it is. Writes
postProcessing/profiles/*.csv, muellerBed.result and muellerBed.png, with the
measured profiles of the run's inlet velocity (benchmarks/muellerBed/measured/)
drawn beside the simulated ones and their mean absolute difference printed."""
import glob
import os
import re
import sys

import numpy as np

PROJECT = os.environ.get("VFM_PROJECT_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "../.."))
sys.path[:0] = [os.path.join(PROJECT, "tutorials"), os.path.join(PROJECT, "benchmarks", "muellerBed")]
import caseProperties
import measurement

PARAMETERS = caseProperties.dem_parameters(".")
WIDTH, DEPTH, TOP = PARAMETERS["width"], PARAMETERS["depth"], PARAMETERS["top"]
HEIGHTS = (PARAMETERS["sliceLow"], PARAMETERS["sliceHigh"])
VELOCITY_HEIGHTS = sorted(v for k, v in PARAMETERS.items() if re.fullmatch(r"velocity\d+", k))
BIN = 0.002


def label(height):
    return "h%.1fmm" % (1000*height)


def probe_locations(nx, ny, nz):
    dz = TOP/nz
    points = []
    for h in HEIGHTS:
        below = min(max(int(np.floor(h/dz - 0.5)), 0), nz - 2)
        for row in (below, below + 1):
            points += [((i + 0.5)*WIDTH/nx, (j + 0.5)*DEPTH/ny, (row + 0.5)*dz) for j in range(ny) for i in range(nx)]
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


BLOCK = 0.5     # s: several bubble periods, for batch means


def windows(t, window):
    """masks of the averaging window (start, stop], its halves, and its
    consecutive blocks of BLOCK seconds"""
    start, stop = window
    inside = (t > start) & (t <= stop)
    mid = 0.5*(start + stop)
    found = {"all": inside, "first half": inside & (t <= mid), "second half": inside & (t > mid)}
    for k in range(int((stop - start)/BLOCK + 1e-9)):
        found["block %d" % k] = (t > start + k*BLOCK) & (t <= start + (k + 1)*BLOCK)
    return found


def convergence(averages):
    """(the halves' mean difference expected of a window of the run's
    length, the window for which it would be 0.01) from batch means: with
    blocks longer than a bubble's life independent, each profile point's
    halves of a window T differ by sqrt(8/pi) s sqrt(BLOCK/T) on average,
    s the spread of its block means"""
    blocks = [v for k, v in averages.items() if k.startswith("block ")]
    if len(blocks) < 3:
        return float("nan"), float("nan")
    spread = float(np.nanmean(np.std(np.array(blocks), axis=0, ddof=1)))
    T = len(blocks)*BLOCK
    return np.sqrt(8/np.pi)*spread*np.sqrt(BLOCK/T), BLOCK*8/np.pi*(spread/0.01)**2


def void_fraction_profiles(window):
    t, points, values = read_probes()
    profiles = {}
    for h in HEIGHTS:
        levels = np.unique(points[:, 2])
        z0, z1 = levels[levels <= h].max(initial=levels.min()), levels[levels > h].min(initial=levels.max())
        lower, upper = np.isclose(points[:, 2], z0), np.isclose(points[:, 2], z1)
        weight = (h - z0)/(z1 - z0) if z1 > z0 else 0.0
        at_height = (1 - weight)*values[:, lower] + weight*values[:, upper]
        x, column = np.unique(points[lower, 0], return_inverse=True)
        across_depth = np.stack([at_height[:, column == i].mean(axis=1) for i in range(len(x))], axis=1)
        profiles[h] = (x, {k: across_depth[w].mean(axis=0) for k, w in windows(t, window).items()})
    return profiles


def read_band(path):
    """per snapshot: (time step, x, z, vz) of the particles in the dumped band"""
    snapshots, lines, i = [], open(path).read().split("\n"), 0
    while i < len(lines) and lines[i].startswith("ITEM: TIMESTEP"):
        step, n = int(lines[i + 1]), int(lines[i + 3])
        columns = lines[i + 8].split()[2:]
        data = np.array(" ".join(lines[i + 9:i + 9 + n]).split(), float).reshape(n, len(columns))
        snapshots.append((step, data[:, columns.index("x")], data[:, columns.index("z")], data[:, columns.index("vz")]))
        i += 9 + n
    return snapshots


def velocity_profiles(snapshots, window):
    edges = np.linspace(0, WIDTH, int(round(WIDTH/BIN)) + 1)
    t = np.array([s[0]*PARAMETERS["demStep"] for s in snapshots])
    profiles = {}
    for h in VELOCITY_HEIGHTS:
        inside = [np.abs(z - h) < PARAMETERS["sliceHalf"] for _, _, z, _ in snapshots]
        sums = np.array([np.histogram(x[k], edges, weights=vz[k])[0] for (_, x, _, vz), k in zip(snapshots, inside)])
        counts = np.array([np.histogram(x[k], edges)[0] for (_, x, _, _), k in zip(snapshots, inside)])
        profiles[h] = (0.5*(edges[1:] + edges[:-1]),
                       {k: mean_per_bin(sums[w].sum(axis=0), counts[w].sum(axis=0))
                        for k, w in windows(t, window).items()})
    return profiles


def slice_profiles(snapshots, window):
    """the void fraction of a slice one diameter thick at each measured
    height, from the particles alone: each sphere's volume between the
    slice's planes, binned by its centre in 2 mm across the width, over the
    whole depth (what a thin magnetic resonance slice sees, without the
    fluid cells' height)"""
    r, half = PARAMETERS["radius"], PARAMETERS["sliceHalf"]
    edges = np.linspace(0, WIDTH, int(round(WIDTH/BIN)) + 1)
    t = np.array([s[0]*PARAMETERS["demStep"] for s in snapshots])
    band = (VELOCITY_HEIGHTS[0] - half, VELOCITY_HEIGHTS[-1] + half)
    profiles = {}
    for h in (h for h in HEIGHTS if band[0] <= h - half - r and h + half + r <= band[1]):
        solid = []
        for _, x, z, _ in snapshots:
            a, b = np.clip(h - half - z, -r, r), np.clip(h + half - z, -r, r)
            solid.append(np.histogram(x, edges, weights=np.pi*(r*r*(b - a) - (b**3 - a**3)/3))[0])
        alpha = 1 - np.array(solid)/(BIN*DEPTH*2*half)
        profiles[h] = (0.5*(edges[1:] + edges[:-1]), {k: alpha[w].mean(axis=0) for k, w in windows(t, window).items()})
    return profiles


def mean_per_bin(sums, counts):
    """NaN where no particle passed: a bin without particles has no velocity"""
    return np.where(counts > 0, sums/np.maximum(counts, 1), np.nan)


def inlet_velocity():
    """the superficial velocity Allrun wrote into 0/U (the last entry of the inlet's table)"""
    m = re.findall(r"\(\s*[-+0-9.eE]+\s+\(\s*0\s+0\s+([-+0-9.eE]+)\s*\)\s*\)", open("0/U").read())
    return float(m[-1]) if m else None


def write_csv(path, x, values, column):
    np.savetxt(path, np.column_stack([x, values]), fmt="%.6g", delimiter=",",
               header="x_m,%s" % column, comments="")


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "--probes":
        sys.stdout.write(probe_locations(*(int(n) for n in sys.argv[2:])))
        return
    t_dp = np.loadtxt("postProcessing/inletPressure/0/surfaceFieldValue.dat", comments="#", ndmin=2)
    end = min(float(sys.argv[sys.argv.index("--end") + 1]), t_dp[-1, 0]) if "--end" in sys.argv else t_dp[-1, 0]
    start = float(sys.argv[sys.argv.index("--start") + 1]) if "--start" in sys.argv else min(1.0, end/3)
    window = (start, end)
    nu, rho_f, _ = caseProperties.fluid()
    rho_p, g, d = caseProperties.particle_density(), caseProperties.gravity(), caseProperties.particle_diameter()
    weight = PARAMETERS["count"]*np.pi/6*d**3*(rho_p - rho_f)*g/(WIDTH*DEPTH)
    dp = rho_f*t_dp[(t_dp[:, 0] > start) & (t_dp[:, 0] <= end), 1].mean()
    bed = np.loadtxt("DEM/post/bed.txt", comments="#", ndmin=2)
    height = 2*bed[(bed[:, 0] > start) & (bed[:, 0] <= end), 1].mean()

    os.makedirs("postProcessing/profiles", exist_ok=True)
    result = {"start_s": start, "end_s": end, "dp_Pa": dp, "weight_Pa": weight, "dp_over_weight": dp/weight,
              "bed_height_m": height}
    band = read_band(os.path.join("DEM", "post", "band.dump"))
    kinds = (("voidfraction", void_fraction_profiles(window), "voidfraction"),
             ("particleVelocity", velocity_profiles(band, window), "vz_m_s"),
             ("voidfractionSlice", slice_profiles(band, window), "voidfraction"))
    u = inlet_velocity()
    print("averages over %.4g to %.4g s:" % (start, end))
    print("    pressure drop %.4g Pa, bed weight per area %.4g Pa (ratio %.4g); bed height (twice the "
          "particles' mean height) %.4g mm" % (dp, weight, dp/weight, 1000*height))
    for kind, profiles, column in kinds:
        for h, (x, averages) in profiles.items():
            name = "%s_%s" % (kind, label(h))
            write_csv("postProcessing/profiles/%s.csv" % name, x, averages["all"], column)
            halves = np.nanmean(np.abs(averages["first half"] - averages["second half"]))
            result[name + "_mean"] = np.nanmean(averages["all"])
            result[name + "_halves"] = halves
            expected, needed = convergence(averages)
            result[name + "_halves_expected"] = expected
            result[name + "_window_for_0.01"] = needed
            line = "    %s at %.1f mm: mean %.4g, halves differ by %.3g on average (%.3g expected from %g s blocks;" \
                   " 0.01 after about %.3g s)" % (kind, 1000*h, np.nanmean(averages["all"]), halves, expected, BLOCK,
                                                  needed)
            points = measured_points(kind, u, h)
            if points is not None:
                result[name + "_mad"], result[name + "_bias"] = measurement.difference(points, x, averages["all"])
                line += "; from the measurement: %.3g on average, %+.3g signed" % (
                    result[name + "_mad"], result[name + "_bias"])
            print(line)
    with open("muellerBed.result", "w") as f:
        f.writelines("%s %.8g\n" % kv for kv in result.items())
    plot(kinds, u)
    print("profiles in postProcessing/profiles/, plot muellerBed.png")


def measured_points(kind, u, h):
    kind = "voidfraction" if kind.startswith("voidfraction") else kind
    return measurement.measured(kind, u, label(h)) if u is not None else None


def plot(kinds, u):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    model = re.search(r"(?m)^voidFractionModel\s+(\w+);", open("constant/couplingProperties").read()).group(1)
    fig, axes = plt.subplots(1, 3, figsize=(13, 4), sharex=True)
    (_, void, _), (_, velocity, _), (_, thin, _) = kinds
    panels = [(axes[0], "voidfraction", HEIGHTS[1:]), (axes[1], "voidfraction", HEIGHTS[:1]),
              (axes[2], "particleVelocity", VELOCITY_HEIGHTS)]
    for ax, kind, heights in panels:
        profiles = void if kind == "voidfraction" else velocity
        for i, h in enumerate(heights):
            x, averages = profiles[h]
            colour = "k" if len(heights) == 1 else "C%d" % i
            if len(heights) == 1:
                for half in ("first half", "second half"):
                    ax.plot(1000*x, averages[half], lw=0.8, alpha=0.5, label=half)
            ax.plot(1000*x, averages["all"], "-", color=colour, lw=1.6,
                    label=model if len(heights) == 1 else "%s, %.0f mm" % (model, 1000*h))
            if kind == "voidfraction" and h in thin:
                ax.plot(1000*thin[h][0], thin[h][1]["all"], "--", color=colour, lw=1.2,
                        label="particles in a %.1f mm slice" % (2000*PARAMETERS["sliceHalf"]))
            points = measured_points(kind, u, h)
            if points is not None:
                ax.plot(1000*points[:, 0], points[:, 1], "o", color=colour, mfc="none",
                        label="measured" if len(heights) == 1 else "measured, %.0f mm" % (1000*h))
        ax.set_title(("%s mm above the distributor" if len(heights) == 1 else "at %s mm") % " / ".join(
            "%.1f" % (1000*h) for h in heights), fontsize=10)
        ax.set_ylabel({"voidfraction": "void fraction", "particleVelocity": "particle v_z (m/s)"}[kind])
        ax.set_xlabel("x from the left wall (mm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("muellerBed.png", dpi=110)

if __name__ == "__main__":
    main()
