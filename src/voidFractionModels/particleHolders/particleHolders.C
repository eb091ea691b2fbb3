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
    nOwned_(nOwned)
{
    // the lowest rank a particle was sent to counts it
    boolList first(nOwned, true);
    const labelListList& sends = map_.subMap();
    List<boolList> flags(sends.size());
    forAll(sends, rank)
    {
        flags[rank].setSize(sends[rank].size());
        forAll(sends[rank], i)
        {
            const label p = sends[rank][i];
            flags[rank][i] = first[p];
            first[p] = false;
        }
    }
    // every owned particle must reach a holder
    forAll(first, p)
    {
        if (first[p])
        {
            FatalErrorInFunction
                << "owned particle " << p << " is sent to no processor"
                << abort(FatalError);
        }
    }
    // the flags travel as the particles do: the i-th sent to each rank
    counted_.setSize(nHeld, false);
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(sends, rank)
    {
        if (rank == Pstream::myProcNo() || sends[rank].empty()) continue;
        UOPstream os(rank, buffers);
        os << flags[rank];
    }
    buffers.finishedSends();
    const labelListList& lands = map_.constructMap();
    forAll(lands, rank)
    {
        if (lands[rank].empty()) continue;
        boolList received;
        if (rank == Pstream::myProcNo())
        {
            received = flags[rank];
        }
        else
        {
            UIPstream is(rank, buffers);
            is >> received;
        }
        forAll(lands[rank], i) counted_[lands[rank][i]] = received[i];
    }
}
