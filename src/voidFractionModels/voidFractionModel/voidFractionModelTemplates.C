#include "voidFractionModel.H"

template<class Type>
void Foam::voidFractionModel::smoothComponents(Field<Type>& cellValues)
{
    for (direction d = 0; d < pTraits<Type>::nComponents; ++d)
    {
        scalarField component(cellValues.component(d));
        smoothVolumes(component);
        cellValues.replace(d, component);
    }
}


template<class Type>
void Foam::voidFractionModel::spread
(
    const Field<Type>& perParticle,
    Field<Type>& perCell
)
{
    perCell.setSize(mesh_.nCells());
    perCell = pTraits<Type>::zero;
    forAll(perParticle, p)
    {
        for (label k = weights_.begin(p); k < weights_.end(p); ++k)
        {
            perCell[weights_.cell(k)] += weights_.fraction(k)*perParticle[p];
        }
    }
    if (smooths()) smoothComponents(perCell);
}


template<class Type>
void Foam::voidFractionModel::gather
(
    const Field<Type>& perCell,
    Field<Type>& perParticle
)
{
    // the smoothing S acts on volumes as V M^-1 with M symmetric, so its
    // transpose on an intensive field f is S(V f)/V
    tmp<Field<Type>> tTransposed(perCell);
    if (smooths())
    {
        const scalarField& V = mesh_.V();
        tTransposed = perCell*V;
        Field<Type>& transposed = tTransposed.ref();
        smoothComponents(transposed);
        transposed /= V;
    }
    const Field<Type>& f = tTransposed();

    perParticle.setSize(weights_.nParticles());
    forAll(perParticle, p)
    {
        Type sum(pTraits<Type>::zero);
        for (label k = weights_.begin(p); k < weights_.end(p); ++k)
        {
            sum += weights_.fraction(k)*f[weights_.cell(k)];
        }
        perParticle[p] = sum;
    }
    holders_.combine(perParticle, plusEqOp<Type>());
}
