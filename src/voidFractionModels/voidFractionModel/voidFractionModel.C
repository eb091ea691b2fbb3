/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "voidFractionModel.H"
#include "mathematicalConstants.H"
#include "zeroGradientFvPatchFields.H"
#include "UIndirectList.H"
#include "modelCoefficients.H"

namespace Foam
{
    defineTypeNameAndDebug(voidFractionModel, 0);
    defineRunTimeSelectionTable(voidFractionModel, dictionary);
}


Foam::dictionary Foam::voidFractionModel::checkedCoeffs
(
    const word& modelType,
    const dictionary& dict
)
{
    // the kinds of what this constructor reads, for any caller's dictionary
    keywordSchema::checkKind(dict, "alphaMin", keywordSchema::oneNumber);
    keywordSchema::checkKind(dict, "twoDimensional", keywordSchema::onOff);
    keywordSchema::checkKind(dict, "keepVolumeBeyondMesh", keywordSchema::onOff);
    keywordSchema::checkKind(dict, modelType + "Coeffs", keywordSchema::subDictionary);
    const dictionary coeffs(dict.subOrEmptyDict(modelType + "Coeffs"));
    modelCoefficients::schema(modelType).check(coeffs);
    return coeffs;
}


Foam::voidFractionModel::voidFractionModel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    coeffs_(checkedCoeffs(modelType, dict)),
    alphaMin_(dict.lookupOrDefault<scalar>("alphaMin", 0.1)),
    locator_(mesh),
    limiter_(mesh, alphaMin_),
    twoD_(dict.lookupOrDefault<bool>("twoDimensional", false)),
    keepBeyondMesh_(dict.lookupOrDefault<bool>("keepVolumeBeyondMesh", false)),
    emptyDir_(0),
    slabMid_(0),
    thickness_(0),
    images_(mesh),
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
    ),
    split_(this)
{
    step_.solid.setSize(mesh.nCells(), 0);
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
}


Foam::label Foam::voidFractionModel::collectStatistics(const particleData& particles)
{
    // per-particle sums over the holders; each particle is added once
    scalarField& found = centreHolders_;
    found.setSize(particles.size());
    forAll(found, p) found[p] = (step_.centreCells[p] >= 0);
    combineSums(step_.fractionSum, found);
    if (keepBeyondMesh_) keepVolumeBeyondMesh(found);
    const label nOver = stats_.collect
    (
        step_.fractionSum, found, step_.particleVolumes, step_.holders, step_.solid,
        limiter_.nOverLimit(step_.solid), keepBeyondMesh_
    );
    if (keepBeyondMesh_)
    {
        // the weights now sum to one: gathers (forces, interpolation)
        // divide by these sums
        forAll(found, p) if (found[p] > 0 && step_.fractionSum[p] > 0) step_.fractionSum[p] = 1;
    }
    return nOver;
}


void Foam::voidFractionModel::keepVolumeBeyondMesh(const scalarField& found)
{
    // the sums are combined over the ranks and the periodic images joined:
    // what a particle misses is beyond a boundary patch, and each rank
    // holding part of it scales its part by the same factor. fractionSum
    // keeps the share inside for the statistics
    forAll(step_.fractionSum, p)
    {
        const scalar f = step_.fractionSum[p];
        if (found[p] <= 0 || f >= 1 || f <= 0) continue;
        const scalar s = 1/f;
        const scalar volume = step_.particleVolumes[p];
        for (label k = step_.weights.begin(p); k < step_.weights.end(p); ++k)
        {
            step_.solid[step_.weights.cell(k)] += (s - 1)*step_.weights.fraction(k)*volume;
        }
        step_.weights.scale(p, s);
    }
}


void Foam::voidFractionModel::carryHints(const labelList& ids)
{
    if (ids == hintIds_) return;
    labelList hints(ids.size(), -1);
    auto ascending = [](const labelList& l)
    {
        for (label i = 1; i < l.size(); ++i) if (l[i] <= l[i - 1]) return false;
        return true;
    };
    if (ascending(ids) && ascending(hintIds_))
    {
        label j = 0;
        forAll(ids, i)
        {
            while (j < hintIds_.size() && hintIds_[j] < ids[i]) ++j;
            if (j < hintIds_.size() && hintIds_[j] == ids[i])
            {
                hints[i] = hints_[j];
            }
        }
    }
    hints_.transfer(hints);
    hintIds_ = ids;
}


void Foam::voidFractionModel::computeRows
(
    const UList<point>& x0,
    const scalarField& r0,
    const labelUList& centres
)
{
    // without periodic images the particles are the entries (no copy)
    const label n = x0.size();
    step_.nParticles = n;
    const bool periodic =
        images_.shifts().size() && images_.make(x0, r0, centres, imageRules{*split_});
    // views of the lists' contents (a swapStep moves none)
    const UList<point> x(periodic ? images_.entries() : x0);
    const UList<scalar> r(periodic ? images_.radii() : r0);

    // images lie outside the mesh unless a particle is outside it
    step_.centreCells.setSize(x.size());
    if (periodic)
    {
        forAll(x, i)
        {
            step_.centreCells[i] = images_.isParticle(i) ? centres[images_.parent(i)]
              : images_.bounds().contains(x[i]) ? locator_.findCell(x[i]) : -1;
        }
    }
    else
    {
        step_.centreCells = centres;
    }

    step_.weights.clear();
    if (split_ == this)
    {
        distribute(x, r);
    }
    else
    {
        swapStep(*split_);
        split_->distribute(x, r);
        swapStep(*split_);
    }
    if (step_.weights.nParticles() != x.size())
    {
        FatalErrorInFunction
            << split_->type() << " produced weights for " << step_.weights.nParticles()
            << " of " << x.size() << " particles and images" << abort(FatalError);
    }
    if (x.size() > n) step_.weights.joinRows(images_.firstEntry());
}


void Foam::voidFractionModel::update
(
    const particleData& particles,
    particleHolders&& holders
)
{
    step_.holders = std::move(holders);
    const label n = particles.size();
    if (twoD_)
    {
        projected_ = particles.positions();
        projected_.replace(emptyDir_, slabMid_);
    }
    const UList<point>& x0 = twoD_ ? projected_ : particles.positions();

    const scalarField& r = particles.radii();
    carryHints(particles.ids());
    locator_.findCells(x0, hints_);
    step_.particleVolumes.setSize(n);
    forAll(step_.particleVolumes, p)
    {
        step_.particleVolumes[p] = particleVolume(r[p]);
    }
    step_.spreadAsMade = !smooths();
    step_.rowsSpread = false;
    if (step_.spreadAsMade)
    {
        step_.solid = Zero;
        step_.fractionSum.setSize(n);
        step_.fractionSum = Zero;
    }
    computeRows(x0, r, hints_);
    step_.centreCells = hints_;

    stats_ = mappingStatistics();
    if (!step_.rowsSpread) spreadVolumes();
    const label nOver = collectStatistics(particles);
    stats_.movedVolume = limiter_.limit(step_.solid, nOver, stats_.solidVolume);

    const scalarField& V = mesh_.V();
    scalarField& alpha = voidFraction_.primitiveFieldRef();
    forAll(alpha, celli)
    {
        // solid volumes are sums of non-negative parts; a smoothing solve
        // may leave round-off below zero, which must not lift alpha above 1
        alpha[celli] = min(1 - step_.solid[celli]/V[celli], scalar(1));
    }
    voidFraction_.correctBoundaryConditions();
    // the limiter moves volume; the total it keeps is what is reported
    if (nOver) stats_.solidVolume = gSum(step_.solid);
    stats_.setRange(alpha);
}


void Foam::voidFractionModel::spreadVolumes()
{
    // each particle's share from the same read of the rows: they are the
    // largest array of a step, and reading them dominates
    step_.fractionSum.setSize(step_.weights.nParticles());
    step_.fractionSum = Zero;
    spreadAlso
    (
        step_.particleVolumes, step_.solid,
        [&](const label p, const label, const scalar w) { step_.fractionSum[p] += w; }
    );
}


void Foam::voidFractionModel::distributeToCentreCells()
{
    forAll(step_.centreCells, i)
    {
        if (step_.centreCells[i] >= 0) step_.weights.append(step_.centreCells[i], 1.0);
        endRow(i);
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
