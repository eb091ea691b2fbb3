/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "dragForce.H"
#include "keywordSchema.H"
#include "voidFractionModel.H"
#include "parcelScaling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(dragForce, 0);
    addToRunTimeSelectionTable(particleForce, dragForce, dictionary);
}


Foam::dragForce::dragForce
(
    const word& name,
    const dictionary& dict,
    const setup& s
)
:
    particleForce(name),
    formulationB_(s.formulationB)
{
    keywordSchema schema(dict.dictName());
    schema.add("model", keywordSchema::oneWord);
    schema.check(dict);
    law_ = dragModel::New(dict, "model");
}


void Foam::dragForce::beginInterval(const state& s, intervalExchange& e)
{
    const particleData& particles = s.particles;
    const vectorField& v = s.velocities;
    const scalar mu = s.rho*s.nu;
    scalarField& beta = e.beta;
    beta.setSize(particles.size());
    scalarField cellBeta;
    vectorField cellBetaV;
    s.voidFraction.gatherApplySpread
    (
        s.voidFraction.voidFraction().primitiveField(), s.U.primitiveField(),
        cellBeta, cellBetaV,
        [&](const label i, const scalar alphaP, const vector& Up, scalar& b, vector& bv)
        {
            const scalar w = s.weightSum[i];
            if (w <= SMALL)
            {
                beta[i] = 0;
            }
            else
            {
                const scalar a = alphaP/w;
                const label type = s.type(i);
                // a parcel: the law for one of its particles, scaled
                beta[i] = s.parcels.dragFactor(type)*law_->beta
                (
                    {
                        s.parcels.particleDiameter(2*particles.radii()[i], type),
                        s.parcels.particleVolume(s.volumes[i], type),
                        a, mag(Up/w - v[i]), s.rho, mu
                    }
                );
                if (formulationB_) beta[i] /= a;
            }
            b = beta[i];
            bv = beta[i]*v[i];
        }
    );
    e.cellBeta = std::move(cellBeta);
    e.cellBetaV = std::move(cellBetaV);
}
