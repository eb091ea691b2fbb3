#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Packed bed through fluidisation: the coupled run's pressure drop against
independent references: the Ergun equation for the bed's measured porosity
(packed range), the buoyant bed weight per area (fluidised plateau), and the
minimum fluidisation velocity of Wen and Yu. Writes ergun.png, ergun.csv and
ergun.result."""
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import os
import sys

# tutorials/caseProperties.py, also from a copy of the case elsewhere
sys.path.insert(0, os.path.join(os.environ.get("VFM_PROJECT_DIR",
                                               os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")),
                                "tutorials"))
import caseProperties

# the fluid and particles of this case, whatever they were set to
nu, rho_f, mu = caseProperties.fluid()
rho_p, g = caseProperties.particle_density(), caseProperties.gravity()
area = 0.024*0.024


def read_dump(path):
    lines = open(path).read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[start].split()[2:]
    data = np.array([l.split() for l in lines[start + 1:]], float)
    return {c: data[:, i] for i, c in enumerate(cols)}


def slab_solid(z, r, lo, hi):
    """Exact volume of spheres (centres z, radii r) between planes lo and hi"""
    def below(h):  # volume of each sphere below the plane z = h
        t = np.clip(h - (z - r), 0, 2*r)
        return np.pi*t*t*(3*r - t)/3
    return np.sum(below(hi) - below(lo))


p = read_dump("DEM/post/initial.dump")
z, r = p["z"], p["radius"]
d = 2*r.mean()
solid = np.sum(4/3*np.pi*r**3)
# porosity profile in thin slabs; the bed top is where the solid fraction
# falls to half its bulk value
dz = d/20
edges = np.arange(0, z.max() + 2*d, dz)
fraction = np.array([slab_solid(z, r, a, b) for a, b in zip(edges[:-1], edges[1:])])/(area*dz)
bulk = fraction[(edges[:-1] > 2*d) & (edges[1:] < z.max() - 2*d)].mean()
top = edges[np.argmax((fraction < bulk/2) & (edges[:-1] > z.mean()))]
eps = 1 - solid/(area*top)
weight = solid*(rho_p - rho_f)*g/area

t, dp, U = [], [], []
for line in open("postProcessing/inletPressure/0/surfaceFieldValue.dat"):
    if line.startswith("#"):
        continue
    v = line.replace("(", " ").replace(")", " ").split()
    t.append(float(v[0]))
    dp.append(rho_f*float(v[1]))      # kinematic pressure at the plenum
    U.append(float(v[4]))
t, dp, U = map(np.array, (t, dp, U))


def ergun(u, e=eps, h=top):
    return h*(150*mu*(1 - e)**2*u/(e**3*d*d) + 1.75*rho_f*(1 - e)*u*u/(e**3*d))


# inside the bed between the two probes (cell centres), away from the grid
# and the free surface: gradient against Ergun for the porosity there
probe = np.loadtxt("postProcessing/bedProbes/0/p")
z_lo, z_hi = 0.009, 0.033
eps_inner = 1 - slab_solid(z, r, z_lo, z_hi)/(area*(z_hi - z_lo))
dp_inner = rho_f*(probe[:, 1] - probe[:, 2])
U_inner = np.interp(probe[:, 0], t, U)

Ar = rho_f*(rho_p - rho_f)*g*d**3/mu**2
umf_wen_yu = (np.sqrt(33.7**2 + 0.0408*Ar) - 33.7)*mu/(rho_f*d)
# packed range: well below fluidisation
packed = (U > 0.1*umf_wen_yu) & (U < 0.6*umf_wen_yu)
packed_error = np.max(np.abs(dp[packed] - ergun(U[packed]))/ergun(U[packed]))
inner = (U_inner > 0.1*umf_wen_yu) & (U_inner < 0.6*umf_wen_yu)
reference = ergun(U_inner[inner], eps_inner, z_hi - z_lo)
inner_error = np.max(np.abs(dp_inner[inner] - reference)/reference)
# fluidised plateau: the hold at constant velocity, after a settling second
hold = t >= t.max() - 1.0
plateau = dp[hold].mean()
plateau_error = abs(plateau - weight)/weight
# the run's minimum fluidisation velocity: the packed-range Ergun-form fit
# (a u + b u^2, least squares) meets the plateau
A = np.column_stack([U[packed], U[packed]**2])
a, b = np.linalg.lstsq(A, dp[packed], rcond=None)[0]
umf_run = (-a + np.sqrt(a*a + 4*b*plateau))/(2*b)
umf_error = abs(umf_run - umf_wen_yu)/umf_wen_yu

print(f"bed: {len(z)} spheres d = {1e3*d:.1f} mm, height {1e3*top:.1f} mm, porosity {eps:.3f} "
      f"(bulk {1 - bulk:.3f}), buoyant weight per area {weight:.1f} Pa")
print(f"packed range (0.1 to 0.6 Umf), largest deviation from Ergun: whole bed {100*packed_error:.1f} %, "
      f"inside the bed ({1e3*z_lo:.0f} to {1e3*z_hi:.0f} mm, porosity {eps_inner:.3f}) {100*inner_error:.1f} %")
print(f"plateau (last second at U = {U[hold].mean():.3f} m/s): {plateau:.1f} Pa, "
      f"{100*(plateau/weight - 1):+.1f} % from bed weight")
print(f"minimum fluidisation: run {1e3*umf_run:.1f} mm/s, Wen-Yu {1e3*umf_wen_yu:.1f} mm/s "
      f"({100*(umf_run/umf_wen_yu - 1):+.1f} %)")
np.savetxt("ergun.csv", np.column_stack([t, U, dp, ergun(U)]), delimiter=",",
           header="t_s,U_superficial_m_s,dp_Pa,dp_ergun_Pa", comments="")
with open("ergun.result", "w") as f:
    f.write(f"packed_error {packed_error}\ninner_error {inner_error}\nplateau_error {plateau_error}\numf_error {umf_error}\n")

ramp = t < t.max() - 1.0
uu = np.linspace(0, U.max(), 200)
plt.figure(figsize=(6.4, 4.4))
plt.plot(U[ramp], dp[ramp], ".", ms=3, label="pimpleDEMFoam + LIGGGHTS (ramp)")
plt.plot(U[hold], dp[hold], ".", ms=3, color="C2", label="hold at constant U")
plt.plot(uu, ergun(uu), "k-", lw=1, label=f"Ergun, porosity {eps:.3f}")
plt.axhline(weight, color="k", ls="--", lw=1, label="buoyant bed weight / area")
plt.axvline(umf_wen_yu, color="grey", ls=":", lw=1, label="Umf Wen-Yu")
plt.ylim(0, 1.3*weight)
plt.xlabel("superficial velocity [m/s]")
plt.ylabel("bed pressure drop [Pa]")
plt.title(f"{len(z)} glass spheres (d = {1e3*d:.0f} mm) in water")
plt.legend(fontsize=8, loc="lower right")
plt.tight_layout()
plt.savefig("ergun.png", dpi=120)
