/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "analytical.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoefficients.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(analytical, 0);
    addToRunTimeSelectionTable(voidFractionModel, analytical, dictionary);
    // what scaleCase needs to know of the coefficients
    const modelCoefficients::add analyticalCoefficients
    (
        analytical::typeName,
        {}
    );
}
}


Foam::voidFractionModels::analytical::analytical
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    sphereWalkVoidFraction(modelType, dict, mesh)
{}


unsigned Foam::voidFractionModels::analytical::wrappedDirections
(
    const point& c,
    const scalar r,
    const label centreCell
) const
{
    return gridWrapsSphere(c, r, centreCell);
}


unsigned Foam::voidFractionModels::analytical::wrappedAlways() const
{
    return gridWraps_;
}


Foam::scalar Foam::voidFractionModels::analytical::wrappedRadius() const
{
    // a sphere narrower than every cell is always split on the grid
    return gridWraps_ ? 0.5*locator().minWidth() : -1;
}


void Foam::voidFractionModels::analytical::distribute
(
    const UList<point>& x,
    const UList<scalar>& r
)
{
    forAll(x, p)
    {
        const label seed = centreCells()[p];
        if (locator().isTensorGrid() && splitOnGrid(seed, x[p], r[p], 3, gridWraps_ && isParticleEntry(p)))
        {
            // done
        }
        else if (seed >= 0 && overlap_.holdsSphere(seed, x[p], r[p]))
        {
            rows().append(seed, 1.0);
        }
        else
        {
            exactVolumes(seed, x[p], r[p]);
            appendVolumes(r[p]);
        }
        endRow(p);
    }
}
