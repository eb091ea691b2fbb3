/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testParticleCellWeights

Description
    particleCellWeights, the compressed rows every model fills, against
    rows written out by hand: rows made by append and by extend (with the
    unused end dropped), the rows of particles and their periodic images
    joined, a row scaled, rows truncated, appended from other weights and
    swapped, every entry visited in row order, and clear for a new step.
    Ends with 'particleCellWeights: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "particleCellWeights.H"
#include "labelList.H"
#include "testHarness.H"

#include <vector>
#include <utility>

using namespace Foam;
using testHarness::near;

namespace
{
    typedef std::vector<std::vector<std::pair<label, scalar>>> rowsByHand;

    //- The weights equal the rows by hand, entry by entry
    void checkRows(const char* what, const particleCellWeights& w, const rowsByHand& want)
    {
        std::string s(what);
        near((s + ": particle count").c_str(), w.nParticles(), want.size(), 0);
        label nEntries = 0;
        for (std::size_t p = 0; p < want.size() && label(p) < w.nParticles(); ++p)
        {
            near((s + ": row length").c_str(), w.end(p) - w.begin(p), want[p].size(), 0);
            nEntries += want[p].size();
            for (std::size_t e = 0; e < want[p].size() && label(e) < w.end(p) - w.begin(p); ++e)
            {
                near((s + ": cell").c_str(), w.cell(w.begin(p) + e), want[p][e].first, 0);
                near((s + ": fraction").c_str(), w.fraction(w.begin(p) + e), want[p][e].second, 0);
            }
        }
        near((s + ": entry count").c_str(), w.size(), nEntries, 0);
    }
}


int main()
{
    particleCellWeights w;
    checkRows("new", w, {});

    // particle 0 whole in cell 4; particle 1 in two cells; particle 2 in
    // none (outside the mesh)
    w.append(4, 1.0);
    w.endParticle();
    w.append(7, 0.25);
    w.append(8, 0.75);
    w.endParticle();
    w.endParticle();
    checkRows("appended", w, {{{4, 1.0}}, {{7, 0.25}, {8, 0.75}}, {}});

    // a row filled through the raw arrays, three of five opened entries used
    const label k = w.extend(5);
    w.cellsData()[k] = 1;
    w.fractionsData()[k] = 0.5;
    w.cellsData()[k + 1] = 2;
    w.fractionsData()[k + 1] = 0.375;
    w.cellsData()[k + 2] = 3;
    w.fractionsData()[k + 2] = 0.125;
    near("extend opens at the end of the entries", k, 3, 0);
    w.truncateEntries(k + 3);
    w.endParticle();
    checkRows("extended", w, {{{4, 1.0}}, {{7, 0.25}, {8, 0.75}}, {}, {{1, 0.5}, {2, 0.375}, {3, 0.125}}});

    // scaled and set
    w.scale(1, 2);
    w.setFraction(w.begin(0), 0.5);
    checkRows("scaled", w, {{{4, 0.5}}, {{7, 0.5}, {8, 1.5}}, {}, {{1, 0.5}, {2, 0.375}, {3, 0.125}}});

    // the four rows are particle A, then particle B and its two images
    // (first entries 0 and 1, end 4): joined into two rows
    w.joinRows(labelList({0, 1, 4}));
    checkRows("joined", w, {{{4, 0.5}}, {{7, 0.5}, {8, 1.5}, {1, 0.5}, {2, 0.375}, {3, 0.125}}});

    // every entry in row order
    std::vector<label> visited;
    scalar sum1 = 0;
    w.forAllEntries([&](const label p, const label c, const scalar f)
    {
        visited.push_back(p*100 + c);
        if (p == 1) sum1 += f;
    });
    const std::vector<label> order({4, 107, 108, 101, 102, 103});
    near("visited every entry", visited.size(), order.size(), 0);
    bool inOrder = visited == order;
    near("visited in row order", inOrder, 1, 0);
    near("row 1's fractions summed by the visit", sum1, 3.0, 1e-15);

    // appended from other weights, then truncated back
    particleCellWeights other;
    other.append(9, 0.125);
    other.endParticle();
    other.append(5, 0.5);
    other.append(6, 0.5);
    other.endParticle();
    w.appendRow(other, 1);
    w.append(3, 0.25);
    w.endParticle();
    checkRows("row appended from another", w,
              {{{4, 0.5}}, {{7, 0.5}, {8, 1.5}, {1, 0.5}, {2, 0.375}, {3, 0.125}}, {{5, 0.5}, {6, 0.5}, {3, 0.25}}});
    w.truncate(1);
    checkRows("truncated to one row", w, {{{4, 0.5}}});

    // swapped, and back
    w.swap(other);
    checkRows("swapped: the other's rows", w, {{{9, 0.125}}, {{5, 0.5}, {6, 0.5}}});
    checkRows("swapped: this one's rows", other, {{{4, 0.5}}});
    w.swap(other);
    checkRows("swapped back", w, {{{4, 0.5}}});

    // a new step
    w.clear();
    checkRows("cleared", w, {});
    w.append(2, 1.0);
    w.endParticle();
    checkRows("a row after clear", w, {{{2, 1.0}}});

    return testHarness::summary("particleCellWeights");
}
