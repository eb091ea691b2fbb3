/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "particleVtkWriter.H"
#include "foamVtkOutput.H"

Foam::particleVtkWriter::particleVtkWriter
(
    const vtk::outputOptions opts,
    const fileName& file
)
:
    vtk::fileWriter(vtk::fileTag::POLY_DATA, opts),
    nParticles_(0)
{
    // legacy VTK has no vertex cells in OpenFOAM's formatters; appended
    // data would hold the whole file back until close
    opts_.legacy(false);
    opts_.append(false);
    open(file, false);
}


void Foam::particleVtkWriter::writeVertices()
{
    // each vertex cell holds one particle: connectivity 0..n-1, offsets 1..n
    const uint64_t payLoad = vtk::sizeofData<label>(nParticles_);
    format().tag(vtk::fileTag::VERTS);
    for (const auto attr : {vtk::dataArrayAttr::CONNECTIVITY, vtk::dataArrayAttr::OFFSETS})
    {
        format().beginDataArray<label>(attr);
        format().writeSize(payLoad);
        vtk::writeIdentity(format(), nParticles_, attr == vtk::dataArrayAttr::OFFSETS ? 1 : 0);
        format().flush();
        format().endDataArray();
    }
    format().endTag(vtk::fileTag::VERTS);
}


bool Foam::particleVtkWriter::writeGeometry
(
    const pointField& centres,
    const std::string& title
)
{
    if (isState(outputState::OPENED)) beginFile(title);
    enter_Piece();
    nParticles_ = centres.size();
    format().tag
    (
        vtk::fileTag::PIECE,
        vtk::fileAttr::NUMBER_OF_POINTS, nParticles_,
        vtk::fileAttr::NUMBER_OF_VERTS, nParticles_
    );
    format().tag(vtk::fileTag::POINTS).beginDataArray<float, 3>(vtk::dataArrayAttr::POINTS);
    format().writeSize(vtk::sizeofData<float, 3>(nParticles_));
    vtk::writeList(format(), centres);
    format().flush();
    format().endDataArray();
    format().endTag(vtk::fileTag::POINTS);
    writeVertices();
    return true;
}


bool Foam::particleVtkWriter::writeGeometry()
{
    FatalErrorInFunction
        << "give the particle centres: writeGeometry(centres, title)" << exit(FatalError);
    return false;
}


bool Foam::particleVtkWriter::beginCellData(label nFields)
{
    return enter_CellData(nParticles_, nFields);
}


bool Foam::particleVtkWriter::beginPointData(label nFields)
{
    return enter_PointData(nParticles_, nFields);
}
