/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "voidFractionModel.H"

void Foam::voidFractionModel::selectMoved
(
    const UList<point>& x,
    const scalarField& r
)
{
    // a particle keeps its row when every rank decides the same for it (all
    // hold all), the row took no periodic images and needs none, and the
    // particle is within keepDistance of where the row was computed
    const label n = x.size();
    const bool keeping =
        keepDistance_ > 0 && !holders_.distributed() && rowPositions_.size();
    moved_.setSize(n);
    label nMoved = 0;
    const scalar tolSqr = sqr(keepDistance_);
    forAll(x, p)
    {
        const label q = keeping ? previous_[p] : -1;
        const bool keep =
            q >= 0 && !rowImages_[q] && rowRadii_[q] == r[p]
         && magSqr(x[p] - rowPositions_[q]) <= tolSqr
         && !nearPeriodicSide(x[p], imageReach(r[p]));
        if (!keep) moved_[nMoved++] = p;
    }
    moved_.setSize(nMoved);
}


void Foam::voidFractionModel::keepRows
(
    const UList<point>& x,
    const scalarField& r
)
{
    const label n = x.size();
    pointField positions(n);
    boolList images(n, false);
    if (moved_.size() == n)
    {
        positions = x;
        images = computedImages_;
    }
    else
    {
        merged_.clear();
        label k = 0;
        for (label p = 0; p < n; ++p)
        {
            if (k < moved_.size() && moved_[k] == p)
            {
                merged_.appendRow(weights_, k);
                positions[p] = x[p];
                images[p] = computedImages_[k];
                ++k;
            }
            else
            {
                merged_.appendRow(lastWeights_, previous_[p]);
                positions[p] = rowPositions_[previous_[p]];
            }
            merged_.endParticle();
        }
        weights_.swap(merged_);
    }
    lastWeights_ = weights_;
    rowPositions_.transfer(positions);
    rowRadii_ = r;
    rowImages_.transfer(images);
}
