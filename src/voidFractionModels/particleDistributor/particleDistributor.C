/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleDistributor.H"
#include "PstreamBuffers.H"
#include "ListOps.H"
#include "UIndirectList.H"
#include "processorPolyPatch.H"

namespace
{
    //- The named fields of the particles send
    template<class Type>
    Foam::particleFields<Type> selected
    (
        const Foam::particleFields<Type>& all,
        const Foam::labelUList& send
    )
    {
        Foam::particleFields<Type> part(2*all.size());
        forAllConstIters(all, iter) part.set(iter.key(), Foam::Field<Type>(iter.val(), send));
        return part;
    }

    //- Into held, each named field of the held particles: from this rank's
    //  own (those of kept) and from what each rank sent, placed as
    //  constructMap says
    template<class Type>
    void heldFields
    (
        const Foam::particleFields<Type>& own,
        const Foam::List<Foam::particleFields<Type>>& received,
        const Foam::labelListList& constructMap,
        const Foam::labelList& kept,
        Foam::particleData& held
    )
    {
        using namespace Foam;
        const label me = Pstream::myProcNo();
        wordHashSet names(own.toc());
        for (const particleFields<Type>& from : received) names.insert(from.toc());
        for (const word& name : names.sortedToc())
        {
            Field<Type> values(held.size());
            label filled = 0;
            forAll(constructMap, rank)
            {
                const bool mine = (rank == me);
                const auto iter = (mine ? own : received[rank]).cfind(name);
                if (!iter.found()) continue;
                const labelList& to = constructMap[rank];
                forAll(to, i) values[to[i]] = (*iter)[mine ? kept[i] : i];
                filled += to.size();
            }
            if (filled != held.size())
            {
                FatalErrorInFunction
                    << "some ranks' particles have the field " << name
                    << " and others not" << abort(FatalError);
            }
            held.set(name, std::move(values));
        }
    }
}

Foam::particleDistributor::particleDistributor(const voidFractionModel& model)
:
    model_(model),
    boxes_(Pstream::nProcs()),
    splitDirections_(0),
    alone_(true)
{
    const polyMesh& mesh = model.mesh();
    boxes_[Pstream::myProcNo()] = boundBox(mesh.points(), false);
    Pstream::gatherList(boxes_);
    Pstream::scatterList(boxes_);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (!model.twoDimensional() || mesh.solutionD()[d] != -1)
        {
            directions_.append(d);
        }
    }
    boundBox all(boxes_[0]);
    for (const boundBox& box : boxes_) all.add(box);
    const scalar tol = 1e-9*all.mag();
    for (const label d : directions_)
    {
        for (const boundBox& box : boxes_)
        {
            if (box.min()[d] > all.min()[d] + tol || box.max()[d] < all.max()[d] - tol)
            {
                splitDirections_ |= 1u << d;
            }
        }
    }
    const List<vector>& shifts = model.images().shifts();
    forAll(shifts, s)
    {
        if ((model.images().shiftDirections()[s] & ~splitDirections_) == 0)
        {
            splitShifts_.append(shifts[s]);
        }
    }
    const boundBox& mine = boxes_[Pstream::myProcNo()];
    forAll(boxes_, rank)
    {
        if (rank == Pstream::myProcNo()) continue;
        bool overlaps = true;
        for (const label d : directions_)
        {
            overlaps = overlaps
             && boxes_[rank].min()[d] < mine.max()[d] && boxes_[rank].max()[d] > mine.min()[d];
        }
        if (overlaps) alone_ = false;
    }
    // the same decision on every rank: the boxes are the same everywhere
    bool anyOverlap = false;
    forAll(boxes_, a)
    {
        for (label b = a + 1; b < boxes_.size(); ++b)
        {
            bool overlaps = true;
            for (const label d : directions_)
            {
                overlaps = overlaps
                 && boxes_[a].min()[d] < boxes_[b].max()[d] - tol
                 && boxes_[a].max()[d] > boxes_[b].min()[d] + tol;
            }
            anyOverlap = anyOverlap || overlaps;
        }
    }
    if (anyOverlap) bins_.reset(new rankCellBins(mesh, all, directions_));
}


const Foam::labelList& Foam::particleDistributor::idOrder(const labelList& ids) const
{
    if (ids != lastIds_)
    {
        sortedOrder(ids, lastOrder_);
        lastIds_ = ids;
    }
    return lastOrder_;
}


Foam::particleHolders Foam::particleDistributor::distribute
(
    particleData&& owned,
    particleData& held
) const
{
    if (!Pstream::parRun())
    {
        const labelList& ids = owned.ids();
        bool ascending = true;
        for (label i = 1; ascending && i < ids.size(); ++i) ascending = ids[i] > ids[i - 1];
        if (ascending)
        {
            last_ = exchangeCounts();
            last_.owned = last_.held = owned.size();
            held = std::move(owned);
            return particleHolders();
        }
    }
    return distribute(static_cast<const particleData&>(owned), held);
}


Foam::labelListList Foam::particleDistributor::destinations
(
    const particleData& owned
) const
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const List<vector>& shifts = splitShifts_;
    const pointField& x = owned.positions();
    const scalarField& r = owned.radii();

    scalar maxReach = 0;
    forAll(r, p) maxReach = max(maxReach, model_.reach(r[p]));
    if (!index_.valid() || maxReach > index_->reach())
    {
        boundBox all(boxes_[0]);
        for (const boundBox& box : boxes_) all.add(box);
        index_.reset(new rankBoxIndex(boxes_, all, splitDirections_, directions_, maxReach));
    }
    const rankBoxIndex& index = index_();

    List<DynamicList<label>> sends(nProcs);
    labelList marked(nProcs, -1);
    forAll(x, p)
    {
        const scalar R = model_.reach(r[p]);
        // only a particle near a periodic side has images that matter
        const bool nearSide =
            splitDirections_ && model_.images().nearSide(x[p], R, splitDirections_);
        // most of the owned particles lie well inside this rank's cells
        if (alone_ && !nearSide && inside(boxes_[me], x[p], R))
        {
            sends[me].append(p);
            continue;
        }
        bool sent = false;
        auto sendNear = [&](const point& c)
        {
            for (const label rank : index.ranks(c))
            {
                if (marked[rank] != p && reaches(rank, c, R))
                {
                    marked[rank] = p;
                    sends[rank].append(p);
                    sent = true;
                }
            }
        };
        sendNear(x[p]);
        for (label s = 0; nearSide && s < shifts.size(); ++s) sendNear(x[p] + shifts[s]);
        if (!sent) sends[Pstream::masterNo()].append(p);
    }
    labelListList subMap(nProcs);
    forAll(sends, rank) subMap[rank].transfer(sends[rank]);
    return subMap;
}


void Foam::particleDistributor::incomingParticles::exchange
(
    const particleData& owned,
    const labelListList& subMap,
    const labelListList& flags
)
{
    // one message per rank with everything: the ids tell the receiver in
    // which order it keeps the particles
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const pointField& x = owned.positions();
    const scalarField& r = owned.radii();
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    receivedIds.setSize(nProcs);
    receivedFlags.setSize(nProcs);
    receivedX.setSize(nProcs);
    receivedR.setSize(nProcs);
    receivedScalars.setSize(nProcs);
    receivedVectors.setSize(nProcs);
    receivedLabels.setSize(nProcs);
    forAll(subMap, rank)
    {
        const labelList& send = subMap[rank];
        if (send.empty()) continue;
        labelList ids(UIndirectList<label>(owned.ids(), send));
        if (rank == me)
        {
            receivedIds[rank].transfer(ids);
            receivedFlags[rank] = flags[rank];
            continue;
        }
        UOPstream os(rank, buffers);
        os << ids << pointField(x, send) << scalarField(r, send)
           << selected(owned.fields<scalar>(), send) << selected(owned.fields<vector>(), send)
           << selected(owned.fields<label>(), send) << flags[rank];
    }
    buffers.finishedSends(bytesFrom);
    const labelList& recvSizes = bytesFrom;
    nHeld = 0;
    forAll(receivedIds, rank)
    {
        if (rank != me && recvSizes[rank])
        {
            UIPstream is(rank, buffers);
            is >> receivedIds[rank] >> receivedX[rank] >> receivedR[rank]
               >> receivedScalars[rank] >> receivedVectors[rank] >> receivedLabels[rank]
               >> receivedFlags[rank];
        }
        nHeld += receivedIds[rank].size();
    }
}


Foam::particleHolders Foam::particleDistributor::distribute
(
    const particleData& owned,
    particleData& held
) const
{
    if (!Pstream::parRun())
    {
        // one rank holds all: only the id order to make
        last_ = exchangeCounts();
        last_.owned = last_.held = owned.size();
        held = owned.reordered(idOrder(owned.ids()));
        return particleHolders();
    }

    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const pointField& x = owned.positions();
    const scalarField& r = owned.radii();
    labelListList subMap(destinations(owned));
    const labelListList flags(particleHolders::sentFlags(owned.size(), subMap));
    incomingParticles in;
    in.exchange(owned, subMap, flags);
    const List<labelList>& receivedIds = in.receivedIds;
    const label nHeld = in.nHeld;
    last_.owned = owned.size();
    last_.held = nHeld;
    last_.sentTo.setSize(nProcs);
    forAll(subMap, rank) last_.sentTo[rank] = (rank == me) ? 0 : subMap[rank].size();
    last_.bytesFrom = in.bytesFrom;

    labelList allIds(nHeld);
    label k = 0;
    for (const labelList& ids : receivedIds)
    {
        for (const label id : ids) allIds[k++] = id;
    }
    const labelList slot(invert(nHeld, idOrder(allIds)));
    labelListList constructMap(nProcs);
    pointField heldX(nHeld);
    scalarField heldR(nHeld);
    labelList heldIds(nHeld), heldFlags(nHeld);
    k = 0;
    forAll(receivedIds, rank)
    {
        // the particles kept here come straight from owned
        const bool mine = (rank == me);
        const labelList& send = subMap[me];
        const pointField& fromX = mine ? x : in.receivedX[rank];
        const scalarField& fromR = mine ? r : in.receivedR[rank];
        labelList& construct = constructMap[rank];
        construct.setSize(receivedIds[rank].size());
        forAll(construct, i)
        {
            const label to = slot[k++];
            const label from = mine ? send[i] : i;
            construct[i] = to;
            heldX[to] = fromX[from];
            heldR[to] = fromR[from];
            heldIds[to] = receivedIds[rank][i];
            heldFlags[to] = in.receivedFlags[rank][i];
        }
    }

    held = particleData(std::move(heldX), std::move(heldR), std::move(heldIds));
    // the named fields go where the particles went
    heldFields(owned.fields<scalar>(), in.receivedScalars, constructMap, subMap[me], held);
    heldFields(owned.fields<vector>(), in.receivedVectors, constructMap, subMap[me], held);
    heldFields(owned.fields<label>(), in.receivedLabels, constructMap, subMap[me], held);
    return particleHolders
    (
        owned.size(), std::move(subMap), flags, std::move(constructMap), heldFlags
    );
}


void Foam::particleDistributor::writeExchange(Ostream& os) const
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const polyMesh& mesh = model_.mesh();
    label faces = 0;
    scalar area = 0;
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        if (isA<processorPolyPatch>(patch))
        {
            faces += patch.size();
            area += sum(patch.magFaceAreas());
        }
    }
    List<labelList> sentTo(nProcs), bytesFrom(nProcs), sizes(nProcs);
    List<scalar> areas(nProcs);
    sentTo[me] = last_.sentTo.size() ? last_.sentTo : labelList(nProcs, Zero);
    bytesFrom[me] = last_.bytesFrom.size() ? last_.bytesFrom : labelList(nProcs, Zero);
    sizes[me] = labelList({last_.owned, last_.held, mesh.nCells(), faces});
    areas[me] = area;
    Pstream::gatherList(sentTo);
    Pstream::gatherList(bytesFrom);
    Pstream::gatherList(sizes);
    Pstream::gatherList(areas);
    if (!Pstream::master()) return;
    forAll(sentTo, rank)
    {
        label sent = 0, sentBytes = 0, to = 0, received = 0, receivedBytes = 0, from = 0;
        for (label other = 0; other < nProcs; ++other)
        {
            if (other == rank) continue;
            sent += sentTo[rank][other];
            sentBytes += bytesFrom[other][rank];
            to += (sentTo[rank][other] > 0);
            received += sentTo[other][rank];
            receivedBytes += bytesFrom[rank][other];
            from += (sentTo[other][rank] > 0);
        }
        os  << "exchange rank " << rank << ": owns " << sizes[rank][0]
            << " holds " << sizes[rank][1] << " sends " << sent << " particles "
            << sentBytes << " bytes to " << to << " ranks receives " << received
            << " particles " << receivedBytes << " bytes from " << from
            << " ranks; cells " << sizes[rank][2] << " processor faces "
            << sizes[rank][3] << " area " << areas[rank] << " m2" << nl;
    }
    os.flush();
}
