/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "foamVtkOutput.H"

template<class Type>
void Foam::particleVtkWriter::write(const word& name, const UList<Type>& values)
{
    if (values.size() != nParticles_)
    {
        FatalErrorInFunction
            << "point data " << name << " has " << values.size() << " values for "
            << nParticles_ << " particles in " << outputFile_ << exit(FatalError);
    }
    beginPointData();
    ++nPointData_;

    const direction nCmpt(pTraits<Type>::nComponents);
    if (std::is_same<label, typename pTraits<Type>::cmptType>::value)
    {
        format().beginDataArray<label, nCmpt>(name);
        format().writeSize(vtk::sizeofData<label, nCmpt>(nParticles_));
    }
    else
    {
        format().beginDataArray<float, nCmpt>(name);
        format().writeSize(vtk::sizeofData<float, nCmpt>(nParticles_));
    }
    vtk::writeList(format(), values);
    format().flush();
    format().endDataArray();
}
