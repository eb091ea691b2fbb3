#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Settling sphere: the coupled run's velocity history against the
Schiller-Naumann single-sphere solution (an ODE integrated here with scipy,
independent of the solver). Writes settling.png and settling.csv and prints
the terminal velocities and the largest deviation after the start."""
import sys
import numpy as np
from scipy.integrate import solve_ivp
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import os

# tutorials/caseProperties.py, also from a copy of the case elsewhere
sys.path.insert(0, os.path.join(os.environ.get("VFM_PROJECT_DIR",
                                               os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")),
                                "tutorials"))
import caseProperties

# the fluid and the sphere of this case, whatever they were set to
nu, rho_f, mu = caseProperties.fluid()
rho_p, d = caseProperties.particle_density(), caseProperties.particle_diameter()
g = caseProperties.gravity()


def accel(v):
    """dv/dt of a sphere falling at speed v (down positive): gravity, buoyancy, drag"""
    re = max(rho_f*abs(v)*d/mu, 1e-12)
    drag = 0.75*rho_f/(rho_p*d)*caseProperties.schiller_naumann_cd(re)*abs(v)*v
    return (1 - rho_f/rho_p)*g - drag


v_terminal = caseProperties.terminal_velocity()
data = np.loadtxt("DEM/post/history.txt")
t, z, vz = data[:, 0], data[:, 1], -data[:, 2]
ref = solve_ivp(lambda s, v: [accel(v[0])], (0, t[-1]), [0.0], t_eval=t,
                rtol=1e-10, atol=1e-12).y[0]
v_end = vz[-1]
terminal_error = abs(v_end - v_terminal)/v_terminal
# the history after the first tenth of the relaxation, relative to terminal
late = t > 0.02
history_error = np.max(np.abs(vz[late] - ref[late]))/v_terminal
re_t = rho_f*v_terminal*d/mu
print(f"terminal velocity: coupled {v_end:.5f} m/s, Schiller-Naumann {v_terminal:.5f} m/s "
      f"(Re {re_t:.0f}), error {100*terminal_error:.2f} %")
print(f"velocity history: largest deviation after t = 0.02 s {100*history_error:.2f} % of terminal")
np.savetxt("settling.csv", np.column_stack([t, vz, ref]), delimiter=",",
           header="t_s,v_coupled_m_s,v_schiller_naumann_m_s", comments="")
plt.figure(figsize=(6, 4))
plt.plot(t, ref, "k-", label="Schiller-Naumann ODE")
plt.plot(t[::8], vz[::8], "o", ms=3, label="pimpleDEMFoam + LIGGGHTS")
plt.axhline(v_terminal, color="grey", ls=":", lw=1)
plt.xlabel("t [s]")
plt.ylabel("settling velocity [m/s]")
plt.title(f"1 mm glass sphere in water: terminal {v_end:.4f} vs {v_terminal:.4f} m/s")
plt.legend()
plt.tight_layout()
plt.savefig("settling.png", dpi=120)
with open("settling.result", "w") as f:
    f.write(f"terminal_error {terminal_error}\nhistory_error {history_error}\n")
