/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "kernel.H"
#include "smoothingDefaults.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoefficients.H"
#include "kernelConstants.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(kernel, 0);
    addToRunTimeSelectionTable(voidFractionModel, kernel, dictionary);
    // what scaleCase needs to know of the coefficients
    const modelCoefficients::add kernelCoefficients
    (
        kernel::typeName,
        {
            {"bandwidth", modelCoefficients::smoothingLength, nullptr, ""},
            {
                "bandwidthOverCellSize", modelCoefficients::perCellSize,
                [](bool) { return smoothingDefaults::kernelBandwidthOverCellSize(); }, "bandwidth"
            },
            {"cutoff", modelCoefficients::number, nullptr, ""},
            {"reflectAtWalls", modelCoefficients::flag, nullptr, ""}
        }
    );
}
}

Foam::voidFractionModels::kernel::kernel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    sphereWalkVoidFraction(modelType, dict, mesh),
    bandwidth_(0),
    bandwidthOverCellSize_(0),
    cutoff_(positiveCoeff("cutoff", 3)),
    gridPath_(false),
    uniform_(false),
    factorised_(false)
{
    if (coeffs().found("bandwidth") && coeffs().found("bandwidthOverCellSize"))
    {
        FatalIOErrorInFunction(coeffs())
            << "give bandwidth or bandwidthOverCellSize in " << coeffs().name()
            << ", not both" << exit(FatalIOError);
    }
    if (coeffs().found("bandwidth"))
    {
        bandwidth_ = positiveCoeff("bandwidth");
    }
    else
    {
        bandwidthOverCellSize_ =
            positiveCoeff
            (
                "bandwidthOverCellSize",
                smoothingDefaults::kernelBandwidthOverCellSize()
            );
    }
    cellSize_.setSize(mesh.nCells());
    forAll(cellSize_, celli) cellSize_[celli] = cellSize(celli);
    maxCellSize_ = returnReduce(max(cellSize_), maxOp<scalar>());
    collectWalls(mesh, coeffs().lookupOrDefault<bool>("reflectAtWalls", true));
    gridPath_ = locator().isTensorGrid() && !locator().hasHoles();
    uniform_ = gridPath_
     && locator().invSpacing(0) > 0 && locator().invSpacing(1) > 0 && locator().invSpacing(2) > 0;
    // 4 cutoff^2 within the exponentials' clamp
    factorised_ = uniform_ && cutoff_ <= kernelConstants::maxFactorisedCutoff;
    if (uniform_)
    {
        for (direction d = 0; d < 3; ++d) spacing_[d] = 1/locator().invSpacing(d);
    }
    if (gridPath_)
    {
        for (direction d = 0; d < 3; ++d)
        {
            // three cells more beyond the last: a fixed window of four
            // reads them (and never uses them) without a bound check
            const scalarList& g = locator().gridPlanes(d);
            const label nCells = g.size() - 1;
            gridCentres_[d].setSize(nCells + 3);
            gridWidths_[d].setSize(nCells + 3);
            forAll(gridCentres_[d], i)
            {
                const scalar lo = i < nCells ? g[i] : g.last() + (i - nCells)*(g[nCells] - g[nCells - 1]);
                const scalar hi = i < nCells ? g[i + 1] : lo + (g[nCells] - g[nCells - 1]);
                gridCentres_[d][i] = 0.5*(lo + hi);
                gridWidths_[d][i] = hi - lo;
            }
        }
    }
}


Foam::scalar Foam::voidFractionModels::kernel::reach(const scalar) const
{
    return cutoff_*(bandwidth_ > 0 ? bandwidth_ : bandwidthOverCellSize_*maxCellSize_);
}


void Foam::voidFractionModels::kernel::distribute
(
    const UList<point>& x,
    const UList<scalar>& r
)
{
    const label n = x.size();

    // the rank holding the centre sets the bandwidth for all
    b_.setSize(n);
    sums_.setSize(n);
    forAll(x, p)
    {
        const label seed = centreCells()[p];
        b_[p] = (seed < 0) ? 0 : cellBandwidth(seed);
    }
    combineOverGroup(b_, maxEqOp<scalar>());

    // a kernel that reaches no cell centre (bandwidth far below the cell
    // size) leaves the particle in its cell: both paths open the row with
    // the centre cell, set to 1 here once the combined sum is known
    auto normalise = [&](const label p, const bool spreadNow)
    {
        scalar s = 1;
        if (sums_[p] > 0) s = 1/sums_[p];
        else if (centreCells()[p] >= 0) rows().setFraction(rows().begin(p), 1);
        if (spreadNow) spreadRow(p, s);
        else if (sums_[p] > 0) rows().scale(p, s);
    };

    // whole particles are normalised (and spread, where allowed) while
    // their row is in cache; otherwise over all ranks and images once all
    // rows are made
    const bool whole = entriesAreWhole(n);
    const bool spread = spreadsRows(n);
    for (label p0 = 0; p0 < n; p0 += kernelConstants::blockSize)
    {
        const label p1 = min(p0 + kernelConstants::blockSize, n);
        if (uniform_) prepareBlock(x, p0, p1, whole);
        for (label p = p0; p < p1; ++p)
        {
            sums_[p] = 0;
            if (b_[p] > 0 && !(uniform_ && blockRows(p, p0)))
            {
                const scalar rc = cutoff_*b_[p];
                if (gridPath_)
                {
                    gridWeights(p, x[p], b_[p], rc, findMirrors(x[p], centreCells()[p], rc));
                }
                else
                {
                    findWallMirrors(x[p], centreCells()[p], rc);
                    walkWeights(p, x[p], b_[p], rc);
                }
            }
            rows().endParticle();
            if (whole) normalise(p, spread);
        }
    }
    if (!whole)
    {
        combineOverGroup(sums_, plusEqOp<scalar>());
        forAll(x, p) normalise(p, false);
    }
}
