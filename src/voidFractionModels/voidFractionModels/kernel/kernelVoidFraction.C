#include "kernelVoidFraction.H"
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
    cutoff_(positiveCoeff("cutoff", 3))
{
    if (coeffs_.found("bandwidth") && coeffs_.found("bandwidthOverCellSize"))
    {
        FatalIOErrorInFunction(coeffs_)
            << "give bandwidth or bandwidthOverCellSize in " << coeffs_.name()
            << ", not both" << exit(FatalIOError);
    }
    if (coeffs_.found("bandwidth"))
    {
        bandwidth_ = positiveCoeff("bandwidth");
    }
    else
    {
        bandwidthOverCellSize_ =
            positiveCoeff("bandwidthOverCellSize", 0.4);
    }
    cellSize_.setSize(mesh.nCells());
    forAll(cellSize_, celli) cellSize_[celli] = cellSize(celli);
    maxCellSize_ = returnReduce(max(cellSize_), maxOp<scalar>());
    collectWalls(mesh, coeffs_.lookupOrDefault<bool>("reflectAtWalls", true));
    if (locator_.isTensorGrid())
    {
        for (direction d = 0; d < 3; ++d)
        {
            const scalarList& g = locator_.gridPlanes(d);
            gridCentres_[d].setSize(g.size() - 1);
            gridWidths_[d].setSize(g.size() - 1);
            forAll(gridCentres_[d], i)
            {
                gridCentres_[d][i] = 0.5*(g[i] + g[i + 1]);
                gridWidths_[d][i] = g[i + 1] - g[i];
            }
        }
    }
}


Foam::scalar Foam::voidFractionModels::kernel::imageReach(const scalar) const
{
    return cutoff_*(bandwidth_ > 0 ? bandwidth_ : bandwidthOverCellSize_*maxCellSize_);
}


void Foam::voidFractionModels::kernel::collectWalls(const fvMesh& mesh, const bool reflect)
{
    // no wall: no particle has images
    nearWalls_.setSize(mesh.nCells(), 0);
    if (!reflect) return;
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

    if (normals.size() > 64)
    {
        WarningInFunction
            << "the walls form " << normals.size() << " planes (curved walls):"
            << " the kernel is normalised there but not reflected" << endl;
        return;
    }
    walls_.setSize(normals.size());
    forAll(walls_, i) walls_[i] = wallPlane{normals[order[i]], offsets[order[i]]};

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


void Foam::voidFractionModels::kernel::findImages
(
    const point& c,
    const label celli,
    const scalar rc
)
{
    images_.clear();
    images_.append(c);
    imageWall_.clear();
    imageWall_.append(-1);
    nMirrors_ = 0;
    // a centre in this mesh: only the walls its cell's kernel may reach
    const uint64_t candidates =
        (celli >= 0 && rc <= cellReach(celli)) ? nearWalls_[celli] : ~uint64_t(0);
    if (!candidates) return;
    label nNear = 0;
    forAll(walls_, w)
    {
        if (!((candidates >> w) & 1)) continue;
        const wallPlane& P = walls_[w];
        const scalar d = P.offset - (P.normal & c);
        if (d < 0 || d >= rc || nNear == 3) continue;
        ++nNear;
        const label m = images_.size();
        for (label i = 0; i < m; ++i)
        {
            // no image of an image across the opposite wall of a slab
            if (imageWall_[i] >= 0 && (walls_[imageWall_[i]].normal & P.normal) < -0.5) continue;
            const point x = images_[i];
            images_.append(x - 2*((P.normal & x) - P.offset)*P.normal);
            imageWall_.append(w);
        }
    }
    for (label i = 1; i < images_.size(); ++i)
    {
        const vector shift = images_[i] - c;
        for (direction d = 0; d < 3; ++d)
        {
            if
            (
                shift[(d + 1) % 3] == 0 && shift[(d + 2) % 3] == 0
             && nMirrors_[d] < 2
            )
            {
                mirrors_[d][nMirrors_[d]++] = images_[i][d];
            }
        }
    }
}


Foam::label Foam::voidFractionModels::kernel::axisWindow
(
    const direction d,
    const scalar x,
    const scalar rc
)
{
    const scalarList& g = locator_.gridPlanes(d);
    const label nCells = g.size() - 1;
    if (x + rc < g.first() || x - rc > g.last())
    {
        firstIndex_[d] = 0;
        return 0;
    }
    label first, end;
    const scalar inv = locator_.invSpacing(d);
    if (inv > 0)
    {
        // centre k at g0 + (k + 1/2) h: the window by arithmetic, widened
        // by round-off; the ball test of gridWeights is the exact one
        const scalar lo = (x - rc - g.first())*inv - 0.5 - 1e-9;
        const scalar hi = (x + rc - g.first())*inv - 0.5 + 1e-9;
        first = (lo <= 0) ? 0 : label(lo) + 1;
        end = (hi < 0) ? 0 : min(label(hi) + 1, nCells);
    }
    else
    {
        // the intervals holding the ends of the reach, then the centres
        const scalarList& xc = gridCentres_[d];
        const scalar from = max(x - rc, g.first());
        const scalar to = min(x + rc, g.last());
        first = locator_.interval(d, from);
        first += (xc[first] < from);
        end = locator_.interval(d, to) + 1;
        end -= (xc[end - 1] > to);
    }
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
    const scalarList& fx = factor_[0];
    const scalarList& fy = factor_[1];
    const scalarList& fz = factor_[2];
    const scalarList& dx = distSqr_[0];
    const scalarList& dy = distSqr_[1];
    const scalarList& dz = distSqr_[2];

    // room for the whole box of cells; the ball keeps about half of it
    const label k0 = weights_.extend(fx.size()*fy.size()*fz.size());
    label* cells = weights_.cellsData() + k0;
    scalar* fractions = weights_.fractionsData() + k0;
    const scalar rc2 = sqr(rc);
    scalar sum = 0;
    label n = 0;
    forAll(fz, kz)
    {
        forAll(fy, ky)
        {
            // the squared distances along x fall, then rise: the cells in
            // the ball are one run [lo, hi) of the row
            const scalar left = rc2 - (dy[ky] + dz[kz]);
            label lo = 0, hi = dx.size();
            while (lo < hi && dx[lo] > left) ++lo;
            while (hi > lo && dx[hi - 1] > left) --hi;
            if (lo == hi) continue;
            const scalar fyz = fy[ky]*fz[kz];
            const label* row = locator_.gridRow
            (
                firstIndex_[0], firstIndex_[1] + ky, firstIndex_[2] + kz
            );
            for (label kx = lo; kx < hi; ++kx)
            {
                cells[n] = row[kx];
                fractions[n] = fx[kx]*fyz;
                sum += fractions[n++];
            }
        }
    }

    // nothing positive here: the row is the centre cell alone, where the
    // fallback of distribute finds it
    weights_.truncateEntries(sum > 0 ? k0 + n : k0);
    if (sum == 0 && centreCells_[p] >= 0) weights_.append(centreCells_[p], 0);
    sums_[p] = sum;
}


void Foam::voidFractionModels::kernel::walkWeights
(
    const label p,
    const point& c,
    const scalar b,
    const scalar rc
)
{
    const label seed = centreCells_[p];
    const label k0 = weights_.size();
    if (seed >= 0) weights_.append(seed, 0);
    const scalarField& V = mesh_.V();
    const vectorField& C = mesh_.C();
    const scalar rc2 = sqr(rc);
    const scalar invB2 = 1/sqr(b);
    scalar sum = 0;
    findSeeds(seed, c, rc);
    overlap_.forEachReachedCell
    (
        c, rc, seeds_,
        [&](const label celli)
        {
            const point& x = C[celli];
            if (magSqr(x - c) > rc2) return true;
            scalar w = 0;
            for (const point& image : images_)
            {
                w += exp(-magSqr(x - image)*invB2);
            }
            w *= V[celli];
            sum += w;
            if (celli == seed) weights_.setFraction(k0, w);
            else weights_.append(celli, w);
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
        const label seed = centreCells_[p];
        b_[p] = (seed < 0) ? 0 : cellBandwidth(seed);
    }
    combineOverGroup(b_, maxEqOp<scalar>());

    // a kernel that reaches no cell centre (bandwidth far below the cell
    // size) leaves the particle in its cell
    auto normalise = [&](const label p)
    {
        if (sums_[p] > 0) weights_.scale(p, 1/sums_[p]);
        else if (centreCells_[p] >= 0) weights_.setFraction(weights_.begin(p), 1);
    };

    // whole particles are normalised while their row is in cache;
    // otherwise over all ranks and images once all rows are made
    const bool whole = entriesAreWhole(n);
    forAll(x, p)
    {
        sums_[p] = 0;
        if (b_[p] > 0)
        {
            const scalar rc = cutoff_*b_[p];
            findImages(x[p], centreCells_[p], rc);
            if (locator_.isTensorGrid()) gridWeights(p, x[p], b_[p], rc);
            else walkWeights(p, x[p], b_[p], rc);
        }
        weights_.endParticle();
        if (whole) normalise(p);
    }
    if (!whole)
    {
        combineOverGroup(sums_, plusEqOp<scalar>());
        forAll(x, p) normalise(p);
    }
}
