/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testParticleData

Description
    particleData against values written in the test: a reordering keeps
    each particle's position, radius, id, velocity, type and a registered
    field together; lists of different sizes, a field of the wrong size and
    a field not set are FatalErrors saying so;
    readLiggghtsDump reads the first snapshot of a dump of two. Ends with
    'particleData: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "particleData.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "testHarness.H"

using namespace Foam;
using testHarness::near;

namespace
{
    //- f() stops with a FatalError whose message holds the needle
    template<class F>
    void refused(const char* what, const F& f, const std::string& needle)
    {
        bool ok = false;
        try { f(); }
        catch (const Foam::error& e) { ok = e.message().find(needle) != std::string::npos; }
        near(what, ok, 1, 0);
    }
}


int main()
{
    FatalError.throwExceptions();

    particleData p
    (
        pointField({point(1, 2, 3), point(4, 5, 6), point(7, 8, 9)}),
        scalarField({0.1, 0.2, 0.3}),
        labelList({10, 20, 30})
    );
    p.setVelocities(vectorField({vector(1, 0, 0), vector(0, 2, 0), vector(0, 0, 3)}));

    const particleData q(p.reordered(labelList({2, 0})));
    near("reordered: two particles", q.size(), 2, 0);
    near("reordered: first is the old third (id)", q.ids()[0], 30, 0);
    near("reordered: its radius", q.radii()[0], 0.3, 0);
    near("reordered: its position", mag(q.positions()[0] - point(7, 8, 9)), 0, 0);
    near("reordered: its velocity", mag(q.velocities()[0] - vector(0, 0, 3)), 0, 0);
    near("reordered: second is the old first (id)", q.ids()[1], 10, 0);
    near("reordered: its velocity", mag(q.velocities()[1] - vector(1, 0, 0)), 0, 0);
    const particleData r(particleData(pointField(1, Zero), scalarField(1, 1.0), labelList(1, 5)).reordered(labelList(1, 0)));
    near("reordered without velocities: none", r.velocities().size(), 0, 0);

    refused
    (
        "lists of different sizes: FatalError",
        [] { particleData(pointField(2, Zero), scalarField(1, 1.0), labelList(2, 0)); },
        "differ in size"
    );
    refused
    (
        "velocities of the wrong count: FatalError",
        [&] { p.setVelocities(vectorField(2, Zero)); },
        "2 values of velocity for 3 particles"
    );

    // a field a model registers goes with its particles
    p.set("temperature", scalarField({300, 310, 320}));
    p.setTypes(labelList({1, 2, 1}));
    const particleData t(p.reordered(labelList({2, 1})));
    near("a registered field, reordered: the old third's", t.field<scalar>("temperature")[0], 320, 0);
    near("a registered field, reordered: the old second's", t.field<scalar>("temperature")[1], 310, 0);
    near("types, reordered", t.type(1), 2, 0);
    near("the fields of a kind: velocity only among the vectors", t.fields<vector>().size(), 1, 0);
    refused
    (
        "a field not set: FatalError naming it",
        [&] { t.field<scalar>("heatFlux"); },
        "no field heatFlux"
    );
    refused
    (
        "a registered field of the wrong count: FatalError naming it",
        [&] { p.set("temperature", scalarField(1, 300.0)); },
        "1 values of temperature for 3 particles"
    );

    const fileName dir(getEnv("VFM_PROJECT_DIR")/"build"/"unit"/"particleData");
    mkDir(dir);
    {
        OFstream os(dir/"two.dump");
        for (const label step : {0, 5})
        {
            os  << "ITEM: TIMESTEP\n" << step << "\nITEM: NUMBER OF ATOMS\n2\n"
                << "ITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z radius\n"
                << "1 " << step << " 0 0 0.5\n2 0 " << step << " 0 0.25\n";
        }
    }
    const particleData first(particleData::readLiggghtsDump(dir/"two.dump"));
    near("readLiggghtsDump: two particles", first.size(), 2, 0);
    near("readLiggghtsDump: the first snapshot (x of atom 1)", first.positions()[0].x(), 0, 0);
    near("readLiggghtsDump: radius of atom 2", first.radii()[1], 0.25, 0);

    return testHarness::summary("particleData");
}
