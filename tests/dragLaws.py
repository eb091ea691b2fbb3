# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The drag laws written here from their papers, independently of the C++
dragModels: the force on one sphere of diameter d at void fraction a and
interstitial slip u (the fluid's frame), in a fluid of density rho and
dynamic viscosity mu. Used by the tests as the reference and by the
benchmarks to compare the laws."""
import math


def force_gidaspow(d, a, u, rho, mu):
    # Gidaspow (1994): Ergun's coefficient below a = 0.8, shared by volume;
    # above it Wen and Yu's (1966) single-sphere law times a^-2.65
    if a < 0.8:
        beta = 150*(1 - a)**2*mu/(a*d*d) + 1.75*(1 - a)*rho*u/d
        return beta*math.pi*d**3/6/(1 - a)*u
    re = a*rho*u*d/mu
    cd = 24/re*(1 + 0.15*re**0.687) if re < 1000 else 0.44
    return 0.75*cd*rho*u*u*math.pi*d**2/6*a**-1.65


def force_difelice(d, a, u, rho, mu):
    # Di Felice (1994): Cd (0.63 + 4.8/sqrt(Re))^2 at the superficial Re, a^-chi
    re = a*rho*u*d/mu
    chi = 3.7 - 0.65*math.exp(-0.5*(1.5 - math.log10(re))**2)
    cd = (0.63 + 4.8/math.sqrt(re))**2
    return 0.5*cd*rho*math.pi*d*d/4*(a*u)**2*a**-chi


def force_beetstra(d, a, u, rho, mu):
    # Beetstra, van der Hoef and Kuipers (2007): 3 pi mu d (a u) F(phi, Re)
    phi, re = 1 - a, a*rho*u*d/mu
    F = (10*phi/a**2 + a**2*(1 + 1.5*math.sqrt(phi))
         + 0.413*re/(24*a**2)*(1/a + 3*a*phi + 8.4*re**-0.343)/(1 + 10**(3*phi)*re**(-(1 + 4*phi)/2)))
    return 3*math.pi*mu*d*a*u*F


LAWS = {"Gidaspow": force_gidaspow, "DiFelice": force_difelice, "Beetstra": force_beetstra}
