/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "mappingStatistics.H"
#include "vector2D.H"


Foam::label Foam::mappingStatistics::collect
(
    const scalarField& fractionSum,
    const scalarField& centreFound,
    const scalarField& particleVolumes,
    const particleHolders& holders,
    const scalarField& solid,
    const label nOverLimit,
    const bool keepsOutside
)
{
    // counts travel as scalars: exact far beyond any particle count
    enum { kNParticles, kNOutside, kNCut, kParticleVolume, kMeshedVolume, kKept, kSolid, kNOver, kNSums };
    scalarField sums(kNSums, Zero);
    forAll(fractionSum, p)
    {
        if (!holders.counted(p)) continue;
        sums[kNParticles] += 1;
        const scalar Vp = particleVolumes[p];
        sums[kParticleVolume] += Vp;
        sums[kMeshedVolume] += fractionSum[p]*Vp;
        if (centreFound[p] == 0) sums[kNOutside] += 1;
        else if (fractionSum[p] < 1 - wholeTolerance) sums[kNCut] += 1;
        if (keepsOutside && centreFound[p] > 0 && fractionSum[p] > 0 && fractionSum[p] < 1)
        {
            sums[kKept] += (1 - fractionSum[p])*Vp;
        }
    }
    sums[kSolid] = sum(solid);
    sums[kNOver] = nOverLimit;
    reduce(sums, sumOp<scalarField>());
    nParticles = label(sums[kNParticles]);
    nOutside = label(sums[kNOutside]);
    nCut = label(sums[kNCut]);
    particleVolume = sums[kParticleVolume];
    meshedVolume = sums[kMeshedVolume];
    keptVolume = sums[kKept];
    solidVolume = sums[kSolid];
    return label(sums[kNOver]);
}


void Foam::mappingStatistics::setRange(const scalarField& voidFraction)
{
    vector2D range(min(voidFraction), -max(voidFraction));
    reduce(range, minOp<vector2D>());
    minVoidFraction = range.x();
    maxVoidFraction = -range.y();
}


Foam::scalar Foam::mappingStatistics::conservationError() const
{
    const scalar held = meshedVolume + keptVolume;
    return mag(solidVolume - held)/max(held, VSMALL);
}


void Foam::mappingStatistics::write(Ostream& os, const word& modelType) const
{
    // the conservation error is relative, so 4 digits keep its meaning
    const int precision = os.precision(4);
    os  << modelType << ": " << nParticles << " particles, volume "
        << particleVolume << nl
        << "    solid volume in the field " << solidVolume
        << ", of the particles inside the mesh " << meshedVolume
        << ", conservation error " << conservationError() << nl
        << "    particles with centre outside the mesh " << nOutside
        << ", reaching outside " << nCut
        << ", volume outside " << particleVolume - meshedVolume
        << ", kept in the mesh " << keptVolume << nl
        << "    void fraction min " << minVoidFraction
        << " max " << maxVoidFraction
        << ", volume moved by alphaMin " << movedVolume << endl;
    os.precision(precision);
}
