/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testExactScaling

Description
    exactScaling against every row of Table 1 and Eqs. 34-35 of Zhang,
    Huang and Zhao (2021), and the quantities a coupled case holds, at
    h = 2 and 3: the expected factors are written here from the paper, not
    computed by the library. Ends with 'exactScaling: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "exactScaling.H"
#include "dimensionSets.H"
#include "error.H"
#include "IOstreams.H"

#include <cmath>
#include <cstdio>
#include <string>

using namespace Foam;

static int passed = 0, failed = 0;

static void near(const char* what, double got, double want, double tol)
{
    const bool ok = std::isfinite(got) && std::fabs(got - want) <= tol*std::fabs(want);
    ok ? ++passed : ++failed;
    std::printf("  %s %s (got %.17g, want %.17g)\n", ok ? "ok  " : "FAIL", what, got, want);
}


int main()
{
    struct row { const char* name; dimensionSet dims; double power; };
    // the powers of h, from the paper: Table 1, Eq. 34 (3D), Eq. 35 (2D,
    // per unit thickness), and the other inputs of a coupled case
    const row rows[] =
    {
        {"length", dimLength, 1},
        {"time", dimTime, 1},
        {"density", dimDensity, 0},
        {"force (Table 1, Eq. 34)", dimForce, 2},
        {"strain", dimless, 0},
        {"stress", dimPressure, 0},
        {"kinetic energy density", dimEnergy/dimVolume, 0},
        {"strain energy density", dimEnergy/dimVolume, 0},
        {"mass", dimMass, 3},
        {"velocity", dimVelocity, 0},
        {"gravity", dimAcceleration, -1},
        {"kinematic viscosity", dimViscosity, 1},
        {"Hooke stiffness", dimForce/dimLength, 1},
        {"time step", dimTime, 1},
        {"kinematic pressure", dimPressure/dimDensity, 0},
        {"drag coefficient per volume", dimDensity/dimTime, -1},
        {"2D: force per unit thickness (Eq. 35)", dimForce/dimLength, 1},
        {"2D: mass per unit thickness", dimMass/dimLength, 2},
        {"2D: Hooke stiffness per unit thickness", dimForce/dimLength/dimLength, 0}
    };
    for (const double h : {2.0, 3.0})
    {
        for (const row& r : rows)
        {
            char what[200];
            std::snprintf(what, sizeof(what), "h = %g, %s: h^%g", h, r.name, r.power);
            near(what, exactScaling::factor(r.dims, h, r.name), std::pow(h, r.power), 1e-15);
        }
    }

    // quantities with no scaling law, and a bad h: errors that name them
    FatalError.throwExceptions();
    auto refused = [](const char* what, void (*call)(), const char* needle)
    {
        bool threw = false;
        try { call(); }
        catch (const Foam::error& e) { threw = std::string(e.message()).find(needle) != std::string::npos; }
        threw ? ++passed : ++failed;
        std::printf("  %s %s\n", threw ? "ok  " : "FAIL", what);
    };
    refused("temperature: error names the quantity",
        [] { exactScaling::factor(dimTemperature, 2, "fluidTemperature"); }, "fluidTemperature");
    refused("h = 0: error",
        [] { exactScaling::factor(dimLength, 0, "length"); }, "positive");
    refused("h = -2: error",
        [] { exactScaling::factor(dimLength, -2, "length"); }, "positive");

    std::printf("exactScaling: %d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
