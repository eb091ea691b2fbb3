/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleCellLocator.H"
#include "boundBox.H"
#include "volFields.H"

#include <algorithm>

namespace
{
    // unique sorted values, merged within tol
    Foam::scalarList uniqueCoordinates(std::vector<double> v, double tol)
    {
        std::sort(v.begin(), v.end());
        Foam::DynamicList<Foam::scalar> u;
        for (double x : v)
        {
            if (u.empty() || x - u.last() > tol) u.append(x);
        }
        return Foam::scalarList(u);
    }

}


bool Foam::particleCellLocator::detectTensorGrid()
{
    const pointField& pts = mesh_.points();
    const cellList& cells = mesh_.cells();
    if (cells.empty()) return false;
    const scalar tol = 1e-9*boundBox(pts).mag();

    for (direction d = 0; d < 3; ++d)
    {
        std::vector<double> v(pts.size());
        forAll(pts, i) v[i] = pts[i][d];
        grid_[d] = uniqueCoordinates(std::move(v), tol);
    }
    const label nx = grid_[0].size() - 1, ny = grid_[1].size() - 1, nz = grid_[2].size() - 1;
    // holes allowed, but not a sparse grid (an index over mostly nothing)
    bool ok = (nx*ny*nz >= cells.size() && nx*ny*nz <= 2*cells.size());
    if (ok)
    {
        ijkCell_.setSize(nx*ny*nz, -1);
        cellIjk_.setSize(3*nx*ny*nz, -1);
        forAll(cells, celli)
        {
            if (cells[celli].size() != 6) { ok = false; break; }
            const boundBox bb(cells[celli].points(mesh_.faces(), pts), false);
            if (mag(bb.volume() - mesh_.V()[celli]) > 1e-9*mesh_.V()[celli])
            {
                ok = false; break;
            }
            const point c = bb.centre();
            const label i = searchInterval(grid_[0], c.x());
            const label j = searchInterval(grid_[1], c.y());
            const label k = searchInterval(grid_[2], c.z());
            // the cell must span exactly one interval in each direction
            if
            (
                mag(bb.min().x() - grid_[0][i]) > tol || mag(bb.max().x() - grid_[0][i+1]) > tol
             || mag(bb.min().y() - grid_[1][j]) > tol || mag(bb.max().y() - grid_[1][j+1]) > tol
             || mag(bb.min().z() - grid_[2][k]) > tol || mag(bb.max().z() - grid_[2][k+1]) > tol
            )
            {
                ok = false; break;
            }
            if (ijkCell_[i + nx*(j + ny*k)] != -1) { ok = false; break; }
            ijkCell_[i + nx*(j + ny*k)] = celli;
            cellIjk_[3*celli] = i;
            cellIjk_[3*celli + 1] = j;
            cellIjk_[3*celli + 2] = k;
        }
    }
    if (!ok)
    {
        ijkCell_.clear();
        cellIjk_.clear();
        for (auto& g : grid_) g.clear();
    }
    else
    {
        holes_ = nx*ny*nz - cells.size();
        for (direction d = 0; d < 3; ++d)
        {
            const scalarList& g = grid_[d];
            const scalar h = (g.last() - g.first())/(g.size() - 1);
            bool uniform = true;
            for (label i = 1; i < g.size(); ++i)
            {
                uniform = uniform && mag(g[i] - g[i - 1] - h) < 1e-9*h;
            }
            invSpacing_[d] = uniform ? 1/h : 0;
            for (label i = 1; i < g.size(); ++i)
            {
                minWidth_ = min(minWidth_, g[i] - g[i - 1]);
            }
        }
    }
    return ok;
}


Foam::particleCellLocator::particleCellLocator(const fvMesh& mesh)
:
    mesh_(mesh),
    holes_(0),
    invSpacing_{0, 0, 0},
    minWidth_(GREAT)
{
    // decomposed cases: a processor's part of a box mesh is a box mesh too
    if (detectTensorGrid())
    {
        Info<< "particleCellLocator: tensor-product mesh "
            << grid_[0].size() - 1 << " x " << grid_[1].size() - 1 << " x "
            << grid_[2].size() - 1;
        if (holes_) Info<< " with " << holes_ << " holes";
        Info<< ", cells found by index arithmetic" << endl;
    }
    // polyMesh::findCell builds the tetrahedra's base points on first use,
    // synchronised over the processors: build them now on every rank (some
    // ranks' cells may be tensor grids and others not), not later on only
    // the ranks with a particle to search for
    (void)mesh_.tetBasePtIs();
}


bool Foam::particleCellLocator::inCell(const point& p, const label celli) const
{
    const cell& c = mesh_.cells()[celli];
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& Sf = mesh_.faceAreas();
    for (const label facei : c)
    {
        const scalar s = ((p - Cf[facei]) & Sf[facei]);
        const bool owner = (mesh_.faceOwner()[facei] == celli);
        if ((owner && s > 0) || (!owner && s < 0)) return false;
    }
    return true;
}


Foam::label Foam::particleCellLocator::walk(const point& p, label celli) const
{
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& Sf = mesh_.faceAreas();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    for (label step = 0; step < 1000; ++step)
    {
        // leave through the face the point is farthest outside of
        label exitFace = -1;
        scalar worst = 0;
        for (const label facei : mesh_.cells()[celli])
        {
            scalar s = ((p - Cf[facei]) & Sf[facei])/mag(Sf[facei]);
            if (own[facei] != celli) s = -s;
            if (s > worst) { worst = s; exitFace = facei; }
        }
        if (exitFace < 0) return celli;
        if (exitFace >= mesh_.nInternalFaces()) return -1;
        celli = (own[exitFace] == celli) ? nei[exitFace] : own[exitFace];
    }
    return -1;
}


Foam::label Foam::particleCellLocator::searchInterval
(
    const scalarList& g,
    const scalar x
)
{
    if (x < g.first() || x > g.last()) return -1;
    const auto it = std::upper_bound(g.begin(), g.end(), x);
    const label i = label(it - g.begin()) - 1;
    return min(i, g.size() - 2);
}


Foam::label Foam::particleCellLocator::findCell
(
    const point& p,
    const label hint
) const
{
    if (isTensorGrid())
    {
        const label i = interval(0, p.x());
        const label j = interval(1, p.y());
        const label k = interval(2, p.z());
        if (i < 0 || j < 0 || k < 0) return -1;
        return gridCell(i, j, k);
    }
    if (hint >= 0)
    {
        const label celli = walk(p, hint);
        if (celli >= 0) return celli;
    }
    return mesh_.findCell(p, polyMesh::CELL_TETS);
}


void Foam::particleCellLocator::findCells
(
    const UList<point>& x,
    labelList& cells
) const
{
    if (!isTensorGrid())
    {
        forAll(x, i) cells[i] = findCell(x[i], cells[i]);
        return;
    }
    const scalar* g[3] = {grid_[0].cdata(), grid_[1].cdata(), grid_[2].cdata()};
    forAll(x, i)
    {
        const label hint = cells[i];
        if (hint >= 0)
        {
            // the half-open intervals interval() finds
            const label* ijk = cellIjk_.cdata() + 3*hint;
            bool in = true;
            for (direction d = 0; d < 3; ++d)
            {
                const scalar c = x[i][d];
                in = in && c >= g[d][ijk[d]] && c < g[d][ijk[d] + 1];
            }
            if (in) continue;
        }
        const label a = interval(0, x[i].x());
        const label b = interval(1, x[i].y());
        const label c = interval(2, x[i].z());
        cells[i] = (a < 0 || b < 0 || c < 0) ? -1 : gridCell(a, b, c);
    }
}


Foam::label Foam::particleCellLocator::planesCrossed
(
    const label centreCell,
    const point& c,
    const scalar R,
    const label skip
) const
{
    label index[3];
    gridIndex(centreCell, index);
    label n = 0;
    for (direction d = 0; d < 3; ++d)
    {
        if (label(d) == skip) continue;
        const scalarList& g = grid_[d];
        n += (c[d] - g[index[d]] < R) + (g[index[d] + 1] - c[d] < R);
    }
    return n;
}


bool Foam::particleCellLocator::piecesFit
(
    const scalar R,
    const bool cut[3],
    const scalar offset[3],
    const FixedList<label, 3> low,
    const FixedList<label, 3> high
) const
{
    for (direction d = 0; d < 3; ++d)
    {
        if (!cut[d]) continue;
        // the piece beyond the plane, offset from the centre, reaches
        // R - |offset| into the cell on its side
        const scalarList& g = grid_[d];
        const label next = (offset[d] <= 0) ? low[d] : high[d];
        if (next >= 0 && R - mag(offset[d]) > g[next + 1] - g[next]) return false;
    }
    return true;
}
