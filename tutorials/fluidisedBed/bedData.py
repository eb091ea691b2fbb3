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


read_vtk = particleVtk.read     # positions, radii and velocities of a particles_N.vtk file


def snapshots(case):
    files = glob.glob(os.path.join(case, "VTK", "particles_*.vtk"))
    return sorted(files, key=lambda f: int(re.findall(r"_(\d+)\.vtk", f)[0]))


def bed_weight(case):
    """from the particle count the solver reports at start and the beads'
    (or parcels') radius in the case's DEM parameters"""
    text = open(os.path.join(case, "log.pimpleDEMFoam")).read()
    n = int(re.search(r"particleFluidCoupling: formulation \w+, (\d+) particles", text).group(1))
    r = caseProperties.particle_diameter(case)/2
    box = caseProperties.dem_parameters(case)
    return n*4/3*np.pi*r**3*(RHO_P - RHO_F)*G/(box["width"]*box["depth"])


def pressure_drop(case):
    data = np.loadtxt(os.path.join(case, "postProcessing", "inletPressure", "0", "surfaceFieldValue.dat"))
    return data[:, 0], RHO_F*data[:, 1]


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
