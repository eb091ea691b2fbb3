# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Reading a fluidisedBed run: the particles of a VTK file, the bed weight
per area, the inlet pressure history and the solver log's extremes."""
import glob
import os
import re

import sys

import numpy as np

# tutorials/caseProperties.py, also from a copy of the case elsewhere
sys.path.insert(0, os.path.join(os.environ.get("VFM_PROJECT_DIR",
                                               os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")),
                                "tutorials"))
import caseProperties
import particleVtk

# the fluid and particles of this case (read where the script runs: the case)
RHO_F = caseProperties.fluid()[1]
RHO_P, G = caseProperties.particle_density(), caseProperties.gravity()


read_vtk = particleVtk.read     # positions, radii and velocities of a particle file
snapshots = particleVtk.files   # a case's particle files in time order
step = particleVtk.step         # the time step a particle file was written at


def _inlet_files(case):
    """the inlet pressure files, one per start of the run (a continued run starts another)"""
    top = os.path.join(case, "postProcessing", "inletPressure")
    starts = sorted((d for d in os.listdir(top) if re.fullmatch(r"[0-9.eE+-]+", d)), key=float) \
        if os.path.isdir(top) else []
    return [os.path.join(top, d, "surfaceFieldValue.dat") for d in starts] or \
        [os.path.join(top, "0", "surfaceFieldValue.dat")]


def _inlet_data(case):
    return _inlet_files(case)[0]


def inlet_area(case):
    """the mesh's inlet area, as the surfaceFieldValue file's header gives it"""
    return float(re.search(r"^# Area\s*:\s*(\S+)", open(_inlet_data(case)).read(), re.M).group(1))


def bed_weight(case, area=None):
    """from the particle count the solver reports at start and the beads'
    (or parcels') radius in the case's DEM parameters, per area (default:
    the box's width x depth from the DEM parameters)"""
    # a continued run's first log may be kept without its header: any log that has it
    for log in sorted(glob.glob(os.path.join(case, "log.pimpleDEMFoam*"))):
        m = re.search(r"particleFluidCoupling: formulation \w+, (\d+) particles", open(log).read())
        if m:
            break
    else:
        raise ValueError("bed_weight: no particle count in %s/log.pimpleDEMFoam*" % case)
    n = int(m.group(1))
    r = caseProperties.particle_diameter(case)/2
    if area is None:
        box = caseProperties.dem_parameters(case)
        area = box["width"]*box["depth"]
    return n*4/3*np.pi*r**3*(RHO_P - RHO_F)*G/area


def pressure_drop(case):
    """(time, inlet pressure) over every start of the run: each file up to where the next
    one starts (a continued run repeats the times after its last written time)"""
    parts = [np.loadtxt(f, ndmin=2) for f in _inlet_files(case)]
    kept = [p[p[:, 0] <= q[0, 0]] if len(q) else p for p, q in zip(parts[:-1], parts[1:])] + parts[-1:]
    data = np.concatenate(kept)
    return data[:, 0], RHO_F*data[:, 1]


def pressure_panel(ax, t, dp, weight, mean, start, per="area"):
    """the pressure drop against time beside the bed weight per area and the
    mean after the start-up"""
    ax.plot(t, dp, lw=0.8, label="pimpleDEMFoam + LIGGGHTS")
    ax.axhline(weight, color="k", ls="--", lw=1, label=f"bed weight / {per}")
    ax.axhline(mean, color="C1", ls=":", lw=1, label=f"mean t > {start} s ({100*(mean/weight - 1):+.1f} %)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("pressure drop [Pa]")
    ax.set_ylim(0, 2*weight)
    ax.legend(fontsize=7)


def log_extremes(case):
    """finished, min void fraction, max continuity error (sum local), max Courant number"""
    path = os.path.join(case, "log.pimpleDEMFoam")
    if not os.path.isfile(path):
        return False, np.nan, np.nan, np.nan
    text = open(path).read()
    alpha = [float(a) for a in re.findall(r"; alpha (\S+?)\.\.", text)]
    cont = [float(c) for c in re.findall(r"continuity errors : sum local = (\S+),", text)]
    co = [float(c) for c in re.findall(r"Courant Number max: (\S+)", text)]
    finished = "\nEnd\n" in text
    return (finished, min(alpha) if alpha else np.nan, max(cont) if cont else np.nan,
            max(co) if co else np.nan)
