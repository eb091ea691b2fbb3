/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "parcelScaling.H"
#include "readChoice.H"
#include <cmath>

const Foam::Enum<Foam::parcelScaling::law> Foam::parcelScaling::lawNames
({
    { law::cubic, "cubic" },
    { law::exact, "exact" },
});


Foam::parcelScaling::parcelScaling
(
    const dictionary& couplingDict,
    const bool twoDimensional
)
:
    h_(1, scalar(1)),
    law_(law::cubic),
    dims_(twoDimensional ? 2 : 3)
{
    // `coarseGraining 2;` must not read as no coarse graining
    keywordSchema schema("couplingProperties");
    addKeywords(schema);
    schema.checkKeyword(couplingDict, "coarseGraining");
    const dictionary* dictPtr = couplingDict.findDict("coarseGraining");
    if (!dictPtr) return;
    dict_ = *dictPtr;
    const entry* factorEntry = dict_.findEntry("factor", keyType::LITERAL);
    if (!factorEntry)
    {
        FatalIOErrorInFunction(dict_)
            << "coarseGraining has no factor (the parcel's radius per"
            << " particle radius, h >= 1, or a list of one per DEM type)"
            << exit(FatalIOError);
    }
    ITstream& is = factorEntry->stream();
    const bool list = is.size() > 1 && is[0].isPunctuation()
        && is[0].pToken() == token::BEGIN_LIST;
    if (!list && is.size() != 1)
    {
        FatalIOErrorInFunction(dict_)
            << "coarseGraining factor must be one number or a list (h1 h2 ...)"
            << " of one per DEM type" << exit(FatalIOError);
    }
    h_ = list ? dict_.get<scalarList>("factor") : scalarList(1, dict_.get<scalar>("factor"));
    if (h_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "coarseGraining factor () is empty: one factor per DEM type"
            << exit(FatalIOError);
    }
    forAll(h_, t)
    {
        if (!(h_[t] >= 1) || !std::isfinite(h_[t]))
        {
            const std::string which(list ? " (of type " + std::to_string(t + 1) + ")" : "");
            FatalIOErrorInFunction(dict_)
                << "coarseGraining factor " << h_[t] << which.c_str()
                << " is below 1 or not finite: a parcel stands for h^" << dims_
                << " >= 1 particles"
                << exit(FatalIOError);
        }
    }
    law_ = readChoice(dict_, "forceScaling", lawNames, law::cubic);
}


bool Foam::parcelScaling::active() const
{
    for (const scalar h : h_)
    {
        if (h != 1) return true;
    }
    return false;
}


void Foam::parcelScaling::checkTypes(const label nTypes) const
{
    if (h_.size() != 1 && h_.size() != nTypes)
    {
        FatalIOErrorInFunction(dict_)
            << "coarseGraining factor " << h_ << " has " << h_.size()
            << " values for the DEM's " << nTypes << " particle types: give one"
            << " per type, or one number for all" << exit(FatalIOError);
    }
}


void Foam::parcelScaling::addKeywords(keywordSchema& schema)
{
    keywordSchema coarse("coarseGraining");
    coarse.add("factor", keywordSchema::numberOrList);
    coarse.add("forceScaling", keywordSchema::oneWord);
    schema.add("coarseGraining", coarse);
}
