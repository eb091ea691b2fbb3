template<class Visitor>
void Foam::sphereCellOverlap::forEachReachedCell
(
    const point& c,
    const scalar R,
    const labelUList& seeds,
    Visitor&& visitor,
    const bool cube
) const
{
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();

    queue_.clear();
    ++walkCount_;
    auto reached = [&](const label celli)
    {
        if (!cube) return reachesBox(celli, c, R);
        const sphereOverlap::vec3& lo = cellMin_[celli];
        const sphereOverlap::vec3& hi = cellMax_[celli];
        return lo.x <= c.x() + R && hi.x >= c.x() - R
            && lo.y <= c.y() + R && hi.y >= c.y() - R
            && lo.z <= c.z() + R && hi.z >= c.z() - R;
    };
    auto enqueue = [&](const label celli)
    {
        if (queuedAt_[celli] == walkCount_ || !reached(celli)) return;
        queuedAt_[celli] = walkCount_;
        queue_.append(celli);
    };
    for (const label seed : seeds) enqueue(seed);

    // queue_ grows while it is read: a breadth-first walk
    for (label q = 0; q < queue_.size(); ++q)
    {
        const label celli = queue_[q];
        if (!visitor(celli)) continue;
        if (!cube && isConvex(celli))
        {
            // a cell the sphere reaches beyond this one is reached through
            // faces the sphere crosses: whole on a face plane's inner side,
            // it does not lead on through that face
            const sphereOverlap::vec3 c3 = toVec3(c);
            for (label k = cellPlaneStart_[celli]; k < cellPlaneStart_[celli + 1]; ++k)
            {
                const cellPlane& p = cellPlanes_[k];
                if (p.face < nInternal && p.inside(c3) < R)
                {
                    enqueue(own[p.face] == celli ? nei[p.face] : own[p.face]);
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
        }
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
