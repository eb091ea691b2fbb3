/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "heatTransferCorrelation.H"
#include "keywordSchema.H"

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
    keywordSchema::checkKind(dict, keyword, keywordSchema::oneWord);
    const word modelType(dict.get<word>(keyword));
    Info<< "Selecting heatTransferCorrelation " << modelType << endl;
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "heatTransferCorrelation",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<heatTransferCorrelation>(cstrIter()(dict));
}
