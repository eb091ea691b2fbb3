/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "sphereWalkVoidFraction.H"


Foam::sphereWalkVoidFraction::sphereWalkVoidFraction
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(modelType, dict, mesh),
    overlap_(mesh),
    gridWraps_(0)
{
    if (twoDimensional()) overlap_.setTwoDimensional(emptyDirection(), slabThickness());
    if (!locator().isTensorGrid() || twoDimensional()) return;
    const scalar tol = 1e-9*images().bounds().mag();
    for (direction d = 0; d < 3; ++d)
    {
        if (!((images().directions() >> d) & 1)) continue;
        const scalarList& g = locator().gridPlanes(d);
        const scalar span = images().bounds().span()[d];
        bool wraps =
            mag(g.first() - images().bounds().min()[d]) < tol
         && mag(g.last() - images().bounds().max()[d]) < tol;
        for (const vector& S : images().shifts())
        {
            if (mag(S[d]) > tol && mag(mag(S[d]) - span) > tol) wraps = false;
        }
        if (wraps) gridWraps_ |= 1u << d;
    }
}


unsigned Foam::sphereWalkVoidFraction::gridWrapsSphere
(
    const point& c,
    const scalar R,
    const label centreCell
) const
{
    if (!gridWraps_ || centreCell < 0) return 0;
    // a sphere narrower than every cell crosses at most one plane per
    // direction, and its pieces fit: the split cannot fail
    if (2*R <= locator().minWidth()) return gridWraps_;
    bool cut[3];
    scalar offset[3];
    label low[3], high[3];
    return gridPieces(centreCell, c, R, true, cut, offset, low, high) ? gridWraps_ : 0;
}


bool Foam::sphereWalkVoidFraction::splitOnGrid
(
    const label centreCell,
    const point& c,
    const scalar R,
    const label maxCuts,
    const bool wrap
)
{
    if (twoDimensional()) return false;     // the one-go split is for spheres
    bool cut[3];
    scalar offset[3];
    label low[3], high[3];
    if (!gridPieces(centreCell, c, R, wrap, cut, offset, low, high)) return false;
    const int cutMask = int(cut[0]) | int(cut[1]) << 1 | int(cut[2]) << 2;
    if (cutMask == 0)
    {
        // whole in one cell: no volume to compute
        const label celli = (low[0] >= 0 && low[1] >= 0 && low[2] >= 0)
            ? locator().gridCell(low[0], low[1], low[2]) : -1;
        if (celli >= 0) rows().append(celli, 1.0);
        return true;
    }
    const label nCut = cut[0] + cut[1] + cut[2];
    if (nCut > maxCuts) return false;
    const scalar perVolume = 1/particleVolume(R);
    auto add = [&](const label i, const label j, const label k, const scalar volume)
    {
        // a piece beyond the grid's ends or in a hole is not in this mesh
        const label celli = (volume > 0 && i >= 0 && j >= 0 && k >= 0) ? locator().gridCell(i, j, k) : -1;
        if (celli >= 0) rows().append(celli, volume*perVolume);
    };
    scalar piece[8];
    sphereOverlap::planeSplit(R, offset, cut, piece);
    // the pieces are the sides of the cut axes only
    for (int s = cutMask; ; s = (s - 1) & cutMask)
    {
        add((s & 1) ? high[0] : low[0], (s & 2) ? high[1] : low[1], (s & 4) ? high[2] : low[2], piece[s]);
        if (s == 0) break;
    }
    return true;
}


void Foam::sphereWalkVoidFraction::exactVolumes
(
    const label centreCell,
    const point& c,
    const scalar R
)
{
    cells_.clear();
    volumes_.clear();
    overlap_.overlaps(c, R, centreCell, cells_, volumes_);
}


void Foam::sphereWalkVoidFraction::appendVolumes(const scalar R)
{
    const scalar Vp = particleVolume(R);
    forAll(cells_, k)
    {
        rows().append(cells_[k], volumes_[k]/Vp);
    }
}


void Foam::sphereWalkVoidFraction::appendLatticeSplit
(
    const label centreCell,
    const point& c,
    const scalar R,
    const sphereOverlap::lattice& L,
    const sphereOverlap::sphereLatticeTable* table
)
{
    cells_.clear();
    counts_.clear();
    label total = 0;
    if (locator().isTensorGrid())
    {
        // the cells the sphere's box covers, by index: no walk
        total = label(table ? table->total() : sphereOverlap::latticeCount({c.x(), c.y(), c.z()}, R, L));
        label first[3], last[3];
        for (direction d = 0; d < 3; ++d)
        {
            const scalarList& g = locator().gridPlanes(d);
            if (c[d] + R < g.first() || c[d] - R > g.last()) return;
            first[d] = locator().interval(d, max(c[d] - R, g.first()));
            last[d] = locator().interval(d, min(c[d] + R, g.last()));
        }
        const scalarList& gx = locator().gridPlanes(0);
        const scalarList& gy = locator().gridPlanes(1);
        const scalarList& gz = locator().gridPlanes(2);
        const sphereOverlap::vec3 c3{c.x(), c.y(), c.z()};
        for (label k = first[2]; k <= last[2]; ++k)
        for (label j = first[1]; j <= last[1]; ++j)
        for (label i = first[0]; i <= last[0]; ++i)
        {
            const sphereOverlap::vec3 lo{gx[i], gy[j], gz[k]}, hi{gx[i + 1], gy[j + 1], gz[k + 1]};
            const long n = table ? table->count(c3, R, lo, hi) : sphereOverlap::latticeCount(c3, R, L, lo, hi);
            const label celli = locator().gridCell(i, j, k);
            if (n && celli >= 0)
            {
                cells_.append(celli);
                counts_.append(label(n));
            }
        }
    }
    else
    {
        total = overlap_.latticeCounts(c, R, L, centreCell, cells_, counts_, table);
    }
    if (total == 0)
    {
        if (centreCell >= 0) rows().append(centreCell, 1.0);
        return;
    }
    forAll(cells_, k)
    {
        rows().append(cells_[k], scalar(counts_[k])/total);
    }
}
