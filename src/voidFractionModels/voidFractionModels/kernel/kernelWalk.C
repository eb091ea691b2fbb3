/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
// The kernel on any mesh: the particle's mirror images across the walls it
// reaches, and the cells the walk over faces finds within the cut-off.

#include "kernel.H"

void Foam::voidFractionModels::kernel::findWallMirrors
(
    const point& c,
    const label celli,
    const scalar rc
)
{
    wallMirrors_.clear();
    wallMirrors_.append(c);
    lastMirrorWall_.clear();
    lastMirrorWall_.append(-1);
    forEachNearWall
    (
        c, celli, rc,
        [&](const wallPlane& P, const label w)
        {
            const label m = wallMirrors_.size();
            for (label i = 0; i < m; ++i)
            {
                // no image of an image across the opposite wall of a slab
                if (lastMirrorWall_[i] >= 0 && (walls_[lastMirrorWall_[i]].normal & P.normal) < -0.5)
                {
                    continue;
                }
                const point x = wallMirrors_[i];
                wallMirrors_.append(x - 2*((P.normal & x) - P.offset)*P.normal);
                lastMirrorWall_.append(w);
            }
        }
    );
}


void Foam::voidFractionModels::kernel::walkWeights
(
    const label p,
    const point& c,
    const scalar b,
    const scalar rc
)
{
    const label seed = centreCells()[p];
    const label k0 = rows().size();
    if (seed >= 0) rows().append(seed, 0);
    const scalarField& V = mesh().V();
    const vectorField& C = mesh().C();
    const scalar rc2 = sqr(rc);
    const scalar invB2 = 1/sqr(b);
    scalar sum = 0;
    overlap_.forEachReachedCell
    (
        c, rc, seed,
        [&](const label celli)
        {
            const point& x = C[celli];
            if (magSqr(x - c) > rc2) return true;
            scalar w = 0;
            for (const point& mirror : wallMirrors_)
            {
                w += exp(gaussianArgument(magSqr(x - mirror), invB2));
            }
            w *= V[celli];
            sum += w;
            if (celli == seed) rows().setFraction(k0, w);
            else rows().append(celli, w);
            return true;
        }
    );
    sums_[p] = sum;
}
