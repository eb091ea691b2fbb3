/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "parcelScaling.H"
#include "readChoice.H"

const Foam::Enum<Foam::parcelScaling::law> Foam::parcelScaling::lawNames
({
    { law::cubic, "cubic" },
    { law::exact, "exact" },
});


Foam::parcelScaling::parcelScaling(const dictionary& couplingDict)
:
    h_(1),
    law_(law::cubic)
{
    const dictionary* dictPtr = couplingDict.findDict("coarseGraining");
    if (!dictPtr) return;
    const dictionary& dict = *dictPtr;
    const entry* factorEntry = dict.findEntry("factor", keyType::LITERAL);
    if (!factorEntry)
    {
        FatalIOErrorInFunction(dict)
            << "coarseGraining has no factor (the parcel's radius per"
            << " particle radius, h >= 1)" << exit(FatalIOError);
    }
    if (factorEntry->stream().size() != 1)
    {
        FatalIOErrorInFunction(dict)
            << "coarseGraining factor must be one number; a factor per"
            << " particle type is not supported" << exit(FatalIOError);
    }
    h_ = dict.get<scalar>("factor");
    if (!(h_ >= 1))
    {
        FatalIOErrorInFunction(dict)
            << "coarseGraining factor " << h_ << " is below 1: a parcel stands"
            << " for h^3 >= 1 particles" << exit(FatalIOError);
    }
    law_ = readChoice(dict, "forceScaling", lawNames, law::cubic);
}
