/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "voidFractionModel.H"
#include "processorCyclicPolyPatch.H"
#include "syncTools.H"


Foam::label Foam::voidFractionModel::cellsOverLimit() const
{
    label nOver = 0;
    forAll(solid_, celli) nOver += overLimit(celli);
    return nOver;
}


Foam::scalar Foam::voidFractionModel::limitSolidFraction(const label nOverAll)
{
    // the usual step: nothing to move, nothing to allocate
    if (nOverAll == 0) return 0;

    const scalarField& V = mesh_.V();
    const scalar maxSolid = 1 - alphaMin_;
    if (stats_.solidVolume > maxSolid*gSum(V))
    {
        FatalErrorInFunction
            << "the particles hold " << stats_.solidVolume << " m3, more than (1 - alphaMin)"
            << " of the mesh volume " << gSum(V) << " (alphaMin " << alphaMin_
            << "): no void fraction >= alphaMin exists" << exit(FatalError);
    }

    // Faces across which volume moves: internal faces and processor faces
    // (so a decomposed case moves it exactly as the whole one does)
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    DynamicList<label> procFaces;
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<processorPolyPatch>(pp) && !isA<processorCyclicPolyPatch>(pp))
        {
            forAll(pp, i) procFaces.append(pp.start() + i);
        }
    }
    const label nBoundary = mesh_.nFaces() - nInternal;

    // Each sweep hands the excess of every overfull cell to its neighbours,
    // in proportion to their free room at the start of the sweep, or, when
    // they are all full, by volume: they pass it on in the next sweep, so
    // the excess spreads until it finds room. Nothing is deleted.
    scalarField room(mesh_.nCells()), excess(mesh_.nCells());
    scalarField roomSum(mesh_.nCells()), volSum(mesh_.nCells()), delta(mesh_.nCells());
    scalarField nbrRoom(nBoundary, 0), nbrV(nBoundary, 0), sent(nBoundary, 0);
    scalar moved = 0;
    for (label sweep = 0; sweep < 100000; ++sweep)
    {
        label nOver = 0;
        forAll(solid_, celli)
        {
            room[celli] = max(maxSolid*V[celli] - solid_[celli], 0.0);
            const bool over = overLimit(celli);
            excess[celli] = over ? solid_[celli] - maxSolid*V[celli] : 0;
            nOver += over;
        }
        if (returnReduce(nOver, sumOp<label>()) == 0)
        {
            return returnReduce(moved, sumOp<scalar>());
        }

        for (const label facei : procFaces)
        {
            nbrRoom[facei - nInternal] = room[own[facei]];
            nbrV[facei - nInternal] = V[own[facei]];
        }
        syncTools::swapBoundaryFaceList(mesh_, nbrRoom);
        syncTools::swapBoundaryFaceList(mesh_, nbrV);

        roomSum = 0;
        volSum = 0;
        for (label facei = 0; facei < nInternal; ++facei)
        {
            roomSum[own[facei]] += room[nei[facei]];
            roomSum[nei[facei]] += room[own[facei]];
            volSum[own[facei]] += V[nei[facei]];
            volSum[nei[facei]] += V[own[facei]];
        }
        for (const label facei : procFaces)
        {
            roomSum[own[facei]] += nbrRoom[facei - nInternal];
            volSum[own[facei]] += nbrV[facei - nInternal];
        }

        // the part of cell a's excess that goes to a neighbour of the given
        // room and volume
        auto share = [&](const label a, const scalar nbrRoomA, const scalar nbrVA)
        {
            if (excess[a] <= 0) return scalar(0);
            if (roomSum[a] > 0) return min(excess[a], roomSum[a])*nbrRoomA/roomSum[a];
            return excess[a]*nbrVA/volSum[a];
        };
        delta = 0;
        for (label facei = 0; facei < nInternal; ++facei)
        {
            const label a = own[facei], b = nei[facei];
            const scalar ab = share(a, room[b], V[b]);
            const scalar ba = share(b, room[a], V[a]);
            delta[a] += ba - ab;
            delta[b] += ab - ba;
            moved += ab + ba;
        }
        for (const label facei : procFaces)
        {
            const label a = own[facei];
            const scalar out = share(a, nbrRoom[facei - nInternal], nbrV[facei - nInternal]);
            sent[facei - nInternal] = out;
            delta[a] -= out;
            moved += out;
        }
        syncTools::swapBoundaryFaceList(mesh_, sent);
        for (const label facei : procFaces)
        {
            delta[own[facei]] += sent[facei - nInternal];
        }
        solid_ += delta;
    }

    FatalErrorInFunction
        << "the alphaMin limiter did not find room for the excess solid volume"
        << " (alphaMin " << alphaMin_ << ")" << exit(FatalError);
    return moved;
}
