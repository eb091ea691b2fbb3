/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "couplingKeywords.H"
#include "particleFluidCoupling.H"

Foam::keywordSchema Foam::couplingKeywords()
{
    keywordSchema schema("couplingProperties");
    particleFluidCoupling::addKeywords(schema);
    voidFractionModel::addKeywords(schema);
    liggghtsCoupling::addKeywords(schema);
    parcelScaling::addKeywords(schema);
    return schema;
}


void Foam::checkCouplingProperties(const dictionary& dict, const fileName& file)
{
    keywordSchema::checkRepeats(file);
    couplingKeywords().check(dict);
}
