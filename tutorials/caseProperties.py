# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The physical properties of a tutorial case, read from the case itself so
that the plots compare with the fluid and particles actually simulated:
nu and rho from constant/transportProperties, |g| from constant/g, and the
particle density (and diameter, where the script sets one) from the DEM
input scripts in DEM/, with the variables of DEM/in.parameters."""
import glob
import os
import re

NUMBER = r"([-+]?[0-9.][-+0-9.eE]*)"


def _entry(path, key):
    """The value of 'key value;' in an OpenFOAM dictionary (dimensions in
    brackets before the value are skipped)."""
    text = re.sub(r"//.*", "", open(path).read())
    m = re.search(r"(?m)^\s*%s\s+(?:\[[^\]]*\]\s*)?%s\s*;" % (key, NUMBER), text)
    if not m:
        raise SystemExit("caseProperties: no '%s' in %s" % (key, path))
    return float(m.group(1))


def fluid(case="."):
    """(nu in m2/s, rho in kg/m3, mu in Pa s)"""
    path = os.path.join(case, "constant", "transportProperties")
    nu, rho = _entry(path, "nu"), _entry(path, "rho")
    return nu, rho, nu*rho


def gravity(case="."):
    """|g| in m/s2"""
    text = open(os.path.join(case, "constant", "g")).read()
    m = re.search(r"value\s*\(\s*%s\s+%s\s+%s\s*\)" % (NUMBER, NUMBER, NUMBER), text)
    if not m:
        raise SystemExit("caseProperties: no value in %s" % os.path.join(case, "constant", "g"))
    return sum(float(v)**2 for v in m.groups())**0.5


def dem_parameters(case="."):
    """The variables of DEM/in.parameters ('variable NAME equal NUMBER')"""
    path = os.path.join(case, "DEM", "in.parameters")
    if not os.path.isfile(path):
        return {}
    found = re.findall(r"(?m)^\s*variable\s+(\S+)\s+equal\s+%s" % NUMBER, open(path).read())
    return {k: float(v) for k, v in found}


def _dem(case, pattern, what):
    variables = dem_parameters(case)
    for path in sorted(glob.glob(os.path.join(case, "DEM", "in.*"))):
        text = re.sub(r"#.*", "", open(path).read())
        text = re.sub(r"\$\{(\w+)\}", lambda v: repr(variables.get(v.group(1), v.group(0))), text)
        m = re.search(pattern, text)
        if m:
            return float(m.group(1))
    raise SystemExit("caseProperties: no particle %s in %s" % (what, os.path.join(case, "DEM", "in.*")))


def particle_density(case="."):
    """kg/m3, from 'density constant X' or 'density X' in the DEM scripts"""
    return _dem(case, r"\bdensity\s+(?:constant\s+)?%s" % NUMBER, "density")


def particle_diameter(case="."):
    """m, from 'diameter X' (or 'radius constant X') in the DEM scripts"""
    try:
        return _dem(case, r"\bdiameter\s+%s" % NUMBER, "diameter")
    except SystemExit:
        return 2*_dem(case, r"\bradius\s+constant\s+%s" % NUMBER, "diameter")


def schiller_naumann_cd(re_p):
    """drag coefficient of a single sphere (Schiller and Naumann 1933), 0.44 above Re 1000"""
    return 24/re_p*(1 + 0.15*re_p**0.687) if re_p < 1000 else 0.44


def terminal_velocity(case="."):
    """m/s, the case's particle settling alone in its fluid with Schiller-Naumann drag"""
    from scipy.optimize import brentq
    nu, rho_f, _ = fluid(case)
    rho_p, d, g = particle_density(case), particle_diameter(case), gravity(case)

    def excess(v):
        """weight less buoyancy less drag, divided by pi"""
        return (rho_p - rho_f)*g*d**3/6 - schiller_naumann_cd(v*d/nu)*rho_f*d*d*v*v/8
    return brentq(excess, 1e-9, 100.0)
