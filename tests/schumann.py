# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""A fixed bed heated by the fluid flowing through it: Schumann's (1929)
solution and a second-order integration of the same two equations, written
here independently of the C++.

Plug flow, no conduction, lumped particles; per unit bed volume
    eps rho_f c_f (dT/dt + u dT/dz) = h a (T_s - T)
    (1 - eps) rho_s c_s dT_s/dt     = h a (T - T_s)
with u = U/eps the interstitial speed. In xi = h a z/(rho_f c_f U) and
eta = h a (t - z/u)/((1 - eps) rho_s c_s) they read dT/dxi = T_s - T,
dT_s/deta = T - T_s; the fluid enters at theta = 1 from eta = 0 into a bed
at theta = 0. The Laplace transform in eta gives
    theta_s = int_0^eta exp(-xi - v) I0(2 sqrt(xi v)) dv,
    theta_f = theta_s + exp(-xi - eta) I0(2 sqrt(xi eta)).
"""
import numpy as np
from scipy.integrate import quad
from scipy.special import i0e


def _kernel(xi, v):
    # exp(-xi - v) I0(2 sqrt(xi v)) without overflow
    return i0e(2*np.sqrt(xi*v))*np.exp(-(np.sqrt(xi) - np.sqrt(v))**2)


def solid(xi, eta):
    if eta <= 0:
        return 0.0
    peak = [xi] if 0 < xi < eta else None
    return quad(lambda v: _kernel(xi, v), 0, eta, points=peak, limit=200, epsabs=1e-12)[0]


def fluid(xi, eta):
    if eta < 0:
        return 0.0
    return solid(xi, eta) + _kernel(xi, eta)


def integrated(xi_max, eta_max, n):
    """theta_f and theta_s on an n x n grid of [0, xi_max] x [0, eta_max], the
    trapezoidal rule along both characteristics (second order)"""
    dx, de = xi_max/(n - 1), eta_max/(n - 1)
    f = np.zeros((n, n))
    s = np.zeros((n, n))
    xi = np.linspace(0, xi_max, n)
    f[:, 0] = np.exp(-xi)                  # the fluid first in, met by cold particles
    f[0, 1:] = 1
    for j in range(1, n):
        s[0, j] = (s[0, j - 1]*(1 - de/2) + de/2*(f[0, j] + f[0, j - 1]))/(1 + de/2)
    a, b = dx/2, de/2
    for i in range(1, n):
        for j in range(1, n):
            # (1 + a) f - a s = f[i-1,j](1 - a) + a s[i-1,j];  -b f + (1 + b) s = s[i,j-1](1 - b) + b f[i,j-1]
            r1 = f[i - 1, j]*(1 - a) + a*s[i - 1, j]
            r2 = s[i, j - 1]*(1 - b) + b*f[i, j - 1]
            det = (1 + a)*(1 + b) - a*b
            f[i, j] = (r1*(1 + b) + a*r2)/det
            s[i, j] = (r2*(1 + a) + b*r1)/det
    return xi, np.linspace(0, eta_max, n), f, s


def bed(z, t, U, eps, rho_f, c_f, rho_s, c_s, h, a):
    """(theta_f, theta_s) at heights z (m, from the inlet) and time t (s)"""
    xi = h*a*np.asarray(z)/(rho_f*c_f*U)
    eta = h*a*(t - np.asarray(z)*eps/U)/((1 - eps)*rho_s*c_s)
    return (np.array([fluid(x, e) for x, e in zip(xi, eta)]),
            np.array([solid(x, e) for x, e in zip(xi, eta)]))
