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


bool Foam::voidFractionModels::analytical::splitOnGrid
(
    const label centreCell,
    const point& c,
    const scalar R
)
{
    bool cut[3];
    scalar offset[3];
    label low[3], high[3];
    if (!locator_.planeCuts(centreCell, c, R, cut, offset, low, high)) return false;

    scalar piece[8];
    sphereOverlap::planeSplit(R, offset, cut, piece);
    const scalar Vp = sphereOverlap::sphereVolume(R);
    for (int s = 0; s < 8; ++s)
    {
        if (piece[s] <= 0) continue;
        const label i = (s & 1) ? high[0] : low[0];
        const label j = (s & 2) ? high[1] : low[1];
        const label k = (s & 4) ? high[2] : low[2];
        if (i >= 0 && j >= 0 && k >= 0)
        {
            weights_.append(locator_.gridCell(i, j, k), piece[s]/Vp);
        }
    }
    return true;
}


void Foam::voidFractionModels::analytical::distribute(const particleData& particles)
{
    const pointField& x = particles.positions();
    const scalarField& r = particles.radii();

    forAll(x, p)
    {
        const label seed = centreCells_[p];
        if (seed >= 0 && locator_.isTensorGrid() && splitOnGrid(seed, x[p], r[p]))
        {
            weights_.endParticle();
            continue;
        }
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
