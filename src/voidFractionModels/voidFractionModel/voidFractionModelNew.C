/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "voidFractionModel.H"
#include "modelCoefficients.H"
#include "selectedConstructor.H"

Foam::autoPtr<Foam::voidFractionModel> Foam::voidFractionModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    word modelType;
    const auto cstr = selectedConstructor<voidFractionModel>
    (
        dict, "voidFractionModel", "voidFractionModel", modelType
    );
    return autoPtr<voidFractionModel>(cstr(modelType, dict, mesh));
}


Foam::wordList Foam::voidFractionModel::modelNames()
{
    static const wordList papersOrder
    ({
        "centroid", "analytical", "voxel", "hybrid", "kernel", "diffusion"
    });
    const wordList registered(dictionaryConstructorTablePtr_->sortedToc());
    DynamicList<word> names(registered.size());
    for (const word& m : papersOrder)
    {
        if (registered.found(m)) names.append(m);
    }
    for (const word& m : registered)
    {
        if (!papersOrder.found(m)) names.append(m);
    }
    return wordList(std::move(names));
}


void Foam::voidFractionModel::addKeywords(keywordSchema& schema)
{
    schema.add("voidFractionModel", keywordSchema::oneWord);
    schema.add("alphaMin", keywordSchema::oneNumber);
    schema.add("twoDimensional", keywordSchema::onOff);
    schema.add("keepVolumeBeyondMesh", keywordSchema::onOff);
    // any model's, so that one file can hold them all for -model to choose
    for (const word& m : modelCoefficients::models())
    {
        schema.add(m + "Coeffs", modelCoefficients::schema(m));
    }
}
