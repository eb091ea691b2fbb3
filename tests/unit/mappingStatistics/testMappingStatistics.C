/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testMappingStatistics

Description
    mappingStatistics on four particles of 1 to 4 nL (serial): one whole
    inside, one half inside, one with its centre outside, one whole to
    1e-12: the counts of particles outside and cut, the particles' and the
    meshed volume, the conservation error against the field's solid and
    the void fraction range against hand-computed values, and the summary
    in 4 significant digits; the same particles with the part outside kept
    in the mesh. Ends with 'mappingStatistics: N passed, M
    failed'.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mappingStatistics.H"
#include "OStringStream.H"
#include "testHarness.H"

using namespace Foam;
using testHarness::near;

namespace
{
    bool contains(const std::string& text, const std::string& part)
    {
        const bool found = text.find(part) != std::string::npos;
        if (!found) std::printf("summary lacks '%s' in:\n%s\n", part.c_str(), text.c_str());
        return found;
    }
}


int main(int argc, char *argv[])
{
    const scalar nL = 1e-9;
    {
        const mappingStatistics fresh;
        near("nothing mapped: no particles", fresh.nParticles, 0, 0);
        near("nothing mapped: void fraction range 1..1", fresh.minVoidFraction + fresh.maxVoidFraction, 2, 0);
        near("nothing mapped: conservation error 0", fresh.conservationError(), 0, 0);
    }

    const scalarField volumes({1*nL, 2*nL, 3*nL, 4*nL});
    const scalarField fractionSum({1, 0.5, 0, 1 - 1e-12});
    const scalarField centreFound({1, 1, 0, 1});
    const scalarField solid(List<scalar>({3*nL, 3*nL + 1e-7*nL}));
    const particleHolders everyParticleHere;

    mappingStatistics s;
    s.collect(fractionSum, centreFound, volumes, everyParticleHere, solid, 2);
    near("four particles", s.nParticles, 4, 0);
    near("one centre outside the mesh", s.nOutside, 1, 0);
    near("one cut by the boundary (the one whole to 1e-12 is not)", s.nCut, 1, 0);
    near("particle volume 10 nL (rel)", s.particleVolume/(10*nL), 1, 1e-15);
    const scalar meshed = 1 + 0.5*2 + 4*(1 - 1e-12);
    near("meshed volume 1 + 1 + 0 + 4(1 - 1e-12) nL (rel)", s.meshedVolume/(meshed*nL), 1, 1e-15);
    near("solid volume in the field (rel)", s.solidVolume/((6 + 1e-7)*nL), 1, 1e-15);
    const scalar error = (6 + 1e-7 - meshed)/meshed;
    near("conservation error |solid - meshed|/meshed (rel)", s.conservationError()/error, 1, 1e-8);

    s.setRange(scalarField({0.7, 0.35, 1}));
    near("void fraction min", s.minVoidFraction, 0.35, 0);
    near("void fraction max", s.maxVoidFraction, 1, 0);
    s.movedVolume = 0.123456*nL;

    OStringStream os;
    s.write(os, "analytical");
    const std::string text = os.str();
    near("summary names the model and the count", contains(text, "analytical: 4 particles, volume 1e-08"), 1, 0);
    near("summary: conservation error in 4 digits", contains(text, "conservation error 1.667e-08"), 1, 0);
    near("summary: outside and cut", contains(text, "outside the mesh 1, reaching outside 1"), 1, 0);
    near("summary: moved volume in 4 digits", contains(text, "volume moved by alphaMin 1.235e-10"), 1, 0);
    near("summary: range", contains(text, "void fraction min 0.35 max 1"), 1, 0);
    near("the stream's precision is given back", os.precision(), IOstream::defaultPrecision(), 0);

    // kept: the parts outside of the particles centred inside, 1 nL and
    // 4e-12 nL, are in the field; the one centred outside is not
    const scalarField keptSolid(List<scalar>({4*nL, 3*nL}));
    mappingStatistics k;
    k.collect(fractionSum, centreFound, volumes, everyParticleHere, keptSolid, 0, true);
    near("kept: the parts outside of particles centred inside (rel)", k.keptVolume/((1 + 4e-12)*nL), 1, 1e-15);
    near("kept: still one cut by the boundary", k.nCut, 1, 0);
    near("kept: the field holds meshed + kept (rel error)", k.conservationError(), 0, 1e-15);
    OStringStream ks;
    k.write(ks, "analytical");
    near("summary: outside and kept", contains(ks.str(), "volume outside 4e-09, kept in the mesh 1e-09"), 1, 0);

    return testHarness::summary("mappingStatistics");
}
