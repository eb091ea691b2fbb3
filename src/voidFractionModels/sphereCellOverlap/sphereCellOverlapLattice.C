/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "sphereCellOverlap.H"

#include <limits>

long Foam::sphereCellOverlap::convexCellCount
(
    const label celli,
    const sphereOverlap::vec3& c,
    const scalar R,
    const sphereOverlap::lattice& L
) const
{
    using namespace sphereOverlap;
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& own = mesh_.faceOwner();
    const label nInternal = mesh_.nInternalFaces();
    const cell& faces = mesh_.cells()[celli];
    const double inf = std::numeric_limits<double>::infinity();

    // each row of the sphere's lattice in the cell's box meets the cell (its
    // face planes) in one interval of z: count its points in closed form. A
    // point on an internal face is the neighbour's, on a boundary face the
    // cell's, so the cells partition space
    long n = 0;
    forEachLatticeRow
    (
        c, R, L, cellMin_[celli], cellMax_[celli] + vec3{L.h.x, L.h.y, L.h.z},
        [&](const long i, const long j, const long k0, const long k1)
        {
            const double x = L.o.x + (i + 0.5)*L.h.x, y = L.o.y + (j + 0.5)*L.h.y;
            double zLo = -inf, zHi = inf;
            bool loStrict = false, hiStrict = false;
            for (const label facei : faces)
            {
                const bool owner = (own[facei] == celli);
                const vec3 nn = (owner ? 1.0 : -1.0)*facePlanes_[facei].normal;
                const bool strict = owner && facei < nInternal;
                const double rhs = dot(nn, toVec3(Cf[facei])) - nn.x*x - nn.y*y;
                if (nn.z > 0)
                {
                    const double b = rhs/nn.z;
                    if (b < zHi || (b == zHi && strict)) { zHi = b; hiStrict = strict; }
                }
                else if (nn.z < 0)
                {
                    const double b = rhs/nn.z;
                    if (b > zLo || (b == zLo && strict)) { zLo = b; loStrict = strict; }
                }
                else if (strict ? !(rhs > 0) : !(rhs >= 0))
                {
                    return;
                }
            }
            const double tLo = (zLo - L.o.z)/L.h.z - 0.5, tHi = (zHi - L.o.z)/L.h.z - 0.5;
            long kMin = k0, kMax = k1;
            if (zLo > -inf) kMin = std::max(kMin, long(loStrict ? std::floor(tLo) + 1 : std::ceil(tLo)));
            if (zHi < inf) kMax = std::min(kMax, long(hiStrict ? std::ceil(tHi) - 1 : std::floor(tHi)));
            if (kMax >= kMin) n += kMax - kMin + 1;
        }
    );
    return n;
}


Foam::label Foam::sphereCellOverlap::latticeCounts
(
    const point& c,
    const scalar R,
    const sphereOverlap::lattice& L,
    const label centreCell,
    DynamicList<label>& cells,
    DynamicList<label>& counts,
    const sphereOverlap::sphereLatticeTable* table
) const
{
    using namespace sphereOverlap;
    const vec3 c3 = toVec3(c);

    // box cells count in closed form, the others row by row
    general_.clear();
    forEachReachedCell
    (
        c, R, centreCell,
        [&](const label celli)
        {
            if (!isBox_[celli])
            {
                general_.append(celli);
                return true;
            }
            const long n = table
                ? table->count(c3, R, cellMin_[celli], cellMax_[celli])
                : latticeCount(c3, R, L, cellMin_[celli], cellMax_[celli]);
            if (n)
            {
                cells.append(celli);
                counts.append(label(n));
            }
            return true;
        }
    );

    for (const label celli : general_)
    {
        const long n = convexCellCount(celli, c3, R, L);
        if (n)
        {
            cells.append(celli);
            counts.append(label(n));
        }
    }
    return label(table ? table->total() : latticeCount(c3, R, L));
}
