/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "voidFractionModel.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "syncTools.H"

#include <algorithm>


void Foam::voidFractionModel::collectPeriodicShifts()
{
    // the face paired with each face of a cyclic or processorCyclic patch
    // (its centre, untransformed): the translation to the other side
    const label nInternal = mesh_.nInternalFaces();
    const vectorField& Cf = mesh_.faceCentres();
    List<vector> other(mesh_.nFaces() - nInternal);
    forAll(other, i) other[i] = Cf[nInternal + i];
    syncTools::swapBoundaryFaceList(mesh_, other);

    const scalar tol = 1e-9*globalBounds_.mag();
    DynamicList<vector> directions;
    auto addDirection = [&](const vector& t)
    {
        if (mag(t) < tol) return;
        for (const vector& d : directions)
        {
            if (mag(d - t) < tol || mag(d + t) < tol) return;
        }
        directions.append(t);
    };
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if ((isA<cyclicPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp)) && pp.size())
        {
            addDirection(other[pp.start() - nInternal] - Cf[pp.start()]);
        }
    }
    List<List<vector>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = directions;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    directions.clear();
    for (const List<vector>& dirs : all)
    {
        for (const vector& t : dirs) addDirection(t);
    }
    // the same order on every decomposition (only round-off depends on it)
    std::sort
    (
        directions.begin(), directions.end(),
        [&](const vector& a, const vector& b)
        {
            const direction da = findMax(cmptMag(a)), db = findMax(cmptMag(b));
            return da < db;
        }
    );

    // every combination: a particle by an edge or a corner of a periodic
    // box has images across one, two or three sides
    DynamicList<vector> shifts;
    const label K = directions.size();
    label nComb = 1;
    for (label k = 0; k < K; ++k) nComb *= 3;
    for (label comb = 0; comb < nComb; ++comb)
    {
        vector S(Zero);
        for (label k = 0, c = comb; k < K; ++k, c /= 3)
        {
            S += scalar((c % 3) - 1)*directions[k];
        }
        if (mag(S) > tol) shifts.append(S);
    }
    periodicShifts_.transfer(shifts);
    shiftDirections_.setSize(periodicShifts_.size());
    forAll(periodicShifts_, s)
    {
        shiftDirections_[s] = 0;
        for (direction d = 0; d < 3; ++d)
        {
            if (mag(periodicShifts_[s][d]) > tol) shiftDirections_[s] |= 1u << d;
        }
        periodicDirections_ |= shiftDirections_[s];
    }
    if (periodicShifts_.size())
    {
        Info<< "voidFractionModel: periodic translations " << directions
            << ": particles by a cyclic patch get periodic images" << endl;
    }
}


bool Foam::voidFractionModel::nearPeriodicSide
(
    const point& c,
    const scalar reach,
    const unsigned mask
) const
{
    // a particle clear of every periodic side of the box has no image that
    // reaches it (the translations span the box)
    const point& lo = globalBounds_.min();
    const point& hi = globalBounds_.max();
    const unsigned tested = periodicDirections_ & mask;
    for (direction d = 0; d < 3; ++d)
    {
        if (((tested >> d) & 1) && (c[d] - reach <= lo[d] || c[d] + reach >= hi[d]))
        {
            return true;
        }
    }
    return false;
}


bool Foam::voidFractionModel::makeImages
(
    const UList<point>& x,
    const scalarField& r,
    const labelUList& centres
)
{
    const label n = x.size();
    nParticles_ = n;
    entries_.clear();
    entryRadii_.clear();
    parent_.clear();
    shift_.clear();
    firstEntry_.setSize(n + 1);
    const point& lo = globalBounds_.min();
    const point& hi = globalBounds_.max();
    auto overlaps = [&](const point& c, const scalar reach)
    {
        return c.x() - reach < hi.x() && c.x() + reach > lo.x()
            && c.y() - reach < hi.y() && c.y() + reach > lo.y()
            && c.z() - reach < hi.z() && c.z() + reach > lo.z();
    };
    auto add = [&](const point& c, const label p, const vector& S)
    {
        entries_.append(c);
        entryRadii_.append(r[p]);
        parent_.append(p);
        shift_.append(S);
    };
    // the particles are copied into the entries only once one has an
    // image: in many steps none has (a model that wraps, a bed clear of
    // the periodic sides)
    label nCopied = 0;
    auto copyUpTo = [&](const label end)
    {
        for (; nCopied < end; ++nCopied)
        {
            firstEntry_[nCopied] = entries_.size();
            add(x[nCopied], nCopied, Zero);
        }
    };
    // an image across a side the model wraps is never needed: a particle
    // it always wraps is tested against the other periodic sides only
    const unsigned unwrapped = ~wrappedAlways();
    const scalar wrappedR = wrappedRadius();
    forAll(x, p)
    {
        const unsigned tested = (centres[p] >= 0 && r[p] <= wrappedR) ? unwrapped : ~0u;
        if ((periodicDirections_ & tested) == 0) continue;
        const scalar reach = imageReach(r[p]);
        if (!nearPeriodicSide(x[p], reach, tested)) continue;
        // a shift along wrapped directions only is the model's own wrap
        const unsigned wrapped = wrappedDirections(x[p], r[p], centres[p]);
        if ((periodicDirections_ & ~wrapped) == 0) continue;
        forAll(periodicShifts_, s)
        {
            if ((shiftDirections_[s] & ~wrapped) == 0) continue;
            const vector& S = periodicShifts_[s];
            if (overlaps(x[p] + S, reach))
            {
                copyUpTo(p + 1);
                add(x[p] + S, p, S);
            }
        }
    }
    if (entries_.empty()) return false;
    copyUpTo(n);
    firstEntry_[n] = entries_.size();
    return true;
}
