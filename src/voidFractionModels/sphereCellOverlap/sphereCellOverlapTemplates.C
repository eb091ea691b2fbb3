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
    const vectorField& Cf = mesh_.faceCentres();
    const label nInternal = mesh_.nInternalFaces();
    const scalar shiftTol = 1e-6*R;

    queue_.clear();
    ++walkCount_;
    auto reached = [&](const label celli, const vector& shift)
    {
        if (!cube) return reachesBox(celli, c + shift, R);
        const sphereOverlap::vec3& lo = cellMin_[celli];
        const sphereOverlap::vec3& hi = cellMax_[celli];
        const point x = c + shift;
        return lo.x <= x.x() + R && hi.x >= x.x() - R
            && lo.y <= x.y() + R && hi.y >= x.y() - R
            && lo.z <= x.z() + R && hi.z >= x.z() - R;
    };
    auto enqueue = [&](const label celli, const vector& shift)
    {
        const bool unshifted = (magSqr(shift) < sqr(shiftTol));
        if (unshifted)
        {
            if (queuedAt_[celli] == walkCount_) return;
        }
        else
        {
            for (const visit& v : queue_)
            {
                if (v.cell == celli && magSqr(v.shift - shift) < sqr(shiftTol)) return;
            }
        }
        if (reached(celli, shift))
        {
            if (unshifted) queuedAt_[celli] = walkCount_;
            queue_.append(visit{celli, shift});
        }
    };
    for (const label seed : seeds) enqueue(seed, Zero);

    // queue_ grows while it is read: a breadth-first walk
    for (label q = 0; q < queue_.size(); ++q)
    {
        const label celli = queue_[q].cell;
        const vector shift = queue_[q].shift;
        visitor(celli, shift);
        for (const label facei : mesh_.cells()[celli])
        {
            if (facei < nInternal)
            {
                enqueue(own[facei] == celli ? nei[facei] : own[facei], shift);
            }
            else
            {
                const label nbrFace = coupledFace_[facei - nInternal];
                if (nbrFace >= 0)
                {
                    // the image enters through nbrFace: shift by the translation
                    enqueue(own[nbrFace], shift + Cf[nbrFace] - Cf[facei]);
                }
            }
        }
    }
}
