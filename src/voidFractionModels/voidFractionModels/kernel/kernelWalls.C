/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// The kernel's walls: the planes of the mesh's wall faces, and the cells
// whose particles' kernels may reach each.

#include "kernel.H"
#include "kernelConstants.H"
#include "emptyPolyPatch.H"

#include <algorithm>

void Foam::voidFractionModels::kernel::collectWallPlanes
(
    const fvMesh& mesh,
    List<vector>& wallNormals,
    List<scalar>& wallOffsets
)
{
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    const scalar tol = kernelConstants::planeTolerance*mesh.bounds().mag();

    DynamicList<vector> normals;
    DynamicList<scalar> offsets;
    auto add = [&](const vector& n, const scalar offset)
    {
        forAll(normals, i)
        {
            if (mag(normals[i] - n) < kernelConstants::planeTolerance && mag(offsets[i] - offset) < tol) return;
        }
        normals.append(n);
        offsets.append(offset);
    };
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (pp.coupled() || isA<emptyPolyPatch>(pp)) continue;
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const vector n = Sf[facei]/mag(Sf[facei]);
            add(n, n & Cf[facei]);
        }
    }

    // every rank needs every wall: a kernel may reach beyond its own cells
    List<List<vector>> allNormals(Pstream::nProcs());
    List<List<scalar>> allOffsets(Pstream::nProcs());
    allNormals[Pstream::myProcNo()] = normals;
    allOffsets[Pstream::myProcNo()] = offsets;
    Pstream::gatherList(allNormals);
    Pstream::scatterList(allNormals);
    Pstream::gatherList(allOffsets);
    Pstream::scatterList(allOffsets);
    normals.clear();
    offsets.clear();
    forAll(allNormals, proci)
    {
        forAll(allNormals[proci], i) add(allNormals[proci][i], allOffsets[proci][i]);
    }
    // one order on every decomposition: mirror images across two walls
    // that are not orthogonal depend on the order of the mirrors
    labelList order(identity(normals.size()));
    std::sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b)
        {
            for (direction d = 0; d < 3; ++d)
            {
                if (mag(normals[a][d] - normals[b][d]) > kernelConstants::planeTolerance)
                {
                    return normals[a][d] < normals[b][d];
                }
            }
            return offsets[a] < offsets[b];
        }
    );

    wallNormals.setSize(order.size());
    wallOffsets.setSize(order.size());
    forAll(order, i)
    {
        wallNormals[i] = normals[order[i]];
        wallOffsets[i] = offsets[order[i]];
    }
}


void Foam::voidFractionModels::kernel::collectWalls(const fvMesh& mesh, const bool reflect)
{
    // no wall: no particle has images
    nearWalls_.setSize(mesh.nCells(), 0);
    if (!reflect) return;
    List<vector> normals;
    List<scalar> offsets;
    collectWallPlanes(mesh, normals, offsets);
    if (normals.size() > kernelConstants::maxWallPlanes)
    {
        WarningInFunction
            << "the walls form " << normals.size() << " planes (curved walls):"
            << " the kernel is normalised there but not reflected" << endl;
        return;
    }
    walls_.setSize(normals.size());
    forAll(walls_, i)
    {
        const vector& n = normals[i];
        label axis = -1;
        for (direction d = 0; d < 3; ++d)
        {
            const scalar tolerance = kernelConstants::planeTolerance;
            if (mag(n[(d + 1) % 3]) < tolerance && mag(n[(d + 2) % 3]) < tolerance) axis = d;
        }
        walls_[i] = wallPlane{n, offsets[i], axis};
    }

    markCellsNearWalls(mesh);
}


void Foam::voidFractionModels::kernel::markCellsNearWalls(const fvMesh& mesh)
{
    const pointField& points = mesh.points();
    const labelListList& cellPoints = mesh.cellPoints();
    forAll(nearWalls_, celli)
    {
        const scalar rc = cellReach(celli);
        forAll(walls_, w)
        {
            const wallPlane& P = walls_[w];
            scalar clearance = GREAT;
            for (const label pointi : cellPoints[celli])
            {
                clearance = min(clearance, P.offset - (P.normal & points[pointi]));
            }
            if (clearance < rc) nearWalls_[celli] |= uint64_t(1) << w;
        }
    }
}
