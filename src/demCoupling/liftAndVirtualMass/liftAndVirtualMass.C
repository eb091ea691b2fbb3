/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "liftAndVirtualMass.H"
#include "SaffmanMeiLift.H"
#include "fvc.H"

Foam::liftAndVirtualMass::liftAndVirtualMass
(
    const fvMesh& mesh,
    const dictionary& dict,
    const wordList& forces
)
:
    lift_(forces.found("SaffmanMeiLift")),
    virtualMass_(forces.found("virtualMass")),
    Cvm_(dict.getOrDefault<scalar>("virtualMassCoefficient", 0.5)),
    havePrevious_(false)
{
    if (virtualMass_)
    {
        IOobject io
        (
            "UlastCoupling",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        );
        havePrevious_ = io.typeHeaderOk<volVectorField>(true);
        Uprevious_.reset
        (
            havePrevious_
          ? new volVectorField(io, mesh)
          : new volVectorField(io, mesh, dimensionedVector(dimVelocity, Zero))
        );
    }
    if (!(Cvm_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "virtualMassCoefficient must be zero or positive, not " << Cvm_
            << exit(FatalIOError);
    }
}


void Foam::liftAndVirtualMass::addKeywords(keywordSchema& schema)
{
    schema.add("virtualMassCoefficient", keywordSchema::oneNumber);
}


bool Foam::liftAndVirtualMass::handles(const word& force)
{
    return force == "SaffmanMeiLift" || force == "virtualMass";
}


void Foam::liftAndVirtualMass::cellFields
(
    const volVectorField& U,
    const scalar interval,
    vectorField& vorticity,
    vectorField& DUDt
)
{
    const label n = U.size();
    vorticity = vectorField(n, Zero);
    DUDt = vectorField(n, Zero);
    if (lift_)
    {
        vorticity = fvc::curl(U)().primitiveField();
    }
    if (virtualMass_)
    {
        DUDt = U.primitiveField() & fvc::grad(U)().primitiveField();
        vectorField& previous = Uprevious_->primitiveFieldRef();
        if (havePrevious_)
        {
            DUDt += (U.primitiveField() - previous)/interval;
        }
        previous = U.primitiveField();
        havePrevious_ = true;
    }
}


Foam::vector Foam::liftAndVirtualMass::lift
(
    const scalar d,
    const scalar rho,
    const scalar nu,
    const vector& Uf,
    const vector& vorticity,
    const vector& v
) const
{
    return lift_ ? SaffmanMeiLift(d, rho, nu, Uf - v, vorticity) : Zero;
}


Foam::vector Foam::liftAndVirtualMass::virtualMassForce
(
    const scalar Vp,
    const scalar rho,
    const vector& DUDt,
    const vector& a
) const
{
    return virtualMass_ ? Cvm_*rho*Vp*(DUDt - a) : Zero;
}
