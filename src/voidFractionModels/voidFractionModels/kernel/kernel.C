/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "kernel.H"
#include "smoothingDefaults.H"
#include "addToRunTimeSelectionTable.H"
#include "emptyPolyPatch.H"
#include "expBatch.H"

#include <algorithm>

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(kernel, 0);
    addToRunTimeSelectionTable(voidFractionModel, kernel, dictionary);
}
}

namespace
{
// Uniform planes g (1/spacing inv): the first cell and the number of cells
// whose centres, at g0 + (k + 1/2) h, lie within rc of x; by arithmetic,
// widened by round-off (the ball test of ballRows is the exact one)
inline Foam::label uniformWindow
(
    const Foam::scalarList& g,
    const Foam::scalar inv,
    const Foam::scalar x,
    const Foam::scalar rc,
    Foam::label& first
)
{
    const Foam::scalar lo = (x - rc - g.first())*inv - 0.5 - 1e-9;
    const Foam::scalar hi = (x + rc - g.first())*inv - 0.5 + 1e-9;
    first = (lo <= 0) ? 0 : Foam::label(lo) + 1;
    const Foam::label end = (hi < 0) ? 0 : Foam::min(Foam::label(hi) + 1, g.size() - 1);
    return Foam::max(end - first, Foam::label(0));
}

// Tensor grids: the cells of the windows (first index and size per
// direction) inside the ball of radius sqrt(rc2), from the factors and
// squared distances per direction, written from cells and fractions on;
// their number returned, their weights added to sum. Inlined into both
// callers: the compiler then sees the arrays are not the rows. NX, NY, NZ:
// the window sizes when fixed at compile time (0: n).
template<int NX = 0, int NY = 0, int NZ = 0>
inline Foam::label ballRows
(
    const Foam::particleCellLocator& locator,
    const Foam::label first[3],
    const Foam::label n[3],
    const Foam::scalar* fx, const Foam::scalar* fy, const Foam::scalar* fz,
    const Foam::scalar* dx, const Foam::scalar* dy, const Foam::scalar* dz,
    const Foam::scalar rc2,
    Foam::label* cells,
    Foam::scalar* fractions,
    Foam::scalar& sum
)
{
    Foam::label m = 0;
    for (Foam::label kz = 0; kz < (NZ ? NZ : n[2]); ++kz)
    {
        for (Foam::label ky = 0; ky < (NY ? NY : n[1]); ++ky)
        {
            // every cell of the row is written and only those in the ball
            // are kept, and their weights added as a product (a choice
            // compiled to a branch): no branch on the data, whose outcome
            // the branch predictor cannot know
            const Foam::scalar left = rc2 - (dy[ky] + dz[kz]);
            const Foam::scalar fyz = fy[ky]*fz[kz];
            const Foam::label* row = locator.gridRow(first[0], first[1] + ky, first[2] + kz);
            for (Foam::label kx = 0; kx < (NX ? NX : n[0]); ++kx)
            {
                const Foam::scalar f = fx[kx]*fyz;
                const bool inside = dx[kx] <= left;
                cells[m] = row[kx];
                fractions[m] = f;
                sum += f*Foam::scalar(inside);
                m += inside;
            }
        }
    }
    return m;
}
}



Foam::voidFractionModels::kernel::kernel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    sphereWalkVoidFraction(modelType, dict, mesh),
    bandwidth_(0),
    bandwidthOverCellSize_(0),
    cutoff_(positiveCoeff("cutoff", 3)),
    uniform_(false),
    factorised_(false)
{
    if (coeffs().found("bandwidth") && coeffs().found("bandwidthOverCellSize"))
    {
        FatalIOErrorInFunction(coeffs())
            << "give bandwidth or bandwidthOverCellSize in " << coeffs().name()
            << ", not both" << exit(FatalIOError);
    }
    if (coeffs().found("bandwidth"))
    {
        bandwidth_ = positiveCoeff("bandwidth");
    }
    else
    {
        bandwidthOverCellSize_ =
            positiveCoeff
            (
                "bandwidthOverCellSize",
                smoothingDefaults::kernelBandwidthOverCellSize()
            );
    }
    cellSize_.setSize(mesh.nCells());
    forAll(cellSize_, celli) cellSize_[celli] = cellSize(celli);
    maxCellSize_ = returnReduce(max(cellSize_), maxOp<scalar>());
    collectWalls(mesh, coeffs().lookupOrDefault<bool>("reflectAtWalls", true));
    uniform_ = locator().isTensorGrid()
     && locator().invSpacing(0) > 0 && locator().invSpacing(1) > 0 && locator().invSpacing(2) > 0;
    // 4 cutoff^2 within prepareBlock's clamp
    factorised_ = uniform_ && cutoff_ <= 6;
    if (uniform_)
    {
        for (direction d = 0; d < 3; ++d) spacing_[d] = 1/locator().invSpacing(d);
    }
    if (locator().isTensorGrid())
    {
        for (direction d = 0; d < 3; ++d)
        {
            // three cells more beyond the last: a fixed window of four
            // reads them (and never uses them) without a bound check
            const scalarList& g = locator().gridPlanes(d);
            const label nCells = g.size() - 1;
            gridCentres_[d].setSize(nCells + 3);
            gridWidths_[d].setSize(nCells + 3);
            forAll(gridCentres_[d], i)
            {
                const scalar lo = i < nCells ? g[i] : g.last() + (i - nCells)*(g[nCells] - g[nCells - 1]);
                const scalar hi = i < nCells ? g[i + 1] : lo + (g[nCells] - g[nCells - 1]);
                gridCentres_[d][i] = 0.5*(lo + hi);
                gridWidths_[d][i] = hi - lo;
            }
        }
    }
}


Foam::scalar Foam::voidFractionModels::kernel::reach(const scalar) const
{
    return cutoff_*(bandwidth_ > 0 ? bandwidth_ : bandwidthOverCellSize_*maxCellSize_);
}


void Foam::voidFractionModels::kernel::collectWallPlanes
(
    const fvMesh& mesh,
    List<vector>& wallNormals,
    List<scalar>& wallOffsets
)
{
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    const scalar tol = 1e-9*mesh.bounds().mag();

    DynamicList<vector> normals;
    DynamicList<scalar> offsets;
    auto add = [&](const vector& n, const scalar offset)
    {
        forAll(normals, i)
        {
            if (mag(normals[i] - n) < 1e-9 && mag(offsets[i] - offset) < tol) return;
        }
        normals.append(n);
        offsets.append(offset);
    };
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (pp.coupled() || isA<emptyPolyPatch>(pp)) continue;
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const vector n = Sf[facei]/mag(Sf[facei]);
            add(n, n & Cf[facei]);
        }
    }

    // every rank needs every wall: a kernel may reach beyond its own cells
    List<List<vector>> allNormals(Pstream::nProcs());
    List<List<scalar>> allOffsets(Pstream::nProcs());
    allNormals[Pstream::myProcNo()] = normals;
    allOffsets[Pstream::myProcNo()] = offsets;
    Pstream::gatherList(allNormals);
    Pstream::scatterList(allNormals);
    Pstream::gatherList(allOffsets);
    Pstream::scatterList(allOffsets);
    normals.clear();
    offsets.clear();
    forAll(allNormals, proci)
    {
        forAll(allNormals[proci], i) add(allNormals[proci][i], allOffsets[proci][i]);
    }
    // one order on every decomposition: mirror images across two walls
    // that are not orthogonal depend on the order of the mirrors
    labelList order(identity(normals.size()));
    std::sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b)
        {
            for (direction d = 0; d < 3; ++d)
            {
                if (mag(normals[a][d] - normals[b][d]) > 1e-9) return normals[a][d] < normals[b][d];
            }
            return offsets[a] < offsets[b];
        }
    );

    wallNormals.setSize(order.size());
    wallOffsets.setSize(order.size());
    forAll(order, i)
    {
        wallNormals[i] = normals[order[i]];
        wallOffsets[i] = offsets[order[i]];
    }
}


void Foam::voidFractionModels::kernel::collectWalls(const fvMesh& mesh, const bool reflect)
{
    // no wall: no particle has images
    nearWalls_.setSize(mesh.nCells(), 0);
    if (!reflect) return;
    List<vector> normals;
    List<scalar> offsets;
    collectWallPlanes(mesh, normals, offsets);
    if (normals.size() > 64)
    {
        WarningInFunction
            << "the walls form " << normals.size() << " planes (curved walls):"
            << " the kernel is normalised there but not reflected" << endl;
        return;
    }
    walls_.setSize(normals.size());
    forAll(walls_, i)
    {
        const vector& n = normals[i];
        label axis = -1;
        for (direction d = 0; d < 3; ++d)
        {
            if (mag(n[(d + 1) % 3]) < 1e-9 && mag(n[(d + 2) % 3]) < 1e-9) axis = d;
        }
        walls_[i] = wallPlane{n, offsets[i], axis};
    }

    markCellsNearWalls(mesh);
}


void Foam::voidFractionModels::kernel::markCellsNearWalls(const fvMesh& mesh)
{
    const pointField& points = mesh.points();
    const labelListList& cellPoints = mesh.cellPoints();
    forAll(nearWalls_, celli)
    {
        const scalar rc = cellReach(celli);
        forAll(walls_, w)
        {
            const wallPlane& P = walls_[w];
            scalar clearance = GREAT;
            for (const label pointi : cellPoints[celli])
            {
                clearance = min(clearance, P.offset - (P.normal & points[pointi]));
            }
            if (clearance < rc) nearWalls_[celli] |= uint64_t(1) << w;
        }
    }
}


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


inline void Foam::voidFractionModels::kernel::findMirrors
(
    const point& c,
    const label celli,
    const scalar rc
)
{
    // the images that differ from the particle in one direction: those
    // across a wall normal to it (a corner's images are the products)
    nMirrors_ = 0;
    forEachNearWall
    (
        c, celli, rc,
        [&](const wallPlane& P, const label)
        {
            const label d = P.axis;
            if (d < 0 || nMirrors_[d] == 2) return;
            mirrors_[d][nMirrors_[d]++] = c[d] - 2*(P.normal[d]*c[d] - P.offset)*P.normal[d];
        }
    );
}


Foam::label Foam::voidFractionModels::kernel::axisWindow
(
    const direction d,
    const scalar x,
    const scalar rc
)
{
    const scalarList& g = locator().gridPlanes(d);
    if (x + rc < g.first() || x - rc > g.last())
    {
        firstIndex_[d] = 0;
        return 0;
    }
    const scalar inv = locator().invSpacing(d);
    if (inv > 0) return uniformWindow(g, inv, x, rc, firstIndex_[d]);

    // the intervals holding the ends of the reach, then the centres
    const scalarList& xc = gridCentres_[d];
    const scalar from = max(x - rc, g.first());
    const scalar to = min(x + rc, g.last());
    label first = locator().interval(d, from);
    first += (xc[first] < from);
    label end = locator().interval(d, to) + 1;
    end -= (xc[end - 1] > to);
    firstIndex_[d] = first;
    return max(end - first, label(0));
}


void Foam::voidFractionModels::kernel::axisFactors(const scalar x[3], const scalar b, const scalar rc)
{
    label n[3];
    label total = 0;
    for (direction d = 0; d < 3; ++d)
    {
        n[d] = axisWindow(d, x[d], rc);
        total += n[d]*(1 + nMirrors_[d]);
    }
    const scalar invB2 = 1/sqr(b);

    // all Gaussians of the particle in one call, padded to whole vectors
    // of four: the values are few, so only together do they fill them
    exponents_.setSize((total + 3)/4*4);
    scalar* e = exponents_.data();
    for (direction d = 0; d < 3; ++d)
    {
        distSqr_[d].setSize(n[d]);
        scalar* dd = distSqr_[d].data();
        const scalar* xi = gridCentres_[d].cdata() + firstIndex_[d];
        const FixedList<scalar, 2>& m = mirrors_[d];
        for (label k = 0; k < n[d]; ++k)
        {
            dd[k] = sqr(xi[k] - x[d]);
            *e++ = -dd[k]*invB2;
            for (label j = 0; j < nMirrors_[d]; ++j) *e++ = -sqr(xi[k] - m[j])*invB2;
        }
    }
    for (label i = total; i < exponents_.size(); ++i) *e++ = 0;
    expBatch::expNonPositive(exponents_.cdata(), exponents_.data(), exponents_.size());

    const scalar* gauss = exponents_.cdata();
    for (direction d = 0; d < 3; ++d)
    {
        factor_[d].setSize(n[d]);
        scalar* f = factor_[d].data();
        const scalar* h = gridWidths_[d].cdata() + firstIndex_[d];
        for (label k = 0; k < n[d]; ++k)
        {
            scalar sum = *gauss++;
            for (label j = 0; j < nMirrors_[d]; ++j) sum += *gauss++;
            f[k] = h[k]*sum;
        }
    }
}


inline void Foam::voidFractionModels::kernel::finishRow
(
    const label p,
    const label k0,
    const label m,
    const scalar sum
)
{
    // nothing positive here: the row is the centre cell alone, where the
    // fallback of distribute finds it
    rows().truncateEntries(sum > 0 ? k0 + m : k0);
    if (sum == 0 && centreCells()[p] >= 0) rows().append(centreCells()[p], 0);
    sums_[p] = sum;
}


void Foam::voidFractionModels::kernel::prepareBlock
(
    const UList<point>& x,
    const label p0,
    const label p1,
    const bool relative
)
{
    // the windows of a block of particles and the arguments of all their
    // exponentials, which then run in one batch: a particle's few values
    // alone would leave the batch waiting on its latency; room for every
    // particle's twelve Gaussians and three mirrors' twelve
    block_.setSize(p1 - p0);
    blockArgs_.setSize(24*(p1 - p0));
    scalar* const args = blockArgs_.data();
    label nArgs = 0;
    for (label p = p0; p < p1; ++p)
    {
        windowEntry& W = block_[p - p0];
        W.fixed = false;
        if (b_[p] <= 0) continue;
        const point& c = x[p];
        const scalar rc = cutoff_*b_[p];
        const scalar invB2 = 1/sqr(b_[p]);
        findMirrors(c, centreCells()[p], rc);
        const scalar* xc[3];
        bool fits = true;
        for (direction d = 0; d < 3; ++d)
        {
            const scalarList& g = locator().gridPlanes(d);
            W.n[d] = uniformWindow(g, locator().invSpacing(d), c[d], rc, W.first[d]);
            fits = fits && W.n[d] <= 4;
            // an empty window beyond the grid: read its last cell and the
            // three padded ones after it, never past them
            W.first[d] = min(W.first[d], g.size() - 2);
            xc[d] = gridCentres_[d].cdata() + W.first[d];
            for (label k = 0; k < 4; ++k) W.dist[4*d + k] = sqr(xc[d][k] - c[d]);
            W.nMirrors[d] = nMirrors_[d];
        }
        if (!fits) continue;
        W.fixed = true;
        W.factorised =
            factorised_ && relative && !(nMirrors_[0] || nMirrors_[1] || nMirrors_[2]);
        W.rc = rc;
        W.arg = nArgs;
        if (W.factorised)
        {
            // exp(-(d0 + k h)^2/b^2) = exp(-d0^2/b^2) R^k C^(k^2), d0 the
            // first centre's offset, R = exp(-2 d0 h/b^2), C = exp(-h^2/b^2):
            // the first factor is every cell's and cancels in the
            // normalisation of a whole particle (where ranks or images
            // share one, their windows' first cells differ)
            for (direction d = 0; d < 3; ++d)
            {
                args[nArgs++] = -2*(xc[d][0] - c[d])*spacing_[d]*invB2;
                args[nArgs++] = -sqr(spacing_[d])*invB2;
            }
            continue;
        }
        for (direction d = 0; d < 3; ++d)
        {
            for (label k = 0; k < 4; ++k) args[nArgs++] = -W.dist[4*d + k]*invB2;
            for (label j = 0; j < nMirrors_[d]; ++j)
            {
                for (label k = 0; k < 4; ++k)
                {
                    args[nArgs++] = -sqr(xc[d][k] - mirrors_[d][j])*invB2;
                }
            }
        }
    }
    // the clamp keeps the factorised products of the cells beyond a window
    // finite; those in it need at most exp(4 cutoff^2), as a window of two
    // or more cells is at most 2 cutoff b wide; a direct Gaussian clamped
    // at exp(-150) adds nothing next to its particle's own, at least
    // exp(-cutoff^2) in a cell it keeps
    expBatch::expClamped(args, args, nArgs, factorised_ ? 150 : 700);
}


bool Foam::voidFractionModels::kernel::blockRows(const label p, const label p0)
{
    const windowEntry& W = block_[p - p0];
    if (!W.fixed) return false;

    // four cells per direction whatever the window holds: fixed loops over
    // local arrays; the cells beyond a shorter window are never read
    scalar e[12];
    const scalar* a = blockArgs_.cdata() + W.arg;
    for (direction d = 0; d < 3; ++d)
    {
        scalar* f = e + 4*d;
        if (W.factorised)
        {
            // the cells' volume, the same in every cell of uniform planes,
            // cancels in the normalisation like the first cell's Gaussian
            const scalar RC = a[2*d]*a[2*d + 1];
            const scalar C2 = sqr(a[2*d + 1]);
            f[0] = 1;
            f[1] = RC;
            f[2] = RC*RC*C2;
            f[3] = f[2]*RC*sqr(C2);
            continue;
        }
        for (label k = 0; k < 4; ++k) f[k] = a[k];
        a += 4;
        for (label j = 0; j < W.nMirrors[d]; ++j, a += 4)
        {
            for (label k = 0; k < 4; ++k) f[k] += a[k];
        }
        // each cell's own width: the planes are uniform to round-off only
        const scalar* h = gridWidths_[d].cdata() + W.first[d];
        for (label k = 0; k < 4; ++k) f[k] *= h[k];
    }

    const label k0 = rows().extend(W.n[0]*W.n[1]*W.n[2]);
    scalar sum = 0;
    label* cells = rows().cellsData() + k0;
    scalar* fractions = rows().fractionsData() + k0;
    const scalar* dist = W.dist;
    const scalar rc2 = sqr(W.rc);

    // windows of two or three cells per direction (those of the default
    // bandwidth) in loops of fixed length: one choice among eight instead
    // of a loop end per row, which the branch predictor cannot know
    #define ROWS(NX, NY, NZ)                                                 \
        ballRows<NX, NY, NZ>                                                 \
        (                                                                    \
            locator(), W.first, W.n, e, e + 4, e + 8,                         \
            dist, dist + 4, dist + 8, rc2, cells, fractions, sum             \
        )
    const unsigned twos = (W.n[0] == 2) | (W.n[1] == 2) << 1 | (W.n[2] == 2) << 2;
    const unsigned threes = (W.n[0] == 3) | (W.n[1] == 3) << 1 | (W.n[2] == 3) << 2;
    label m = 0;
    if ((twos | threes) != 7) m = ROWS(0, 0, 0);
    else switch (twos)
    {
        case 0: m = ROWS(3, 3, 3); break;
        case 1: m = ROWS(2, 3, 3); break;
        case 2: m = ROWS(3, 2, 3); break;
        case 3: m = ROWS(2, 2, 3); break;
        case 4: m = ROWS(3, 3, 2); break;
        case 5: m = ROWS(2, 3, 2); break;
        case 6: m = ROWS(3, 2, 2); break;
        default: m = ROWS(2, 2, 2); break;
    }
    #undef ROWS
    finishRow(p, k0, m, sum);
    return true;
}


void Foam::voidFractionModels::kernel::gridWeights
(
    const label p,
    const point& c,
    const scalar b,
    const scalar rc
)
{
    const scalar x[3] = {c.x(), c.y(), c.z()};
    axisFactors(x, b, rc);
    const label n[3] = {factor_[0].size(), factor_[1].size(), factor_[2].size()};
    const label first[3] = {firstIndex_[0], firstIndex_[1], firstIndex_[2]};

    // room for the whole box of cells; the ball keeps about half of it
    const label k0 = rows().extend(n[0]*n[1]*n[2]);
    scalar sum = 0;
    const label m = ballRows<>
    (
        locator(), first, n,
        factor_[0].cdata(), factor_[1].cdata(), factor_[2].cdata(),
        distSqr_[0].cdata(), distSqr_[1].cdata(), distSqr_[2].cdata(), sqr(rc),
        rows().cellsData() + k0, rows().fractionsData() + k0, sum
    );
    finishRow(p, k0, m, sum);
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
                w += exp(-magSqr(x - mirror)*invB2);
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


void Foam::voidFractionModels::kernel::distribute
(
    const UList<point>& x,
    const UList<scalar>& r
)
{
    const label n = x.size();

    // the rank holding the centre sets the bandwidth for all
    b_.setSize(n);
    sums_.setSize(n);
    forAll(x, p)
    {
        const label seed = centreCells()[p];
        b_[p] = (seed < 0) ? 0 : cellBandwidth(seed);
    }
    combineOverGroup(b_, maxEqOp<scalar>());

    // a kernel that reaches no cell centre (bandwidth far below the cell
    // size) leaves the particle in its cell
    auto normalise = [&](const label p, const bool spreadNow)
    {
        scalar s = 1;
        if (sums_[p] > 0) s = 1/sums_[p];
        else if (centreCells()[p] >= 0) rows().setFraction(rows().begin(p), 1);
        if (spreadNow) spreadRow(p, s);
        else if (sums_[p] > 0) rows().scale(p, s);
    };

    // whole particles are normalised (and spread, where allowed) while
    // their row is in cache; otherwise over all ranks and images once all
    // rows are made
    const bool whole = entriesAreWhole(n);
    const bool spread = spreadsRows(n);
    const label blockSize = 64;
    for (label p0 = 0; p0 < n; p0 += blockSize)
    {
        const label p1 = min(p0 + blockSize, n);
        if (uniform_) prepareBlock(x, p0, p1, whole);
        for (label p = p0; p < p1; ++p)
        {
            sums_[p] = 0;
            if (b_[p] > 0 && !(uniform_ && blockRows(p, p0)))
            {
                const scalar rc = cutoff_*b_[p];
                if (locator().isTensorGrid()) findMirrors(x[p], centreCells()[p], rc);
                else findWallMirrors(x[p], centreCells()[p], rc);
                if (locator().isTensorGrid()) gridWeights(p, x[p], b_[p], rc);
                else walkWeights(p, x[p], b_[p], rc);
            }
            rows().endParticle();
            if (whole) normalise(p, spread);
        }
    }
    if (!whole)
    {
        combineOverGroup(sums_, plusEqOp<scalar>());
        forAll(x, p) normalise(p, false);
    }
}
