/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "voxelVoidFraction.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(voxel, 0);
    addToRunTimeSelectionTable(voidFractionModel, voxel, dictionary);
}
}


Foam::voidFractionModels::voxel::voxel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    sphereWalkVoidFraction(modelType, dict, mesh),
    origin_(mesh.bounds().min()),
    voxelSize_(Zero),
    voxelsPerDiameter_(0),
    alignedWithCells_(false)
{
    const wordList keys
    ({"voxelsPerSide", "voxelSize", "voxelsPerDiameter", "voxelsPerCell"});
    label nGiven = 0;
    for (const word& key : keys) nGiven += coeffs_.found(key);
    if (nGiven > 1)
    {
        FatalIOErrorInFunction(coeffs_)
            << "give one of " << keys << " in " << coeffs_.name()
            << ", not several" << exit(FatalIOError);
    }
    if (coeffs_.found("voxelSize"))
    {
        const scalar h = positiveCoeff("voxelSize");
        voxelSize_ = vector(h, h, h);
    }
    else if (coeffs_.found("voxelsPerDiameter"))
    {
        voxelsPerDiameter_ = positiveCoeff("voxelsPerDiameter");
    }
    else if (coeffs_.found("voxelsPerCell"))
    {
        const scalar n = positiveCoeff("voxelsPerCell");
        if (n != std::round(n))
        {
            FatalIOErrorInFunction(coeffs_)
                << "voxelsPerCell must be a whole number, got " << n
                << " in " << coeffs_.name() << exit(FatalIOError);
        }
        voxelSize_ = equalBoxCellSize()/n;
        alignedWithCells_ = true;
    }
    else
    {
        voxelSize_ = mesh.bounds().span()/positiveCoeff("voxelsPerSide", seedDefault(50, 300));
    }
    // 2D: one layer of voxels through the slab, centres on its mid-plane
    if (twoD_) voxelSize_[emptyDir_] = thickness_;
    Info<< "voxel: voxel size ";
    if (voxelsPerDiameter_ > 0) Info<< "diameter/" << voxelsPerDiameter_ << endl;
    else Info<< voxelSize_ << " m" << endl;
}


Foam::vector Foam::voidFractionModels::voxel::equalBoxCellSize() const
{
    // each cell's bounding box must be the cell (volume) and every box the
    // same, on every rank
    const scalar tol = 1e-9;
    vector lo(vector::max), hi(vector::min);
    const labelListList& cellPoints = mesh_.cellPoints();
    forAll(cellPoints, celli)
    {
        const boundBox bb(mesh_.points(), cellPoints[celli], false);
        const vector span = bb.span();
        if (mag(span.x()*span.y()*span.z() - mesh_.V()[celli]) > tol*mesh_.V()[celli])
        {
            FatalIOErrorInFunction(coeffs_)
                << "voxelsPerCell needs a mesh of equal axis-aligned box cells"
                << " (a uniform blockMesh); cell " << celli << " at "
                << mesh_.C()[celli] << " is not a box. Use voxelsPerSide,"
                << " voxelSize or voxelsPerDiameter in " << coeffs_.name()
                << exit(FatalIOError);
        }
        lo = min(lo, span);
        hi = max(hi, span);
    }
    reduce(lo, minOp<vector>());
    reduce(hi, maxOp<vector>());
    if (cmptMax(hi - lo) > tol*cmptMax(hi))
    {
        FatalIOErrorInFunction(coeffs_)
            << "voxelsPerCell needs cells of one size; the cell edges range"
            << " from " << lo << " to " << hi << " m. Use voxelsPerSide,"
            << " voxelSize or voxelsPerDiameter in " << coeffs_.name()
            << exit(FatalIOError);
    }
    return hi;
}


void Foam::voidFractionModels::voxel::distribute
(
    const UList<point>& x,
    const UList<scalar>& r
)
{
    forAll(x, p)
    {
        const label seed = centreCells_[p];
        if (seed >= 0 && overlap_.holdsSphere(seed, x[p], r[p]))
        {
            // all its voxels are in this cell: the share is exactly 1
            weights_.append(seed, 1.0);
        }
        else
        {
            vector h = voxelSize_;
            if (voxelsPerDiameter_ > 0)
            {
                h = vector::one*2*r[p]/voxelsPerDiameter_;
                if (twoD_) h[emptyDir_] = thickness_;
            }
            // shifted by irrational fractions of a voxel, so that voxel
            // centres do not fall on the faces of a regular mesh, where the
            // side a tied centre lands on would depend on round-off (and on
            // the decomposition)
            // a periodic image carries the particle's voxels with it
            // (voxels dividing the cells evenly have their centres half a
            // voxel from every face already)
            vector o = origin_ + imageShift(p);
            if (!alignedWithCells_)
            {
                o += cmptMultiply(h, vector(0.1*sqrt(2.0), 0.1*sqrt(3.0), 0.1*sqrt(5.0)));
            }
            if (twoD_) o[emptyDir_] = origin_[emptyDir_];
            const sphereOverlap::lattice L{{o.x(), o.y(), o.z()}, {h.x(), h.y(), h.z()}};
            appendLatticeSplit(seed, x[p], r[p], L);
        }
        endRow(p);
    }
}
