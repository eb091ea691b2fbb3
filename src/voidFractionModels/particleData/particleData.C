/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleData.H"
#include "liggghtsDumpReader.H"
#include "error.H"
#include "UIndirectList.H"

const Foam::word Foam::particleData::velocityName("velocity");
const Foam::word Foam::particleData::typeFieldName("type");


Foam::particleData::particleData
(
    pointField&& positions,
    scalarField&& radii,
    labelList&& ids
)
:
    positions_(std::move(positions)),
    radii_(std::move(radii)),
    ids_(std::move(ids))
{
    if (positions_.size() != radii_.size() || positions_.size() != ids_.size())
    {
        FatalErrorInFunction
            << "positions (" << positions_.size() << "), radii ("
            << radii_.size() << ") and ids (" << ids_.size()
            << ") differ in size" << exit(FatalError);
    }
}


namespace
{
    template<class Type>
    const Foam::Field<Type>& fieldOrEmpty
    (
        const Foam::particleFields<Type>& table,
        const Foam::word& name
    )
    {
        static const Foam::Field<Type> none;
        const auto iter = table.cfind(name);
        return iter.found() ? *iter : none;
    }
}


namespace Foam
{
    template<>
    const particleFields<scalar>& particleData::fields<scalar>() const
    {
        return scalarFields_;
    }

    template<>
    const particleFields<vector>& particleData::fields<vector>() const
    {
        return vectorFields_;
    }

    template<>
    const particleFields<label>& particleData::fields<label>() const
    {
        return labelFields_;
    }
}


const Foam::vectorField& Foam::particleData::velocities() const
{
    return fieldOrEmpty(vectorFields_, velocityName);
}


void Foam::particleData::setVelocities(vectorField&& velocities)
{
    set(velocityName, std::move(velocities));
}


const Foam::labelList& Foam::particleData::types() const
{
    return fieldOrEmpty(labelFields_, typeFieldName);
}


void Foam::particleData::setTypes(labelList&& types)
{
    set(typeFieldName, labelField(std::move(types)));
}


Foam::particleData Foam::particleData::reordered(const labelUList& order) const
{
    particleData result
    (
        pointField(positions_, order),
        scalarField(radii_, order),
        labelList(UIndirectList<label>(ids_, order))
    );
    reorderFields<scalar>(order, result);
    reorderFields<vector>(order, result);
    reorderFields<label>(order, result);
    return result;
}


Foam::particleData Foam::particleData::readLiggghtsDump(const fileName& file)
{
    liggghtsDumpReader dump(file);
    particleData particles;
    dump.read(particles);
    return particles;
}
