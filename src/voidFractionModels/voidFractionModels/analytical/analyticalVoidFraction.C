#include "analyticalVoidFraction.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "indexedOctree.H"
#include "treeDataCell.H"

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
        label seed = centreCells_[p];
        if (seed >= 0 && overlap_.holdsSphere(seed, x[p], r[p]))
        {
            weights_.append(seed, 1.0);
            weights_.endParticle();
            continue;
        }
        if (seed < 0)
        {
            // centre outside the mesh: start from the nearest cell it reaches
            const pointIndexHit hit =
                mesh_.cellTree().findNearest(x[p], sqr(4*r[p]));
            if (hit.hit() && overlap_.reachesBox(hit.index(), x[p], r[p]))
            {
                seed = hit.index();
            }
        }
        if (seed >= 0)
        {
            cells_.clear();
            volumes_.clear();
            overlap_.overlaps(x[p], r[p], seed, cells_, volumes_);
            const scalar Vp = 4.0/3.0*constant::mathematical::pi*pow3(r[p]);
            forAll(cells_, k)
            {
                weights_.append(cells_[k], volumes_[k]/Vp);
            }
        }
        weights_.endParticle();
    }
}
