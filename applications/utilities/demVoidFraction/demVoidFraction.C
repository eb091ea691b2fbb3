/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    demVoidFraction

Description
    Computes the void fraction field of a case from a LIGGGHTS text dump with
    the model selected in constant/couplingProperties, writes "voidfraction"
    into the time directory and prints the particle count, volumes, the
    conservation error, min/max void fraction, the particles reaching
    outside the mesh and the time per call.

Usage
    demVoidFraction -dump FILE [-model NAME] [-name FIELD] [-repeat N] [-distribute]
    demVoidFraction -liggghts ...   (runs couplingProperties' demScript in-process)
        [-case DIR] [-parallel]

    -model overrides the dictionary's voidFractionModel; -repeat N calls the
    model N more times after a warm-up and reports the median time per call.
    In parallel a dump's particles are held by every rank, unless
    -distribute deals them out and sends each to the ranks whose cells it
    reaches, as pimpleDEMFoam and -liggghts do.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "voidFractionModel.H"
#include "medianCallTime.H"
#include "particleDistributor.H"
#include "liggghtsCoupling.H"

int main(int argc, char *argv[])
{
    argList::addNote("Void fraction field from a LIGGGHTS dump");
    argList::addOption("dump", "file", "LIGGGHTS text dump (id x y z radius)");
    argList::addBoolOption
    (
        "distribute",
        "parallel -dump: deal the particles out to the ranks and map them through"
        " the exchange pimpleDEMFoam uses (each rank holds only those near its cells)"
    );
    argList::addBoolOption
    (
        "liggghts",
        "run couplingProperties' demScript in this process (LIGGGHTS as a library)"
        " and take its particles instead of a dump"
    );
    argList::addOption("model", "name", "override the voidFractionModel");
    argList::addOption("repeat", "N", "time N further calls (median)");
    argList::addOption("name", "field", "write the field under this name");
    argList::addOption
    (
        "previous", "file",
        "map this dump first, as the step before (keepDistance keeps the rows"
        " of particles that moved less)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    if (!args.found("dump") && !args.found("liggghts"))
    {
        FatalErrorInFunction
            << "missing -dump FILE (a LIGGGHTS text dump) or -liggghts" << exit(FatalError);
    }

    IOdictionary couplingProperties
    (
        IOobject
        (
            "couplingProperties",
            runTime.constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    dictionary dict(couplingProperties);
    if (args.found("model"))
    {
        dict.set("voidFractionModel", args.get<word>("model"));
    }

    clockTime clock;
    autoPtr<liggghtsCoupling> dem;
    if (args.found("liggghts")) dem.reset(new liggghtsCoupling(runTime, dict));
    const fileName dumpFile(args.getOrDefault<fileName>("dump", "").expand());
    autoPtr<voidFractionModel> model(voidFractionModel::New(dict, mesh));
    // a dump is read whole on every rank; the DEM's particles go to the
    // ranks whose cells they reach
    particleData particles;
    particleHolders holders;
    if (dem.valid())
    {
        holders = particleDistributor(model()).distribute
        (
            dem->particles(!Pstream::parRun()), particles
        );
    }
    else if (args.found("distribute") && Pstream::parRun())
    {
        // each rank owns every nProcs-th particle of the dump, as a DEM
        // would own some, and keeps those its cells reach
        const particleData all(particleData::readLiggghtsDump(dumpFile));
        labelList mine;
        for (label i = Pstream::myProcNo(); i < all.size(); i += Pstream::nProcs())
        {
            mine.append(i);
        }
        holders = particleDistributor(model()).distribute(all.reordered(mine), particles);
        Info<< "Particles held: at most "
            << returnReduce(particles.size(), maxOp<label>()) << " of " << all.size()
            << " on a rank" << endl;
    }
    else
    {
        particles = particleData::readLiggghtsDump(dumpFile);
    }
    Info<< "Read " << (dem.valid() ? dem->nParticles() : particles.size()) << " particles from "
        << (dem.valid() ? fileName("LIGGGHTS") : dumpFile)
        << " in " << clock.timeIncrement() << " s" << endl;

    if (args.found("previous"))
    {
        model->update
        (
            particleData::readLiggghtsDump(args.get<fileName>("previous").expand())
        );
        clock.timeIncrement();
    }
    model->update(particles, particleHolders(holders));
    const scalar firstCall = clock.timeIncrement();
    model->report(Info);

    const label repeat = args.getOrDefault<label>("repeat", 0);
    Info<< "time per call: first " << firstCall << " s";
    if (repeat > 0)
    {
        const scalar median = medianCallTime(model(), particles, repeat, holders);
        Info<< ", median of " << repeat << " " << median << " s, "
            << model->stats().nParticles/max(median, VSMALL) << " particles/s";
    }
    Info<< endl;

    const word fieldName(args.getOrDefault<word>("name", "voidfraction"));
    volScalarField out
    (
        IOobject(fieldName, runTime.timeName(), mesh),
        model->voidFraction()
    );
    out.write();
    Info<< "Wrote " << fieldName << " to " << runTime.timePath() << nl
        << "End" << endl;
    return 0;
}
