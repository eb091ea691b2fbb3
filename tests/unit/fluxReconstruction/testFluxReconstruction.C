/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testFluxReconstruction

Description
    fluxReconstruction on meshes whose cells are not boxes: a sheared block
    (parallelepipeds) and the cylinderBed tutorial's five-block O-grid. The
    fluxes of a uniform vector u through every face (S_f . u) must come back
    as u in every cell, to round-off (the least-squares reconstruction is
    exact for uniform fields on any cell); and fluxes scaled by a per-cell
    constant field alpha (a face flux alpha_f S_f . u with alpha uniform)
    scale the result alike. Ends with 'fluxReconstruction: N passed, M
    failed'.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "fluxReconstruction.H"
#include "IFstream.H"
#include "testHarness.H"
#include "blockMeshCase.H"

using namespace Foam;
using testHarness::near;

namespace
{
    //- The largest |U - u| / |u| over the cells, U reconstructed from S.u
    scalar worstUniform(const fvMesh& mesh, const vector& u, const scalar scale)
    {
        const fluxReconstruction reconstruction(mesh);
        const surfaceScalarField phi
        (
            "phi", scale*(mesh.Sf() & dimensionedVector("u", dimVelocity, u))
        );
        const vectorField U(reconstruction.cellValues(phi));
        scalar worst = 0;
        forAll(U, celli)
        {
            worst = max(worst, mag(U[celli] - scale*u)/mag(scale*u));
        }
        return worst;
    }

    //- The tutorial's blockMeshDict without its FoamFile header
    std::string tutorialBlockMesh(const fileName& path)
    {
        IFstream is(path);
        if (!is.good())
        {
            FatalErrorInFunction << "cannot read " << path << exit(FatalError);
        }
        std::string text, line;
        while (is.good())
        {
            is.getLine(line);
            if (line.find("FoamFile") == std::string::npos) text += line + "\n";
        }
        return text;
    }
}


int main(int argc, char *argv[])
{
    const vector u(1, 2, 3);

    {
        // x = a (4 0 0) + b (1 3 0) + c (0 1 2) mm: every cell tensor has
        // off-diagonal parts
        const testHarness::blockMeshCase sheared
        (
            "fluxReconstructionSheared",
            testHarness::blockMeshCase::walledBlock
            (
                "(0 0 0) (4 0 0) (5 3 0) (1 3 0) (0 1 2) (4 1 2) (5 4 2) (1 4 2)",
                "(5 4 3) simpleGrading (3 0.5 1)"
            )
        );
        near("sheared block: uniform flow reconstructed (rel)",
             worstUniform(sheared.mesh(), u, 1), 0, 1e-12);
        near("sheared block: 0.4 of the flux, 0.4 of the flow (rel)",
             worstUniform(sheared.mesh(), u, 0.4), 0, 1e-12);
    }

    {
        const testHarness::blockMeshCase ogrid
        (
            "fluxReconstructionOgrid",
            tutorialBlockMesh
            (
                getEnv("VFM_PROJECT_DIR")/"tutorials"/"cylinderBed"/"system"/"blockMeshDict"
            )
        );
        near("O-grid column: uniform flow reconstructed (rel)",
             worstUniform(ogrid.mesh(), u, 1), 0, 1e-12);
        near("O-grid column: a transverse flow reconstructed (rel)",
             worstUniform(ogrid.mesh(), vector(-3, 1, 0.5), 1), 0, 1e-12);
    }

    return testHarness::summary("fluxReconstruction");
}
