#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The heated bed: the beads' mean temperature (DEM/post/bedTemperature.txt)
against the lumped energy balance of the bed, M c_p dT/dt = m Cp (T_in - T),
the gas leaving at the beads' temperature (its flow rate m with the inlet's
ramp, M c_p from the beads the DEM holds); the gas leaving the bed
(postProcessing/outletTemperature) and the gas temperature at the last
written time, averaged over the depth. Writes heatedBed.csv and
heatedBed.png. Every property is read from the case."""
import glob
import os
import re
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.environ.get("VFM_PROJECT_DIR",
                                               os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")),
                                "tutorials"))
import caseProperties  # noqa: E402


def inlet_temperature(case="."):
    text = open(os.path.join(case, "0.orig", "T")).read()
    return float(re.search(r"inlet\s*\{[^}]*value\s+uniform\s+(\S+);", text).group(1))


def inlet_velocity(case="."):
    """the inlet's (time, vertical velocity) table"""
    text = open(os.path.join(case, "0.orig", "U")).read()
    table = re.search(r"table\s*\((.*)\)\s*;", text).group(1)
    pairs = re.findall(r"\(\s*(\S+)\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)\s*\)", table)
    return np.array([[float(t), float(u)] for t, u in pairs])


def lumped(case, times):
    """the beads' mean temperature of the lumped balance at times"""
    p = caseProperties.dem_parameters(case)
    nu, rho, _ = caseProperties.fluid(case)
    cp_gas = caseProperties._entry(os.path.join(case, "constant", "transportProperties"), "Cp")
    mass = p["count"]*p["density"]*4/3*np.pi*p["radius"]**3
    capacity = mass*p["heatCapacity"]
    area = p["width"]*p["depth"]
    table = inlet_velocity(case)
    t_in, t0 = inlet_temperature(case), p["initialTemperature"]

    def rate(t, y):
        u = np.interp(t, table[:, 0], table[:, 1])
        return [rho*u*area*cp_gas*(t_in - y[0])/capacity]
    sol = solve_ivp(rate, (0, times[-1]), [t0], t_eval=times, rtol=1e-10, atol=1e-12, max_step=0.01)
    return sol.y[0], capacity


def outlet(case="."):
    files = sorted(glob.glob(os.path.join(case, "postProcessing", "outletTemperature", "*",
                                          "surfaceFieldValue.dat")))
    rows = [np.loadtxt(f, comments="#", ndmin=2) for f in files]
    return np.vstack(rows) if rows else np.zeros((0, 2))


def main():
    case = "."
    bed = np.loadtxt(os.path.join(case, "DEM", "post", "bedTemperature.txt"), ndmin=2)
    t, beads = bed[:, 0], bed[:, 1]
    model, capacity = lumped(case, t)
    gas_out = outlet(case)
    t_in = inlet_temperature(case)
    rise, model_rise = beads[-1] - beads[0], model[-1] - model[0]
    with open("heatedBed.csv", "w") as f:
        f.write("time_s,beads_mean_K,lumped_K\n")
        for row in zip(t, beads, model):
            f.write("%.6g,%.8g,%.8g\n" % row)
    print("beads' mean temperature at %.3g s: %.4g K, lumped balance %.4g K: rise %.4g K against %.4g K "
          "(%+.2f %%); bed heat capacity %.4g J/K" % (t[-1], beads[-1], model[-1], rise, model_rise,
                                                        100*(rise/model_rise - 1), capacity))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [1.4, 1]})
    a.plot(t, beads, label="beads' mean (DEM)")
    a.plot(t, model, "--", label="lumped balance of the bed")
    if len(gas_out):
        a.plot(gas_out[:, 0], gas_out[:, 1], ":", label="gas leaving the bed")
    a.set_xlabel("t [s]")
    a.set_ylabel("T [K]")
    a.set_title("gas at %g K heating a bed at %g K" % (t_in, beads[0]))
    a.legend()
    times = sorted((d for d in os.listdir(case) if re.fullmatch(r"[0-9.]+", d) and float(d) > 0), key=float)
    if times:
        # an ascii field (the case's writeFormat); a binary one is not drawn
        field = open(os.path.join(case, times[-1], "T"), errors="replace").read()
        m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s+(\d+)\s*\(([-+0-9.eE\s]*)\)", field)
        if m:
            values = np.array(m.group(2).split(), float)
            nx, ny = 16, 2
            image = values.reshape(-1, ny, nx).mean(axis=1)
            im = b.imshow(image, origin="lower", extent=(0, 48, -6, 120), aspect="auto", cmap="inferno")
            fig.colorbar(im, ax=b, label="gas T [K]")
            b.set_xlabel("x [mm]")
            b.set_ylabel("z [mm]")
            b.set_title("gas temperature at %s s" % times[-1])
    fig.tight_layout()
    fig.savefig("heatedBed.png", dpi=110)


if __name__ == "__main__":
    main()
