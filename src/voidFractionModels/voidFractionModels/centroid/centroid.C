/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "centroid.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoefficients.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(centroid, 0);
    addToRunTimeSelectionTable(voidFractionModel, centroid, dictionary);
    // what scaleCase needs to know of the coefficients
    const modelCoefficients::add centroidCoefficients
    (
        centroid::typeName,
        {}
    );
}
}


Foam::voidFractionModels::centroid::centroid
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(modelType, dict, mesh)
{}


void Foam::voidFractionModels::centroid::distribute(const UList<point>&, const UList<scalar>&)
{
    distributeToCentreCells();
}
