/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "periodicImages.H"


template<class Rules>
bool Foam::periodicImages::make
(
    const UList<point>& x,
    const UList<scalar>& r,
    const labelUList& centres,
    const Rules& rules
)
{
    const label n = x.size();
    entries_.clear();
    radii_.clear();
    parent_.clear();
    shift_.clear();
    firstEntry_.setSize(n + 1);
    const point& lo = bounds_.min();
    const point& hi = bounds_.max();
    auto overlaps = [&](const point& c, const scalar reach)
    {
        return c.x() - reach < hi.x() && c.x() + reach > lo.x()
            && c.y() - reach < hi.y() && c.y() + reach > lo.y()
            && c.z() - reach < hi.z() && c.z() + reach > lo.z();
    };
    auto add = [&](const point& c, const label p, const vector& S)
    {
        entries_.append(c);
        radii_.append(r[p]);
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
    const unsigned unwrapped = ~rules.wrappedAlways();
    const scalar wrappedR = rules.wrappedRadius();
    forAll(x, p)
    {
        const unsigned tested = (centres[p] >= 0 && r[p] <= wrappedR) ? unwrapped : ~0u;
        if ((directions_ & tested) == 0) continue;
        const scalar reach = rules.reach(r[p]);
        if (!nearSide(x[p], reach, tested)) continue;
        // a shift along wrapped directions only is the model's own wrap
        const unsigned wrapped = rules.wrappedDirections(x[p], r[p], centres[p]);
        if ((directions_ & ~wrapped) == 0) continue;
        forAll(shifts_, s)
        {
            if ((shiftDirections_[s] & ~wrapped) == 0) continue;
            const vector& S = shifts_[s];
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
