/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "hybrid.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoefficients.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(hybrid, 0);
    addToRunTimeSelectionTable(voidFractionModel, hybrid, dictionary);
    // what scaleCase needs to know of the coefficients
    const modelCoefficients::add hybridCoefficients
    (
        hybrid::typeName,
        {
            {"subGridResolution", modelCoefficients::number, nullptr, ""}
        }
    );
}
}


Foam::voidFractionModels::hybrid::hybrid
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    sphereWalkVoidFraction(modelType, dict, mesh),
    resolution_(label(positiveCoeff("subGridResolution", seedDefault(20, 50))))
{
    if (scalar(resolution_) != coeffs().lookupOrDefault<scalar>("subGridResolution", resolution_))
    {
        FatalIOErrorInFunction(coeffs())
            << "subGridResolution must be a whole number, got "
            << coeffs().lookup("subGridResolution") << " in " << coeffs().name()
            << exit(FatalIOError);
    }
    if (resolution_ <= 128)
    {
        table_.reset
        (
            new sphereOverlap::sphereLatticeTable(resolution_, twoDimensional() ? int(emptyDirection()) : -1)
        );
    }
}


void Foam::voidFractionModels::hybrid::distribute
(
    const UList<point>& x,
    const UList<scalar>& r
)
{
    crossed_.setSize(x.size());
    forAll(x, p)
    {
        const label seed = centreCells()[p];
        crossed_[p] =
            (seed < 0) ? -1
          : locator().isTensorGrid()
          ? locator().planesCrossed(seed, x[p], r[p], twoDimensional() ? label(emptyDirection()) : -1)
          : overlap_.planesCrossed(seed, x[p], r[p]);
    }
    combineOverGroup(crossed_, maxEqOp<label>());

    forAll(x, p)
    {
        const label seed = centreCells()[p];
        const point& c = x[p];
        const scalar R = r[p];
        if (crossed_[p] == 0 && seed >= 0)
        {
            rows().append(seed, 1.0);
        }
        else if (crossed_[p] == 1)
        {
            if (!(locator().isTensorGrid() && splitOnGrid(seed, c, R, 1)))
            {
                exactVolumes(seed, c, R);
                appendVolumes(R);
            }
        }
        else if (crossed_[p] != 0)
        {
            // 2D: one layer through the centre
            vector h = vector::one*2*R/resolution_;
            if (twoDimensional()) h[emptyDirection()] = 2*R;
            const sphereOverlap::lattice L{{c.x() - R, c.y() - R, c.z() - R}, {h.x(), h.y(), h.z()}};
            appendLatticeSplit(seed, c, R, L, table_.get());
        }
        endRow(p);
    }
}
