/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "sphereCellOverlap.H"
#include "emptyPolyPatch.H"
#include "treeBoundBox.H"
#include "boundBox.H"
#include "volFields.H"

void Foam::sphereCellOverlap::measureFaces()
{
    const pointField& pts = mesh_.points();
    const faceList& faces = mesh_.faces();
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();

    forAll(faces, facei)
    {
        const vector n = Sf[facei]/mag(Sf[facei]);
        facePlanes_[facei] = {toVec3(n), n & Cf[facei]};
        const boundBox fbb(pts, faces[facei], false);
        faceMin_[facei] = toVec3(fbb.min());
        faceMax_[facei] = toVec3(fbb.max());
        const scalar tol = 1e-12*Foam::sqrt(mag(Sf[facei]));
        for (const label pointi : faces[facei])
        {
            if (mag((pts[pointi] - Cf[facei]) & n) > tol)
            {
                planarFace_[facei] = false;
                break;
            }
        }
    }
}


void Foam::sphereCellOverlap::measureCells()
{
    const pointField& pts = mesh_.points();
    const faceList& faces = mesh_.faces();
    DynamicList<cellPlane> planes;
    forAll(mesh_.cells(), celli)
    {
        const cell& c = mesh_.cells()[celli];
        const boundBox bb(c.points(faces, pts), false);
        cellMin_[celli] = toVec3(bb.min());
        cellMax_[celli] = toVec3(bb.max());
        isBox_[celli] =
            c.size() == 6
         && mag(bb.volume() - mesh_.V()[celli]) < 1e-10*mesh_.V()[celli];
        cellPlaneStart_[celli + 1] = cellPlaneStart_[celli];
        if (isBox_[celli]) continue;
        // the outward planes, kept when the cell is convex: every point of
        // the cell on the inner side of every (planar) face
        const label first = planes.size();
        const labelList cellPoints(c.labels(faces));
        const scalar tol = 1e-10*bb.mag();
        bool convex = true;
        for (const label facei : c)
        {
            const scalar sign = mesh_.faceOwner()[facei] == celli ? 1 : -1;
            const facePlane& fp = facePlanes_[facei];
            const cellPlane plane{sign*fp.normal, sign*fp.offset, facei};
            convex = convex && planarFace_[facei];
            for (const label pointi : cellPoints)
            {
                convex = convex && plane.inside(toVec3(pts[pointi])) >= -tol;
            }
            planes.append(plane);
        }
        if (!convex) planes.setSize(first);
        cellPlaneStart_[celli + 1] = planes.size();
    }
    cellPlanes_.transfer(planes);
}


void Foam::sphereCellOverlap::buildBoundaryTree()
{
    const pointField& pts = mesh_.points();
    DynamicList<label> bFaces;
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(pp))
        {
            forAll(pp, i) bFaces.append(pp.start() + i);
        }
    }
    boundaryFaces_.transfer(bFaces);
    if (boundaryFaces_.size())
    {
        treeBoundBox bb(pts);
        bb.inflate(1e-6);
        boundaryTree_.reset
        (
            new indexedOctree<treeDataFace>
            (
                treeDataFace(true, mesh_, boundaryFaces_),
                bb, 8, 10.0, 3.0
            )
        );
    }
}


Foam::sphereCellOverlap::sphereCellOverlap(const fvMesh& mesh)
:
    mesh_(mesh),
    cellMin_(mesh.nCells()),
    cellMax_(mesh.nCells()),
    isBox_(mesh.nCells(), false),
    cellPlaneStart_(mesh.nCells() + 1, 0),
    faceMin_(mesh.nFaces()),
    faceMax_(mesh.nFaces()),
    facePlanes_(mesh.nFaces()),
    planarFace_(mesh.nFaces(), true),
    emptyDir_(-1),
    thickness_(0),
    queuedAt_(mesh.nCells(), 0),
    walkCount_(0)
{
    measureFaces();
    measureCells();
    buildBoundaryTree();
    markExitFaces();
}


void Foam::sphereCellOverlap::markExitFaces()
{
    // Boundary faces in the plane of an earlier one share its answer: a
    // box or a slab has a handful of planes however many faces. Past
    // maxPlanes distinct planes (jagged processor boundaries) a face counts
    // as an exit without the test, which is safe: it only costs a search.
    const label maxPlanes = 64;
    const pointField& pts = mesh_.points();
    const label nInternal = mesh_.nInternalFaces();
    const scalar tol = 1e-9*boundBox(pts, false).mag();
    exitFace_.setSize(mesh_.nFaces() - nInternal, true);
    DynamicList<facePlane> planes;
    DynamicList<bool> exits;
    for (const label facei : boundaryFaces_)
    {
        bool& exit = exitFace_[facei - nInternal];
        if (!planarFace_[facei]) continue;
        const facePlane& fp = facePlanes_[facei];
        label k = 0;
        for (; k < planes.size(); ++k)
        {
            const facePlane& q = planes[k];
            if
            (
                mag(q.offset - fp.offset) < tol
             && sphereOverlap::dot(q.normal, fp.normal) > 1 - 1e-12
            )
            {
                break;
            }
        }
        if (k == planes.size())
        {
            if (planes.size() == maxPlanes) continue;
            // the whole mesh on the inner (owner's) side of the plane
            bool bounds = true;
            for (const point& p : pts)
            {
                if (fp.offset - sphereOverlap::dot(fp.normal, toVec3(p)) < -tol)
                {
                    bounds = false;
                    break;
                }
            }
            planes.append(fp);
            exits.append(!bounds);
        }
        exit = exits[k];
    }
    // faces on empty patches are never crossed
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp))
        {
            forAll(pp, i) exitFace_[pp.start() + i - nInternal] = false;
        }
    }
}


bool Foam::sphereCellOverlap::reachesBox
(
    const label celli,
    const point& c,
    const scalar R
) const
{
    return boxReached(cellMin_[celli], cellMax_[celli], toVec3(c), R);
}


bool Foam::sphereCellOverlap::holdsSphere
(
    const label celli,
    const point& c,
    const scalar R
) const
{
    return planesCrossed(celli, c, R) == 0;
}


Foam::label Foam::sphereCellOverlap::planesCrossed
(
    const label celli,
    const point& c,
    const scalar R
) const
{
    label n = 0;
    if (emptyDir_ < 0 && isConvex(celli))
    {
        // planar faces, outward planes side by side
        const sphereOverlap::vec3 c3 = toVec3(c);
        for (label k = cellPlaneStart_[celli]; k < cellPlaneStart_[celli + 1]; ++k)
        {
            n += (cellPlanes_[k].inside(c3) < R);
        }
        return n;
    }
    const labelList& own = mesh_.faceOwner();
    for (const label facei : mesh_.cells()[celli])
    {
        scalar s = planeDistance(facei, toVec3(c));
        if (own[facei] != celli) s = -s;
        if (emptyDir_ >= 0 && emptyFace_[facei]) continue;
        if (s < R || !planarFace_[facei]) ++n;
    }
    return n;
}


Foam::scalar Foam::sphereCellOverlap::faceCone
(
    const label facei,
    const sphereOverlap::vec3& c,
    const scalar R
) const
{
    using namespace sphereOverlap;
    const pointField& pts = mesh_.points();
    const face& f = mesh_.faces()[facei];
    const label n = f.size();
    auto pt = [&](std::size_t i) { return toVec3(pts[f[i]]); };
    if (!boxReached(faceMin_[facei], faceMax_[facei], c, R))
    {
        return R*R*R/3.0*polygonSolidAngle(c, pt, n);
    }
    if (planarFace_[facei])
    {
        return polygonCone(c, R, pt, n, facePlanes_[facei].normal);
    }
    // warped: the fan of triangles around the face centre
    const vec3 fc = toVec3(mesh_.faceCentres()[facei]);
    scalar v = 0;
    for (label i = 0; i < n; ++i)
    {
        const vec3 tri[3] = {fc, pt(i), pt(i + 1 == n ? 0 : i + 1)};
        vec3 normal = cross(tri[1] - tri[0], tri[2] - tri[0]);
        const double a = mag(normal);
        if (a == 0) continue;
        normal = (1.0/a)*normal;
        v += polygonCone(c, R, [&](std::size_t k) { return tri[k]; }, 3, normal);
    }
    return v;
}


Foam::scalar Foam::sphereCellOverlap::generalCellVolume
(
    const label celli,
    const sphereOverlap::vec3& c,
    const scalar R
) const
{
    scalar v = 0;
    for (const label facei : mesh_.cells()[celli])
    {
        const scalar sign = (mesh_.faceOwner()[facei] == celli) ? 1 : -1;
        v += sign*faceValue
        (
            facei, doneFaces_, doneValues_,
            [&](const label f) { return faceCone(f, c, R); }
        );
    }
    return v;
}


Foam::scalar Foam::sphereCellOverlap::convexCellVolume
(
    const label celli,
    const sphereOverlap::vec3& c,
    const scalar R
) const
{
    using namespace sphereOverlap;
    const cellPlane* first = cellPlanes_.cdata() + cellPlaneStart_[celli];
    const cellPlane* last = cellPlanes_.cdata() + cellPlaneStart_[celli + 1];
    bool inside = true;
    for (const cellPlane* p = first; p != last; ++p)
    {
        const scalar ds = p->inside(c);
        if (ds <= -R) return 0;
        // on a face plane, inside or not is round-off: the cones decide
        if (std::fabs(ds) < 1e-9*R) return generalCellVolume(celli, c, R);
        inside = inside && ds > 0;
    }
    const pointField& pts = mesh_.points();
    scalar v = inside ? sphereVolume(R) : 0;
    for (const cellPlane* p = first; p != last; ++p)
    {
        const scalar ds = p->inside(c);
        if (ds >= R) continue;
        const scalar cap = faceValue
        (
            p->face, doneCapFaces_, doneCaps_,
            [&](const label f)
            {
                if (!boxReached(faceMin_[f], faceMax_[f], c, R)) return 0.0;
                const face& fp = mesh_.faces()[f];
                return polygonCap
                (
                    c, R, [&](std::size_t i) { return toVec3(pts[fp[i]]); },
                    fp.size(), facePlanes_[f].normal
                );
            }
        );
        v += ds > 0 ? -cap : cap;
    }
    return v;
}


Foam::scalar Foam::sphereCellOverlap::cellVolume
(
    const label celli,
    const point& c,
    const scalar R
) const
{
    if (emptyDir_ >= 0)
    {
        return sectionVolume(celli, c, R);
    }
    if (isBox_[celli])
    {
        return sphereOverlap::ballBoxVolume(toVec3(c), R, cellMin_[celli], cellMax_[celli]);
    }
    if (isConvex(celli))
    {
        return convexCellVolume(celli, toVec3(c), R);
    }
    return generalCellVolume(celli, toVec3(c), R);
}


void Foam::sphereCellOverlap::overlaps
(
    const point& c,
    const scalar R,
    const label centreCell,
    DynamicList<label>& cells,
    DynamicList<scalar>& volumes
) const
{
    doneFaces_.clear();
    doneValues_.clear();
    doneCapFaces_.clear();
    doneCaps_.clear();
    forEachReachedCell
    (
        c, R, centreCell,
        [&](const label celli)
        {
            const scalar v = cellVolume(celli, c, R);
            if (v > 0)
            {
                cells.append(celli);
                volumes.append(v);
            }
            return v > 0;
        }
    );
}


void Foam::sphereCellOverlap::setTwoDimensional(const direction d, const scalar thickness)
{
    emptyDir_ = d;
    thickness_ = thickness;
    emptyFace_.setSize(mesh_.nFaces(), false);
    sectionFace_.setSize(mesh_.nCells(), -1);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(pp)) continue;
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            emptyFace_[facei] = true;
            sectionFace_[mesh_.faceOwner()[facei]] = facei;
        }
    }
}


Foam::scalar Foam::sphereCellOverlap::sectionVolume
(
    const label celli,
    const point& c,
    const scalar R
) const
{
    const direction e1 = (emptyDir_ + 1) % 3, e2 = (emptyDir_ + 2) % 3;
    const pointField& pts = mesh_.points();
    const face& f = mesh_.faces()[sectionFace_[celli]];
    return thickness_*sphereOverlap::diskPolygonArea
    (
        {c[e1], c[e2]},
        R,
        [&](std::size_t i) { return sphereOverlap::vec2{pts[f[i]][e1], pts[f[i]][e2]}; },
        f.size()
    );
}
