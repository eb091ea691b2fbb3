/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "periodicImages.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "syncTools.H"

#include <algorithm>


Foam::List<Foam::vector> Foam::periodicImages::cyclicTranslations
(
    const fvMesh& mesh,
    const scalar tol
)
{
    // the face paired with each face of a cyclic or processorCyclic patch
    // (its centre, untransformed): the translation to the other side
    const label nInternal = mesh.nInternalFaces();
    const vectorField& Cf = mesh.faceCentres();
    List<vector> other(mesh.nFaces() - nInternal);
    forAll(other, i) other[i] = Cf[nInternal + i];
    syncTools::swapBoundaryFaceList(mesh, other);

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
    for (const polyPatch& pp : mesh.boundaryMesh())
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
    List<vector> sorted;
    sorted.transfer(directions);
    return sorted;
}


void Foam::periodicImages::combine
(
    const List<vector>& translations,
    const scalar tol
)
{
    DynamicList<vector> shifts;
    const label K = translations.size();
    label nComb = 1;
    for (label k = 0; k < K; ++k) nComb *= 3;
    for (label comb = 0; comb < nComb; ++comb)
    {
        vector S(Zero);
        for (label k = 0, c = comb; k < K; ++k, c /= 3)
        {
            S += scalar((c % 3) - 1)*translations[k];
        }
        if (mag(S) > tol) shifts.append(S);
    }
    shifts_.transfer(shifts);
    shiftDirections_.setSize(shifts_.size());
    forAll(shifts_, s)
    {
        shiftDirections_[s] = 0;
        for (direction d = 0; d < 3; ++d)
        {
            if (mag(shifts_[s][d]) > tol) shiftDirections_[s] |= 1u << d;
        }
        directions_ |= shiftDirections_[s];
    }
}


Foam::periodicImages::periodicImages(const fvMesh& mesh)
:
    bounds_(mesh.bounds()),
    directions_(0)
{
    const scalar tol = 1e-9*bounds_.mag();
    const List<vector> translations(cyclicTranslations(mesh, tol));
    combine(translations, tol);
    if (shifts_.size())
    {
        // as a person reads them: 4 digits, round-off components as 0
        List<vector> shown(translations);
        for (vector& t : shown)
        {
            for (direction d = 0; d < 3; ++d) if (mag(t[d]) <= tol) t[d] = 0;
        }
        const label precision = Sout.precision(4);
        Info<< "voidFractionModel: periodic translations " << shown
            << ": particles by a cyclic patch get periodic images" << endl;
        Sout.precision(precision);
    }
}


bool Foam::periodicImages::nearSide
(
    const point& c,
    const scalar reach,
    const unsigned mask
) const
{
    // a particle clear of every periodic side of the box has no image that
    // reaches it (the translations span the box)
    const point& lo = bounds_.min();
    const point& hi = bounds_.max();
    const unsigned tested = directions_ & mask;
    for (direction d = 0; d < 3; ++d)
    {
        if (((tested >> d) & 1) && (c[d] - reach <= lo[d] || c[d] + reach >= hi[d]))
        {
            return true;
        }
    }
    return false;
}
