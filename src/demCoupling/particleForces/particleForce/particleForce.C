/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleForce.H"

namespace Foam
{
    defineTypeNameAndDebug(particleForce, 0);
    defineRunTimeSelectionTable(particleForce, dictionary);
}


Foam::particleForce::particleForce(const word& name)
:
    name_(name)
{}


Foam::autoPtr<Foam::particleForce> Foam::particleForce::New
(
    const word& name,
    const dictionary& dict,
    const setup& s
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "unknown entry " << name << " in forces; valid: "
            << dictionaryConstructorTablePtr_->sortedToc() << exit(FatalIOError);
    }
    return autoPtr<particleForce>(cstrIter()(name, dict, s));
}
