#include "voidFractionModel.H"
#include "mathematicalConstants.H"
#include "zeroGradientFvPatchFields.H"
#include "processorCyclicPolyPatch.H"
#include "syncTools.H"
#include "cyclicPolyPatch.H"

#include <algorithm>

namespace Foam
{
    defineTypeNameAndDebug(voidFractionModel, 0);
    defineRunTimeSelectionTable(voidFractionModel, dictionary);
}


Foam::voidFractionModel::voidFractionModel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    coeffs_(dict.subOrEmptyDict(modelType + "Coeffs")),
    alphaMin_(dict.lookupOrDefault<scalar>("alphaMin", 0.1)),
    locator_(mesh),
    twoD_(dict.lookupOrDefault<bool>("twoDimensional", false)),
    emptyDir_(0),
    slabMid_(0),
    thickness_(0),
    globalBounds_(mesh.bounds()),
    nParticles_(0),
    solid_(mesh.nCells(), 0),
    voidFraction_
    (
        IOobject
        (
            "voidfraction",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        zeroGradientFvPatchScalarField::typeName
    )
{
    if (!(alphaMin_ >= 0 && alphaMin_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "alphaMin must lie in [0, 1), got " << alphaMin_
            << exit(FatalIOError);
    }
    if (twoD_)
    {
        if (mesh.nSolutionD() != 2)
        {
            FatalIOErrorInFunction(dict)
                << "twoDimensional is set but the mesh solves in "
                << mesh.nSolutionD() << " directions: it must be one cell thick"
                << " with empty patches front and back" << exit(FatalIOError);
        }
        for (direction d = 0; d < 3; ++d)
        {
            if (mesh.solutionD()[d] == -1) emptyDir_ = d;
        }
        const boundBox& bb = mesh.bounds();
        thickness_ = bb.span()[emptyDir_];
        slabMid_ = 0.5*(bb.min()[emptyDir_] + bb.max()[emptyDir_]);
        Info<< "voidFractionModel: 2D, particles are disks through the slab of thickness "
            << thickness_ << " m normal to " << vector::componentNames[emptyDir_] << endl;
    }
    collectPeriodicShifts();
}


void Foam::voidFractionModel::collectPeriodicShifts()
{
    // the face paired with each face of a cyclic or processorCyclic patch
    // (its centre, untransformed): the translation to the other side
    const label nInternal = mesh_.nInternalFaces();
    const vectorField& Cf = mesh_.faceCentres();
    List<vector> other(mesh_.nFaces() - nInternal);
    forAll(other, i) other[i] = Cf[nInternal + i];
    syncTools::swapBoundaryFaceList(mesh_, other);

    const scalar tol = 1e-9*globalBounds_.mag();
    DynamicList<vector> directions;
    auto addDirection = [&](const vector& t)
    {
        if (mag(t) < tol) return;
        for (const vector& d : directions)
        {
            if (mag(d - t) < tol || mag(d + t) < tol) return;
        }
        directions.append(t);
    };
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if ((isA<cyclicPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp)) && pp.size())
        {
            addDirection(other[pp.start() - nInternal] - Cf[pp.start()]);
        }
    }
    List<List<vector>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = directions;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    directions.clear();
    for (const List<vector>& dirs : all)
    {
        for (const vector& t : dirs) addDirection(t);
    }
    // the same order on every decomposition (only round-off depends on it)
    std::sort
    (
        directions.begin(), directions.end(),
        [&](const vector& a, const vector& b)
        {
            const direction da = findMax(cmptMag(a)), db = findMax(cmptMag(b));
            return da < db;
        }
    );

    // every combination: a particle by an edge or a corner of a periodic
    // box has images across one, two or three sides
    DynamicList<vector> shifts;
    const label K = directions.size();
    label nComb = 1;
    for (label k = 0; k < K; ++k) nComb *= 3;
    for (label comb = 0; comb < nComb; ++comb)
    {
        vector S(Zero);
        for (label k = 0, c = comb; k < K; ++k, c /= 3)
        {
            S += scalar((c % 3) - 1)*directions[k];
        }
        if (mag(S) > tol) shifts.append(S);
    }
    periodicShifts_.transfer(shifts);
    if (periodicShifts_.size())
    {
        Info<< "voidFractionModel: periodic translations " << directions
            << ": particles by a cyclic patch get periodic images" << endl;
    }
}


void Foam::voidFractionModel::makeImages
(
    const UList<point>& x,
    const scalarField& r
)
{
    const label n = x.size();
    nParticles_ = n;
    entries_.clear();
    entryRadii_.clear();
    parent_.clear();
    shift_.clear();
    forAll(x, p)
    {
        entries_.append(x[p]);
        entryRadii_.append(r[p]);
        parent_.append(p);
        shift_.append(Zero);
    }
    imageOffsets_.setSize(n + 1);
    imageOffsets_[0] = 0;
    const point& lo = globalBounds_.min();
    const point& hi = globalBounds_.max();
    auto overlaps = [&](const point& c, const scalar reach)
    {
        return c.x() - reach < hi.x() && c.x() + reach > lo.x()
            && c.y() - reach < hi.y() && c.y() + reach > lo.y()
            && c.z() - reach < hi.z() && c.z() + reach > lo.z();
    };
    label nImages = 0;
    forAll(x, p)
    {
        const scalar reach = imageReach(r[p]);
        const point& c = x[p];
        // a particle clear of every side of the box has no image that
        // reaches it (the translations span the box)
        const bool clear =
            c.x() - reach > lo.x() && c.x() + reach < hi.x()
         && c.y() - reach > lo.y() && c.y() + reach < hi.y()
         && c.z() - reach > lo.z() && c.z() + reach < hi.z();
        if (!clear)
        {
            for (const vector& S : periodicShifts_)
            {
                if (!overlaps(c + S, reach)) continue;
                entries_.append(c + S);
                entryRadii_.append(r[p]);
                parent_.append(p);
                shift_.append(S);
                ++nImages;
            }
        }
        imageOffsets_[p + 1] = nImages;
    }
}


void Foam::voidFractionModel::mergeImageRows()
{
    const label n = nParticles_;
    merged_.clear();
    for (label p = 0; p < n; ++p)
    {
        merged_.appendRow(weights_, p);
        for (label k = imageOffsets_[p]; k < imageOffsets_[p + 1]; ++k)
        {
            merged_.appendRow(weights_, n + k);
        }
        merged_.endParticle();
    }
    weights_.swap(merged_);
}


Foam::scalar Foam::voidFractionModel::limitSolidFraction()
{
    const scalarField& V = mesh_.V();
    const scalar maxSolid = 1 - alphaMin_;

    if (gSum(solid_) > maxSolid*gSum(V))
    {
        FatalErrorInFunction
            << "the particles hold " << gSum(solid_) << " m3, more than (1 - alphaMin)"
            << " of the mesh volume " << gSum(V) << " (alphaMin " << alphaMin_
            << "): no void fraction >= alphaMin exists" << exit(FatalError);
    }

    // Faces across which volume moves: internal faces and processor faces
    // (so a decomposed case moves it exactly as the whole one does)
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    DynamicList<label> procFaces;
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<processorPolyPatch>(pp) && !isA<processorCyclicPolyPatch>(pp))
        {
            forAll(pp, i) procFaces.append(pp.start() + i);
        }
    }
    const label nBoundary = mesh_.nFaces() - nInternal;

    // Each sweep hands the excess of every overfull cell to its neighbours,
    // in proportion to their free room at the start of the sweep, or, when
    // they are all full, by volume: they pass it on in the next sweep, so
    // the excess spreads until it finds room. Nothing is deleted.
    scalarField room(mesh_.nCells()), excess(mesh_.nCells());
    scalarField roomSum(mesh_.nCells()), volSum(mesh_.nCells()), delta(mesh_.nCells());
    scalarField nbrRoom(nBoundary, 0), nbrV(nBoundary, 0), sent(nBoundary, 0);
    scalar moved = 0;
    for (label sweep = 0; sweep < 100000; ++sweep)
    {
        label nOver = 0;
        forAll(solid_, celli)
        {
            room[celli] = max(maxSolid*V[celli] - solid_[celli], 0.0);
            const bool over = solid_[celli] > maxSolid*V[celli]*(1 + 1e-12);
            excess[celli] = over ? solid_[celli] - maxSolid*V[celli] : 0;
            nOver += over;
        }
        if (returnReduce(nOver, sumOp<label>()) == 0)
        {
            return returnReduce(moved, sumOp<scalar>());
        }

        for (const label facei : procFaces)
        {
            nbrRoom[facei - nInternal] = room[own[facei]];
            nbrV[facei - nInternal] = V[own[facei]];
        }
        syncTools::swapBoundaryFaceList(mesh_, nbrRoom);
        syncTools::swapBoundaryFaceList(mesh_, nbrV);

        roomSum = 0;
        volSum = 0;
        for (label facei = 0; facei < nInternal; ++facei)
        {
            roomSum[own[facei]] += room[nei[facei]];
            roomSum[nei[facei]] += room[own[facei]];
            volSum[own[facei]] += V[nei[facei]];
            volSum[nei[facei]] += V[own[facei]];
        }
        for (const label facei : procFaces)
        {
            roomSum[own[facei]] += nbrRoom[facei - nInternal];
            volSum[own[facei]] += nbrV[facei - nInternal];
        }

        // the part of cell a's excess that goes to a neighbour of the given
        // room and volume
        auto share = [&](const label a, const scalar nbrRoomA, const scalar nbrVA)
        {
            if (excess[a] <= 0) return scalar(0);
            if (roomSum[a] > 0) return min(excess[a], roomSum[a])*nbrRoomA/roomSum[a];
            return excess[a]*nbrVA/volSum[a];
        };
        delta = 0;
        for (label facei = 0; facei < nInternal; ++facei)
        {
            const label a = own[facei], b = nei[facei];
            const scalar ab = share(a, room[b], V[b]);
            const scalar ba = share(b, room[a], V[a]);
            delta[a] += ba - ab;
            delta[b] += ab - ba;
            moved += ab + ba;
        }
        for (const label facei : procFaces)
        {
            const label a = own[facei];
            const scalar out = share(a, nbrRoom[facei - nInternal], nbrV[facei - nInternal]);
            sent[facei - nInternal] = out;
            delta[a] -= out;
            moved += out;
        }
        syncTools::swapBoundaryFaceList(mesh_, sent);
        for (const label facei : procFaces)
        {
            delta[own[facei]] += sent[facei - nInternal];
        }
        solid_ += delta;
    }

    FatalErrorInFunction
        << "the alphaMin limiter did not find room for the excess solid volume"
        << " (alphaMin " << alphaMin_ << ")" << exit(FatalError);
    return moved;
}


void Foam::voidFractionModel::collectStatistics(const particleData& particles)
{
    // every processor holds every particle of the step here (the utility
    // reads the whole dump): the per-particle sums are reduced over ranks
    const label n = particles.size();
    scalarField& fractionSum = fractionSum_;
    labelList& found = found_;
    fractionSum.setSize(n);
    found.setSize(n);
    forAll(fractionSum, p)
    {
        fractionSum[p] = weights_.sum(p);
        found[p] = (centreCells_[p] >= 0);
    }
    combineOverRanks(fractionSum, plusEqOp<scalar>());
    combineOverRanks(found, plusEqOp<label>());
    const scalarField& r = particles.radii();
    for (label p = 0; p < n; ++p)
    {
        const scalar Vp = particleVolume(r[p]);
        stats_.particleVolume += Vp;
        stats_.meshedVolume += fractionSum[p]*Vp;
        if (!found[p]) ++stats_.nOutside;
        else if (fractionSum[p] < 1 - 1e-9) ++stats_.nCut;
    }
}


void Foam::voidFractionModel::update(const particleData& particles)
{
    const label n = particles.size();
    if (twoD_)
    {
        projected_ = particles.positions();
        projected_.replace(emptyDir_, slabMid_);
    }
    const UList<point>& x0 = twoD_ ? projected_ : particles.positions();

    // without cyclic patches the particles are the entries (no copy)
    const bool periodic = periodicShifts_.size();
    nParticles_ = n;
    if (periodic) makeImages(x0, particles.radii());
    const UList<point>& x = periodic ? static_cast<const UList<point>&>(entries_) : x0;
    const UList<scalar>& r =
        periodic ? static_cast<const UList<scalar>&>(entryRadii_) : particles.radii();

    // hints from the previous step are valid while the particle list is;
    // images lie outside the mesh unless a particle is outside it
    if (hints_.size() != n) hints_.setSize(n, -1);
    centreCells_.setSize(x.size());
    forAll(x, i)
    {
        if (i < n)
        {
            hints_[i] = locator_.findCell(x[i], hints_[i]);
            centreCells_[i] = hints_[i];
        }
        else
        {
            centreCells_[i] = globalBounds_.contains(x[i]) ? locator_.findCell(x[i]) : -1;
        }
    }

    weights_.clear();
    distribute(x, r);
    if (weights_.nParticles() != x.size())
    {
        FatalErrorInFunction
            << type() << " produced weights for " << weights_.nParticles()
            << " of " << x.size() << " particles and images" << abort(FatalError);
    }
    if (x.size() > n)
    {
        // most images reach no cell of this processor: nothing to merge
        if (weights_.begin(n) == weights_.size()) weights_.truncate(n);
        else mergeImageRows();
    }
    centreCells_.setSize(n);

    stats_ = statistics();
    stats_.nParticles = n;
    particleVolumes_.setSize(n);
    forAll(particleVolumes_, p)
    {
        particleVolumes_[p] = particleVolume(particles.radii()[p]);
    }
    spread(particleVolumes_, solid_);
    collectStatistics(particles);

    stats_.movedVolume = limitSolidFraction();

    const scalarField& V = mesh_.V();
    scalarField& alpha = voidFraction_.primitiveFieldRef();
    forAll(alpha, celli)
    {
        // solid volumes are sums of non-negative parts; a smoothing solve
        // may leave round-off below zero, which must not lift alpha above 1
        alpha[celli] = min(1 - solid_[celli]/V[celli], scalar(1));
    }
    voidFraction_.correctBoundaryConditions();
    stats_.solidVolume = gSum(solid_);
    stats_.minVoidFraction = gMin(alpha);
    stats_.maxVoidFraction = gMax(alpha);
}


void Foam::voidFractionModel::spread
(
    const scalarField& perParticle,
    scalarField& perCell
)
{
    perCell.setSize(mesh_.nCells());
    perCell = 0;
    forAll(perParticle, p)
    {
        for (label k = weights_.begin(p); k < weights_.end(p); ++k)
        {
            perCell[weights_.cell(k)] += weights_.fraction(k)*perParticle[p];
        }
    }
    smoothVolumes(perCell);
}


void Foam::voidFractionModel::distributeToCentreCells()
{
    for (const label celli : centreCells_)
    {
        if (celli >= 0) weights_.append(celli, 1.0);
        weights_.endParticle();
    }
}


Foam::scalar Foam::voidFractionModel::positiveCoeff(const word& key) const
{
    if (!coeffs_.found(key))
    {
        FatalIOErrorInFunction(coeffs_)
            << "missing keyword " << key << " in " << coeffs_.name()
            << exit(FatalIOError);
    }
    return positiveCoeff(key, 1);
}


Foam::scalar Foam::voidFractionModel::positiveCoeff
(
    const word& key,
    const scalar deflt
) const
{
    const scalar value = coeffs_.lookupOrDefault<scalar>(key, deflt);
    if (!(value > 0) || !std::isfinite(value))
    {
        FatalIOErrorInFunction(coeffs_)
            << key << " must be a positive number, got " << value
            << " in " << coeffs_.name() << exit(FatalIOError);
    }
    return value;
}


void Foam::voidFractionModel::report(Ostream& os) const
{
    const statistics& s = stats_;
    os  << type() << ": " << s.nParticles << " particles, volume "
        << s.particleVolume << nl
        << "    solid volume in the field " << s.solidVolume
        << ", of the particles inside the mesh " << s.meshedVolume
        << ", conservation error "
        << mag(s.solidVolume - s.meshedVolume)/max(s.meshedVolume, VSMALL) << nl
        << "    particles with centre outside the mesh " << s.nOutside
        << ", reaching outside " << s.nCut
        << ", volume outside " << s.particleVolume - s.meshedVolume << nl
        << "    void fraction min " << s.minVoidFraction
        << " max " << s.maxVoidFraction
        << ", volume moved by alphaMin " << s.movedVolume << endl;
}
