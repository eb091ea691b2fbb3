/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
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


template<class Type, class Also>
void Foam::voidFractionModel::spreadAlso
(
    const Field<Type>& perParticle,
    Field<Type>& perCell,
    const Also& also
)
{
    perCell.setSize(mesh_.nCells());
    perCell = Zero;
    step_.weights.forAllEntries
    (
        [&](const label p, const label celli, const scalar w)
        {
            perCell[celli] += w*perParticle[p];
            also(p, celli, w);
        }
    );
    if (smooths()) smoothComponents(perCell);
}


template<class Type>
void Foam::voidFractionModel::spread
(
    const Field<Type>& perParticle,
    Field<Type>& perCell
)
{
    spreadAlso(perParticle, perCell, [](const label, const label, const scalar) {});
}


template<class TypeA, class TypeB>
void Foam::voidFractionModel::spread
(
    const Field<TypeA>& perParticleA,
    Field<TypeA>& perCellA,
    const Field<TypeB>& perParticleB,
    Field<TypeB>& perCellB
)
{
    perCellB.setSize(mesh_.nCells());
    perCellB = Zero;
    spreadAlso
    (
        perParticleA, perCellA,
        [&](const label p, const label celli, const scalar w)
        {
            perCellB[celli] += w*perParticleB[p];
        }
    );
    if (smooths()) smoothComponents(perCellB);
}


template<class Type>
void Foam::voidFractionModel::gatherHere
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

    perParticle.setSize(step_.weights.nParticles());
    forAll(perParticle, p)
    {
        Type sum(pTraits<Type>::zero);
        for (const particleCellWeights::entry e : step_.weights.row(p))
        {
            sum += e.fraction*f[e.cell];
        }
        perParticle[p] = sum;
    }
}


template<class Type>
void Foam::voidFractionModel::gather
(
    const Field<Type>& perCell,
    Field<Type>& perParticle
)
{
    gatherHere(perCell, perParticle);
    step_.holders.combine(perParticle, plusEqOp<Type>());
}


template<class TypeA, class TypeB>
void Foam::voidFractionModel::combineSums
(
    Field<TypeA>& a,
    Field<TypeB>& b
) const
{
    const direction nA = pTraits<TypeA>::nComponents;
    const direction nB = pTraits<TypeB>::nComponents;
    static_assert(nA + nB <= 6, "two sums of at most six components");

    // a symmTensor only carries the six sums through the exchange
    step_.holders.combine<symmTensor>
    (
        a.size(), plusEqOp<symmTensor>(),
        [&](const label p)
        {
            symmTensor both(Zero);
            for (direction d = 0; d < nA; ++d) both[d] = component(a[p], d);
            for (direction d = 0; d < nB; ++d) both[nA + d] = component(b[p], d);
            return both;
        },
        [&](const label p, const symmTensor& both)
        {
            for (direction d = 0; d < nA; ++d) setComponent(a[p], d) = both[d];
            for (direction d = 0; d < nB; ++d) setComponent(b[p], d) = both[nA + d];
        }
    );
}


template<class TypeA, class TypeB>
void Foam::voidFractionModel::gather
(
    const Field<TypeA>& perCellA,
    Field<TypeA>& perParticleA,
    const Field<TypeB>& perCellB,
    Field<TypeB>& perParticleB
)
{
    if (smooths())
    {
        gatherHere(perCellA, perParticleA);
        gatherHere(perCellB, perParticleB);
    }
    else
    {
        // one pass over the rows for both fields
        perParticleA.setSize(step_.weights.nParticles());
        perParticleB.setSize(step_.weights.nParticles());
        forAll(perParticleA, p)
        {
            TypeA sumA;
            TypeB sumB;
            rowSums(p, perCellA, perCellB, sumA, sumB);
            perParticleA[p] = sumA;
            perParticleB[p] = sumB;
        }
    }
    combineSums(perParticleA, perParticleB);
}


template<class TypeA, class TypeB, class PerParticle>
void Foam::voidFractionModel::gatherApply
(
    const Field<TypeA>& perCellA,
    const Field<TypeB>& perCellB,
    const PerParticle& apply
)
{
    if (smooths() || Pstream::parRun())
    {
        Field<TypeA> a;
        Field<TypeB> b;
        gather(perCellA, a, perCellB, b);
        forAll(a, p) apply(p, a[p], b[p]);
        return;
    }
    const label n = step_.weights.nParticles();
    for (label p = 0; p < n; ++p)
    {
        TypeA sumA;
        TypeB sumB;
        rowSums(p, perCellA, perCellB, sumA, sumB);
        apply(p, sumA, sumB);
    }
}


template<class TypeA, class TypeB, class SpreadA, class SpreadB, class PerParticle>
void Foam::voidFractionModel::gatherApplySpread
(
    const Field<TypeA>& perCellA,
    const Field<TypeB>& perCellB,
    Field<SpreadA>& spreadA,
    Field<SpreadB>& spreadB,
    const PerParticle& apply
)
{
    if (smooths() || Pstream::parRun())
    {
        // the sums are complete after the gather's exchange only
        const label n = step_.weights.nParticles();
        Field<SpreadA> sa(n);
        Field<SpreadB> sb(n);
        gatherApply
        (
            perCellA, perCellB,
            [&](const label p, const TypeA& a, const TypeB& b) { apply(p, a, b, sa[p], sb[p]); }
        );
        spread(sa, spreadA, sb, spreadB);
        return;
    }
    // each particle's rows are read once: gathered, turned, spread back,
    // with the arithmetic (and the order of the sums) of the three steps
    spreadA.setSize(mesh_.nCells());
    spreadA = Zero;
    spreadB.setSize(mesh_.nCells());
    spreadB = Zero;
    gatherApply
    (
        perCellA, perCellB,
        [&](const label p, const TypeA& a, const TypeB& b)
        {
            SpreadA sa;
            SpreadB sb;
            apply(p, a, b, sa, sb);
            for (const particleCellWeights::entry e : step_.weights.row(p))
            {
                spreadA[e.cell] += e.fraction*sa;
                spreadB[e.cell] += e.fraction*sb;
            }
        }
    );
}
