/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "voxel.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoefficients.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(voxel, 0);
    addToRunTimeSelectionTable(voidFractionModel, voxel, dictionary);
    // what scaleCase needs to know of the coefficients
    const modelCoefficients::add voxelCoefficients
    (
        voxel::typeName,
        {
            {"voxelSize", modelCoefficients::particleLength, nullptr, ""},
            {"voxelsPerSide", modelCoefficients::number, nullptr, ""},
            {"voxelsPerDiameter", modelCoefficients::number, nullptr, ""},
            {"voxelsPerCell", modelCoefficients::number, nullptr, ""}
        }
    );
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
    for (const word& key : keys) nGiven += coeffs().found(key);
    if (nGiven > 1)
    {
        FatalIOErrorInFunction(coeffs())
            << "give one of " << keys << " in " << coeffs().name()
            << ", not several" << exit(FatalIOError);
    }
    if (coeffs().found("voxelSize"))
    {
        const scalar h = positiveCoeff("voxelSize");
        voxelSize_ = vector(h, h, h);
    }
    else if (coeffs().found("voxelsPerDiameter"))
    {
        voxelsPerDiameter_ = positiveCoeff("voxelsPerDiameter");
    }
    else if (coeffs().found("voxelsPerCell"))
    {
        const scalar n = positiveCoeff("voxelsPerCell");
        if (n != std::round(n))
        {
            FatalIOErrorInFunction(coeffs())
                << "voxelsPerCell must be a whole number, got " << n
                << " in " << coeffs().name() << exit(FatalIOError);
        }
        voxelSize_ = equalBoxCellSize()/n;
        alignedWithCells_ = true;
    }
    else
    {
        voxelSize_ = mesh.bounds().span()/positiveCoeff("voxelsPerSide", seedDefault(50, 300));
    }
    // 2D: one layer of voxels through the slab, centres on its mid-plane
    if (twoDimensional()) voxelSize_[emptyDirection()] = slabThickness();
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
    const labelListList& cellPoints = mesh().cellPoints();
    forAll(cellPoints, celli)
    {
        const boundBox bb(mesh().points(), cellPoints[celli], false);
        const vector span = bb.span();
        if (mag(span.x()*span.y()*span.z() - mesh().V()[celli]) > tol*mesh().V()[celli])
        {
            FatalIOErrorInFunction(coeffs())
                << "voxelsPerCell needs a mesh of equal axis-aligned box cells"
                << " (a uniform blockMesh); cell " << celli << " at "
                << mesh().C()[celli] << " is not a box. Use voxelsPerSide,"
                << " voxelSize or voxelsPerDiameter in " << coeffs().name()
                << exit(FatalIOError);
        }
        lo = min(lo, span);
        hi = max(hi, span);
    }
    reduce(lo, minOp<vector>());
    reduce(hi, maxOp<vector>());
    if (cmptMax(hi - lo) > tol*cmptMax(hi))
    {
        FatalIOErrorInFunction(coeffs())
            << "voxelsPerCell needs cells of one size; the cell edges range"
            << " from " << lo << " to " << hi << " m. Use voxelsPerSide,"
            << " voxelSize or voxelsPerDiameter in " << coeffs().name()
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
        const label seed = centreCells()[p];
        if (seed >= 0 && overlap_.holdsSphere(seed, x[p], r[p]))
        {
            // all its voxels are in this cell: the share is exactly 1
            rows().append(seed, 1.0);
        }
        else
        {
            vector h = voxelSize_;
            if (voxelsPerDiameter_ > 0)
            {
                h = vector::one*2*r[p]/voxelsPerDiameter_;
                if (twoDimensional()) h[emptyDirection()] = slabThickness();
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
            if (twoDimensional()) o[emptyDirection()] = origin_[emptyDirection()];
            const sphereOverlap::lattice L{{o.x(), o.y(), o.z()}, {h.x(), h.y(), h.z()}};
            appendLatticeSplit(seed, x[p], r[p], L);
        }
        endRow(p);
    }
}
