/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "Beetstra.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(Beetstra, 0);
    addToRunTimeSelectionTable(dragModel, Beetstra, dictionary);
}
}


Foam::scalar Foam::dragModels::Beetstra::beta(const particleState& p) const
{
    const scalar phi = 1 - p.alpha;
    const scalar Rep = max(p.Re(), SMALL);
    const scalar inertial =
        0.413*Rep/(24*sqr(p.alpha))
       *(1/p.alpha + 3*p.alpha*phi + 8.4*pow(Rep, -0.343))
       /(1 + pow(10.0, 3*phi)*pow(Rep, -0.5*(1 + 4*phi)));
    const scalar F =
        10*phi/sqr(p.alpha) + sqr(p.alpha)*(1 + 1.5*sqrt(phi)) + inertial;
    return 3*constant::mathematical::pi*p.mu*p.d*p.alpha*F;
}
