#include "sphereCellOverlap.H"

bool Foam::sphereCellOverlap::contains(const label celli, const point& p) const
{
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& own = mesh_.faceOwner();
    const label nInternal = mesh_.nInternalFaces();
    for (const label facei : mesh_.cells()[celli])
    {
        const scalar s = sphereOverlap::dot(toVec3(p - Cf[facei]), faceNormal_[facei]);
        if (own[facei] == celli)
        {
            // on an internal face: the neighbour's; on a boundary face: ours
            if (s > 0 || (s == 0 && facei < nInternal)) return false;
        }
        else if (s < 0)
        {
            return false;
        }
    }
    return true;
}


Foam::label Foam::sphereCellOverlap::latticeCounts
(
    const point& c,
    const scalar R,
    const sphereOverlap::lattice& L,
    const labelUList& seeds,
    DynamicList<label>& cells,
    DynamicList<label>& counts,
    const sphereOverlap::sphereLatticeTable* table
) const
{
    using namespace sphereOverlap;
    forEachReachedCell
    (
        c, R, seeds,
        [&](const label celli, const vector& shift)
        {
            const vec3 cs = toVec3(c + shift);
            const lattice Ls{L.o + toVec3(shift), L.h};
            long n = 0;
            if (isBox_[celli] && table)
            {
                n = table->count(cs, R, cellMin_[celli], cellMax_[celli]);
            }
            else if (isBox_[celli])
            {
                n = latticeCount(cs, R, Ls, cellMin_[celli], cellMax_[celli]);
            }
            else
            {
                // the box is only a filter here (closed on both sides)
                const vec3 hi = cellMax_[celli] + vec3{L.h.x, L.h.y, L.h.z};
                forEachLatticePoint
                (
                    cs, R, Ls, cellMin_[celli], hi,
                    [&](const vec3& p)
                    {
                        if (contains(celli, point(p.x, p.y, p.z))) ++n;
                    }
                );
            }
            if (n)
            {
                cells.append(celli);
                counts.append(label(n));
            }
        }
    );
    return label(table ? table->total() : latticeCount(toVec3(c), R, L));
}
