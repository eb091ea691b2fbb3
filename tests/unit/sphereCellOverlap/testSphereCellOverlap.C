/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testSphereCellOverlap

Description
    sphereCellOverlap on two one-block meshes (blockMesh, written under
    build/unit/), against closed forms written in the test. A uniform box of
    1 mm cells: a sphere centred on a grid vertex puts 1/8 of its volume in
    each of the 8 cells around it, one centred on a face 1/2 in each of the
    2 cells beside it. A sheared box (parallelepiped cells, not axis-
    aligned, the convex-cell path): random spheres inside put their whole
    volume 4/3 pi R^3 in the mesh, no cell more than its own volume; a
    sphere through the slanted side keeps all but the cap beyond it,
    pi h^2 (3R - h)/3. Ends with 'sphereCellOverlap: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "sphereCellOverlap.H"
#include "Random.H"
#include "testHarness.H"
#include "blockMeshCase.H"

using namespace Foam;
using testHarness::near;

namespace
{
    scalar ballVolume(const scalar R) { return 4.0/3.0*constant::mathematical::pi*pow3(R); }

    //- The volumes of the sphere per cell, summed (cells counted)
    scalar overlapSum
    (
        const sphereCellOverlap& overlap,
        const fvMesh& mesh,
        const point& c,
        const scalar R,
        scalar& worstOverfill,
        DynamicList<label>& cells,
        DynamicList<scalar>& volumes
    )
    {
        cells.clear();
        volumes.clear();
        overlap.overlaps(c, R, mesh.findCell(c), cells, volumes);
        scalar sum = 0;
        forAll(cells, k)
        {
            sum += volumes[k];
            worstOverfill = max(worstOverfill, volumes[k]/mesh.V()[cells[k]] - 1);
        }
        return sum;
    }
}


int main(int argc, char *argv[])
{
    DynamicList<label> cells;
    DynamicList<scalar> volumes;
    scalar overfill = -1;

    // a uniform box of 1 mm cells
    {
        const testHarness::blockMeshCase box
        (
            "overlapBox",
            testHarness::blockMeshCase::walledBlock
            (
                "(0 0 0) (4 0 0) (4 4 0) (0 4 0) (0 0 4) (4 0 4) (4 4 4) (0 4 4)",
                "(4 4 4) simpleGrading (1 1 1)"
            )
        );
        const fvMesh& mesh = box.mesh();
        const sphereCellOverlap overlap(mesh);
        const scalar R = 0.7e-3;
        const scalar V = ballVolume(R);
        // the centre on the vertex (2, 2, 2) mm: mesh.findCell picks one of 8
        overlapSum(overlap, mesh, point(2e-3, 2e-3, 2e-3), R, overfill, cells, volumes);
        near("vertex-centred sphere: 8 cells", cells.size(), 8, 0);
        forAll(cells, k) near("vertex-centred sphere: 1/8 in each cell (rel)", volumes[k]/V, 0.125, 1e-14);
        overlapSum(overlap, mesh, point(2e-3, 1.5e-3, 1.5e-3), 0.4e-3, overfill, cells, volumes);
        near("face-centred sphere: 2 cells", cells.size(), 2, 0);
        forAll(cells, k) near("face-centred sphere: 1/2 in each cell (rel)", volumes[k]/ballVolume(0.4e-3), 0.5, 1e-14);
    }

    // a sheared box: x = u (4 0 0) + v (1 3 0) + w (0 0 4) mm, 4 x 3 x 4 cells
    {
        const testHarness::blockMeshCase sheared
        (
            "overlapSheared",
            testHarness::blockMeshCase::walledBlock
            (
                "(0 0 0) (4 0 0) (5 3 0) (1 3 0) (0 0 4) (4 0 4) (5 3 4) (1 3 4)",
                "(4 3 4) simpleGrading (1 1 1)"
            )
        );
        const fvMesh& mesh = sheared.mesh();
        const sphereCellOverlap overlap(mesh);
        near("sheared box: its cells are not axis-aligned boxes", overlap.isBox(0), 0, 0);
        Random rng(3);
        label whole = 0;
        scalar worst = 0;
        for (label s = 0; s < 100; ++s)
        {
            // centres at least R from every side: u, w in [0.3, 0.7] mm-fractions
            const scalar R = 1e-3*(0.2 + 0.5*rng.sample01<scalar>());
            const scalar u = 0.3 + 0.4*rng.sample01<scalar>();
            const scalar v = 0.35 + 0.3*rng.sample01<scalar>();
            const scalar w = 0.3 + 0.4*rng.sample01<scalar>();
            const point c = 1e-3*(u*vector(4, 0, 0) + v*vector(1, 3, 0) + w*vector(0, 0, 4));
            const scalar rel = overlapSum(overlap, mesh, c, R, overfill, cells, volumes)/ballVolume(R) - 1;
            worst = max(worst, mag(rel));
            whole += (mag(rel) < 1e-12);
        }
        Info<< "    sheared box: worst relative error of the whole sphere " << worst << endl;
        near("sheared box: 100 spheres inside keep 4/3 pi R^3 (to 1e-12)", whole, 100, 0);
        near("no cell holds more than its volume (relative excess)", max(overfill, scalar(0)), 0, 1e-12);

        // the slanted side x = 4 mm + y/3: outward normal (3, -1, 0)/sqrt(10)
        const vector n = vector(3, -1, 0)/Foam::sqrt(10.0);
        const point onSide(4.5e-3, 1.5e-3, 2e-3);
        const scalar R = 0.8e-3, d = 0.3e-3;     // centre d inside the side
        const scalar h = R - d;
        const scalar cap = constant::mathematical::pi*h*h*(3*R - h)/3;
        const scalar inside = overlapSum(overlap, mesh, onSide - d*n, R, overfill, cells, volumes);
        near("through the slanted side: the sphere less its cap (rel)", inside/(ballVolume(R) - cap), 1, 1e-12);
    }

    return testHarness::summary("sphereCellOverlap");
}
