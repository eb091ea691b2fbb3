#include "particleHolders.H"

Foam::particleHolders::particleHolders()
:
    distributed_(false),
    nOwned_(0)
{}


Foam::particleHolders::particleHolders
(
    const label nOwned,
    labelListList&& subMap,
    labelListList&& constructMap,
    const label nHeld
)
:
    map_(nHeld, std::move(subMap), std::move(constructMap)),
    distributed_(true),
    nOwned_(nOwned),
    nOwnedShared_(0)
{
    // the lowest rank a particle was sent to counts it; a particle sent to
    // several is shared, numbered in the owner's compact list
    const labelListList& sends = map_.subMap();
    labelList nSent(nOwned, 0);
    for (const labelList& toRank : sends)
    {
        for (const label p : toRank) ++nSent[p];
    }
    labelList ownedShared(nOwned, -1);
    forAll(nSent, p)
    {
        // every owned particle must reach a holder
        if (nSent[p] == 0)
        {
            FatalErrorInFunction
                << "owned particle " << p << " is sent to no processor"
                << abort(FatalError);
        }
        if (nSent[p] > 1) ownedShared[p] = nOwnedShared_++;
    }
    boolList first;
    first.setSize(nOwned, true);
    List<boolList> counts(sends.size()), shares(sends.size());
    labelListList sharedSubMap(sends.size());
    forAll(sends, rank)
    {
        counts[rank].setSize(sends[rank].size());
        shares[rank].setSize(sends[rank].size());
        DynamicList<label> sub;
        forAll(sends[rank], i)
        {
            const label p = sends[rank][i];
            counts[rank][i] = first[p];
            first[p] = false;
            shares[rank][i] = (ownedShared[p] >= 0);
            if (shares[rank][i]) sub.append(ownedShared[p]);
        }
        sharedSubMap[rank].transfer(sub);
    }

    // the flags travel as the particles do: the i-th sent to each rank
    counted_.setSize(nHeld, false);
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(sends, rank)
    {
        if (rank == Pstream::myProcNo() || sends[rank].empty()) continue;
        UOPstream os(rank, buffers);
        os << counts[rank] << shares[rank];
    }
    buffers.finishedSends();
    const labelListList& lands = map_.constructMap();
    List<boolList> received(lands.size());
    boolList shared;
    shared.setSize(nHeld, false);
    forAll(lands, rank)
    {
        if (lands[rank].empty()) continue;
        boolList counted;
        if (rank == Pstream::myProcNo())
        {
            counted = counts[rank];
            received[rank] = shares[rank];
        }
        else
        {
            UIPstream is(rank, buffers);
            is >> counted >> received[rank];
        }
        forAll(lands[rank], i)
        {
            counted_[lands[rank][i]] = counted[i];
            shared[lands[rank][i]] = received[rank][i];
        }
    }

    // the holder's compact list: the shared held particles in held order
    labelList heldShared(nHeld, -1);
    DynamicList<label> sharedHeld;
    forAll(shared, h)
    {
        if (shared[h])
        {
            heldShared[h] = sharedHeld.size();
            sharedHeld.append(h);
        }
    }
    sharedHeld_.transfer(sharedHeld);
    labelListList sharedConstructMap(lands.size());
    forAll(lands, rank)
    {
        DynamicList<label> construct;
        forAll(lands[rank], i)
        {
            if (received[rank][i]) construct.append(heldShared[lands[rank][i]]);
        }
        sharedConstructMap[rank].transfer(construct);
    }
    sharedMap_ = mapDistributeBase
    (
        sharedHeld_.size(), std::move(sharedSubMap), std::move(sharedConstructMap)
    );
}
