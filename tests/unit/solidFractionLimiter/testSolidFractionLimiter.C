/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testSolidFractionLimiter

Description
    solidFractionLimiter on a row of 6 cells of 1 mm (blockMesh, written
    under build/unit/): nothing moves when no cell is over the limit; the
    excess of one overfull cell goes to its two neighbours in proportion to
    their room, to the last bit of the hand-computed shares; an excess the
    neighbours cannot hold passes on to the next cells; every result keeps
    the total and leaves no cell over the limit; more solid than the mesh
    can hold is a FatalError. Ends with
    'solidFractionLimiter: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "solidFractionLimiter.H"
#include "testHarness.H"
#include "blockMeshCase.H"

using namespace Foam;
using testHarness::near;

namespace
{
    const scalar cellV = 1e-9;         // 1 mm cubes
    const scalar alphaMin = 0.4;       // at most 0.6 nL of solid per cell

    void checkKept(const char* what, const scalarField& solid, const scalar total)
    {
        near((std::string(what) + ": total kept (rel)").c_str(), sum(solid)/total, 1, 1e-15);
        near((std::string(what) + ": no cell over the limit (largest fraction - 0.6)").c_str(),
             max(max(solid)/cellV - (1 - alphaMin), 0.0), 0, 1e-15);
    }
}


int main(int argc, char *argv[])
{
    const testHarness::blockMeshCase unitCase
    (
        "solidFractionLimiterCase",
        "scale 0.001;\n"
        "vertices ((0 0 0) (6 0 0) (6 1 0) (0 1 0) (0 0 1) (6 0 1) (6 1 1) (0 1 1));\n"
        "blocks (hex (0 1 2 3 4 5 6 7) (6 1 1) simpleGrading (1 1 1));\n"
        "boundary (walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4)"
        " (3 7 6 2) (0 3 2 1) (4 5 6 7)); });"
    );
    const fvMesh& mesh = unitCase.mesh();
    const solidFractionLimiter limiter(mesh, alphaMin);

    // cells are numbered along x
    {
        scalarField solid(6, 0.5*cellV);
        const scalarField before(solid);
        near("under the limit: moved volume", limiter.limit(solid, limiter.nOverLimit(solid), sum(solid)), 0, 0);
        near("under the limit: field unchanged", max(mag(solid - before)), 0, 0);
    }
    {
        // cell 2 holds 0.9: its excess 0.3 goes to cells 1 (room 0.5) and 3
        // (room 0.1) in proportion, 0.25 and 0.05
        scalarField solid(6, 0.1*cellV);
        solid[2] = 0.9*cellV;
        solid[3] = 0.5*cellV;
        const scalar total = sum(solid);
        near("one overfull cell: counted", limiter.nOverLimit(solid), 1, 0);
        const scalar moved = limiter.limit(solid, 1, total);
        near("one overfull cell: moved = its excess 0.3 nL (rel)", moved/(0.3*cellV), 1, 1e-14);
        near("cell 1 receives 0.3 x 0.5/0.6 (fraction)", solid[1]/cellV, 0.1 + 0.25, 1e-15);
        near("cell 3 receives 0.3 x 0.1/0.6 (fraction)", solid[3]/cellV, 0.5 + 0.05, 1e-15);
        near("cell 2 is left at the limit (fraction)", solid[2]/cellV, 0.6, 1e-15);
        near("cells 0, 4, 5 untouched", max(mag(solid[0] - 0.1*cellV), max(mag(solid[4] - 0.1*cellV),
             mag(solid[5] - 0.1*cellV))), 0, 0);
        checkKept("one overfull cell", solid, total);
    }
    {
        // cells 1 to 3 full, cell 2 over: its excess passes through the full
        // neighbours to cells 0 and 4
        scalarField solid(6, 0.0);
        solid[1] = solid[3] = 0.6*cellV;
        solid[2] = 1.0*cellV;
        const scalar total = sum(solid);
        limiter.limit(solid, limiter.nOverLimit(solid), total);
        checkKept("full neighbours", solid, total);
        near("full neighbours: cells 0 and 4 take the 0.4 nL (fraction)", (solid[0] + solid[4])/cellV, 0.4, 1e-14);
        near("full neighbours: symmetric (cell 0 - cell 4)", (solid[0] - solid[4])/cellV, 0, 1e-15);
    }
    {
        scalarField solid(6, 0.7*cellV);
        FatalError.throwExceptions();
        bool refused = false;
        try
        {
            limiter.limit(solid, 6, sum(solid));
        }
        catch (const Foam::error& e)
        {
            refused = e.message().find("more than (1 - alphaMin)") != std::string::npos;
        }
        near("more solid than the mesh can hold: FatalError saying so", refused, 1, 0);
    }
    return testHarness::summary("solidFractionLimiter");
}
