/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "rankCellBins.H"
#include "Pstream.H"

Foam::rankCellBins::rankCellBins
(
    const polyMesh& mesh,
    const boundBox& all,
    const labelList& directions
)
:
    bounds_(all),
    nWords_(0)
{
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    const vector span = all.span();
    label nTested = 0;
    scalar tested = 1;
    for (direction d = 0; d < 3; ++d)
    {
        tested_[d] = directions.found(d);
        if (tested_[d])
        {
            ++nTested;
            tested *= span[d];
        }
    }
    // about two average cells per bin
    const scalar width = 2*Foam::pow(tested/max(nCells, 1), 1.0/max(nTested, 1));
    label nBins = 1;
    for (direction d = 0; d < 3; ++d)
    {
        n_[d] = tested_[d] ? min(max(label(std::ceil(span[d]/width)), 1), 64) : 1;
        invWidth_[d] = n_[d]/max(span[d], VSMALL);
        nBins *= n_[d];
    }
    nWords_ = nBins/32 + 1;

    labelList mine(nWords_, 0);
    const scalar tol = 1e-9*all.mag();
    const pointField& pts = mesh.points();
    const labelListList& cellPoints = mesh.cellPoints();
    forAll(cellPoints, celli)
    {
        const boundBox bb(pts, cellPoints[celli], false);
        label first[3], last[3];
        bool inGrid = true;
        for (direction d = 0; d < 3; ++d)
        {
            inGrid = inGrid && range(d, bb.min()[d] - tol, bb.max()[d] + tol, first[d], last[d]);
        }
        if (!inGrid) continue;
        for (label k = first[2]; k <= last[2]; ++k)
        for (label j = first[1]; j <= last[1]; ++j)
        for (label i = first[0]; i <= last[0]; ++i)
        {
            const label b = i + n_[0]*(j + n_[1]*k);
            mine[b/32] = label(unsigned(mine[b/32]) | (1u << (b % 32)));
        }
    }
    List<labelList> ranks(Pstream::nProcs());
    ranks[Pstream::myProcNo()].transfer(mine);
    Pstream::gatherList(ranks);
    Pstream::scatterList(ranks);
    bits_.setSize(nWords_*ranks.size());
    forAll(ranks, rank)
    {
        SubList<label>(bits_, nWords_, rank*nWords_) = ranks[rank];
    }
}


bool Foam::rankCellBins::range
(
    const direction d,
    const scalar lo,
    const scalar hi,
    label& first,
    label& last
) const
{
    if (!tested_[d])
    {
        first = last = 0;
        return true;
    }
    if (hi < bounds_.min()[d] || lo > bounds_.max()[d]) return false;
    first = max(label((lo - bounds_.min()[d])*invWidth_[d]), 0);
    last = min(label((hi - bounds_.min()[d])*invWidth_[d]), n_[d] - 1);
    first = min(first, n_[d] - 1);
    last = max(last, 0);
    return true;
}


bool Foam::rankCellBins::reaches
(
    const label rank,
    const point& c,
    const scalar R
) const
{
    label first[3], last[3];
    for (direction d = 0; d < 3; ++d)
    {
        if (!range(d, c[d] - R, c[d] + R, first[d], last[d])) return false;
    }
    const label* words = bits_.cdata() + rank*nWords_;
    for (label k = first[2]; k <= last[2]; ++k)
    for (label j = first[1]; j <= last[1]; ++j)
    for (label i = first[0]; i <= last[0]; ++i)
    {
        const label b = i + n_[0]*(j + n_[1]*k);
        if ((unsigned(words[b/32]) >> (b % 32)) & 1u) return true;
    }
    return false;
}
