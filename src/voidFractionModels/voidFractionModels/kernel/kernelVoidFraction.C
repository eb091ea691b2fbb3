#include "kernelVoidFraction.H"
#include "addToRunTimeSelectionTable.H"
#include "emptyPolyPatch.H"

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
    collectWalls(mesh, coeffs_.lookupOrDefault<bool>("reflectAtWalls", true));
    cellSize_.setSize(mesh.nCells());
    forAll(cellSize_, celli) cellSize_[celli] = cellSize(celli);
    maxCellSize_ = returnReduce(max(cellSize_), maxOp<scalar>());
}


Foam::scalar Foam::voidFractionModels::kernel::imageReach(const scalar) const
{
    return cutoff_*(bandwidth_ > 0 ? bandwidth_ : bandwidthOverCellSize_*maxCellSize_);
}


void Foam::voidFractionModels::kernel::collectWalls(const fvMesh& mesh, const bool reflect)
{
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
}


void Foam::voidFractionModels::kernel::findImages(const point& c, const scalar rc)
{
    images_.clear();
    images_.append(c);
    imageWall_.clear();
    imageWall_.append(-1);
    label nNear = 0;
    forAll(walls_, w)
    {
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
}


void Foam::voidFractionModels::kernel::gridWeights
(
    const label p,
    const point& c,
    const scalar b,
    const scalar rc
)
{
    for (direction d = 0; d < 3; ++d)
    {
        DynamicList<label>& index = index_[d];
        DynamicList<scalar>& factor = factor_[d];
        index.clear();
        factor.clear();
        const scalarList& g = locator_.gridPlanes(d);
        const label n = g.size() - 1;
        for (const point& image : images_)
        {
            // the images that differ from the particle in direction d only
            bool sameElsewhere = true;
            for (direction e = 0; e < 3; ++e)
            {
                if (e != d && image[e] != c[e]) sameElsewhere = false;
            }
            if (!sameElsewhere) continue;
            const scalar xm = image[d];
            const scalar lo = max(xm - rc, g.first());
            if (lo > g.last()) continue;
            for (label i = locator_.interval(d, lo); i >= 0 && i < n; ++i)
            {
                const scalar xc = 0.5*(g[i] + g[i + 1]);
                if (xc > xm + rc) break;
                if (xc < xm - rc) continue;
                const scalar f = exp(-sqr(xc - xm)/sqr(b));
                const label k = index.find(i);
                if (k < 0)
                {
                    index.append(i);
                    factor.append(f);
                }
                else
                {
                    factor[k] += f;
                }
            }
        }
    }

    const label seed = centreCells_[p];
    const label k0 = weights_.size();
    if (seed >= 0) weights_.append(seed, 0);
    const scalarField& V = mesh_.V();
    scalar sum = 0;
    forAll(index_[2], kz)
    {
        forAll(index_[1], ky)
        {
            const scalar fyz = factor_[1][ky]*factor_[2][kz];
            forAll(index_[0], kx)
            {
                const label celli = locator_.gridCell(index_[0][kx], index_[1][ky], index_[2][kz]);
                const scalar w = V[celli]*factor_[0][kx]*fyz;
                sum += w;
                if (celli == seed) weights_.setFraction(k0, w);
                else weights_.append(celli, w);
            }
        }
    }
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
    scalar sum = 0;
    findSeeds(seed, c, sqrt(3.0)*rc);
    overlap_.forEachReachedCell
    (
        c, rc, seeds_,
        [&](const label celli)
        {
            const point& x = C[celli];
            scalar w = 0;
            for (const point& image : images_)
            {
                const vector d = x - image;
                if (mag(d.x()) <= rc && mag(d.y()) <= rc && mag(d.z()) <= rc)
                {
                    w += exp(-magSqr(d)/sqr(b));
                }
            }
            w *= V[celli];
            sum += w;
            if (celli == seed) weights_.setFraction(k0, w);
            else if (w > 0) weights_.append(celli, w);
            return true;
        },
        true
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
        b_[p] = (seed < 0) ? 0
              : (bandwidth_ > 0) ? bandwidth_ : bandwidthOverCellSize_*cellSize_[seed];
    }
    combineOverGroup(b_, maxEqOp<scalar>());

    forAll(x, p)
    {
        sums_[p] = 0;
        if (b_[p] > 0)
        {
            const scalar rc = cutoff_*b_[p];
            findImages(x[p], rc);
            if (locator_.isTensorGrid()) gridWeights(p, x[p], b_[p], rc);
            else walkWeights(p, x[p], b_[p], rc);
        }
        weights_.endParticle();
    }

    // normalise over all ranks and images; a kernel that reaches no cell
    // centre (bandwidth far below the cell size) leaves it in its cell
    combineOverGroup(sums_, plusEqOp<scalar>());
    forAll(x, p)
    {
        if (sums_[p] > 0) weights_.scale(p, 1/sums_[p]);
        else if (centreCells_[p] >= 0) weights_.setFraction(weights_.begin(p), 1);
    }
}
