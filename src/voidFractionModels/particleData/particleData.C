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


void Foam::particleData::setVelocities(vectorField&& velocities)
{
    if (velocities.size() != positions_.size())
    {
        FatalErrorInFunction
            << velocities.size() << " velocities for " << positions_.size()
            << " particles" << exit(FatalError);
    }
    velocities_ = std::move(velocities);
}


void Foam::particleData::setTypes(labelList&& types)
{
    if (types.size() != positions_.size())
    {
        FatalErrorInFunction
            << types.size() << " types for " << positions_.size()
            << " particles" << exit(FatalError);
    }
    types_ = std::move(types);
}


Foam::particleData Foam::particleData::reordered(const labelUList& order) const
{
    particleData result
    (
        pointField(positions_, order),
        scalarField(radii_, order),
        labelList(UIndirectList<label>(ids_, order))
    );
    if (velocities_.size()) result.setVelocities(vectorField(velocities_, order));
    if (types_.size()) result.setTypes(labelList(UIndirectList<label>(types_, order)));
    return result;
}


Foam::particleData Foam::particleData::readLiggghtsDump(const fileName& file)
{
    liggghtsDumpReader dump(file);
    particleData particles;
    dump.read(particles);
    return particles;
}
