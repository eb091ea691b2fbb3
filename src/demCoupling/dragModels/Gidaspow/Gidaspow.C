/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "Gidaspow.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(Gidaspow, 0);
    addToRunTimeSelectionTable(dragModel, Gidaspow, dictionary);
}
}


Foam::scalar Foam::dragModels::Gidaspow::beta(const particleState& p) const
{
    if (p.alpha < 0.8)
    {
        return p.Vp*(150*(1 - p.alpha)*p.mu/(p.alpha*p.d*p.d) + 1.75*p.rho*p.magUr/p.d);
    }
    // Cd |Ur| written so that it stays finite as the slip vanishes
    const scalar Rep = p.Re();
    const scalar CdMagUr =
        Rep < 1000
      ? 24*p.mu/(p.alpha*p.rho*p.d)*(1 + 0.15*pow(Rep, 0.687))
      : 0.44*p.magUr;
    return p.Vp*0.75*CdMagUr*p.rho/p.d*pow(p.alpha, -1.65);
}
