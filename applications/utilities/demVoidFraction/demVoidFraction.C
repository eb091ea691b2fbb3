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
    and prints the particle count, volumes, the conservation error, min/max
    void fraction, the particles reaching outside the mesh and the time per
    call.

    A dump of one snapshot is written into the case's start time. A dump of
    several (one file written every N steps, or files 'dump.*' one per step,
    given as a quoted pattern) maps every snapshot, or those -time selects,
    or only the last with -latest, each into its own time directory: time =
    TIMESTEP x -deltaT (default 1, i.e. the step number), with a progress
    line per snapshot.

Usage
    demVoidFraction -dump FILE [-model NAME] [-name FIELD] [-repeat N] [-distribute]
        [-deltaT DT] [-time RANGES] [-latest]
    demVoidFraction -liggghts ...   (runs couplingProperties' demScript in-process)
        [-case DIR] [-parallel]
    demVoidFraction -listModels     (the models' names, one per line)

    -model overrides the dictionary's voidFractionModel; -repeat N calls the
    model N more times after a warm-up and reports the median time per call.
    In parallel a dump's particles are held by every rank, unless
    -distribute deals them out and sends each to the ranks whose cells it
    reaches, as pimpleDEMFoam and -liggghts do.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "voidFractionModel.H"
#include "particleDistributor.H"
#include "liggghtsCoupling.H"
#include "couplingKeywords.H"
#include "scalarRanges.H"
#include "numericOption.H"
#include "dumpSnapshots.H"
#include "snapshotMapper.H"

namespace
{
    void addOptions()
    {
        using namespace Foam;
        argList::addNote("Void fraction field from a LIGGGHTS dump");
        argList::addOption
        (
            "dump", "file",
            "LIGGGHTS text dump (id x y z radius), or a quoted pattern such as 'post/dump.*'"
        );
        argList::addOption("deltaT", "s", "DEM time step: a snapshot's time is TIMESTEP x this");
        argList::addOption("time", "ranges", "map only the snapshots at these times, e.g. '0.1:0.5,1'");
        argList::addBoolOption("latest", "map only the last snapshot");
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
        argList::addBoolOption
        (
            "listModels",
            "print the void fraction models' names, one per line (the papers' six in"
            " their order, then any other), and exit"
        );
        argList::addOption("repeat", "N", "time N further calls (median)");
        argList::addOption("name", "field", "write the field under this name");
        argList::addOption
        (
            "previous", "file",
            "map this dump first, as the step before (the cell search then starts"
            " from each particle's cell in it)"
        );
    }

    //- couplingProperties, with -model's voidFractionModel
    Foam::dictionary couplingDictionary(const Foam::argList& args, const Foam::fvMesh& mesh)
    {
        using namespace Foam;
        IOdictionary couplingProperties
        (
            IOobject
            (
                "couplingProperties",
                mesh.time().constant(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE
            )
        );
        checkCouplingProperties(couplingProperties, couplingProperties.filePath());
        dictionary dict(couplingProperties);
        if (args.found("model"))
        {
            const string model(args["model"]);
            const wordList models(voidFractionModel::modelNames());
            if (!models.found(model))
            {
                FatalErrorInFunction
                    << "-model '" << model.c_str() << "' is not one of " << models
                    << exit(FatalError);
            }
            dict.set("voidFractionModel", word(model));
        }
        return dict;
    }

    //- Which snapshots to map and when: read before any work, so that a bad
    //  value stops the run whether the dump holds one snapshot or many
    struct seriesOptions
    {
        Foam::scalar deltaT;
        Foam::scalarRanges times;
        bool latest;

        explicit seriesOptions(const Foam::argList& args)
        :
            deltaT(Foam::finiteOption(args, "deltaT", 1)),
            times(Foam::rangesOption(args, "time")),
            latest(args.found("latest"))
        {
            using namespace Foam;
            if (!(deltaT > 0))
            {
                FatalErrorInFunction
                    << "-deltaT " << deltaT << ": must be positive" << exit(FatalError);
            }
        }

        void noneSelected(const Foam::argList& args, const Foam::label nSeen) const
        {
            using namespace Foam;
            FatalErrorInFunction
                << "none of the " << nSeen << " snapshots of " << args["dump"]
                << " is at a time -time selects (times are TIMESTEP x deltaT " << deltaT << ")"
                << exit(FatalError);
        }
    };

    //- Map the queue's snapshots (those -time selects, or the last with
    //  -latest), each into the time directory of its TIMESTEP x -deltaT
    void mapSeries
    (
        const Foam::argList& args,
        const seriesOptions& series,
        Foam::Time& runTime,
        snapshotQueue& ahead,
        snapshotMapper& mapper,
        const Foam::clockTime& clock
    )
    {
        using namespace Foam;
        const scalar deltaT = series.deltaT;
        const scalarRanges& times = series.times;
        const bool latest = series.latest;
        label nSeen = 0, nMapped = 0;
        while (ahead.size())
        {
            snapshot now(ahead.pop());
            ++nSeen;
            const scalar t = now.timestep*deltaT;
            if ((latest && ahead.size()) || (times.size() && !times.match(t))) continue;
            runTime.setTime(t, nSeen);
            particleData particles;
            const particleHolders holders(mapper.hold(std::move(now.particles), particles));
            printProgress(nSeen, now, runTime.timeName(), clock.elapsedTime());
            mapper.mapAndWrite(particles, holders);
            ++nMapped;
        }
        if (nMapped == 0) series.noneSelected(args, nSeen);
        Info<< nl << "Mapped " << nMapped << " of " << nSeen << " snapshots in "
            << seconds(clock.elapsedTime()) << " s" << endl;
    }
}


int main(int argc, char *argv[])
{
    addOptions();

    noRepeatedOptions(argc, argv);
    // the list alone on standard output, for scripts to read
    for (int i = 1; i < argc; ++i)
    {
        if (std::string(argv[i]) == "-listModels") argList::noBanner();
    }
    #include "setRootCase.H"
    if (args.found("listModels"))
    {
        for (const word& m : voidFractionModel::modelNames())
        {
            Info<< m.c_str() << nl;
        }
        return 0;
    }
    #include "createTime.H"
    #include "createMesh.H"

    if (!args.found("dump") && !args.found("liggghts"))
    {
        FatalErrorInFunction
            << "missing -dump FILE (a LIGGGHTS text dump) or -liggghts" << exit(FatalError);
    }
    const dictionary dict(couplingDictionary(args, mesh));
    const seriesOptions series(args);

    clockTime clock;
    autoPtr<liggghtsCoupling> dem;
    if (args.found("liggghts")) dem.reset(new liggghtsCoupling(runTime, dict));
    autoPtr<voidFractionModel> model(voidFractionModel::New(dict, mesh));
    snapshotMapper mapper(args, model(), clock);

    if (dem.valid())
    {
        // the DEM's particles go to the ranks whose cells they reach
        particleData particles;
        const particleHolders holders
        (
            particleDistributor(model()).distribute(dem->particles(!Pstream::parRun()), particles)
        );
        Info<< "Read " << dem->nParticles() << " particles from LIGGGHTS in "
            << seconds(clock.timeIncrement()) << " s" << endl;
        mapper.mapAndWrite(particles, holders);
        Info<< "End" << endl;
        return 0;
    }

    // a dump is read whole on every rank (-distribute then deals it out)
    if (args.found("previous"))
    {
        model->update
        (
            particleData::readLiggghtsDump(args.get<fileName>("previous").expand())
        );
    }

    // one read ahead: a single snapshot goes into the start time, and
    // -latest knows the last when nothing follows it
    const fileNameList files(dumpFiles(args.get<fileName>("dump").expand()));
    snapshotQueue ahead(files);
    ahead.readAhead();
    ahead.readAhead();
    Info<< "Read " << ahead.front().particles.size() << " particles from " << files[0];
    if (files.size() > 1) Info<< " (first of " << files.size() << " files)";
    Info<< " in " << seconds(clock.timeIncrement()) << " s" << endl;

    if (ahead.size() == 1)
    {
        // one snapshot goes into the start time; -time must still select it
        const scalar t = ahead.front().timestep*series.deltaT;
        if (series.times.size() && !series.times.match(t)) series.noneSelected(args, 1);
        particleData particles;
        const particleHolders holders(mapper.hold(std::move(ahead.front().particles), particles));
        mapper.mapAndWrite(particles, holders);
    }
    else
    {
        mapSeries(args, series, runTime, ahead, mapper, clock);
    }
    Info<< "End" << endl;
    return 0;
}
