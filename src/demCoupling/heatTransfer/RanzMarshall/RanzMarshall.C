/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "RanzMarshall.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(RanzMarshall, 0);
    addToRunTimeSelectionTable(heatTransferCorrelation, RanzMarshall, dictionary);
}


Foam::scalar Foam::RanzMarshall::Nu
(
    const scalar Re,
    const scalar Pr,
    const scalar
) const
{
    return 2 + 0.6*std::sqrt(Re)*std::cbrt(Pr);
}
