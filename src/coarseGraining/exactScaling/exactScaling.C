/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "exactScaling.H"
#include "error.H"

Foam::scalar Foam::exactScaling::exponent
(
    const dimensionSet& dims,
    const word& what
)
{
    for
    (
        const dimensionSet::dimensionType d :
        {
            dimensionSet::TEMPERATURE, dimensionSet::MOLES,
            dimensionSet::CURRENT, dimensionSet::LUMINOUS_INTENSITY
        }
    )
    {
        if (mag(dims[d]) > dimensionSet::smallExponent)
        {
            FatalErrorInFunction
                << what << " has dimensions " << dims << ": exact scaling has laws"
                << " for mass, length and time only" << exit(FatalError);
        }
    }
    // a mass is a density (scale 1) times a volume (h^3)
    return
        3*dims[dimensionSet::MASS]
      + dims[dimensionSet::LENGTH]
      + dims[dimensionSet::TIME];
}


Foam::scalar Foam::exactScaling::factor
(
    const dimensionSet& dims,
    const scalar h,
    const word& what
)
{
    if (!(h > 0) || !std::isfinite(h))
    {
        FatalErrorInFunction
            << "the scale factor h must be a positive number, got " << h
            << exit(FatalError);
    }
    return Foam::pow(h, exponent(dims, what));
}
