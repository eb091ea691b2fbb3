/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleData.H"

template<class Type>
void Foam::particleData::set(const word& name, Field<Type>&& values)
{
    if (values.size() != positions_.size())
    {
        FatalErrorInFunction
            << values.size() << " values of " << name << " for "
            << positions_.size() << " particles" << exit(FatalError);
    }
    fieldsRef<Type>().set(name, std::move(values));
}


template<class Type>
const Foam::Field<Type>& Foam::particleData::field(const word& name) const
{
    const auto iter = fields<Type>().cfind(name);
    if (!iter.found())
    {
        FatalErrorInFunction
            << "the particles have no field " << name << "; they have "
            << fields<Type>().sortedToc() << exit(FatalError);
    }
    return *iter;
}


template<class Type>
void Foam::particleData::reorderFields
(
    const labelUList& order,
    particleData& result
) const
{
    forAllConstIters(fields<Type>(), iter)
    {
        result.set(iter.key(), Field<Type>(iter.val(), order));
    }
}
