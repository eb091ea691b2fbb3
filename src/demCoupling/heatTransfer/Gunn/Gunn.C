/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "Gunn.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(Gunn, 0);
    addToRunTimeSelectionTable(heatTransferCorrelation, Gunn, dictionary);
}


Foam::scalar Foam::Gunn::Nu
(
    const scalar Re,
    const scalar Pr,
    const scalar alpha
) const
{
    const scalar a = alpha;
    const scalar Pr3 = std::cbrt(Pr);
    return (7 - 10*a + 5*a*a)*(1 + 0.7*std::pow(Re, 0.2)*Pr3)
         + (1.33 - 2.4*a + 1.2*a*a)*std::pow(Re, 0.7)*Pr3;
}
