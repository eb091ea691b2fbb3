#include "analyticalVoidFraction.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(analytical, 0);
    addToRunTimeSelectionTable(voidFractionModel, analytical, dictionary);
}
}


Foam::voidFractionModels::analytical::analytical
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(modelType, dict, mesh),
    overlap_(mesh)
{}


void Foam::voidFractionModels::analytical::distribute(const particleData& particles)
{
    const pointField& x = particles.positions();
    const scalarField& r = particles.radii();

    forAll(x, p)
    {
        const label seed = centreCells_[p];
        if (seed >= 0 && overlap_.holdsSphere(seed, x[p], r[p]))
        {
            weights_.append(seed, 1.0);
            weights_.endParticle();
            continue;
        }
        seeds_.clear();
        if (seed >= 0) seeds_.append(seed);
        else overlap_.boundarySeeds(x[p], r[p], seeds_);
        if (seeds_.size())
        {
            cells_.clear();
            volumes_.clear();
            overlap_.overlaps(x[p], r[p], seeds_, cells_, volumes_);
            const scalar Vp = 4.0/3.0*constant::mathematical::pi*pow3(r[p]);
            forAll(cells_, k)
            {
                weights_.append(cells_[k], volumes_[k]/Vp);
            }
        }
        weights_.endParticle();
    }
}
