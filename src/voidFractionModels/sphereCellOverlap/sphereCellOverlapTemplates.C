/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
template<class Visitor>
void Foam::sphereCellOverlap::forEachReachedCell
(
    const point& c,
    const scalar R,
    const label centreCell,
    Visitor&& visitor
) const
{
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();
    const sphereOverlap::vec3 c3 = toVec3(c);

    queue_.clear();
    ++walkCount_;
    auto enqueue = [&](const label celli)
    {
        if (queuedAt_[celli] == walkCount_ || !reachesBox(celli, c, R)) return;
        queuedAt_[celli] = walkCount_;
        queue_.append(celli);
    };

    // a centre outside this mesh: the sphere enters through boundary faces
    bool fromBoundary = (centreCell < 0);
    if (fromBoundary) boundarySeeds(c, R, enqueue);
    else enqueue(centreCell);

    // the sphere crosses a face beyond which this mesh goes on: its cells
    // there may be joined to the centre's only through other processors'
    // cells or through space outside the mesh
    bool leaves = false;
    for (label q = 0; ; ++q)
    {
        if (q == queue_.size())
        {
            if (!leaves || fromBoundary) break;
            fromBoundary = true;
            boundarySeeds(c, R, enqueue);
            if (q == queue_.size()) break;
        }
        // queue_ grows while it is read: a breadth-first walk
        const label celli = queue_[q];
        if (!visitor(celli)) continue;
        if (isConvex(celli))
        {
            // a cell the sphere reaches beyond this one is reached through
            // faces the sphere crosses: whole on a face plane's inner side,
            // it does not lead on through that face
            for (label k = cellPlaneStart_[celli]; k < cellPlaneStart_[celli + 1]; ++k)
            {
                const cellPlane& p = cellPlanes_[k];
                if (p.inside(c3) >= R) continue;
                if (p.face < nInternal)
                {
                    enqueue(own[p.face] == celli ? nei[p.face] : own[p.face]);
                }
                else
                {
                    leaves = leaves || exitFace_[p.face - nInternal];
                }
            }
            continue;
        }
        for (const label facei : mesh_.cells()[celli])
        {
            if (facei < nInternal)
            {
                enqueue(own[facei] == celli ? nei[facei] : own[facei]);
            }
            else if (!leaves && exitFace_[facei - nInternal])
            {
                leaves = boxReached(faceMin_[facei], faceMax_[facei], c3, R);
            }
        }
    }
}


template<class Enqueue>
void Foam::sphereCellOverlap::boundarySeeds
(
    const point& c,
    const scalar R,
    const Enqueue& enqueue
) const
{
    if (!boundaryTree_.valid()) return;
    const treeBoundBox sphereBox(c - vector(R, R, R), c + vector(R, R, R));
    for (const label i : boundaryTree_->findBox(sphereBox))
    {
        enqueue(mesh_.faceOwner()[boundaryFaces_[i]]);
    }
}


template<class Compute>
Foam::scalar Foam::sphereCellOverlap::faceValue
(
    const label facei,
    DynamicList<label>& done,
    DynamicList<scalar>& values,
    const Compute& compute
) const
{
    if (facei >= mesh_.nInternalFaces()) return compute(facei);
    const label k = done.find(facei);
    if (k >= 0) return values[k];
    done.append(facei);
    values.append(compute(facei));
    return values.last();
}
