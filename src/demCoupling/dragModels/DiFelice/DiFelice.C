/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "DiFelice.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(DiFelice, 0);
    addToRunTimeSelectionTable(dragModel, DiFelice, dictionary);
}
}


Foam::scalar Foam::dragModels::DiFelice::beta(const particleState& p) const
{
    const scalar Rep = max(p.Re(), VSMALL);
    // Cd |Ur| = (0.63 sqrt(Re) + 4.8)^2 mu/(alpha rho d): finite as Re -> 0
    const scalar CdMagUr = sqr(0.63*sqrt(Rep) + 4.8)*p.mu/(p.alpha*p.rho*p.d);
    const scalar chi = 3.7 - 0.65*exp(-0.5*sqr(1.5 - log10(Rep)));
    return constant::mathematical::pi/8*p.d*p.d*p.rho*CdMagUr*pow(p.alpha, 2 - chi);
}
