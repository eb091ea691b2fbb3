/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "gasEnergyBalance.H"
#include "fvc.H"

void Foam::gasEnergyBalance::add
(
    const volScalarField& alpha,
    const surfaceScalarField& alphaPhi,
    const surfaceScalarField& conductance,
    const volScalarField& T,
    const scalarField& sources
)
{
    const fvMesh& mesh = T.mesh();
    const scalarField& V = mesh.V();
    const scalar rDeltaT = 1/mesh.time().deltaTValue();
    const scalarField stored(V*fvc::ddt(alpha, T)().primitiveField());
    const scalarField continuity
    (
        V*(fvc::ddt(alpha) + fvc::div(alphaPhi))().primitiveField()*T.primitiveField()
    );
    const scalarField added(V*sources);

    scalar out = 0, crossing = 0;
    forAll(T.boundaryField(), patchi)
    {
        const fvPatchScalarField& Tb = T.boundaryField()[patchi];
        if (Tb.coupled()) continue;
        const scalarField convected(alphaPhi.boundaryField()[patchi]*Tb);
        const scalarField conducted
        (
            conductance.boundaryField()[patchi]*mesh.magSf().boundaryField()[patchi]*Tb.snGrad()
        );
        out += sum(convected) - sum(conducted);
        crossing += sum(mag(convected)) + sum(mag(conducted));
    }
    // round-off is relative to what is differenced: the cells' contents
    // (temperatures in kelvin) as well as the flows
    const scalarField held
    (
        rDeltaT*V*
        (
            mag(alpha.primitiveField()*T.primitiveField())
          + mag(alpha.oldTime().primitiveField()*T.oldTime().primitiveField())
        )
    );
    scalarField sums(6);
    sums[0] = sum(stored);
    sums[1] = sum(continuity);
    sums[2] = sum(added);
    sums[3] = out;
    sums[4] = crossing + sum(mag(added));
    sums[5] = sum(held) + sum(mag(continuity));
    reduce(sums, sumOp<scalarField>());
    const scalar flows = max(sums[4], VSMALL);
    worstBalance_ =
        max(worstBalance_, mag(sums[0] + sums[3] - sums[1] - sums[2])/(flows + sums[5]));
    worstContinuity_ = max(worstContinuity_, mag(sums[1])/flows);
}
