#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""pimpleDEMFoam with LIGGGHTS: the tutorials against their independent
references (Schiller-Naumann, Di Felice and Beetstra single-sphere drag,
Saffman-Mei lift, the added-mass ODE, Richardson-Zaki, Ergun, bed weight,
Wen-Yu), exact momentum exchange, restart, serial against 2 ranks, and bad
input stopping with a clear error and no hang."""
import csv
import glob
import json
import math
import os
import re
import shutil
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import checks
from checks import WORK, check, near
from foamCase import ROOT, set_dem, sh
import schumann
import snappyColumn

TUTORIALS = os.path.join(ROOT, "tutorials")
sys.path.insert(0, TUTORIALS)
import particleVtk
import weightShares


def copy_tutorial(name, dest):
    path = os.path.join(WORK, dest)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(os.path.join(TUTORIALS, name), path)
    sh("./Allclean", path)
    return path


def edit(path, pattern, replacement):
    with open(path) as f:
        text = f.read()
    new, matches = re.subn(pattern, replacement, text, flags=re.M)
    if not matches:
        raise RuntimeError("%s: no match for %r" % (path, pattern))
    with open(path, "w") as f:
        f.write(new)


def results(path):
    return {k: float(v) for k, v in (l.split() for l in open(path))}


def coupling_lines(log):
    """(min alpha, max alpha, momentum balance) of every coupling line"""
    pattern = re.compile(r"^coupling \d+: .*alpha (\S+)\.\.(\S+), momentum balance (\S+);")
    rows = []
    for line in open(log):
        m = pattern.match(line)
        if m:
            rows.append(tuple(float(m.group(i).rstrip(",")) for i in (1, 2, 3)))
    return rows


def coupling_forces(log):
    """(most particles on a rank, total fluid force on the particles) per coupling"""
    pattern = re.compile(r"^coupling \d+: \d+ particles \(at most (\d+) on a rank\).*"
                         r"total fluid force on the particles \((\S+) (\S+) (\S+)\)")
    rows = []
    for line in open(log):
        m = pattern.match(line)
        if m:
            rows.append((int(m.group(1)), tuple(float(m.group(i)) for i in (2, 3, 4))))
    return rows


def forces_agree(what, runs, reference, tolerance, least=1):
    """A run on some ranks against one on others (coupling_forces of each): as
    many couplings, at least least, and at every coupling each component of the
    total fluid force on the particles the same within tolerance of the largest
    component in the reference. True when both hold."""
    count = len(runs) >= least and len(reference) == len(runs)
    check("%s: %d and %d couplings, at least %d" % (what, len(runs), len(reference), least), count)
    if not count:
        return False
    scale = max(abs(c) for _, f in reference for c in f)
    diff = max(abs(a - b) for (_, f), (_, g) in zip(runs, reference) for a, b in zip(f, g))/scale
    check("%s: the total fluid force on the particles at every coupling" % what, diff <= tolerance,
          "(largest difference %.1e of the largest force, tolerance %.0e)" % (diff, tolerance))
    return diff <= tolerance


def check_coupling_log(label, log, alpha_min):
    rows = coupling_lines(log)
    check("%s: coupling steps logged" % label, len(rows) > 10, "(%d)" % len(rows))
    if not rows:
        return
    lo = min(r[0] for r in rows)
    hi = max(r[1] for r in rows)
    balance = max(r[2] for r in rows)
    # (at most 1 by construction: the field is min(1 - solid/V, 1))
    check("%s: void fraction at least alphaMin, never NaN" % label,
          all(math.isfinite(v) for r in rows for v in r) and lo >= alpha_min,
          "(min %.4f, max %.6f)" % (lo, hi))
    check("%s: momentum the particles gain = momentum the fluid loses" % label, balance < 1e-12,
          "(worst relative difference %.2e)" % balance)


def history(case, name="history.txt"):
    return np.loadtxt(os.path.join(case, "DEM", "post", name))


def serial_and_two_ranks(case, end, split="(1 1 2)"):
    """the DEM histories of case run from its start for end s in serial and on 2 ranks (the
    mesh split as split, in z by default, the linear solvers converged to round-off so that
    only the decomposition differs); the second is None if the parallel run failed"""
    edit(os.path.join(case, "system", "fvSolution"), r"tolerance 1e-10; relTol [0-9.]+;", "tolerance 1e-13; relTol 0;")
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+\S+;", "endTime %g;" % end)
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n %s; }\n" % split)
    sh("rm -rf 0.[0-9]* [1-9]* DEM/post/* && mkdir -p DEM/post && pimpleDEMFoam > log.serial 2>&1", case)
    serial = history(case)
    sh("rm -rf DEM/post/* 0.[0-9]*", case)
    rc, out = sh("decomposePar -force > log.decomposePar && "
                 "timeout 300 mpirun -np 2 pimpleDEMFoam -parallel > log.parallel 2>&1", case, check=False)
    check("%s: the run on 2 ranks completed" % os.path.basename(case), rc == 0, out[-800:] if rc else "")
    return serial, (history(case) if rc == 0 else None)


# single-sphere drag laws, written here from the papers (independent of the C++)
rho_f, nu, rho_p, d, g = 1000.0, 1e-6, 2500.0, 1e-3, 9.81
mu = rho_f*nu


def cd_schiller_naumann(re):
    return 24/re*(1 + 0.15*re**0.687) if re < 1000 else 0.44


def cd_di_felice(re):
    return (0.63 + 4.8/math.sqrt(re))**2


def cd_beetstra_single(re):
    # Beetstra et al. (2007) at solid fraction 0: F = 1 + 0.413 Re/24 (1 + 8.4 Re^-0.343)/(1 + Re^-1/2),
    # drag 3 pi mu d U F, so Cd = 24 F/Re
    f = 1 + 0.413*re/24*(1 + 8.4*re**-0.343)/(1 + re**-0.5)
    return 24*f/re


def terminal_velocity(cd):
    def excess(v):
        re = rho_f*v*d/mu
        return (rho_p - rho_f)*g*math.pi*d**3/6 - 0.5*cd(re)*rho_f*math.pi*d*d/4*v*v
    return brentq(excess, 1e-5, 5.0)


def test_settling_sphere():
    print("settlingSphere tutorial (Gidaspow drag, formulation A)")
    case = copy_tutorial("settlingSphere", "settling")
    rc, out = sh("./Allrun", case, check=False)
    check("Allrun completed", rc == 0, out[-1500:] if rc else "")
    r = results(os.path.join(case, "settling.result"))
    check("terminal velocity within 2 % of Schiller-Naumann", r["terminal_error"] < 0.02,
          "(%.3f %%)" % (100*r["terminal_error"]))
    check("velocity history within 2 % of the Schiller-Naumann ODE", r["history_error"] < 0.02,
          "(%.3f %% of terminal)" % (100*r["history_error"]))
    check_coupling_log("settlingSphere", os.path.join(case, "log.pimpleDEMFoam"), 0.99)
    # every write time's particle file, listed at its time in the series ParaView opens
    dt = float(re.search(r"(?m)^deltaT\s+(\S+);", open(os.path.join(case, "system", "controlDict")).read()).group(1))
    written = [(os.path.basename(f), particleVtk.step(f)*dt) for f in particleVtk.files(case)]
    series = json.load(open(os.path.join(case, "VTK", "particles.vtp.series")))["files"]
    listed = [(s["name"], s["time"]) for s in series]
    check("particles written for ParaView: 4 files, each in particles.vtp.series at its time",
          len(written) == 4 and len(listed) == 4 and
          all(a == b and abs(t - s) < 1e-9 for (a, t), (b, s) in zip(written, listed)), str(listed))
    x, r, v = particleVtk.read(os.path.join(case, "VTK", written[-1][0])) if written else ([], [], [])
    check("the file's sphere: radius 0.5 mm, settling down", len(r) == 1 and abs(r[0] - 5e-4) < 1e-9
          and v[0][2] < 0, "(%s, %s)" % (r, v))


def settle_with(dest, coupling_edits, reference, label):
    case = copy_tutorial("settlingSphere", dest)
    props = os.path.join(case, "constant", "couplingProperties")
    for pattern, replacement in coupling_edits:
        edit(props, pattern, replacement)
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.25;")
    sh("cp -r 0.orig 0 && blockMesh", case)
    rc, out = sh("pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
    check("%s: run completed" % label, rc == 0)
    v = -history(case)[-1, 2]
    near("%s: terminal velocity / single-sphere law" % label, v/reference, 1.0, 0.02)
    return case


def test_drag_laws():
    print("drag laws and formulation B on the settling sphere, against single-sphere laws")
    settle_with("settle-difelice", [(r"^dragModel\s+\w+;", "dragModel DiFelice;")],
                terminal_velocity(cd_di_felice), "DiFelice")
    settle_with("settle-beetstra", [(r"^dragModel\s+\w+;", "dragModel Beetstra;")],
                terminal_velocity(cd_beetstra_single), "Beetstra")
    case = settle_with("settle-modelB", [(r"^formulation\s+A;", "formulation B;"),
                                        (r"^forces\s+\(.*\);", "forces (buoyancy);")],
                       terminal_velocity(cd_schiller_naumann), "Gidaspow, formulation B")
    check_coupling_log("formulation B", os.path.join(case, "log.pimpleDEMFoam"), 0.99)


def sphere_velocity_ode(t, cvm):
    """settling velocity of the 1 mm glass sphere in water released from rest, Schiller-Naumann
    drag and the added mass cvm rho V: (rho_p + cvm rho) V dv/dt = (rho_p - rho) g V - drag"""
    volume = math.pi*d**3/6

    def accel(s, v):
        re = max(rho_f*abs(v[0])*d/mu, 1e-12)
        drag = 0.5*rho_f*cd_schiller_naumann(re)*math.pi*d*d/4*abs(v[0])*v[0]
        return [((rho_p - rho_f)*g*volume - drag)/((rho_p + cvm*rho_f)*volume)]
    return solve_ivp(accel, (0, t[-1]), [0.0], t_eval=t, rtol=1e-10, atol=1e-12).y[0]


def saffman_mei_lift(slip, shear, diameter):
    """Saffman (1965) 6.46 mu a^2 |u - v| (kappa/nu)^1/2 with Mei's (1992) factor"""
    re_p, re_s = diameter*slip/nu, diameter**2*shear/nu
    b = 0.5*re_s/re_p
    f = ((1 - 0.3314*math.sqrt(b))*math.exp(-0.1*re_p) + 0.3314*math.sqrt(b) if re_p <= 40
         else 0.0524*math.sqrt(b*re_p))
    return 6.46*mu*(diameter/2)**2*slip*math.sqrt(shear/nu)*f


def nusselt(correlation, re, pr, alpha):
    """the two correlations as their papers give them: Ranz and Marshall
    (1952), a single sphere; Gunn (1978), fixed and fluidised beds"""
    if correlation == "RanzMarshall":
        return 2 + 0.6*re**0.5*pr**(1/3)
    return ((7 - 10*alpha + 5*alpha**2)*(1 + 0.7*re**0.2*pr**(1/3))
            + (1.33 - 2.4*alpha + 1.2*alpha**2)*re**0.7*pr**(1/3))


def sphere_heating(correlation, t, h=1, size=d):
    """the 1 mm glass sphere (300 K, c_p 840) held in the Couette flow of
    water at 350 K (tests/cases/sphereHeating), a sphere of another size, or
    a parcel of h^3 of them:
    the lumped solution
    T = Tg + (T0 - Tg) exp(-t hA/(m c_p)) with h from the correlation at
    the fluid velocity and void fraction of the cell that holds it"""
    nu_w, rho_w, cp_w, kappa_w = 1e-6, 1000.0, 4180.0, 0.6
    volume = math.pi/6*size**3
    # a parcel of h^3 such spheres: their conductance and heat capacity, its volume
    alpha = 1 - h**3*volume/0.008**3
    re = alpha*(0.05*0.044/0.096)*size/nu_w
    pr = nu_w*rho_w*cp_w/kappa_w
    ha = nusselt(correlation, re, pr, alpha)*kappa_w/size*math.pi*size**2
    tau = rho_p*volume*840.0/ha
    return 350.0 - 50.0*np.exp(-np.maximum(t, 0)/tau)


def read_internal(path, n):
    text = open(path).read()
    m = re.search(r"internalField\s+uniform\s+(\S+);", text)
    if m:
        return np.full(n, float(m.group(1)))
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s+\d+\s*\(([^)]*)\)", text)
    return np.array(m.group(1).split(), float)


def test_heat_transfer():
    print("heat transfer: a sphere heating in a uniform flow against the lumped solution")
    interval = 5e-4
    runs = {}
    for correlation in ("RanzMarshall", "Gunn"):
        case = os.path.join(WORK, "sphere-heating-" + correlation)
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "tests", "cases", "sphereHeating"), case)
        edit(os.path.join(case, "constant", "couplingProperties"), r"correlation\s+\w+;",
             "correlation %s;" % correlation)
        rc, out = sh("blockMesh > log.blockMesh && pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
        check("%s: run completed" % correlation, rc == 0, out[-800:] if rc else "")
        if rc:
            return
        runs[correlation] = case
    for correlation, case in runs.items():
        data = np.loadtxt(os.path.join(case, "DEM", "post", "temperature.txt"))
        t, temperature = data[:, 0], data[:, 1]
        other = "Gunn" if correlation == "RanzMarshall" else "RanzMarshall"
        # the heat of an interval reaches the DEM in the next, as the forces do
        right = np.max(np.abs(temperature - sphere_heating(correlation, t - interval)))/50
        unlagged = np.max(np.abs(temperature - sphere_heating(correlation, t)))/50
        wrong = np.max(np.abs(temperature - sphere_heating(other, t - interval)))/50
        check("%s: the sphere's temperature within 1 %% of the lumped solution with its Nusselt number, "
              "0 to 1.9 time constants (one coupling interval behind)" % correlation, right < 0.01,
              "(%.3f %% of the difference; %.2f %% without the interval's lag)" % (100*right, 100*unlagged))
        check("%s: the lumped solution with %s's Nusselt number is more than 3 %% away (the check "
              "discriminates)" % (correlation, other), wrong > 0.03, "(%.2f %%)" % (100*wrong))
        log = open(os.path.join(case, "log.pimpleDEMFoam")).read()
        balances = [float(x) for x in re.findall(r"^heat exchange \d+: .* W, balance (\S+);", log, re.M)]
        check("%s: heat the sphere receives = heat the water loses, every fluid step (%d couplings)"
              % (correlation, len(balances)), len(balances) == 300 and max(balances) < 1e-12,
              "(worst %.1e)" % max(balances) if balances else "")
        budget, continuity = gas_energy(log)
        check("%s: the water's energy: change = heat from the sphere + the continuity error's heat, every "
              "step, to round-off; that heat within the pressure solver's tolerance (1e-10)" % correlation,
              budget < 1e-12 and continuity < 1e-8,
              "(worst %.1e of what is differenced; continuity errors' heat %.1e of the heat that flows)"
              % (budget, continuity))
        # energy: the water's change, the sphere's, and the last interval's heat the DEM has yet to take
        gas = 1000*4180*0.008**3*np.sum(read_internal(os.path.join(case, "0.15", "alpha"), 300)
                                         * (read_internal(os.path.join(case, "0.15", "T"), 300) - 350))
        sphere = rho_p*math.pi/6*d**3*840*(temperature[-1] - 300)
        pending = float(re.findall(r"^heat exchange \d+: to the particles (\S+) W", log, re.M)[-1])*interval
        energy = abs(gas + sphere + pending)/sphere
        check("%s: energy of water and sphere conserved over the run" % correlation, energy < 1e-6,
              "(%.1e of the heat exchanged)" % energy)

    # a parcel of 8 spheres (h = 2, cubic) heats as each of its spheres
    case = os.path.join(WORK, "sphere-heating-parcel")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "tests", "cases", "sphereHeating"), case)
    edit(os.path.join(case, "DEM", "in.liggghts"), r"diameter 0.001 ", "diameter 0.002 ")
    edit(os.path.join(case, "constant", "couplingProperties"), r"^particlesOutside",
         "coarseGraining { factor 2; forceScaling cubic; }\nparticlesOutside")
    rc, out = sh("blockMesh > log.blockMesh && pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
    check("a parcel, h = 2: run completed", rc == 0, out[-800:] if rc else "")
    if rc == 0:
        data = np.loadtxt(os.path.join(case, "DEM", "post", "temperature.txt"))
        t, temperature = data[:, 0], data[:, 1]
        right = np.max(np.abs(temperature - sphere_heating("RanzMarshall", t - interval, h=2)))/50
        wrong = np.max(np.abs(temperature - sphere_heating("RanzMarshall", t - interval, size=2*d)))/50
        check("a 2 mm parcel of 1 mm spheres: the lumped solution of its spheres within 1 %", right < 0.01,
              "(%.3f %% of the difference)" % (100*right))
        check("the lumped solution of one 2 mm sphere is more than 3 % away (the check discriminates)",
              wrong > 0.03, "(%.2f %%)" % (100*wrong))

    # serial = 2 ranks (the mesh split in x), the linear solvers converged to
    # round-off so that only the decomposition differs
    case = runs["RanzMarshall"]
    edit(os.path.join(case, "system", "fvSolution"), r"tolerance 1e-1\d; relTol [0-9.]+;", "tolerance 1e-14; relTol 0;")
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n")
    sh("rm -rf 0.[0-9]* DEM/post && pimpleDEMFoam > log.serial 2>&1", case)
    serial = np.loadtxt(os.path.join(case, "DEM", "post", "temperature.txt"))
    rc, out = sh("rm -rf 0.[0-9]* DEM/post && decomposePar -force > log.decomposePar && "
                 "timeout 300 mpirun -np 2 pimpleDEMFoam -parallel > log.parallel 2>&1", case, check=False)
    check("heat transfer on 2 ranks: run completed", rc == 0, out[-800:] if rc else "")
    if rc == 0:
        par = np.loadtxt(os.path.join(case, "DEM", "post", "temperature.txt"))
        diff = np.max(np.abs(par[:, 1] - serial[:, 1]))/50 if par.shape == serial.shape else float("inf")
        # equal to 1e-13 for 100 couplings; then the pressure of the sphere's
        # wake, a field near zero whose solver tolerance is relative, parts them
        check("heat transfer: 2 ranks = serial (the sphere's temperature history)", diff < 1e-7,
              "(%.1e of the difference)" % diff)

    # bad entries: a clear error naming what is wrong
    bad = [
        ("unknown correlation", "constant/couplingProperties", r"correlation\s+\w+;", "correlation Whitaker;",
         "Unknown heatTransferCorrelation type Whitaker"),
        ("negative gas heat capacity", "constant/transportProperties", r"^Cp\s+\S+;", "Cp -4180;",
         "Cp must be positive"),
        ("no gas conductivity", "constant/transportProperties", r"^kappa\s+\S+;.*$", "", "kappa"),
        ("a DEM without the gas's heat", "DEM/in.liggghts", r"^fix cfd3 all couple/cfd/convection.*$", "",
         "has no per-particle convectiveHeatFlux"),
        ("a DEM without heat capacities", "DEM/in.liggghts", r"^fix m6 .*$", "", "thermalCapacity"),
    ]
    for name, rel, pattern, replacement, needle in bad:
        case = os.path.join(WORK, "sphere-heating-bad")
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "tests", "cases", "sphereHeating"), case)
        edit(os.path.join(case, rel), pattern, replacement)
        rc, out = sh("blockMesh > log.blockMesh && timeout 120 pimpleDEMFoam", case, check=False)
        check("%s: error says '%s'" % (name, needle), rc not in (0, 124) and needle in out,
              "" if needle in out else out[-600:])


def gas_energy(log):
    """(worst budget residual, worst continuity errors' heat) of the gas's
    energy over the logged couplings, each relative to the gross flows"""
    rows = [(float(a), float(b)) for a, b in
            re.findall(r"^heat exchange \d+: .*; gas energy balance (\S+), continuity errors' heat (\S+)$", log, re.M)]
    return (max(a for a, _ in rows), max(b for _, b in rows)) if rows else (float("inf"), float("inf"))


def thermal_front(case, cells, correlation="Gunn"):
    """the largest differences from Schumann's solution of the fixed bed
    (tests/cases/packedBedHeating): of the particles' temperature, averaged
    over each cell's layer, at 1, 1.5 and 2 s, and of the gas at 2 s (by
    then the first water in has left: its front is a jump no mesh resolves)"""
    d_p, U, nu_w, rho_w, cp_w, kappa_w = 5e-3, 0.2, 1e-6, 1000.0, 4180.0, 0.6
    eps = 1 - math.pi/6/1.1**3
    a = 6*(1 - eps)/d_p
    h = nusselt(correlation, U*d_p/nu_w, nu_w*rho_w*cp_w/kappa_w, eps)*kappa_w/d_p
    dz = 0.55/cells
    solid = 0
    for step in (2000, 3000, 4000):
        t = step*5e-4
        data = np.loadtxt(os.path.join(case, "DEM", "post", "particles.%d.txt" % step), skiprows=9)
        cell = np.floor(data[:, 1]/dz).astype(int)
        # the heat of an interval reaches the DEM in the next
        _, want = schumann.bed(data[:, 1], t - 2.5e-3, U, eps, rho_w, cp_w, rho_p, 840.0, h, a)
        count = np.bincount(cell)
        got = np.bincount(cell, (data[:, 2] - 300)/10)/count
        solid = max(solid, np.max(np.abs(got - np.bincount(cell, want)/count)))
    want, _ = schumann.bed((np.arange(cells) + 0.5)*dz, 2.0, U, eps, rho_w, cp_w, rho_p, 840.0, h, a)
    gas = np.max(np.abs((read_internal(os.path.join(case, "2", "T"), cells) - 300)/10 - want))
    return solid, gas


def test_thermal_front():
    print("thermal front: a fixed bed heated by water against Schumann's solution, three meshes")
    xi, eta, f, s = schumann.integrated(4, 8, 401)
    every = slice(None, None, 40)
    closed = np.array([[schumann.solid(x, e) for e in eta[every]] for x in xi[every]])
    near("Schumann's closed form against the trapezoidal integration of its equations (401^2 points)",
         np.max(np.abs(s[every, every] - closed)), 0, 1e-4)
    errors = {}
    for cells in (25, 50, 100):
        case = os.path.join(WORK, "thermal-front-%d" % cells)
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "tests", "cases", "packedBedHeating"), case)
        edit(os.path.join(case, "system", "blockMeshDict"), r"\(1 1 100\)", "(1 1 %d)" % cells)
        rc, out = sh("blockMesh > log.blockMesh && timeout 300 pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case,
                     check=False)
        check("%d cells: run completed" % cells, rc == 0, out[-800:] if rc else "")
        if rc:
            return
        errors[cells] = thermal_front(case, cells)
        log = open(os.path.join(case, "log.pimpleDEMFoam")).read()
        balances = [float(x) for x in re.findall(r"^heat exchange \d+: .* W, balance (\S+);", log, re.M)]
        check("%d cells: heat the particles receive = heat the water loses, every step" % cells,
              len(balances) == 800 and max(balances) < 1e-12, "(worst %.1e)" % max(balances) if balances else "")
        budget, continuity = gas_energy(log)
        check("%d cells: the water's energy: change = inflow - outflow - heat to the particles, every "
              "step, to round-off (no continuity error's heat either)" % cells,
              budget < 1e-12 and continuity < 1e-12, "(worst %.1e of what is differenced; continuity errors' "
              "heat %.1e of the heat that flows)" % (budget, continuity))
    solid, gas = errors[100]
    check("100 cells of 1.1 d: the particles' temperature per cell within 0.03 of Schumann's "
          "(of the inlet's rise), 1 to 2 s", solid < 0.03, "(largest %.4f)" % solid)
    check("100 cells: the water's temperature within 0.03 of Schumann's at 2 s", gas < 0.03, "(largest %.4f)" % gas)
    check("the difference shrinks as the cells do (25, 50, 100 cells)",
          errors[25][0] > errors[50][0] > errors[100][0] and errors[25][1] > errors[50][1] > errors[100][1],
          "(particles %s; water %s)" % (", ".join("%.4f" % errors[n][0] for n in (25, 50, 100)),
                                        ", ".join("%.4f" % errors[n][1] for n in (25, 50, 100))))
    other, _ = thermal_front(os.path.join(WORK, "thermal-front-100"), 100, "RanzMarshall")
    check("Schumann's solution with Ranz and Marshall's Nusselt number is more than 0.1 away (the check "
          "discriminates)", other > 0.1, "(%.3f)" % other)


def test_particle_conduction():
    print("conduction between particles (LIGGGHTS's heat/gran conducts where they overlap) in the coupled fixed bed")
    runs = {}
    for conductivity in ("1e-6", "1e4"):
        case = os.path.join(WORK, "thermal-front-conductivity-" + conductivity)
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "tests", "cases", "packedBedHeating"), case)
        # the lattice closed to 4.99 mm: neighbours overlap by 0.01 mm and conduct, 1e4 W/m/K
        # making it matter against the water's exchange
        script = os.path.join(case, "DEM", "in.liggghts")
        edit(script, r"sc 0.0055 ", "sc 0.00499 ")
        edit(script, r"block 0 0.0275 0 0.0275 0 0.55 ", "block 0 0.02495 0 0.02495 0 0.499 ")
        edit(script, r"thermalConductivity peratomtype 1.0", "thermalConductivity peratomtype " + conductivity)
        edit(script, r"^run ", "compute heat all reduce sum f_Temp\nvariable heat equal c_heat\n"
             "fix heatSum all print 5 \"${heat}\" file post/heat.txt screen no\nrun ")
        mesh = os.path.join(case, "system", "blockMeshDict")
        edit(mesh, r"27\.5", "24.95")
        edit(mesh, r"550\)", "499)")
        rc, out = sh("blockMesh > log.blockMesh && timeout 300 pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case,
                     check=False)
        label = "particles' conductivity %s W/m/K" % conductivity
        check("%s: run completed" % label, rc == 0, out[-800:] if rc else "")
        if rc:
            return
        log = open(os.path.join(case, "log.pimpleDEMFoam")).read()
        handed = [float(q) for q in re.findall(r"^heat exchange \d+: to the particles (\S+) W", log, re.M)]
        # the sum of the temperatures at each coupling; each interval's heat acts through the next
        sums = np.loadtxt(os.path.join(case, "DEM", "post", "heat.txt"), comments="#")
        capacity = rho_p*math.pi/6*0.005**3*840
        held = capacity*(sums[-1] - sums[0])
        given = sum(handed[:-1])*2.5e-3
        check("%s: the particles hold the heat they were handed (%.4g J)" % (label, given),
              abs(held/given - 1) < 1e-5, "(%.1e apart)" % abs(held/given - 1))
        data = np.loadtxt(os.path.join(case, "DEM", "post", "particles.4000.txt"), skiprows=9)
        layer = np.round(data[:, 1]/0.00499 - 0.5).astype(int)
        runs[conductivity] = np.bincount(layer, data[:, 2])/np.bincount(layer)
    moved = np.max(np.abs(runs["1e4"] - runs["1e-6"]))/10
    check("conduction moves heat along the bed: the layers' temperatures at 2 s differ from the run "
          "without it by more than 0.02 of the inlet's rise", moved > 0.02, "(%.3f)" % moved)


def test_heated_bed():
    print("heatedBed tutorial, 0.02 s: heat the beads receive, as LIGGGHTS integrates it; continued = uninterrupted")
    case = copy_tutorial("heatedBed", "heatedBed")
    control = os.path.join(case, "system", "controlDict")
    edit(control, r"^writeInterval\s+\S+;", "writeInterval 100;")
    edit(control, r"^writeFormat\s+\S+;", "writeFormat binary;")
    rc, out = sh("./Allrun 0.02", case, check=False)
    check("Allrun completed", rc == 0, out[-1500:] if rc else "")
    if rc:
        return
    log = open(os.path.join(case, "log.pimpleDEMFoam")).read()
    exchange = [(float(q), float(b)) for q, b in
                re.findall(r"^heat exchange \d+: to the particles (\S+) W, balance (\S+);", log, re.M)]
    check("heat the beads receive = heat the gas loses, every fluid step (%d couplings)" % len(exchange),
          len(exchange) == 200 and max(b for _, b in exchange) < 1e-12,
          "(worst %.1e)" % max(b for _, b in exchange) if exchange else "")
    budget, continuity = gas_energy(log)
    check("the gas's energy: change = inflow - outflow - heat to the beads + the continuity error's heat, "
          "every step, to round-off", budget < 1e-12, "(worst %.1e of what is differenced)" % budget)
    check("the continuity error's heat within the pressure solver's tolerance (1e-8)", continuity < 1e-8,
          "(worst %.1e of the heat that flows)" % continuity)
    bed = np.loadtxt(os.path.join(case, "DEM", "post", "bedTemperature.txt"))
    p = {k: float(v) for k, v in re.findall(r"(?m)^variable\s+(\w+)\s+equal\s+(\S+)",
                                           open(os.path.join(case, "DEM", "in.parameters")).read())}
    capacity = p["count"]*p["density"]*4/3*math.pi*p["radius"]**3*p["heatCapacity"]
    # each interval's heat acts through the next: by the last print, all but the last interval's
    handed = sum(q for q, _ in exchange[:-1])*1e-4
    held = capacity*(bed[-1, 1] - bed[0, 1])
    check("the beads hold the heat they were handed (%.4g J), as LIGGGHTS integrates it" % handed,
          abs(held/handed - 1) < 1e-5, "(%.1e apart)" % abs(held/handed - 1))
    outlet = np.vstack([np.loadtxt(f, comments="#", ndmin=2) for f in
                        glob.glob(os.path.join(case, "postProcessing", "outletTemperature", "*",
                                               "surfaceFieldValue.dat"))])
    gas = binary_field(os.path.join(case, "0.02", "T"))
    check("the gas (in the bed and leaving) and the beads between the start's 300 K and the inlet's 400 K",
          gas.min() >= 300 - 1e-6 and gas.max() <= 400 + 1e-6 and outlet[:, 1].min() >= 300 - 1e-6 and
          outlet[:, 1].max() <= 400 and bed[:, 1].min() >= 300 - 1e-9 and bed[:, 1].max() <= 400,
          "(gas %.4f..%.4f K)" % (gas.min(), gas.max()))
    # continued from the written 0.01 s: the heat handed to the beads comes back with DEM.heat
    sh("rm -rf 0.02", case)
    rc, out = sh("timeout 300 pimpleDEMFoam > log.continued 2>&1", case, check=False)
    check("continued from t = 0.01", rc == 0, out[-800:] if rc else "")
    if rc:
        return
    rest = re.findall(r"^heat exchange (\d+): to the particles (\S+) W", open(os.path.join(case, "log.continued")).read(),
                      re.M)
    full = [("%d" % k, "%.8g" % q) for k, (q, _) in enumerate(exchange)][100:]
    check("the heat to the beads over the 100 couplings continued = the uninterrupted run's (8 digits logged)",
          [(k, "%.8g" % float(q)) for k, q in rest] == full, "(%d logged)" % len(rest))
    worst = np.abs(binary_field(os.path.join(case, "0.02", "T")) - gas).max()/np.abs(gas).max()
    near("gas temperature at t = 0.02, continued against uninterrupted (relative to its largest)", worst, 0, 1e-12)


def test_lift_virtual_mass():
    print("lift on a sphere in Couette flow (Saffman-Mei), virtual mass of a sphere released from rest")
    for lid in (0.05, 0.2):
        case = os.path.join(WORK, "shear-lift")
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "tests", "cases", "shearLift"), case)
        # the lid and the linear profile at the cell centres scaled together
        edit(os.path.join(case, "0", "U"), r"uniform \(0.05 0 0\)", "uniform (%g 0 0)" % lid)
        edit(os.path.join(case, "0", "U"), r"^\((\S+) 0 0\)$",
             lambda m: "(%.12g 0 0)" % (float(m.group(1))*lid/0.05))
        rc, out = sh("blockMesh > log.blockMesh && pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
        check("Couette, lid %g m/s: run completed" % lid, rc == 0, out[-800:] if rc else "")
        if rc:
            continue
        shear = lid/0.096
        slip = shear*0.044
        force = coupling_forces(os.path.join(case, "log.pimpleDEMFoam"))[-1][1]
        expected = saffman_mei_lift(slip, shear, d)
        near("Couette, lid %g m/s (Re_p %.0f): lift toward the faster fluid / Saffman-Mei"
             % (lid, d*slip/nu), force[2]/expected, 1.0, 0.01)
        check_coupling_log("Couette with lift", os.path.join(case, "log.pimpleDEMFoam"), 0.99)

    histories = {}
    for cvm_on in (True, False):
        case = copy_tutorial("settlingSphere", "settle-vm" if cvm_on else "settle-novm")
        edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.1;")
        if cvm_on:
            edit(os.path.join(case, "constant", "couplingProperties"), r"^forces\s+\(.*\);",
                 "forces (pressureGradient buoyancy virtualMass);")
        rc, out = sh("cp -r 0.orig 0 && blockMesh > log.blockMesh && pimpleDEMFoam > log.pimpleDEMFoam 2>&1",
                     case, check=False)
        check("settling sphere, virtual mass %s: run completed" % ("on" if cvm_on else "off"), rc == 0,
              out[-800:] if rc else "")
        if rc:
            return
        histories[cvm_on] = history(case)
        if cvm_on:
            check_coupling_log("settling with virtual mass", os.path.join(case, "log.pimpleDEMFoam"), 0.99)
    for cvm_on, data in histories.items():
        t, v = data[:, 0], -data[:, 2]
        terminal = terminal_velocity(cd_schiller_naumann)
        right = np.max(np.abs(v - sphere_velocity_ode(t, 0.5 if cvm_on else 0.0)))/terminal
        wrong = np.max(np.abs(v - sphere_velocity_ode(t, 0.0 if cvm_on else 0.5)))/terminal
        label = "virtual mass" if cvm_on else "no virtual mass"
        check("sphere from rest, %s: velocity within 2.5 %% of terminal of the ODE with Cvm = %s"
              % (label, "0.5" if cvm_on else "0"), right < 0.025, "(%.2f %%)" % (100*right))
        check("sphere from rest, %s: the other ODE is more than 5 %% away (the check discriminates)"
              % label, wrong > 0.05, "(%.2f %%)" % (100*wrong))

    # continued from a written time: the particle's last velocity and the fluid's come back
    case = copy_tutorial("settlingSphere", "settle-vm-restart")
    edit(os.path.join(case, "constant", "couplingProperties"), r"^forces\s+\(.*\);",
         "forces (pressureGradient buoyancy SaffmanMeiLift virtualMass);")
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.2;")
    edit(os.path.join(case, "system", "controlDict"), r"^writeInterval\s+200;", "writeInterval 100;")
    sh("cp -r 0.orig 0 && blockMesh > log.blockMesh && pimpleDEMFoam > log.full 2>&1", case)
    full = history(case)
    sh("rm -rf 0.15 0.2 && pimpleDEMFoam > log.restart 2>&1", case)
    rest = history(case, "history.restart.txt")
    diff = abs(rest[-1, 2]/full[-1, 2] - 1)
    check("lift and virtual mass continued from t = 0.1: velocity at 0.2 s = uninterrupted run's",
          diff < 1e-12, "(relative difference %.1e)" % diff)

    # both forces on a sphere whose spheres both ranks hold (split at x = 16 mm)
    case = os.path.join(WORK, "settle-vm")
    edit(os.path.join(case, "constant", "couplingProperties"), r"^forces\s+\(.*\);",
         "forces (pressureGradient buoyancy SaffmanMeiLift virtualMass);\nreportExchange true;")
    set_dem(case, releaseXY=0.0162)
    serial, par = serial_and_two_ranks(case, 0.1, split="(2 1 1)")
    if par is not None:
        diff = np.max(np.abs(par[:, 2] - serial[:, 2]))/np.max(np.abs(serial[:, 2]))
        check("lift and virtual mass: 2 ranks = serial (velocity history)", diff < 1e-10, "(%.1e)" % diff)
        holds = [int(h) for h in re.findall(r"^exchange rank [01]: owns \d+ holds (\d+)",
                                            open(os.path.join(case, "log.parallel")).read(), re.M)]
        both = sum(1 for a, b in zip(holds[::2], holds[1::2]) if a == b == 1)
        check("lift and virtual mass: both ranks hold the sphere", both > 0.9*len(holds)//2,
              "(%d of %d couplings)" % (both, len(holds)//2))


def test_restart():
    print("restart from a written time continues the same particle")
    case = copy_tutorial("settlingSphere", "settle-restart")
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.2;")
    edit(os.path.join(case, "system", "controlDict"), r"^writeInterval\s+200;", "writeInterval 100;")
    sh("cp -r 0.orig 0 && blockMesh && pimpleDEMFoam > log.full 2>&1", case)
    full = history(case)
    check("DEM restart file written with the time", os.path.isfile(os.path.join(case, "0.1", "DEM.restart")))
    for t in ("0.15", "0.2"):
        shutil.rmtree(os.path.join(case, t))
    rc, out = sh("pimpleDEMFoam > log.restart 2>&1", case, check=False)
    check("restarted run completed", rc == 0, out[-800:] if rc else "")
    log = open(os.path.join(case, "log.restart")).read()
    check("restart ran demRestartScript", "in.restart" in log and "Starting time loop" in log)
    rest = history(case, "history.restart.txt")
    check("restart continues from t = 0.1 with one particle", abs(rest[0, 0] - 0.1) < 1e-3 and
          "1 particles" in log, "(first time %g)" % rest[0, 0])
    z_full = full[np.argmin(abs(full[:, 0] - 0.2)), 1]
    near("position at t = 0.2, restarted / uninterrupted", rest[-1, 1]/z_full, 1.0, 1e-6)


def binary_field(path):
    """the internal field of a field file written with writeFormat binary"""
    data = open(path, "rb").read()
    at = data.index(b"internalField")
    m = re.search(rb"nonuniform List<(\w+)>\s*(\d+)\s*\(", data[at:])
    n, width = int(m.group(2)), {b"scalar": 1, b"vector": 3}[m.group(1)]
    start = at + m.end()
    return np.frombuffer(data[start:start + 8*n*width], dtype="<f8").reshape(n, width)


def test_bed_restart():
    print("fluidisedBed on 2 ranks stopped at a written time and continued = uninterrupted")
    case = copy_tutorial("fluidisedBed", "bed-restart")
    control = os.path.join(case, "system", "controlDict")
    edit(control, r"^writeInterval\s+\S+;", "writeInterval 20;")
    edit(control, r"^writeFormat\s+\S+;", "writeFormat binary;")
    rc, out = sh("./Allrun analytical 3 0.004 2", case, check=False)
    check("uninterrupted run of 40 couplings completed", rc == 0, out[-800:] if rc else "")
    if rc:
        return
    full_forces = coupling_forces(os.path.join(case, "log.pimpleDEMFoam"))[20:]
    fields = ("U", "p", "alpha", "phi")
    full = {(r, f): binary_field(os.path.join(case, "processor%d" % r, "0.004", f))
            for r in (0, 1) for f in fields if f != "phi"}
    sh("rm -rf processor*/0.004 0.004", case)
    rc, out = sh("timeout 300 mpirun -np 2 pimpleDEMFoam -parallel > log.continued 2>&1", case, check=False)
    check("continued from t = 0.002 without a second DEM script", rc == 0, out[-800:] if rc else "")
    if rc:
        return
    log = open(os.path.join(case, "log.continued")).read()
    rest_forces = coupling_forces(os.path.join(case, "log.continued"))
    check("20 couplings continued, numbered on from 20",
          len(rest_forces) == 20 and re.search(r"^coupling 20: ", log, re.M) is not None,
          "(%d)" % len(rest_forces))
    if len(rest_forces) == len(full_forces):
        worst = max(abs(a[1][2] - b[1][2])/abs(b[1][2]) for a, b in zip(rest_forces, full_forces))
        near("vertical fluid force on the bed over 20 couplings, continued / uninterrupted - 1 "
             "(8 digits logged)", worst, 0, 2e-7)
    for f in ("U", "p", "alpha"):
        worst = max(np.abs(binary_field(os.path.join(case, "processor%d" % r, "0.004", f)) -
                           full[(r, f)]).max()/np.abs(full[(r, f)]).max() for r in (0, 1))
        near("%s at t = 0.004, continued against uninterrupted (relative to its largest)" % f,
             worst, 0, 1e-12)
    listed = [(s["name"], s["time"]) for s in
              json.load(open(os.path.join(case, "VTK", "particles.vtp.series")))["files"]]
    check("the particles' time series continued: each write time once, in order",
          [round(t, 9) for _, t in listed] == [0.002, 0.004] and
          [n for n, _ in listed] == ["particles_20.vtp", "particles_40.vtp"], str(listed))

    print("  a time directory written incompletely is an error naming it, never a silent restart")
    last = os.path.join(case, "0.004")
    for damage, says in (("rm %s/DEM.forces" % last, "has no DEM.forces"),
                         ("truncate -s 1000 %s/DEM.restart" % last, "bytes where the run wrote"),
                         ("rm %s/DEM.restart" % last, "has no DEM.restart")):
        sh("cp -a 0.004 saved.0.004 && " + damage, case)
        rc, out = sh("timeout 120 mpirun -np 2 pimpleDEMFoam -parallel", case, check=False)
        check("'%s': stops at once with '%s' and the directory" % (damage.split()[0], says),
              rc not in (0, 124) and says in out and last in out, out[-600:] if rc in (0, 124) else "")
        sh("rm -rf 0.004 && mv saved.0.004 0.004", case)
    sh("cp -a 0.004 saved.0.004 && truncate -s 300 0.004/DEM.forces", case)
    rc, out = sh("timeout 120 mpirun -np 2 pimpleDEMFoam -parallel", case, check=False)
    check("a damaged DEM.forces stops the run, naming it", rc not in (0, 124) and "damaged" in out and
          os.path.join(last, "DEM.forces") in out, out[-600:] if rc in (0, 124) else "")
    sh("rm -rf 0.004 && mv saved.0.004 0.004", case)


def test_serial_parallel():
    print("serial against mpirun -np 2 (the mesh split across the sphere's path)")
    case = copy_tutorial("settlingSphere", "settle-parallel")
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (1 1 2); }\n")
    # linear solvers converged to round-off, so that only the decomposition differs
    edit(os.path.join(case, "system", "fvSolution"), r"tolerance 1e-10; relTol [0-9.]+;", "tolerance 1e-13; relTol 0;")
    sh("cp -r 0.orig 0 && blockMesh && pimpleDEMFoam > log.serial 2>&1", case)
    serial = history(case)
    shutil.rmtree(os.path.join(case, "DEM", "post"))
    sh("rm -rf 0.[1-9]*", case)
    rc, out = sh("decomposePar -force > log.decomposePar && "
                 "timeout 300 mpirun -np 2 pimpleDEMFoam -parallel > log.parallel 2>&1", case, check=False)
    check("parallel run completed", rc == 0, out[-800:] if rc else "")
    par = history(case)
    early = serial[:, 0] <= 0.1
    diff_early = np.max(np.abs(par[early, 2] - serial[early, 2]))/np.max(np.abs(serial[:, 2]))
    check("velocity history equal to round-off while the flow keeps it (t <= 0.1 s)", diff_early < 1e-10,
          "(%.1e)" % diff_early)
    # later the wake amplifies round-off: the serial run with a different
    # (converged) solver tolerance moves as far from itself
    near("terminal velocity, 2 ranks / serial", par[-1, 2]/serial[-1, 2], 1.0, 1e-3)


def parcel_types():
    """two DEM types of parcels in one run, factor (2 3): a 2 mm parcel of 1 mm spheres and a
    2.4 mm parcel of 0.8 mm spheres, each settling as one of its own particles (Schiller-Naumann),
    and on 2 ranks, the mesh split across their paths, as in serial"""
    case = copy_tutorial("settlingSphere", "parcel-types")
    edit(os.path.join(case, "system", "blockMeshDict"), r"^scale\s+0.001;", "scale 0.002;")
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.25;")
    set_dem(case, boxWidth=0.08, boxHeight=0.192, releaseXY=0.04, releaseZ=0.097, diameter=2e-3)
    dem = os.path.join(case, "DEM")
    edit(os.path.join(dem, "in.liggghts"), r"^create_box\s+1 domain", "create_box      2 domain")
    edit(os.path.join(dem, "in.liggghts"), r"^create_atoms.*\n(set .*)$",
         "create_atoms    1 single 0.02 ${releaseXY} ${releaseZ} units box\n"
         "create_atoms    2 single 0.06 ${releaseXY} ${releaseZ} units box\n"
         "set             atom 1 diameter 0.002 density ${density}\n"
         "set             atom 2 diameter 0.0024 density ${density}")
    edit(os.path.join(dem, "in.liggghts"), r'^fix history .*$',
         'fix history all print 10 "${t} ${zp} ${vzp} ${zp2} ${vzp2}" file post/history.txt screen no title "#"')
    edit(os.path.join(dem, "in.settings"), r"^variable\s+vzp equal vz\[1\]$",
         "variable        vzp equal vz[1]\nvariable        zp2 equal z[2]\nvariable        vzp2 equal vz[2]")
    # the materials of the two types as the one type's
    edit(os.path.join(dem, "in.settings"), r"(youngsModulus peratomtype) (\S+)$", r"\g<1> \g<2> \g<2>")
    edit(os.path.join(dem, "in.settings"), r"(poissonsRatio peratomtype) (\S+)$", r"\g<1> \g<2> \g<2>")
    for name in ("coefficientRestitution", "coefficientFriction"):
        edit(os.path.join(dem, "in.settings"), r"(%s peratomtypepair) 1 (\S+)$" % name, r"\g<1> 2 \g<2> \g<2> \g<2> \g<2>")
    with open(os.path.join(case, "constant", "couplingProperties"), "a") as f:
        f.write("coarseGraining { factor (2 3); forceScaling cubic; }\n")
    rc, out = sh("cp -r 0.orig 0 && blockMesh > log.blockMesh && pimpleDEMFoam > log.pimpleDEMFoam 2>&1",
                 case, check=False)
    log = open(os.path.join(case, "log.pimpleDEMFoam")).read()
    check("factor (2 3): two types of parcels coupled, factors per type said", rc == 0 and "per DEM type" in log,
          log[-600:] if rc else "")
    if rc:
        return
    h = history(case)

    def settling(diameter):
        def excess(v):
            re = rho_f*v*diameter/mu
            return (rho_p - rho_f)*g*math.pi*diameter**3/6 - 0.5*cd_schiller_naumann(re)*rho_f*math.pi*diameter**2/4*v*v
        return brentq(excess, 1e-5, 5.0)
    near("type 1 (h = 2, 2 mm): settles as a 1 mm sphere (Schiller-Naumann)", -h[-1, 2]/settling(1e-3), 1.0, 0.02)
    near("type 2 (h = 3, 2.4 mm): settles as a 0.8 mm sphere (Schiller-Naumann)", -h[-1, 4]/settling(0.8e-3), 1.0, 0.02)
    check_coupling_log("two parcel types", os.path.join(case, "log.pimpleDEMFoam"), 0.99)
    # both start across the split of a (1 1 2) decomposition at z = 96 mm and fall through it
    serial, par = serial_and_two_ranks(case, 0.1)
    diff = (max(np.max(np.abs(par[:, k] - serial[:, k]))/np.max(np.abs(serial[:, k])) for k in (2, 4))
            if par is not None and par.shape == serial.shape else float("nan"))
    crossed = serial[0, 1] > 0.096 > serial[-1, 1] and serial[0, 3] > 0.096 > serial[-1, 3]
    check("two parcel types on 2 ranks, both through the split: velocity histories equal to serial (1e-10)",
          diff < 1e-10 and crossed, "(%.1e; z %.4f -> %.4f)" % (diff, serial[0, 1], serial[-1, 1]))


def test_packed_bed():
    print("packedBedErgun tutorial: 3,500 spheres ramped through fluidisation")
    case = copy_tutorial("packedBedErgun", "packedBed")
    rc, out = sh("./Allrun", case, check=False)
    check("Allrun completed", rc == 0, out[-1500:] if rc else "")
    print("\n".join("    " + l for l in out.splitlines() if l.startswith(("bed:", "packed", "plateau", "minimum"))))
    r = results(os.path.join(case, "ergun.result"))
    check("packed range: pressure gradient inside the bed within 10 % of Ergun (measured porosity)",
          r["inner_error"] < 0.10, "(largest %.1f %%)" % (100*r["inner_error"]))
    check("packed range: whole-bed pressure drop within 15 % of Ergun (bed height and porosity measured)",
          r["packed_error"] < 0.15, "(largest %.1f %%)" % (100*r["packed_error"]))
    check("fluidised plateau within 5 % of bed weight per area", r["plateau_error"] < 0.05,
          "(%.1f %%)" % (100*r["plateau_error"]))
    check("minimum fluidisation velocity within 20 % of Wen-Yu", r["umf_error"] < 0.20,
          "(%.1f %%)" % (100*r["umf_error"]))
    check_coupling_log("packedBedErgun", os.path.join(case, "log.pimpleDEMFoam"), 0.2)


def sphere_slab_volume(z, r, lo, hi):
    """exact volume of spheres (centres at heights z, radii r) between the planes lo and hi"""
    def below(h):
        t = np.clip(h - (z - r), 0, 2*r)
        return np.pi*t*t*(3*r - t)/3
    return float(np.sum(below(hi) - below(lo)))


def fixed_bed_gradient(bed, dest, grading, u0=0.25, z_lo=0.0045, z_hi=0.0165, snappy=False):
    """The packed bed of the cylinderBed case bed, frozen (no DEM integration, velocities 0),
    in a copy dest meshed with the z grading given (or by snappyHexMesh: cubic cells of 3 mm
    cut to the column, split once at its wall), under a superficial velocity u0: the
    pressure gradient between two points on the axis against Ergun's for the porosity of the
    spheres between them (Gidaspow's drag is Ergun's below a void fraction of 0.8).
    Returns (gradient, Ergun's gradient, porosity)."""
    case = os.path.join(WORK, dest)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(bed, case, ignore=shutil.ignore_patterns("processor*", "[1-9]*", "0.[0-9]*", "VTK",
                                                              "postProcessing", "log.*"))
    edit(os.path.join(case, "system", "blockMeshDict"), r"simpleGrading \(1 1 1\)", "simpleGrading (1 1 %g)" % grading)
    with open(os.path.join(case, "DEM", "in.liggghts")) as f:
        script = f.read()
    # frozen: no integration and no velocity, the bed as packed
    script = script.replace("run             0", "unfix integr\nvelocity all set 0 0 0\nrun             0")
    with open(os.path.join(case, "DEM", "in.liggghts"), "w") as f:
        f.write(script)
    edit(os.path.join(case, "0.orig", "U"), r"table \(.*\);", "table ( (0 (0 0 0)) (0.02 (0 0 %g)) (100 (0 0 %g)) );" % (u0, u0))
    control = os.path.join(case, "system", "controlDict")
    # the ramp ends at 0.02 s; by 0.03 s the gradient is steady to 1e-5
    edit(control, r"^endTime\s+\S+;", "endTime 0.04;")
    edit(control, r"^writeInterval\s+\S+;", "writeInterval 400;")
    edit(control, r"^functions\s*\n\{", "functions\n{\n    bedProbes\n    {\n        type probes; libs (\"libsampling.so\");\n"
         "        fields (p); interpolationScheme cellPoint;\n"
         "        probeLocations ( (0 0 %g) (0 0 %g) );\n        writeControl timeStep; writeInterval 10;\n    }" % (z_lo, z_hi))
    if snappy:
        rc, out = snappyColumn.mesh_column(case, 0.015, -0.006, 0.12, 0.003)
        check("snappyHexMesh column: meshed, checkMesh OK", rc == 0 and
              "Mesh OK." in open(os.path.join(case, "log.checkMesh")).read(), out[-800:] if rc else "")
        if rc:
            return None
    mesh = "" if snappy else "blockMesh > log.blockMesh && "
    rc, out = sh("rm -rf 0 && cp -r 0.orig 0 && %spimpleDEMFoam > log.pimpleDEMFoam 2>&1" % mesh, case, check=False)
    check("fixed bed, %s: run completed" % ("snappyHexMesh" if snappy else "z grading %g" % grading), rc == 0,
          out[-800:] if rc else "")
    if rc:
        return None
    x, r, _ = particleVtk.read(os.path.join(case, "VTK", "particles_400.vtp"))
    header = open(os.path.join(case, "postProcessing", "inletPressure", "0", "surfaceFieldValue.dat")).read()
    area = float(re.search(r"^# Area\s*:\s*(\S+)", header, re.M).group(1))
    eps = 1 - sphere_slab_volume(x[:, 2], r, z_lo, z_hi)/(area*(z_hi - z_lo))
    probe = np.loadtxt(os.path.join(case, "postProcessing", "bedProbes", "0", "p"))
    rho, mu, d = 1.2, 1.2*1.5e-5, 2*r.mean()
    gradient = rho*(probe[-1, 1] - probe[-1, 2])/(z_hi - z_lo)
    ergun = 150*mu*(1 - eps)**2*u0/(eps**3*d*d) + 1.75*rho*(1 - eps)*u0*u0/(eps**3*d)
    return gradient, ergun, eps


def test_cylinder_bed():
    print("cylinderBed tutorial: a bubbling bed in an O-grid column, serial and 2 ranks (scotch)")
    case = copy_tutorial("cylinderBed", "cylinderBed")
    # the start-up (the bubbling bed's weight carried is measured over 1 s by the tutorial's
    # own run: docs/solver.md#meshes)
    rc, out = sh("./Allrun analytical 0.1 2", case, check=False)
    check("Allrun on 2 ranks completed", rc == 0, out[-1500:] if rc else "")
    if rc:
        return
    check("the mesh is an O-grid (non-orthogonal, skewed cells)",
          re.search(r"Mesh non-orthogonality Max: (\S+)", open(os.path.join(case, "log.checkMesh")).read()) is not None
          and float(re.search(r"Mesh non-orthogonality Max: (\S+)",
                              open(os.path.join(case, "log.checkMesh")).read()).group(1)) > 10)
    log2 = os.path.join(case, "log.2ranks")
    shutil.copy(os.path.join(case, "log.pimpleDEMFoam"), log2)
    check_coupling_log("cylinderBed, 2 ranks", log2, 0.2)
    # Newton for the bed at rest, before the gas lifts it: the walls' measured contact
    # forces and the fluid's force carry the beads' weight (the first 5 ms of the ramp)
    shares = weightShares.weight_shares(case, 0, 0.005)
    check("at rest (t <= 5 ms): fluid + distributor + column wall forces = the beads' weight",
          shares is not None and abs(sum(shares) - 1) < 0.02,
          "(%s)" % (", ".join("%.4f" % x for x in shares) if shares else "no wall forces written"))
    decomposition = open(os.path.join(case, "log.decomposePar")).read()
    check("decomposed by scotch", "scotch" in decomposition)
    rc, out = sh("./Allrun analytical 0.02 1", case, check=False)
    check("serial run of 0.02 s completed", rc == 0, out[-800:] if rc else "")
    forces_agree("2 ranks = 1 rank", coupling_forces(log2)[:200],
                 coupling_forces(os.path.join(case, "log.pimpleDEMFoam")), 1e-6, 200)

    print("  the frozen packed bed in the column (uniform and z-graded O-grids, snappyHexMesh) against Ergun")
    for grading, snappy in ((1, False), (4, False), (1, True)):
        found = fixed_bed_gradient(case, "cylinder-fixed-%s" % ("snappy" if snappy else grading), grading,
                                   snappy=snappy)
        if found:
            gradient, ergun, eps = found
            near("%s: pressure gradient inside the bed / Ergun (porosity %.3f)"
                 % ("snappyHexMesh" if snappy else "O-grid, z grading %g" % grading, eps), gradient/ergun, 1, 0.10)


def test_riser():
    print("riser tutorial on 2 ranks: beads fed by LIGGGHTS at the bottom, removed at the top, 0.5 s")
    case = copy_tutorial("riser", "riser")
    rc, out = sh("./Allrun 0.5 2", case, check=False)
    check("Allrun on 2 ranks completed", rc == 0, out[-1500:] if rc else "")
    if rc:
        return
    r = results(os.path.join(case, "riser.result"))
    check("beads fed = beads removed at the top + beads held, bead for bead",
          r["balance"] == 0 and r["removed"] > 0,
          "(fed %d, removed %d, held %d)" % (r["fed"], r["removed"], r["held"]))
    near("beads fed / the feed rate's 12,000 per s", r["fed"]/(12000*0.5), 1, 0.01)
    near("developed flow: beads leaving the top / beads fed, per second", r["outflow_ratio"], 1, 0.05)
    near("developed flow: slip / terminal velocity x Richardson-Zaki", r["slip"]/r["slip_expected"], 1, 0.03)
    check_coupling_log("riser, 2 ranks", os.path.join(case, "log.pimpleDEMFoam"), 0.9)


def check_carried_run(run):
    """The spouted bed benchmark's carry.py: a run saved on one machine and
    restored on another continues from the same particles and fields; only
    the contacts' tangential history restarts."""
    sys.path.insert(0, os.path.join(ROOT, "benchmarks", "spoutedBed"))
    import carry
    archive, moved = os.path.join(WORK, "spoutedBed-carried.tar.xz"), os.path.join(WORK, "spoutedBed-carried")
    shutil.rmtree(moved, ignore_errors=True)
    script = os.path.join(ROOT, "benchmarks", "spoutedBed", "carry.py")
    rc, out = sh("/usr/bin/python3 %s save %s %s && /usr/bin/python3 %s restore %s %s"
                 % (script, run, archive, script, archive, moved), WORK, check=False)
    check("carry.py: saved and restored", rc == 0, out[-800:] if rc else "")
    if rc:
        return
    t = carry.latest_time(run)
    check("carried: the restored run's last written time is the run's (%g s)" % t, carry.latest_time(moved) == t)
    name = carry.time_dir(run, t)
    states = []
    for case in (run, moved):
        carry.liggghts(case, carry.HEAD + "read_restart ../%s/DEM.restart\ninclude in.parameters\n"
                       "include in.settings\nwrite_data check.data\n" % name)
        states.append(carry.read_data(os.path.join(case, "DEM", "check.data")))
    check("carried: positions, velocities, spins, diameters and densities bit for bit",
          all(np.array_equal(a, b) for a, b in zip(*states)))
    fields = [f for f in sorted(os.listdir(os.path.join(run, name)))
              if f != "DEM.restart" and os.path.isfile(os.path.join(run, name, f))]
    differ = [f for f in fields if f != "DEM.forces" and
              open(os.path.join(run, name, f), "rb").read() != open(os.path.join(moved, name, f), "rb").read()]
    check("carried: the fluid fields byte for byte (%s)" % " ".join(fields), not differ, "differ: %s" % differ)
    # both continue by one write interval
    logs = []
    for case in (run, moved):
        edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+\S+;", "endTime %g;" % (t + 0.06))
        rc, text = sh("timeout 600 pimpleDEMFoam > log.continued 2>&1", case, check=False)
        check("carried: %s continued to %g s" % (os.path.basename(case), t + 0.06), rc == 0, text[-400:])
        logs.append(coupling_forces(os.path.join(case, "log.continued")))
    if len(logs[0]) == len(logs[1]) >= 100:
        first = [abs(a[1][2] - b[1][2])/abs(a[1][2]) for a, b in zip(*logs)][0]
        check("carried: the first coupling's vertical fluid force within 1e-4 of the original run's",
              first < 1e-4, "(%.2e)" % first)
        check("carried: every parcel coupled at every coupling", all(a[0] == b[0] == 2747 for a, b in zip(*logs)))
    else:
        check("carried: as many couplings in both runs, at least 100", False,
              "(%d and %d)" % (len(logs[0]), len(logs[1])))
    check("carried: the particle files continue the run's numbering",
          [os.path.basename(f) for f in particleVtk.files(moved)][-1:] ==
          [os.path.basename(f) for f in particleVtk.files(run)][-1:])


def test_spouted_bed():
    print("spoutedBed tutorial at h = 4: the parcels, the fluid by the bed's rule, the jet, 2 ranks = serial")
    case = copy_tutorial("spoutedBed", "spoutedBed")
    rc, out = sh("./Allrun 4 analytical 0.18 1", case, check=False)
    check("Allrun at h = 4, 0.18 s, serial: completed", rc == 0, out[-1500:] if rc else "")
    if rc:
        return
    run = os.path.join(case, "parcels_h4")
    log = os.path.join(run, "log.pimpleDEMFoam")
    # worked by hand: 175,800 / 4^3 = 2746.9 -> 2747 parcels; cells at most 14 mm wide (280/20)
    # and 16.7 mm tall (200/12): x 10 + 2 + 10, y 1, z 60 over the bed and 3 in the channel
    check("2747 parcels of 10 mm packed and coupled", "2747 particles" in open(log).read()
          and re.search(r"(?m)^variable\s+radius\s+equal\s+0.005\b",
                        open(os.path.join(run, "DEM", "in.parameters")).read()) is not None)
    check("1,326 cells (22 x 1 x 60 + 2 x 1 x 3)", "nCells: 1326" in open(os.path.join(run, "log.blockMesh")).read())
    check("scaleCase warns that the bed's 40 mm depth is 4 parcels, fewer than 10",
          "the bed is 4 parcels across in y" in open(os.path.join(case, "log.scaleCase.parcels_h4")).read())
    check_coupling_log("spouted bed", log, 0.2)
    # the jet: the parcels over the channel rise, those at the side walls stay
    sys.path.insert(0, os.path.join(TUTORIALS))
    import particleVtk
    x, r, v = particleVtk.read(particleVtk.files(run)[-1])
    over_jet = (np.abs(x[:, 0]) < 0.012) & (x[:, 2] < 0.15)
    at_walls = np.abs(x[:, 0]) > 0.1
    rise, still = float(np.mean(v[over_jet, 2])), float(np.mean(np.linalg.norm(v[at_walls], axis=1)))
    check("the jet: parcels over the channel rise at more than 0.25 m/s and 3 times the speed of those "
          "by the side walls", rise > 0.25 and rise > 3*still, "(%.3f and %.4f m/s)" % (rise, still))
    # the averages kept per snapshot (snapshotProfiles.npz) = the averages of the snapshots
    plot = "/usr/bin/python3 %s 0.05" % os.path.join(TUTORIALS, "spoutedBed", "plotSpoutedBed.py")
    result = os.path.join(run, "spoutedBed.result")
    rc, out = sh(plot, run, check=False)
    from_files = open(result).read() if rc == 0 else ""
    os.rename(os.path.join(run, "VTK"), os.path.join(run, "VTK.away"))
    rc, out = sh(plot, run, check=False)
    os.rename(os.path.join(run, "VTK.away"), os.path.join(run, "VTK"))
    check("spouted bed averages from the kept snapshot sums, the snapshots gone, = from the snapshots",
          rc == 0 and from_files and open(result).read() == from_files
          and results(result).get("snapshots") == 3, out[-300:] if rc else "")
    check_carried_run(run)
    # 2 ranks = serial from the same packing, solvers converged to round-off
    edit(os.path.join(run, "system", "fvSolution"), r"tolerance 1e-8; relTol [0-9.]+;", "tolerance 1e-14; relTol 0;")
    edit(os.path.join(run, "system", "controlDict"), r"^endTime\s+\S+;", "endTime 0.03;")
    runs = {}
    for ranks in (1, 2):
        sh("rm -rf 0.[0-9]* [1-9]* processor* VTK postProcessing", run)
        cmd = ("decomposePar -force > log.decomposePar && timeout 600 mpirun -np 2 pimpleDEMFoam -parallel"
               if ranks == 2 else "timeout 600 pimpleDEMFoam")
        rc, text = sh(cmd + " > log.%d 2>&1" % ranks, run, check=False)
        check("0.03 s on %d rank(s) completed" % ranks, rc == 0, text[-400:] if rc else "")
        runs[ranks] = coupling_forces(os.path.join(run, "log.%d" % ranks)) if rc == 0 else []
    if forces_agree("2 ranks = serial (8 digits logged)", runs[2], runs[1], 1e-7, 101):
        check("each rank holds part of the bed", max(p[0] for p in runs[2]) < 2747)


def test_fluidised_bed():
    print("fluidisedBed tutorial: 10,000 beads in air, 2 s")
    case = copy_tutorial("fluidisedBed", "fluidisedBed")
    rc, out = sh("./Allrun analytical 3 2.0", case, check=False)
    check("Allrun completed", rc == 0, out[-1500:] if rc else "")
    print("\n".join("    " + l for l in out.splitlines() if "time-averaged" in l))
    r = results(os.path.join(case, "fluidisedBed.result"))
    check("time-averaged pressure drop within 5 % of bed weight per area", r["dp_error"] < 0.05,
          "(%.1f %%)" % (100*r["dp_error"]))
    # the bed is chaotic: a change of round-off moves its mean by a few tenths of a
    # percent, so validation.md's figures must be within a point of this run's
    row = next((l for l in open(os.path.join(ROOT, "docs", "validation.md"))
                if l.startswith("| `fluidisedBed` (10,000 beads")), "")
    stated = re.search(r"\| −?([\d.]+) % \(fluctuation ([\d.]+) %\)", row)
    check("validation.md's pressure drop and fluctuation within a point of this run's "
          "(%.1f %%, %.1f %%)" % (100*r["dp_error"], 100*r["fluctuation"]),
          stated is not None and abs(float(stated.group(1)) - 100*r["dp_error"]) <= 1
          and abs(float(stated.group(2)) - 100*r["fluctuation"]) <= 1, row[-60:])
    check_coupling_log("fluidisedBed", os.path.join(case, "log.pimpleDEMFoam"), 0.2)
    serial_logs = {"analytical": os.path.join(case, "log.analytical")}
    shutil.copy(os.path.join(case, "log.pimpleDEMFoam"), serial_logs["analytical"])
    print("  every void fraction model runs the bed (0.02 s each)")
    for model in ("centroid", "voxel", "hybrid", "kernel", "diffusion"):
        rc, out = sh("./Allrun %s 3 0.02" % model, case, check=False)
        check("%s: run completed" % model, rc == 0, out[-800:] if rc else "")
        check_coupling_log(model, os.path.join(case, "log.pimpleDEMFoam"), 0.2)
        serial_logs[model] = os.path.join(case, "log." + model)
        shutil.copy(os.path.join(case, "log.pimpleDEMFoam"), serial_logs[model])
    print("  2 ranks against 1: each rank holds only the particles near its cells")
    for model in ("analytical", "kernel", "diffusion"):
        rc, out = sh("./Allrun %s 3 0.02 2" % model, case, check=False)
        check("%s, 2 ranks: run completed" % model, rc == 0, out[-800:] if rc else "")
        log = os.path.join(case, "log.pimpleDEMFoam")
        check_coupling_log(model + ", 2 ranks", log, 0.2)
        par = coupling_forces(log)
        if forces_agree("%s, 2 ranks = 1 rank" % model, par, coupling_forces(serial_logs[model])[:len(par)],
                        1e-6, 200):
            held = max(p[0] for p in par)
            check("%s: no rank holds every particle (at most %d of 10000)" % (model, held),
                  held < 7000)
    print("  3 ranks decomposed by scotch (jagged subdomains through the periodic sides) against 1")
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 3;\nmethod scotch;\n")
    # more ranks than the 2 cores the tests run on
    rc, out = sh("OMPI_MCA_rmaps_base_oversubscribe=1 timeout 600 ./Allrun analytical 3 0.01 3", case,
                 check=False)
    check("scotch, 3 ranks: run completed", rc == 0, out[-800:] if rc else "")
    log = os.path.join(case, "log.pimpleDEMFoam")
    check_coupling_log("analytical, scotch 3 ranks", log, 0.2)
    par = coupling_forces(log)
    forces_agree("scotch, 3 ranks = 1 rank", par, coupling_forces(serial_logs["analytical"])[:len(par)], 1e-6, 100)


# the settling sphere's drag law and forces in the short form
SHORT_FORCES = r"^dragModel\s+\w+;.*\n(.*\n)*?forces\s+\(.*\);"


def forces_dictionary(props, cvm=None):
    """Rewrites the short form (dragModel and the list of forces) of the
    couplingProperties props as the forces dictionary it stands for"""
    text = open(props).read()
    law = re.search(r"^dragModel\s+(\w+);", text, re.M).group(1)
    names = re.search(r"^forces\s+\((.*)\);", text, re.M).group(1).split()
    body = "".join("    %s { %s}\n" % (n, "Cvm %g; " % cvm if n == "virtualMass" and cvm else "")
                   for n in names)
    edit(props, SHORT_FORCES, "forces\n{\n    drag { model %s; }\n%s}" % (law, body))


def test_forces_dictionary():
    print("the forces as a dictionary: the same run as their short form")
    runs = {}
    for form in ("short", "dictionary"):
        case = copy_tutorial("settlingSphere", "settle-forces-" + form)
        props = os.path.join(case, "constant", "couplingProperties")
        edit(props, r"^forces\s+\(.*\);", "forces (pressureGradient buoyancy SaffmanMeiLift virtualMass);"
             "\nvirtualMassCoefficient 0.6;")
        if form == "dictionary":
            edit(props, r"^virtualMassCoefficient.*\n", "")
            forces_dictionary(props, cvm=0.6)
        edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.1;")
        rc, out = sh("cp -r 0.orig 0 && blockMesh > log.blockMesh && pimpleDEMFoam > log.pimpleDEMFoam 2>&1",
                     case, check=False)
        check("settling sphere, forces in the %s form: run completed" % form, rc == 0, out[-800:] if rc else "")
        if rc:
            return
        runs[form] = (history(case), coupling_forces(os.path.join(case, "log.pimpleDEMFoam")))
    (h1, f1), (h2, f2) = runs["short"], runs["dictionary"]
    check("the dictionary form's velocity history = the short form's, all 15 digits written (%d rows)"
          % len(h1),
          h1.shape == h2.shape and np.array_equal(h1, h2),
          "(largest difference %.1e)" % (np.max(np.abs(h1 - h2)) if h1.shape == h2.shape else float("nan")))
    check("the dictionary form's logged forces = the short form's (%d couplings)" % len(f1),
          len(f1) > 0 and f1 == f2)
    log = open(os.path.join(WORK, "settle-forces-dictionary", "log.pimpleDEMFoam")).read()
    check("the dictionary form built its five forces, in its order",
          "particleForceList: forces drag pressureGradient buoyancy SaffmanMeiLift virtualMass" in log)


def test_bad_input():
    print("bad input: a clear error, a non-zero status, no hang")
    base = copy_tutorial("settlingSphere", "settle-bad")
    sh("cp -r 0.orig 0 && blockMesh", base)
    props = "constant/couplingProperties"
    cases = [
        ("unknown drag model", props, r"^dragModel\s+\w+;", "dragModel Stokes;", "Unknown dragModel"),
        ("unknown void fraction model", props, r"^voidFractionModel\s+\w+;", "voidFractionModel pcm;",
         "Unknown voidFractionModel"),
        ("bad formulation", props, r"^formulation\s+A;", "formulation C;", "formulation C is not one of 2(A B)"),
        ("bad particlesOutside", props, r"^particlesOutside\s+error;", "particlesOutside delete;",
         "particlesOutside delete is not one of 2(error remove)"),
        ("unknown force", props, r"^forces\s+\(.*\);", "forces (lift);", "unknown entry lift"),
        ("coarseGraining a number, not its dictionary", props, r"^particlesOutside\s+error;",
         "particlesOutside error;\ncoarseGraining 2;", "coarseGraining in couplingProperties is not a dictionary"),
        ("a force listed twice", props, r"^forces\s+\(.*\);", "forces (pressureGradient buoyancy pressureGradient);",
         "forces in couplingProperties names pressureGradient twice"),
        ("dragModel a dictionary", props, r"^dragModel\s+\w+;", "dragModel { type Gidaspow; }",
         "dragModel in couplingProperties is a dictionary: it must be one word"),
        ("misspelt optional keyword", props, r"^forces\s+\(.*\);", "forces (virtualMass);\nvirtualMassCoeficient 0.3;",
         "unknown keyword virtualMassCoeficient in couplingProperties (did you mean virtualMassCoefficient?)"),
        ("keyword given twice", props, r"^formulation\s+A;", "formulation A;\nformulation B;",
         "duplicate entry: formulation"),
        ("negative virtual mass coefficient", props, r"^forces\s+\(.*\);",
         "forces (virtualMass);\nvirtualMassCoefficient -1;", "virtualMassCoefficient must be zero or positive"),
        ("added mass too heavy for the explicit scheme", props, r"^forces\s+\(.*\);",
         "forces (buoyancy virtualMass);\nvirtualMassCoefficient 3;", "the added mass is explicit"),
        ("pressure gradient with formulation B", props, r"^formulation\s+A;", "formulation B;",
         "remove pressureGradient"),
        ("coupling time not a multiple of deltaT", props, r"^couplingInterval\s+\d+;", "couplingInterval 7;",
         "not a whole multiple or divisor"),
        ("zero coupling interval", props, r"^couplingInterval\s+\d+;", "couplingInterval 0;",
         "couplingInterval must be a positive"),
        ("adjustable time step", "system/controlDict", r"^adjustTimeStep\s+no;", "adjustTimeStep yes;",
         "adjustTimeStep"),
        ("missing DEM script", props, r"^demScript\s+.*;", 'demScript "DEM/in.missing";',
         "no LIGGGHTS input script"),
        ("LIGGGHTS input error", "DEM/in.settings", r"^fix integr", "fix integr all nve/spheres\n#",
         "LIGGGHTS stopped the run"),
        ("DEM script without couple/cfd/force", "DEM/in.settings", r"^fix cfd2 .*$", "",
         "has no 'fix couple/cfd/force'"),
        ("particle outside the mesh", "DEM/in.parameters", r"^variable releaseZ .*$", "variable releaseZ equal 0.15",
         "particles have left the mesh"),
        # the forces as a dictionary
        ("dragModel beside the forces dictionary", props, r"^forces\s+\(.*\);",
         "forces { drag { model Gidaspow; } buoyancy {} }", "dragModel is given with forces as a dictionary"),
        ("forces dictionary without drag", props, SHORT_FORCES, "forces { buoyancy {} }",
         "forces has no drag entry"),
        ("unknown force in the dictionary", props, SHORT_FORCES, "forces { drag { model Gidaspow; } lift {} }",
         "unknown entry lift in forces"),
        ("unknown drag law in the dictionary", props, SHORT_FORCES, "forces { drag { model Stokes; } }",
         "Unknown dragModel type Stokes"),
        ("drag without its law", props, SHORT_FORCES, "forces { drag {} }", "'model' not found"),
        ("misspelt entry of a force", props, SHORT_FORCES,
         "forces { drag { model Gidaspow; } virtualMass { cvm 0.3; } }",
         "unknown keyword cvm in virtualMass (did you mean Cvm?)"),
        ("a force given a value", props, SHORT_FORCES, "forces { drag { model Gidaspow; } buoyancy yes; }",
         "buoyancy in forces must be a dictionary"),
        ("negative Cvm", props, SHORT_FORCES, "forces { drag { model Gidaspow; } virtualMass { Cvm -1; } }",
         "Cvm must be zero or positive"),
        ("pressure gradient force with formulation B", props, r"^formulation\s+A;\n(.*\n)*forces\s+\(.*\);",
         "formulation B;\nforces { drag { model Gidaspow; } pressureGradient {} }", "remove pressureGradient"),
    ]
    for name, rel, pattern, replacement, needle in cases:
        case = os.path.join(WORK, "settle-bad-case")
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(base, case)
        edit(os.path.join(case, rel), pattern, replacement)
        if "outside" in name:
            set_dem(case, boxHeight=0.2)
        rc, out = sh("timeout 120 pimpleDEMFoam", case, check=False)
        check("%s: error says '%s'" % (name, needle),
              rc not in (0, 124) and needle in out and "Segmentation" not in out,
              "" if needle in out else out[-600:])
    # an error LIGGGHTS ends with MPI_Abort: the log names the screen file
    # before the DEM starts, and the reason is there
    case = os.path.join(WORK, "settle-bad-case")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base, case)
    set_dem(case, youngs=1e6)
    rc, out = sh("timeout 120 pimpleDEMFoam", case, check=False)
    screen = os.path.join(case, "DEM", "log.liggghtsScreen")
    reason = open(screen, errors="replace").read() if os.path.isfile(screen) else ""
    check("LIGGGHTS error that aborts: the log names DEM/log.liggghtsScreen, which says why",
          rc not in (0, 124) and "log.liggghtsScreen" in out and "youngsModulus >= 5e6" in reason,
          "" if rc not in (0, 124) else out[-600:])
    # in parallel a LIGGGHTS error stops every rank
    case = os.path.join(WORK, "settle-bad-case")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base, case)
    edit(os.path.join(case, "DEM", "in.settings"), r"^fix integr", "fix integr all nve/spheres\n#")
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (1 1 2); }\n")
    rc, out = sh("decomposePar -force > /dev/null && timeout 120 mpirun -np 2 pimpleDEMFoam -parallel",
                 case, check=False)
    check("LIGGGHTS error on 2 ranks: every rank stops, message shown",
          rc not in (0, 124) and "Invalid fix style" in out, "(status %d)" % rc)
    # removal instead of an error, when the user asks for it
    case = os.path.join(WORK, "settle-remove")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base, case)
    edit(os.path.join(case, props), r"^particlesOutside\s+error;", "particlesOutside remove;")
    set_dem(case, boxHeight=0.2, releaseZ=0.15)
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.01;")
    rc, out = sh("timeout 120 pimpleDEMFoam", case, check=False)
    check("particlesOutside remove: the particle is deleted from the DEM and the run goes on",
          rc == 0 and "removing 1 particles" in out and "coupling 19: 0 particles" in out, out[-400:] if rc else "")
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (1 1 2); }\n")
    rc, out = sh("decomposePar -force > /dev/null && "
                 "timeout 120 mpirun -np 2 pimpleDEMFoam -parallel", case, check=False)
    check("particlesOutside remove on 2 ranks: the particle no rank's cells reach is deleted",
          rc == 0 and "removing 1 particles" in out and "coupling 19: 0 particles" in out, out[-400:] if rc else "")


def test_parcels():
    print("coarse-grained parcels: a 2 mm parcel of 1 mm spheres (h = 2) settling in water")
    def run(dest, diameter, coarse):
        case = copy_tutorial("settlingSphere", dest)
        # cells of 16 mm: the parcel's own fluid fraction stays 0.999
        edit(os.path.join(case, "system", "blockMeshDict"), r"^scale\s+0.001;", "scale 0.002;")
        edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.25;")
        set_dem(case, boxWidth=0.08, boxHeight=0.192, releaseXY=0.04, releaseZ=0.17, diameter=diameter)
        if coarse:
            with open(os.path.join(case, "constant", "couplingProperties"), "a") as f:
                f.write("coarseGraining { %s }\n" % coarse)
        sh("cp -r 0.orig 0 && blockMesh", case)
        rc, out = sh("pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
        check("%s: run completed" % dest, rc == 0)
        return case, (-history(case)[-1, 2] if rc == 0 else float("nan"))

    _, single = run("parcel-single", 1e-3, None)
    case, cubic = run("parcel-cubic", 2e-3, "factor 2; forceScaling cubic;")
    # the parcel stirs its cell eight times as hard: the fluid follows it a little more
    near("cubic: the parcel settles as one of its particles (parcel / 1 mm sphere, same mesh)", cubic/single, 1.0, 1e-2)
    near("cubic: parcel terminal velocity / Schiller-Naumann for 1 mm", cubic/terminal_velocity(cd_schiller_naumann),
         1.0, 0.02)
    check_coupling_log("cubic parcels", os.path.join(case, "log.pimpleDEMFoam"), 0.99)

    # exact: drag, pressure gradient force and buoyancy h^2 those of one
    # particle, the parcel's weight h^3 (gravity left as it is):
    # F_SN(v) = (h rho_p - rho_f) V g
    def excess(v):
        re = rho_f*v*d/mu
        return (2*rho_p - rho_f)*g*math.pi*d**3/6 - 0.5*cd_schiller_naumann(re)*rho_f*math.pi*d*d/4*v*v
    _, exact = run("parcel-exact", 2e-3, "factor 2; forceScaling exact;")
    near("exact: parcel terminal velocity / h^2 Schiller-Naumann against h^3 weight", exact/brentq(excess, 1e-5, 5.0),
         1.0, 0.02)
    # the cubic parcel on 2 ranks, the mesh split across its path
    par = os.path.join(WORK, "parcel-parallel")
    shutil.rmtree(par, ignore_errors=True)
    shutil.copytree(case, par)
    serial, history_par = serial_and_two_ranks(par, 0.1)
    diff = (np.max(np.abs(history_par[:, 2] - serial[:, 2]))/np.max(np.abs(serial[:, 2]))
            if history_par is not None else float("nan"))
    check("cubic parcel on 2 ranks: velocity history equal to serial (1e-10)", diff < 1e-10, "(%.1e)" % diff)

    parcel_types()

    # centroid with parcels wider than a cell: said once
    case = copy_tutorial("settlingSphere", "parcel-centroid")
    set_dem(case, diameter=0.01)
    edit(os.path.join(case, "constant", "couplingProperties"), r"^voidFractionModel\s+\w+;", "voidFractionModel centroid;")
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.005;")
    with open(os.path.join(case, "constant", "couplingProperties"), "a") as f:
        f.write("coarseGraining { factor 2; }\n")
    rc, out = sh("cp -r 0.orig 0 && blockMesh > log.blockMesh && pimpleDEMFoam", case, check=False)
    check("centroid with 10 mm parcels on 8 mm cells: warned once", rc == 0 and out.count("centroid puts each") == 1,
          out[-400:] if rc else "")
    case = copy_tutorial("settlingSphere", "parcel-bad")
    sh("cp -r 0.orig 0 && blockMesh", case)
    for body, needle in (("factor 0.5;", "is below 1"), ("factor (2 3);", "has 2 values for the DEM's 1 particle types"),
                         ("factor (2 0.5);", "(of type 2) is below 1"), ("factor ();", "is empty"),
                         ("factor 2; forceScaling quadratic;", "quadratic"), ("forceScaling cubic;", "has no factor")):
        props = os.path.join(case, "constant", "couplingProperties")
        text = open(props).read().split("coarseGraining")[0]
        with open(props, "w") as f:
            f.write(text + "coarseGraining { %s }\n" % body)
        rc, out = sh("timeout 120 pimpleDEMFoam", case, check=False)
        check("coarseGraining { %s }: error says '%s'" % (body, needle),
              rc not in (0, 124) and needle in out and "coarseGraining" in out, "" if needle in out else out[-500:])


# the 2D settling case: a slab of T = 2 mm, 160 x 384 mm in x and y (cells of 32 mm: a disk of
# 2 mm leaves its cell's fluid fraction at 0.997), gravity along -y, disks released at y = 0.2 m
SLAB, DISK_Y = 2e-3, 0.2


def disk_case(dest, diameter, coarse, dem_2d=True, two_dimensional=True):
    """settlingSphere made 2D: the mesh one cell thick in z, LIGGGHTS in 2D (disks in the x-y
    plane, fix enforce2d), DiFelice drag (written with d^2, so that the count of disks a
    parcel stands for, h^2 in 2D and not h^3, shows in its drag)"""
    case = copy_tutorial("settlingSphere", dest)
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }\n"
                "scale 0.001;\nvertices ( (0 0 -1) (160 0 -1) (160 384 -1) (0 384 -1)"
                " (0 0 1) (160 0 1) (160 384 1) (0 384 1) );\n"
                "blocks ( hex (0 1 2 3 4 5 6 7) (5 12 1) simpleGrading (1 1 1) );\n"
                "boundary ( walls { type wall; faces ( (0 4 7 3) (1 2 6 5) (0 1 5 4) ); }\n"
                "  top { type patch; faces ( (3 7 6 2) ); }\n"
                "  frontAndBack { type empty; faces ( (0 3 2 1) (4 5 6 7) ); } );\n")
    for field in ("U", "p"):
        edit(os.path.join(case, "0.orig", field), r"^(\s*top .*)$", r"\g<1>\n    frontAndBack { type empty; }")
    edit(os.path.join(case, "constant", "g"), r"^value .*;", "value (0 -9.81 0);")
    props = os.path.join(case, "constant", "couplingProperties")
    edit(props, r"^dragModel\s+\w+;.*$", "dragModel DiFelice;")
    with open(props, "a") as f:
        f.write(("twoDimensional true;\n" if two_dimensional else "") +
                ("coarseGraining { %s }\n" % coarse if coarse else ""))
    edit(os.path.join(case, "system", "controlDict"), r"^endTime\s+0.4;", "endTime 0.25;")
    set_dem(case, boxWidth=0.16, boxHeight=0.384, releaseXY=0.08, releaseZ=DISK_Y, diameter=diameter)
    dem = os.path.join(case, "DEM")
    script = os.path.join(dem, "in.liggghts")
    if dem_2d:
        edit(script, r"^atom_style", "dimension       2\natom_style")
        edit(script, r"^boundary .*$", "boundary        f f p")
        edit(script, r"^region .*$", "region          domain block 0 ${boxWidth} 0 ${boxHeight} %g %g units box"
             % (-SLAB/2, SLAB/2))
        edit(script, r"^create_atoms .*$", "create_atoms    1 single ${releaseXY} ${releaseZ} 0 units box")
        settings = os.path.join(dem, "in.settings")
        edit(settings, r"vector 0.0 0.0 -1.0", "vector 0.0 -1.0 0.0")
        edit(settings, r"zplane 0.0", "yplane 0.0")
        edit(settings, r"^(fix integr .*)$", r"\g<1>\nfix plane all enforce2d")
        edit(settings, r"^variable\s+zp equal z\[1\]$", "variable        zp equal y[1]")
        edit(settings, r"^variable\s+vzp equal vz\[1\]$", "variable        vzp equal vy[1]")
    sh("cp -r 0.orig 0 && blockMesh > log.blockMesh", case)
    return case


def disk_settling(h, law):
    """terminal velocity of a 2D parcel of h^2 disks of 1 mm (DiFelice, single-particle limit):
    the drag of one disk h^2 (cubic) or h (exact) times, the buoyancy on the parcel's slab volume
    (times 1/h for exact), the weight of its h^2 disks"""
    volume = math.pi*(h*d/2)**2*SLAB
    buoyancy = rho_f*volume*g*(1 if law == "cubic" else 1/h)
    count = h**2 if law == "cubic" else h
    def excess(v):
        re = rho_f*v*d/mu
        return rho_p*volume*g - buoyancy - count*math.pi/8*d*d*rho_f*cd_di_felice(re)*v*v
    return brentq(excess, 1e-5, 5.0)


def test_parcels_2d():
    print("2D coarse-grained parcels: disks of 1 mm and a 2 mm parcel of them (h = 2) settling in water")
    def run(dest, diameter, coarse):
        case = disk_case(dest, diameter, coarse)
        rc, out = sh("pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
        log = open(os.path.join(case, "log.pimpleDEMFoam")).read()
        check("%s: run completed, forces per metre of depth said" % dest,
              rc == 0 and "2D, forces to the DEM per metre of depth" in log, log[-600:] if rc else "")
        return case, (-history(case)[-1, 2] if rc == 0 else float("nan"))

    _, single = run("disk-single", 1e-3, None)
    near("a 1 mm disk settles at DiFelice's terminal velocity (its mass and fluid forces per slab)",
         single/disk_settling(1, "cubic"), 1.0, 0.02)
    case, cubic = run("disk-cubic", 2e-3, "factor 2; forceScaling cubic;")
    near("cubic: the 2 mm parcel settles as one of its 1 mm disks (h^2 drag)", cubic/single, 1.0, 1e-2)
    check_coupling_log("2D cubic parcel", os.path.join(case, "log.pimpleDEMFoam"), 0.99)
    _, exact = run("disk-exact", 2e-3, "factor 2; forceScaling exact;")
    near("exact: parcel terminal velocity / h DiFelice against h^2 weight (Eq. 35)",
         exact/disk_settling(2, "exact"), 1.0, 0.02)
    par = os.path.join(WORK, "disk-parallel")
    shutil.rmtree(par, ignore_errors=True)
    shutil.copytree(case, par)
    # the mesh split in y at 192 mm, which the parcel's disk reaches from the start
    serial, history_par = serial_and_two_ranks(par, 0.1, "(1 2 1)")
    diff = (np.max(np.abs(history_par[:, 2] - serial[:, 2]))/np.max(np.abs(serial[:, 2]))
            if history_par is not None else float("nan"))
    check("2D cubic parcel on 2 ranks: velocity history equal to serial (1e-10)", diff < 1e-10, "(%.1e)" % diff)
    for dest, dem_2d, two_d, needle in (("disk-3d-dem", False, True, "twoDimensional is set but the DEM script is 3D"),
                                        ("disk-no-2d", True, False, "but twoDimensional is not set")):
        case = disk_case(dest, 1e-3, None, dem_2d, two_d)
        rc, out = sh("timeout 120 pimpleDEMFoam", case, check=False)
        check("%s: error says '%s'" % (dest, needle), rc not in (0, 124) and needle in out,
              "" if needle in out else out[-500:])


def test_mueller_bed():
    print("muellerBed tutorial: 9,240 poppy seeds in a 44 x 10 mm bed with walls, U = 0.9 m/s, 0.2 s")
    case = copy_tutorial("muellerBed", "muellerBed")
    rc, out = sh("./Allrun analytical 0.9 4 0.2", case, check=False)
    check("Allrun completed", rc == 0, out[-1500:] if rc else "")
    print("\n".join("    " + l for l in out.splitlines() if l.startswith("    ") and "t = " not in l))
    log = os.path.join(case, "log.pimpleDEMFoam")
    check_coupling_log("muellerBed", log, 0.2)
    counts = [int(m) for m in re.findall(r"(?m)^coupling \d+: (\d+) particles", open(log).read())]
    check("every seed stays in the bed (9240 particles at every coupling)",
          len(counts) > 100 and set(counts) == {9240}, "(%d couplings, counts %s)" % (len(counts), sorted(set(counts))))
    # the error left after each time step's last pressure corrector
    errors = [float(m[-1]) for m in (re.findall(r"continuity errors : sum local = (\S+),", step)
                                     for step in open(log).read().split("\nTime = ")[1:]) if m]
    check("fluid mass: continuity error of every time step below 1e-9 (sum local)",
          len(errors) > 1000 and max(errors) < 1e-9, "(%d steps, largest %.2e)" % (len(errors), max(errors or [0])))
    result = dict(l.split() for l in open(os.path.join(case, "muellerBed.result")))
    for kind, column, lo, hi, heights in (("voidfraction", "voidfraction", 0.2, 1.0, ("16.4", "31.2")),
                                          ("particleVelocity", "vz_m_s", -5, 5, ("15.0", "20.0", "25.0", "35.0")),
                                          ("voidfractionSlice", "voidfraction", 0.2, 1.0, ("16.4", "31.2"))):
        for height in heights:
            path = os.path.join(case, "postProcessing", "profiles", "%s_h%smm.csv" % (kind, height))
            ok = os.path.isfile(path) and open(path).readline().strip() == "x_m," + column
            data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2) if ok else np.zeros((0, 2))
            check("%s at %s mm: written across the width, finite, within [%g, %g]" % (kind, height, lo, hi),
                  ok and len(data) >= 9 and np.isfinite(data).all() and data[:, 0].min() > 0
                  and data[:, 0].max() < 0.044 and data[:, 1].min() >= lo and data[:, 1].max() <= hi,
                  "(%d points, %.4g..%.4g)" % (len(data), data[:, 1].min(), data[:, 1].max()) if len(data) else "")
            measured = os.path.join(ROOT, "benchmarks", "muellerBed", "measured", "%s_U0.9_h%smm.csv"
                                    % (kind.replace("Slice", ""), height))
            if not os.path.isfile(measured) or not len(data):
                continue
            points = np.loadtxt(measured, delimiter=",", skiprows=1, ndmin=2)
            # the profile's value at each measured x, by hand: between its two neighbours, or its end value
            expected = []
            for x, value in points:
                j = min(max(np.searchsorted(data[:, 0], x), 1), len(data) - 1)
                w = min(max((x - data[j - 1, 0])/(data[j, 0] - data[j - 1, 0]), 0), 1)
                expected.append(abs((1 - w)*data[j - 1, 1] + w*data[j, 1] - value))
            key = "%s_h%smm_mad" % (kind, height)
            check("%s at %s mm: the mean absolute difference from the measurement in muellerBed.result" % (kind, height),
                  key in result and abs(float(result[key]) - np.mean(expected)) < 1e-5,
                  "(%s, by hand %.6g)" % (result.get(key), np.mean(expected)))
    deep = copy_tutorial("muellerBed", "muellerBed-deep")
    shutil.copytree(os.path.join(case, "DEM", "post"), os.path.join(deep, "DEM", "post"))
    set_dem(deep, wallFriction=0.3, wallRestitution=0.9)
    rc, out = sh("./Allrun analytical 0.9 4 0.03 1 2", deep, check=False)
    check("Allrun with 2 cells across the depth completed on a 9 x 2 x 26 mesh",
          rc == 0 and "(9 x 2 x 26)" in out, "" if rc == 0 else out[-1500:])
    # LIGGGHTS echoes the contact settings with each variable substituted, the last line the one it ran
    screen = open(os.path.join(deep, "DEM", "log.liggghtsScreen")).read()
    for name, wall, values in (("Friction", 0.3, "0.1 0.3 0.3 0.3"), ("Restitution", 0.9, "0.98 0.9 0.9 0.9")):
        ran = re.findall(r"(?m)^fix \S+ all property/global coefficient%s peratomtypepair 2\s+(.*?)\s*$" % name, screen)
        check("wall%s %g in DEM/in.parameters: LIGGGHTS ran seed-seed, seed-wall (twice), wall-wall %s"
              % (name, wall, values), ran[-1:] == [values], "(%s)" % ran[-1:])
    walls = re.findall(r"(?m)^fix (\w+) all wall/gran .* primitive type (\d+) [xyz]plane [-0-9.e]+\s*$", screen)
    check("the six walls (four sides, distributor, lid) are of the walls' material, type 2",
          sorted(w for w, t in walls if t == "2") == ["back", "front", "grid", "left", "lid", "right"], "(%s)" % walls)
    u = open(os.path.join(deep, "0", "U")).read()
    check("2 cells across the depth: front and back are no-slip for the gas",
          re.search(r'"\(front\|back\)"\s*\{\s*type\s+noSlip;', u) is not None, "")
    probes = open(os.path.join(deep, "system", "probeLocations")).read()
    ys = {float(m) for m in re.findall(r"\(\S+ (\S+) \S+\)", probes)}
    check("2 cells across the depth: probes at both cells' centres (y = 2.5 and 7.5 mm)",
          len(ys) == 2 and all(any(abs(y - c) < 1e-9 for y in ys) for c in (0.0025, 0.0075)), "(%s)" % sorted(ys))
    path = os.path.join(deep, "postProcessing", "profiles", "voidfraction_h16.4mm.csv")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2) if os.path.isfile(path) else np.zeros((0, 2))
    check("2 cells across the depth: one depth-averaged void fraction per column of cells (9)",
          len(data) == 9 and np.isfinite(data).all() and data[:, 1].min() >= 0.2 and data[:, 1].max() <= 1, "")

def test_coupling_scale():
    """The scale benchmark's short version: its report, the stage split
    against the wall clock, and the exchange counted against the geometry."""
    print("couplingScale --short: report columns, stage split, particles exchanged")
    rc, out = sh("/usr/bin/python3 benchmarks/couplingScale.py --short", ROOT, check=False)
    check("couplingScale --short runs", rc == 0, out[-800:] if rc else "")
    if rc:
        return
    work = os.path.join(ROOT, "build", "couplingScale", "short")
    series = list(csv.DictReader(open(os.path.join(work, "series.csv"))))
    wanted = ("particles,ranks,cells,couplings,dem_ms,exchange_ms,voidfraction_ms,forces_ms,fluid_ms,"
              "peak_rss_mb").split(",")
    check("series.csv: a row per rank count with the required columns",
          len(series) == 2 and all(c in series[0] and series[0][c] for c in wanted), str(list(series[0])))
    for row in series:
        # each stage takes part of every coupling's wall time, so its median is at most the
        # wall time's (medians do not add: their sum may exceed it)
        slowest = max(float(row[c]) for c in wanted[4:9])
        total = float(row["total_ms"])
        check("%s ranks: no stage median exceeds the wall time between couplings" % row["ranks"],
              slowest <= 1.01*total, "(slowest %.2f of %.2f ms)" % (slowest, total))
        # summed over the couplings, the timed stages are the wall time but for the untimed rest
        share = json.load(open(os.path.join(work, "1e4_%s" % row["ranks"], "result_1.json"))).get("stage_share", 0)
        check("%s ranks: the stages take 85 %% to 101 %% of the wall time, summed over the couplings"
              % row["ranks"], 0.85 <= share <= 1.01, "(%.3f)" % share)
        check("%s ranks: the particles are the bed's, peak memory positive" % row["ranks"],
              int(row["particles"]) > 9000 and float(row["peak_rss_mb"]) > 0, "")
    exchange = list(csv.DictReader(open(os.path.join(work, "exchange.csv"))))
    for ranks in ("2", "3"):
        rows = [r for r in exchange if r["ranks"] == ranks]
        total = lambda c: sum(int(r[c]) for r in rows)
        check("%s ranks: every rank reported; particles sent = received; held >= owned" % ranks,
              len(rows) == int(ranks) and total("sent") == total("received")
              and total("sent_bytes") == total("received_bytes") and total("holds") >= total("owns"),
              "(sent %d, received %d)" % (total("sent"), total("received")))
    # on 2 slabs (x below and above half the width, periodic in x) a particle is held
    # by each slab its sphere (or its periodic image) meets
    case = os.path.join(work, "exchange_1e4_2")
    vtks = particleVtk.files(case)
    if not vtks:
        check("the 2-rank exchange run wrote its particles", False, "")
        return
    x, r, _ = particleVtk.read(vtks[-1])
    width = float(re.search(r"^variable width\s+equal\s+(\S+)", open(os.path.join(
        case, "DEM", "in.parameters")).read(), re.M).group(1))
    expected = 0
    for lo, hi in ((0, width/2), (width/2, width)):
        meets = np.zeros(len(x), dtype=bool)
        for shift in (-width, 0, width):
            meets |= (x[:, 0] + shift + r >= lo) & (x[:, 0] + shift - r <= hi)
        expected += int(meets.sum())
    rows = [e for e in exchange if e["ranks"] == "2"]
    held = sum(int(e["holds"]) for e in rows)
    check("2 ranks: the particles held = those whose spheres meet each slab (%d beads)" % len(x),
          held == expected, "(held %d, geometry %d)" % (held, expected))


def main():
    checks.run([test_coupling_scale, test_settling_sphere, test_drag_laws, test_lift_virtual_mass, test_heat_transfer, test_thermal_front, test_particle_conduction, test_heated_bed, test_restart, test_bed_restart, test_serial_parallel,
                test_forces_dictionary, test_bad_input, test_parcels, test_parcels_2d, test_packed_bed,
                test_fluidised_bed, test_riser, test_spouted_bed, test_cylinder_bed, test_mueller_bed], sys.argv[1:])
    return checks.summary("coupling")


if __name__ == "__main__":
    sys.exit(main())
