/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "virtualMassForce.H"
#include "keywordSchema.H"
#include "voidFractionModel.H"
#include "parcelScaling.H"
#include "liggghtsCoupling.H"
#include "fvc.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(virtualMassForce, 0);
    addToRunTimeSelectionTable(particleForce, virtualMassForce, dictionary);
}


Foam::IOobject Foam::virtualMassForce::previousIO(const fvMesh& mesh)
{
    return IOobject
    (
        "UlastCoupling",
        mesh.time().timeName(),
        mesh,
        IOobject::READ_IF_PRESENT,
        IOobject::AUTO_WRITE
    );
}


Foam::virtualMassForce::virtualMassForce
(
    const word& name,
    const dictionary& dict,
    const setup& s
)
:
    particleForce(name),
    dict_(dict),
    Cvm_(dict.getOrDefault<scalar>("Cvm", 0.5)),
    havePrevious_(previousIO(s.mesh).typeHeaderOk<volVectorField>(true)),
    Uprevious_
    (
        havePrevious_
      ? new volVectorField(previousIO(s.mesh), s.mesh)
      : new volVectorField(previousIO(s.mesh), s.mesh, dimensionedVector(dimVelocity, Zero))
    )
{
    keywordSchema schema(dict.dictName());
    schema.add("Cvm", keywordSchema::oneNumber);
    schema.check(dict);
    if (!(Cvm_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Cvm must be zero or positive, not " << Cvm_ << exit(FatalIOError);
    }
}


void Foam::virtualMassForce::beginInterval
(
    const state& s,
    intervalExchange& e
)
{
    const scalar lightest = s.dem.lightestDensity();
    const scalar ratio = Cvm_*s.rho*s.parcels.volumeForceFactor(1)/lightest;
    if (ratio >= 1)
    {
        FatalIOErrorInFunction(dict_)
            << "virtualMass: Cvm rho/rho_p = " << ratio << " for the lightest"
            << " particles (" << lightest << " kg/m^3); the added mass is"
            << " explicit and needs it below 1" << exit(FatalIOError);
    }
    // in the order the coupling read the particles in
    vectorField a(s.dem.meanAccelerations(s.interval, !Pstream::parRun()));
    s.voidFraction.holders().toHeld(a);

    const vectorField& U = s.U.primitiveField();
    vectorField DUDt(U & fvc::grad(s.U)().primitiveField());
    vectorField& previous = Uprevious_->primitiveFieldRef();
    if (havePrevious_) DUDt += (U - previous)/s.interval;
    previous = U;
    havePrevious_ = true;

    vectorField DUDtP;
    s.voidFraction.gather(DUDt, DUDtP);
    vectorField& F = e.addedForce(s.particles.size());
    forAll(DUDtP, i)
    {
        const scalar w = s.weightSum[i];
        if (w <= SMALL) continue;
        const label type = s.type(i);
        // on the parcel's volume, like the pressure gradient force
        F[i] +=
            s.parcels.volumeForceFactor(type)
           *(Cvm_*s.rho*s.volumes[i]*(DUDtP[i]/w - a[i]));
    }
}
