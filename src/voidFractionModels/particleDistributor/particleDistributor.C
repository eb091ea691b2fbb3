#include "particleDistributor.H"
#include "PstreamBuffers.H"
#include "ListOps.H"
#include "UIndirectList.H"

Foam::particleDistributor::particleDistributor(const voidFractionModel& model)
:
    model_(model),
    boxes_(Pstream::nProcs())
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
}


bool Foam::particleDistributor::meets
(
    const boundBox& box,
    const point& c,
    const scalar R
) const
{
    for (const label d : directions_)
    {
        if (c[d] + R < box.min()[d] || c[d] - R > box.max()[d]) return false;
    }
    return true;
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
    const particleData& owned,
    particleData& held
) const
{
    if (!Pstream::parRun())
    {
        // one rank holds all: only the id order to make
        held = owned.reordered(idOrder(owned.ids()));
        return particleHolders();
    }

    const label nProcs = Pstream::nProcs();
    const List<vector>& shifts = model_.periodicShifts();
    const pointField& x = owned.positions();
    const scalarField& r = owned.radii();

    List<DynamicList<label>> sends(nProcs);
    forAll(x, p)
    {
        const scalar R = model_.reach(r[p]);
        // only a particle near a periodic side has images that matter
        const bool nearSide = model_.nearPeriodicSide(x[p], R);
        bool sent = false;
        for (label rank = 0; rank < nProcs; ++rank)
        {
            bool reaches = meets(boxes_[rank], x[p], R);
            for (label s = 0; !reaches && nearSide && s < shifts.size(); ++s)
            {
                reaches = meets(boxes_[rank], x[p] + shifts[s], R);
            }
            if (reaches)
            {
                sends[rank].append(p);
                sent = true;
            }
        }
        if (!sent) sends[Pstream::masterNo()].append(p);
    }

    // the ids tell each rank what it receives and in which order it keeps it
    labelListList subMap(nProcs);
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(sends, rank)
    {
        subMap[rank].transfer(sends[rank]);
        if (rank != Pstream::myProcNo() && subMap[rank].size())
        {
            UOPstream os(rank, buffers);
            os << labelList(UIndirectList<label>(owned.ids(), subMap[rank]));
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    labelListList receivedIds(nProcs);
    label nHeld = 0;
    forAll(receivedIds, rank)
    {
        if (rank == Pstream::myProcNo())
        {
            receivedIds[rank] = labelList(UIndirectList<label>(owned.ids(), subMap[rank]));
        }
        else if (recvSizes[rank])
        {
            UIPstream is(rank, buffers);
            is >> receivedIds[rank];
        }
        nHeld += receivedIds[rank].size();
    }
    labelList allIds(nHeld);
    label k = 0;
    for (const labelList& ids : receivedIds)
    {
        for (const label id : ids) allIds[k++] = id;
    }
    const labelList slot(invert(nHeld, idOrder(allIds)));
    labelListList constructMap(nProcs);
    k = 0;
    forAll(receivedIds, rank)
    {
        constructMap[rank].setSize(receivedIds[rank].size());
        for (label& to : constructMap[rank]) to = slot[k++];
    }

    particleHolders holders(owned.size(), std::move(subMap), std::move(constructMap), nHeld);
    pointField heldX(x);
    scalarField heldR(r);
    labelList heldIds(owned.ids());
    holders.toHeld(heldX);
    holders.toHeld(heldR);
    holders.toHeld(heldIds);
    held = particleData(std::move(heldX), std::move(heldR), std::move(heldIds));
    // a rank may own no particle: all take the same branch
    if (returnReduce(owned.velocities().size() > 0, orOp<bool>()))
    {
        vectorField heldU(owned.velocities());
        holders.toHeld(heldU);
        held.setVelocities(std::move(heldU));
    }
    return holders;
}
