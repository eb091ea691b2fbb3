/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "rankBoxIndex.H"

Foam::rankBoxIndex::rankBoxIndex
(
    const List<boundBox>& boxes,
    const boundBox& all,
    unsigned splitDirections,
    const labelList& tested,
    scalar reach
)
:
    bounds_(all),
    reach_(reach)
{
    // bins of about equal width along the split directions, 8 per rank
    scalar volume = 1;
    label nSplit = 0;
    for (const label d : tested)
    {
        if (splitDirections & (1u << d))
        {
            volume *= max(all.span()[d], VSMALL);
            ++nSplit;
        }
    }
    const scalar width =
        nSplit ? Foam::pow(volume/(8.0*boxes.size()), 1.0/nSplit) : GREAT;
    bool isTested[3] = {false, false, false};
    for (const label d : tested) isTested[d] = true;
    for (direction d = 0; d < 3; ++d)
    {
        n_[d] = 1;
        if (isTested[d] && (splitDirections & (1u << d)))
        {
            n_[d] = max(1, min(64, label(all.span()[d]/width + 0.5)));
        }
        invWidth_[d] = n_[d]/max(all.span()[d], VSMALL);
    }

    // per bin the ranks whose grown box meets it: count, then fill
    const label nBins = n_[0]*n_[1]*n_[2];
    List<FixedList<label, 6>> ranges(boxes.size());
    labelList counts(nBins, Zero);
    forAll(boxes, rank)
    {
        FixedList<label, 6>& r = ranges[rank];
        for (direction d = 0; d < 3; ++d)
        {
            const scalar grow = isTested[d] ? reach : 0;
            r[d] = bin(d, boxes[rank].min()[d] - grow);
            r[3 + d] = bin(d, boxes[rank].max()[d] + grow);
        }
        for (label k = r[2]; k <= r[5]; ++k)
            for (label j = r[1]; j <= r[4]; ++j)
                for (label i = r[0]; i <= r[3]; ++i)
                    ++counts[i + n_[0]*(j + n_[1]*k)];
    }
    offsets_.setSize(nBins + 1);
    offsets_[0] = 0;
    for (label b = 0; b < nBins; ++b) offsets_[b + 1] = offsets_[b] + counts[b];
    ranks_.setSize(offsets_[nBins]);
    counts = 0;
    forAll(boxes, rank)
    {
        const FixedList<label, 6>& r = ranges[rank];
        for (label k = r[2]; k <= r[5]; ++k)
            for (label j = r[1]; j <= r[4]; ++j)
                for (label i = r[0]; i <= r[3]; ++i)
                {
                    const label b = i + n_[0]*(j + n_[1]*k);
                    ranks_[offsets_[b] + counts[b]++] = rank;
                }
    }
}
