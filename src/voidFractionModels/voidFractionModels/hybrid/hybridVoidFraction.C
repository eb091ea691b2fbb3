#include "hybridVoidFraction.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(hybrid, 0);
    addToRunTimeSelectionTable(voidFractionModel, hybrid, dictionary);
}
}


Foam::voidFractionModels::hybrid::hybrid
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    sphereWalkVoidFraction(modelType, dict, mesh),
    resolution_(label(positiveCoeff("subGridResolution", 20)))
{
    if (scalar(resolution_) != coeffs_.lookupOrDefault<scalar>("subGridResolution", 20))
    {
        FatalIOErrorInFunction(coeffs_)
            << "subGridResolution must be a whole number, got "
            << coeffs_.lookup("subGridResolution") << " in " << coeffs_.name()
            << exit(FatalIOError);
    }
    if (resolution_ <= 128)
    {
        table_.reset(new sphereOverlap::sphereLatticeTable(resolution_));
    }
}


void Foam::voidFractionModels::hybrid::distribute(const particleData& particles)
{
    const pointField& x = particles.positions();
    const scalarField& r = particles.radii();

    crossed_.setSize(x.size());
    forAll(x, p)
    {
        const label seed = centreCells_[p];
        crossed_[p] = (seed >= 0) ? overlap_.planesCrossed(seed, x[p], r[p]) : -1;
    }
    combineOverRanks(crossed_, maxEqOp<label>());

    forAll(x, p)
    {
        const label seed = centreCells_[p];
        const point& c = x[p];
        const scalar R = r[p];
        if (crossed_[p] == 0 && seed >= 0)
        {
            weights_.append(seed, 1.0);
        }
        else if (crossed_[p] == 1)
        {
            if (!(seed >= 0 && locator_.isTensorGrid() && splitOnGrid(seed, c, R, 1)))
            {
                findSeeds(seed, c, R);
                exactVolumes(c, R);
                appendVolumes(R);
            }
        }
        else if (crossed_[p] != 0)
        {
            findSeeds(seed, c, R);
            const scalar h = 2*R/resolution_;
            const sphereOverlap::lattice L{{c.x() - R, c.y() - R, c.z() - R}, {h, h, h}};
            appendLatticeSplit(seed, c, R, L, table_.get());
        }
        weights_.endParticle();
    }
}
