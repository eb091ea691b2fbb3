/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "fluxReconstruction.H"
#include "fvcSurfaceIntegrate.H"
#include "volFields.H"

Foam::fluxReconstruction::fluxReconstruction(const fvMesh& mesh)
:
    mesh_(mesh),
    normals_(mesh.Sf()/mesh.magSf()),
    // the library's Field inv: on a 2D mesh it inverts within the plane
    inverse_(inv(fvc::surfaceSum(normals_*mesh.Sf())().primitiveField()))
{}


Foam::tmp<Foam::vectorField> Foam::fluxReconstruction::cellValues
(
    const surfaceScalarField& phi
) const
{
    const vectorField sums(fvc::surfaceSum(normals_*phi)().primitiveField());
    // a new field: the product must not be written over its operand
    tmp<vectorField> tresult(new vectorField(sums.size()));
    vectorField& result = tresult.ref();
    forAll(result, celli)
    {
        result[celli] = inverse_[celli] & sums[celli];
    }
    return tresult;
}
