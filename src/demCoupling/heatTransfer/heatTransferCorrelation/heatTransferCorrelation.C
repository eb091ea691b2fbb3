/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "heatTransferCorrelation.H"
#include "selectedConstructor.H"

namespace Foam
{
    defineTypeNameAndDebug(heatTransferCorrelation, 0);
    defineRunTimeSelectionTable(heatTransferCorrelation, dictionary);
}


Foam::autoPtr<Foam::heatTransferCorrelation> Foam::heatTransferCorrelation::New
(
    const dictionary& dict,
    const word& keyword
)
{
    word modelType;
    return autoPtr<heatTransferCorrelation>
    (
        selectedConstructor<heatTransferCorrelation>
        (
            dict, keyword, "heatTransferCorrelation", modelType
        )(dict)
    );
}
