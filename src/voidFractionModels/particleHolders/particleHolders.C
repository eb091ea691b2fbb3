/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleHolders.H"

Foam::particleHolders::particleHolders()
:
    distributed_(false),
    nOwned_(0)
{}


Foam::labelListList Foam::particleHolders::sentFlags
(
    const label nOwned,
    const labelListList& subMap
)
{
    labelList nSent(nOwned, 0);
    for (const labelList& toRank : subMap)
    {
        for (const label p : toRank) ++nSent[p];
    }
    forAll(nSent, p)
    {
        if (nSent[p] == 0)
        {
            FatalErrorInFunction
                << "owned particle " << p << " is sent to no processor"
                << abort(FatalError);
        }
    }
    // the lowest rank a particle is sent to counts it
    boolList first;
    first.setSize(nOwned, true);
    labelListList flags(subMap.size());
    forAll(subMap, rank)
    {
        flags[rank].setSize(subMap[rank].size());
        forAll(subMap[rank], i)
        {
            const label p = subMap[rank][i];
            flags[rank][i] = (first[p] ? countedFlag : 0) | (nSent[p] > 1 ? sharedFlag : 0);
            first[p] = false;
        }
    }
    return flags;
}


Foam::particleHolders::particleHolders
(
    const label nOwned,
    labelListList&& subMap,
    const labelListList& sentFlags,
    labelListList&& constructMap,
    const labelUList& heldFlags
)
:
    map_(heldFlags.size(), std::move(subMap), std::move(constructMap)),
    distributed_(true),
    nOwned_(nOwned),
    counted_(heldFlags.size()),
    nOwnedShared_(0)
{
    // the owner's compact list: its shared particles, numbered where the
    // one rank that counts each is sent it
    const labelListList& sends = map_.subMap();
    labelList ownedShared(nOwned, -1);
    forAll(sends, rank)
    {
        forAll(sends[rank], i)
        {
            const label f = sentFlags[rank][i];
            if ((f & countedFlag) && (f & sharedFlag))
            {
                ownedShared[sends[rank][i]] = nOwnedShared_++;
            }
        }
    }
    // the holder's: its shared particles in held order
    labelList heldShared(heldFlags.size(), -1);
    DynamicList<label> sharedHeld;
    forAll(heldFlags, h)
    {
        counted_[h] = heldFlags[h] & countedFlag;
        if (heldFlags[h] & sharedFlag)
        {
            heldShared[h] = sharedHeld.size();
            sharedHeld.append(h);
        }
    }
    sharedHeld_.transfer(sharedHeld);

    // both maps list the particles in the order they are sent
    const labelListList& lands = map_.constructMap();
    labelListList sharedSubMap(sends.size()), sharedConstructMap(lands.size());
    forAll(sends, rank)
    {
        DynamicList<label> sub;
        for (const label p : sends[rank])
        {
            if (ownedShared[p] >= 0) sub.append(ownedShared[p]);
        }
        sharedSubMap[rank].transfer(sub);
        DynamicList<label> construct;
        for (const label h : lands[rank])
        {
            if (heldShared[h] >= 0) construct.append(heldShared[h]);
        }
        sharedConstructMap[rank].transfer(construct);
    }
    sharedMap_ = mapDistributeBase
    (
        sharedHeld_.size(), std::move(sharedSubMap), std::move(sharedConstructMap)
    );
}
