/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testParticleCellLocator

Description
    particleCellLocator on two one-block meshes (blockMesh, written under
    build/unit/). A graded box is a tensor grid: the cells found by index
    arithmetic for random points equal OpenFOAM's polyMesh::findCell, points
    beyond each side are outside, and findCells from stale hints gives the
    same cells. A sheared box (parallelepiped cells, planar faces) is not a
    tensor grid: the walk from a hint (a far cell, the right cell's
    neighbour) and the search without one give the cell of the point's
    coordinates in the block, i + nx (j + ny k), computed from the inverse
    of the shear. Ends with 'particleCellLocator: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "particleCellLocator.H"
#include "Random.H"
#include "testHarness.H"
#include "blockMeshCase.H"

using namespace Foam;
using testHarness::near;

int main(int argc, char *argv[])
{
    Random rng(7);

    // a graded box: a tensor grid
    {
        const testHarness::blockMeshCase box
        (
            "locatorGraded",
            testHarness::blockMeshCase::walledBlock
            (
                "(0 0 0) (4 0 0) (4 3 0) (0 3 0) (0 0 2) (4 0 2) (4 3 2) (0 3 2)",
                "(5 4 3) simpleGrading (3 0.5 1)"
            )
        );
        const fvMesh& mesh = box.mesh();
        const particleCellLocator locator(mesh);
        near("graded box: a tensor grid", locator.isTensorGrid(), 1, 0);
        pointField x(200);
        labelList want(x.size());
        label same = 0;
        forAll(x, i)
        {
            x[i] = 1e-3*point(4*rng.sample01<scalar>(), 3*rng.sample01<scalar>(), 2*rng.sample01<scalar>());
            want[i] = mesh.findCell(x[i], polyMesh::CELL_TETS);
            same += (locator.findCell(x[i]) == want[i]);
        }
        near("graded box: 200 random points in polyMesh::findCell's cells", same, 200, 0);
        const point mid(2e-3, 1.5e-3, 1e-3);
        for (direction d = 0; d < 3; ++d)
        {
            point below(mid), above(mid);
            below[d] = -1e-6;
            above[d] = mesh.bounds().max()[d] + 1e-6;
            near("graded box: a point below a side is outside", locator.findCell(below), -1, 0);
            near("graded box: a point above a side is outside", locator.findCell(above), -1, 0);
        }
        labelList cells(x.size());
        forAll(cells, i) cells[i] = (i % 3 == 0) ? -1 : (7*i) % mesh.nCells();
        locator.findCells(x, cells);
        near("graded box: findCells from stale hints", cells == want, 1, 0);
    }

    // a sheared box: x = u (4 0 0) + v (1 3 0) + w (0 0 2) mm, 4 x 3 x 2 cells
    {
        const testHarness::blockMeshCase sheared
        (
            "locatorSheared",
            testHarness::blockMeshCase::walledBlock
            (
                "(0 0 0) (4 0 0) (5 3 0) (1 3 0) (0 0 2) (4 0 2) (5 3 2) (1 3 2)",
                "(4 3 2) simpleGrading (1 1 1)"
            )
        );
        const fvMesh& mesh = sheared.mesh();
        const particleCellLocator locator(mesh);
        near("sheared box: not a tensor grid", locator.isTensorGrid(), 0, 0);
        near("sheared box: 24 cells", mesh.nCells(), 24, 0);
        label fromFar = 0, fromNeighbour = 0, noHint = 0;
        const label n = 200;
        for (label s = 0; s < n; ++s)
        {
            const scalar u = rng.sample01<scalar>(), v = rng.sample01<scalar>(), w = rng.sample01<scalar>();
            const point p = 1e-3*(u*vector(4, 0, 0) + v*vector(1, 3, 0) + w*vector(0, 0, 2));
            const label i = label(4*u), j = label(3*v), k = label(2*w);
            const label want = i + 4*(j + 3*k);
            const label neighbour = ((i + 1) % 4) + 4*(j + 3*k);
            fromFar += (locator.findCell(p, want == 0 ? 23 : 0) == want);
            fromNeighbour += (locator.findCell(p, neighbour) == want);
            noHint += (locator.findCell(p) == want);
        }
        near("sheared box: walk from a far cell finds the block's cell", fromFar, n, 0);
        near("sheared box: walk from a neighbour finds the block's cell", fromNeighbour, n, 0);
        near("sheared box: search without a hint finds the block's cell", noHint, n, 0);
        const point beyond = 1e-3*(1.1*vector(4, 0, 0) + 0.5*vector(1, 3, 0) + 0.5*vector(0, 0, 2));
        near("sheared box: a point beyond a slanted side is outside (hint)", locator.findCell(beyond, 3), -1, 0);
        near("sheared box: a point beyond a slanted side is outside", locator.findCell(beyond), -1, 0);
    }

    return testHarness::summary("particleCellLocator");
}
