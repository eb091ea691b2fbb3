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
    const vec3 c3 = toVec3(c);

    // box cells count in closed form; the others are collected and every
    // lattice point of the sphere is located among them once
    general_.clear();
    forEachReachedCell
    (
        c, R, seeds,
        [&](const label celli)
        {
            if (!isBox_[celli])
            {
                general_.append(celli);
                return;
            }
            const long n = table
                ? table->count(c3, R, cellMin_[celli], cellMax_[celli])
                : latticeCount(c3, R, L, cellMin_[celli], cellMax_[celli]);
            if (n)
            {
                cells.append(celli);
                counts.append(label(n));
            }
        }
    );

    if (general_.size())
    {
        generalCounts_.setSize(general_.size());
        generalCounts_ = 0;
        const label nGeneral = general_.size();
        label last = 0;
        const vec3 margin{R + L.h.x, R + L.h.y, R + L.h.z};
        forEachLatticePoint
        (
            c3, R, L, c3 - margin, c3 + margin,
            [&](const vec3& p)
            {
                // consecutive points mostly share a cell: try the last one first
                for (label t = 0; t < nGeneral; ++t)
                {
                    const label k = (last + t) % nGeneral;
                    const label celli = general_[k];
                    const vec3& lo = cellMin_[celli];
                    const vec3& hi = cellMax_[celli];
                    if
                    (
                        p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y
                     && p.z >= lo.z && p.z <= hi.z
                     && contains(celli, point(p.x, p.y, p.z))
                    )
                    {
                        ++generalCounts_[k];
                        last = k;
                        return;
                    }
                }
            }
        );
        forAll(general_, k)
        {
            if (generalCounts_[k])
            {
                cells.append(general_[k]);
                counts.append(generalCounts_[k]);
            }
        }
    }
    return label(table ? table->total() : latticeCount(c3, R, L));
}
