/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "modelCoefficients.H"

Foam::HashTable<Foam::List<Foam::modelCoefficients::coefficient>>&
Foam::modelCoefficients::table()
{
    // constructed on first use: the models register during static
    // initialisation, in no defined order
    static HashTable<List<coefficient>> models;
    return models;
}


Foam::modelCoefficients::add::add
(
    const word& modelType,
    std::initializer_list<coefficient> coefficients
)
{
    table().set(modelType, List<coefficient>(coefficients));
}


Foam::wordList Foam::modelCoefficients::models()
{
    return table().sortedToc();
}


const Foam::List<Foam::modelCoefficients::coefficient>&
Foam::modelCoefficients::of(const word& modelType)
{
    static const List<coefficient> none;
    const auto iter = table().cfind(modelType);
    return iter.found() ? *iter : none;
}


bool Foam::modelCoefficients::registered(const word& modelType)
{
    return table().found(modelType);
}


const Foam::modelCoefficients::coefficient* Foam::modelCoefficients::find
(
    const word& modelType,
    const word& keyword
)
{
    for (const coefficient& c : of(modelType))
    {
        if (c.keyword == keyword) return &c;
    }
    return nullptr;
}


Foam::keywordSchema Foam::modelCoefficients::schema(const word& modelType)
{
    keywordSchema s(modelType + "Coeffs");
    for (const coefficient& c : of(modelType))
    {
        switch (c.what)
        {
            case splitModel:
                s.add(c.keyword, keywordSchema::oneWord);
                // the split model's coefficients, inside this dictionary
                for (const word& m : models())
                {
                    if (m != modelType) s.add(m + "Coeffs", schema(m));
                }
                break;
            case flag: s.add(c.keyword, keywordSchema::onOff); break;
            case choice: s.add(c.keyword, keywordSchema::oneWord); break;
            case text: s.add(c.keyword, keywordSchema::fileOrWord); break;
            case settings: s.add(c.keyword, keywordSchema::subDictionary); break;
            default: s.add(c.keyword, keywordSchema::oneNumber);
        }
    }
    return s;
}
