/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "solidFractionLimiter.H"
#include "processorCyclicPolyPatch.H"
#include "syncTools.H"


Foam::solidFractionLimiter::sweepFields::sweepFields
(
    const label nCells,
    const label nBoundaryFaces
)
:
    room(nCells),
    excess(nCells),
    roomSum(nCells),
    volSum(nCells),
    delta(nCells),
    nbrRoom(nBoundaryFaces, 0),
    nbrV(nBoundaryFaces, 0),
    sent(nBoundaryFaces, 0)
{}


Foam::solidFractionLimiter::solidFractionLimiter
(
    const fvMesh& mesh,
    const scalar alphaMin
)
:
    mesh_(mesh),
    alphaMin_(alphaMin)
{
    DynamicList<label> faces;
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<processorPolyPatch>(pp) && !isA<processorCyclicPolyPatch>(pp))
        {
            forAll(pp, i) faces.append(pp.start() + i);
        }
    }
    processorFaces_.transfer(faces);
}


Foam::label Foam::solidFractionLimiter::nOverLimit(const scalarField& solid) const
{
    label nOver = 0;
    forAll(solid, celli) nOver += overLimit(solid, celli);
    return nOver;
}


bool Foam::solidFractionLimiter::measure
(
    const scalarField& solid,
    sweepFields& s
) const
{
    const scalarField& V = mesh_.V();
    const scalar maxSolid = 1 - alphaMin_;
    label nOver = 0;
    forAll(solid, celli)
    {
        s.room[celli] = max(maxSolid*V[celli] - solid[celli], 0.0);
        const bool over = overLimit(solid, celli);
        s.excess[celli] = over ? solid[celli] - maxSolid*V[celli] : 0;
        nOver += over;
    }
    return returnReduce(nOver, sumOp<label>()) > 0;
}


void Foam::solidFractionLimiter::sumNeighbours(sweepFields& s) const
{
    const scalarField& V = mesh_.V();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    for (const label facei : processorFaces_)
    {
        s.nbrRoom[facei - nInternal] = s.room[own[facei]];
        s.nbrV[facei - nInternal] = V[own[facei]];
    }
    syncTools::swapBoundaryFaceList(mesh_, s.nbrRoom);
    syncTools::swapBoundaryFaceList(mesh_, s.nbrV);

    s.roomSum = 0;
    s.volSum = 0;
    for (label facei = 0; facei < nInternal; ++facei)
    {
        s.roomSum[own[facei]] += s.room[nei[facei]];
        s.roomSum[nei[facei]] += s.room[own[facei]];
        s.volSum[own[facei]] += V[nei[facei]];
        s.volSum[nei[facei]] += V[own[facei]];
    }
    for (const label facei : processorFaces_)
    {
        s.roomSum[own[facei]] += s.nbrRoom[facei - nInternal];
        s.volSum[own[facei]] += s.nbrV[facei - nInternal];
    }
}


Foam::scalar Foam::solidFractionLimiter::exchange
(
    scalarField& solid,
    sweepFields& s
) const
{
    const scalarField& V = mesh_.V();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();

    // the part of cell a's excess that goes to a neighbour of the given
    // room and volume
    auto share = [&s](const label a, const scalar nbrRoomA, const scalar nbrVA)
    {
        if (s.excess[a] <= 0) return scalar(0);
        if (s.roomSum[a] > 0) return min(s.excess[a], s.roomSum[a])*nbrRoomA/s.roomSum[a];
        return s.excess[a]*nbrVA/s.volSum[a];
    };
    scalar moved = 0;
    s.delta = 0;
    for (label facei = 0; facei < nInternal; ++facei)
    {
        const label a = own[facei], b = nei[facei];
        const scalar ab = share(a, s.room[b], V[b]);
        const scalar ba = share(b, s.room[a], V[a]);
        s.delta[a] += ba - ab;
        s.delta[b] += ab - ba;
        moved += ab + ba;
    }
    for (const label facei : processorFaces_)
    {
        const label a = own[facei];
        const scalar out = share(a, s.nbrRoom[facei - nInternal], s.nbrV[facei - nInternal]);
        s.sent[facei - nInternal] = out;
        s.delta[a] -= out;
        moved += out;
    }
    syncTools::swapBoundaryFaceList(mesh_, s.sent);
    for (const label facei : processorFaces_)
    {
        s.delta[own[facei]] += s.sent[facei - nInternal];
    }
    solid += s.delta;
    return moved;
}


Foam::scalar Foam::solidFractionLimiter::limit
(
    scalarField& solid,
    const label nOverAll,
    const scalar totalSolid
) const
{
    // the usual step: nothing to move, nothing to allocate
    if (nOverAll == 0) return 0;

    const scalar meshVolume = gSum(mesh_.V());
    if (totalSolid > (1 - alphaMin_)*meshVolume)
    {
        FatalErrorInFunction
            << "the particles hold " << totalSolid << " m3, more than (1 - alphaMin)"
            << " of the mesh volume " << meshVolume << " (alphaMin " << alphaMin_
            << "): no void fraction >= alphaMin exists" << exit(FatalError);
    }

    sweepFields s(mesh_.nCells(), mesh_.nFaces() - mesh_.nInternalFaces());
    scalar moved = 0;
    for (label sweep = 0; sweep < 100000; ++sweep)
    {
        if (!measure(solid, s)) return returnReduce(moved, sumOp<scalar>());
        sumNeighbours(s);
        moved += exchange(solid, s);
    }

    FatalErrorInFunction
        << "the alphaMin limiter did not find room for the excess solid volume"
        << " (alphaMin " << alphaMin_ << ")" << exit(FatalError);
    return moved;
}
