/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testRankBoxIndex

Description
    rankBoxIndex against a brute-force test of every box: for random
    spheres (centres inside and outside the grid, as periodic images are)
    every box a sphere meets is among the ranks the index lists for its
    centre, on 512 boxes in an 8 x 8 x 8 block, on 64 random overlapping
    boxes, and in 2D (one direction not tested). On the block of boxes the
    index lists at most the 27 boxes around a bin, not all 512: the cost
    per particle does not grow with the ranks. Ends with
    'rankBoxIndex: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "rankBoxIndex.H"
#include "Random.H"
#include "testHarness.H"

using namespace Foam;
using testHarness::check;

namespace
{
    bool meets(const boundBox& box, const point& c, const scalar R, const labelList& dirs)
    {
        for (const label d : dirs)
        {
            if (c[d] + R < box.min()[d] || c[d] - R > box.max()[d]) return false;
        }
        return true;
    }

    //- Spheres the index misses, and the most ranks it lists for one
    void probe
    (
        const List<boundBox>& boxes,
        const boundBox& all,
        unsigned split,
        const labelList& dirs,
        const scalar reach,
        label& missed,
        label& mostListed,
        scalar& meanListed
    )
    {
        const rankBoxIndex index(boxes, all, split, dirs, reach);
        Random rnd(1234);
        missed = mostListed = 0;
        meanListed = 0;
        const label n = 20000;
        const vector span = all.span();
        for (label i = 0; i < n; ++i)
        {
            const point c = all.min() + cmptMultiply(rnd.sample01<vector>()*1.4 - vector::uniform(0.2), span);
            const scalar R = reach*rnd.sample01<scalar>();
            const SubList<label> listed(index.ranks(c));
            mostListed = max(mostListed, listed.size());
            meanListed += scalar(listed.size())/n;
            forAll(boxes, rank)
            {
                if (meets(boxes[rank], c, R, dirs) && !listed.found(rank)) ++missed;
            }
        }
    }
}


int main()
{
    const labelList xyz({0, 1, 2});
    label missed, most;
    scalar mean;

    // 8 x 8 x 8 boxes of 1 x 1 x 1: slabs in every direction
    List<boundBox> block;
    for (label k = 0; k < 8; ++k)
        for (label j = 0; j < 8; ++j)
            for (label i = 0; i < 8; ++i)
                block.append(boundBox(point(i, j, k), point(i + 1, j + 1, k + 1)));
    const boundBox cube(point::zero, point(8, 8, 8));
    probe(block, cube, 7u, xyz, 0.3, missed, most, mean);
    check(missed == 0, "block of 512 boxes: no sphere misses a box it meets", missed, 0, 0);
    check(most <= 27, "block of 512 boxes: at most 27 ranks listed for a bin", most, 27, 0);
    std::printf("block of 512 boxes: %.2f ranks listed per sphere on average, at most %d\n", mean, most);

    // 64 random boxes overlapping each other (jagged subdomains)
    Random rnd(77);
    List<boundBox> jagged(64);
    for (boundBox& box : jagged)
    {
        const point a = rnd.sample01<vector>()*8, b = rnd.sample01<vector>()*8;
        box = boundBox(min(a, b), max(a, b));
    }
    boundBox jaggedAll(jagged[0]);
    for (const boundBox& box : jagged) jaggedAll.add(box);
    probe(jagged, jaggedAll, 7u, xyz, 0.5, missed, most, mean);
    check(missed == 0, "64 random overlapping boxes: no sphere misses a box it meets", missed, 0, 0);

    // 2D: z not tested, boxes split along x only
    List<boundBox> slabs;
    for (label i = 0; i < 16; ++i) slabs.append(boundBox(point(i, 0, 0), point(i + 1, 4, 0.1)));
    probe(slabs, boundBox(point::zero, point(16, 4, 0.1)), 1u, labelList({0, 1}), 0.4, missed, most, mean);
    check(missed == 0, "2D slabs: no sphere misses a slab it meets", missed, 0, 0);
    check(most <= 3, "2D slabs: at most 3 slabs listed", most, 3, 0);

    // a reach of zero (the centroid model): only the box holding the centre
    probe(block, cube, 7u, xyz, 0, missed, most, mean);
    check(missed == 0, "block, reach 0: the box holding each centre is listed", missed, 0, 0);
    return testHarness::summary("rankBoxIndex");
}
