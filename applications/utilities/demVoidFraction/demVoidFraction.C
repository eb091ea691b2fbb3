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
#include "liggghtsDumpReader.H"
#include "scalarRanges.H"
#include "wordRe.H"
#include "fileNameList.H"
#include "OSspecific.H"

#include <algorithm>
#include <cctype>
#include <deque>
#include <vector>

namespace
{
    //- The files of a dump: the file itself, or those a pattern with * or ?
    //  matches, in the order of the last number in their names
    Foam::fileNameList dumpFiles(const Foam::fileName& pattern)
    {
        using namespace Foam;
        const std::string name(pattern.name());
        if (name.find_first_of("*?") == std::string::npos) return fileNameList(1, pattern);
        std::string regex;
        for (const char c : name)
        {
            if (c == '*') regex += ".*";
            else if (c == '?') regex += '.';
            else if (std::isalnum(static_cast<unsigned char>(c))) regex += c;
            else { regex += '\\'; regex += c; }
        }
        const wordRe matcher(regex, wordRe::REGEX);
        const fileName dir(pattern.path());
        auto lastNumber = [](const std::string& s)
        {
            const auto end = s.find_last_of("0123456789");
            if (end == std::string::npos) return -1.0;
            auto begin = end;
            while (begin > 0 && std::isdigit(static_cast<unsigned char>(s[begin - 1]))) --begin;
            return std::stod(s.substr(begin, end - begin + 1));
        };
        std::vector<std::pair<double, fileName>> found;
        for (const fileName& f : readDir(dir.empty() ? fileName(".") : dir, fileName::FILE, false))
        {
            if (matcher.match(f)) found.emplace_back(lastNumber(f), dir.empty() ? f : dir/f);
        }
        if (found.empty())
        {
            FatalErrorInFunction
                << "no file matches the dump pattern " << pattern << exit(FatalError);
        }
        std::sort(found.begin(), found.end());
        fileNameList files(found.size());
        forAll(files, i) files[i] = found[i].second;
        return files;
    }

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
        argList::addOption("repeat", "N", "time N further calls (median)");
        argList::addOption("name", "field", "write the field under this name");
        argList::addOption
        (
            "previous", "file",
            "map this dump first, as the step before (the cell search then starts"
            " from each particle's cell in it)"
        );
    }

    //- One snapshot of a dump, and the fraction of the dump read once it was
    struct snapshot
    {
        Foam::label timestep;
        Foam::particleData particles;
        Foam::scalar read;
    };

    //- The snapshots of the dump's files in order, read ahead on demand
    class snapshotQueue
    {
        const Foam::fileNameList& files_;
        std::deque<snapshot> ahead_;
        Foam::label nextFile_ = 0;
        Foam::autoPtr<Foam::liggghtsDumpReader> reader_;

    public:

        explicit snapshotQueue(const Foam::fileNameList& files) : files_(files) {}

        //- Read one more snapshot, if the files hold one
        void readAhead()
        {
            using namespace Foam;
            particleData p;
            while (true)
            {
                if (!reader_.valid())
                {
                    if (nextFile_ == files_.size()) return;
                    reader_.reset(new liggghtsDumpReader(files_[nextFile_++]));
                }
                if (reader_->read(p)) break;
                reader_.clear();
            }
            const scalar read = (nextFile_ - 1 + reader_->progress())/files_.size();
            ahead_.push_back({reader_->timestep(), std::move(p), min(max(read, scalar(0)), scalar(1))});
        }

        //- The next snapshot, reading another behind it
        snapshot pop()
        {
            snapshot next(std::move(ahead_.front()));
            ahead_.pop_front();
            readAhead();
            return next;
        }

        std::size_t size() const { return ahead_.size(); }
        snapshot& front() { return ahead_.front(); }
    };

    //- The progress line of a series: snapshot, time, share of the dump
    //  read, elapsed and an estimate of what remains
    void printProgress
    (
        const Foam::label nSeen,
        const snapshot& now,
        const Foam::word& timeName,
        const Foam::scalar elapsed
    )
    {
        using namespace Foam;
        const scalar done = now.read;
        const label precision = Sout.precision(4);
        Info<< nl << "Snapshot " << nSeen << ", TIMESTEP " << now.timestep << ", time "
            << timeName << ": " << label(100*done + 0.5) << " % of the dump read, "
            << elapsed << " s elapsed";
        if (done > 0 && done < 1)
        {
            Info<< ", about " << elapsed*(1 - done)/done << " s left";
        }
        Info<< endl;
        Sout.precision(precision);
    }
}


int main(int argc, char *argv[])
{
    addOptions();

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
    autoPtr<voidFractionModel> model(voidFractionModel::New(dict, mesh));
    const word fieldName(args.getOrDefault<word>("name", "voidfraction"));
    const label repeat = args.getOrDefault<label>("repeat", 0);

    // map particles (holders: who holds which) and write the field into
    // the current time
    auto mapAndWrite = [&](const particleData& particles, const particleHolders& holders)
    {
        clock.timeIncrement();
        model->update(particles, particleHolders(holders));
        const scalar firstCall = clock.timeIncrement();
        // the repeated calls first: their solver output must not split the
        // summary's lines
        const scalar median =
            repeat > 0 ? medianCallTime(model(), particles, repeat, holders) : 0;
        model->report(Info);
        const label precision = Sout.precision(4);
        Info<< "time per call: first " << firstCall << " s";
        if (repeat > 0)
        {
            Info<< ", median of " << repeat << " " << median << " s, "
                << model->stats().nParticles/max(median, VSMALL) << " particles/s";
        }
        Info<< endl;
        Sout.precision(precision);
        volScalarField out
        (
            IOobject(fieldName, runTime.timeName(), mesh),
            model->voidFraction()
        );
        out.write();
        Info<< "Wrote " << fieldName << " to " << runTime.timePath() << endl;
    };

    if (dem.valid())
    {
        // the DEM's particles go to the ranks whose cells they reach
        particleData particles;
        const particleHolders holders
        (
            particleDistributor(model()).distribute(dem->particles(!Pstream::parRun()), particles)
        );
        Info<< "Read " << dem->nParticles() << " particles from LIGGGHTS in "
            << clock.timeIncrement() << " s" << endl;
        mapAndWrite(particles, holders);
        Info<< "End" << endl;
        return 0;
    }

    // a dump is read whole on every rank; with -distribute each rank keeps
    // the particles near its cells, as from a DEM
    const bool distribute = args.found("distribute") && Pstream::parRun();
    // built once (its ranks' boxes and bins are collective work), used for
    // every snapshot
    autoPtr<particleDistributor> distributor;
    auto hold = [&](particleData&& all, particleData& particles)
    {
        if (!distribute)
        {
            particles = std::move(all);
            return particleHolders();
        }
        labelList mine;
        for (label i = Pstream::myProcNo(); i < all.size(); i += Pstream::nProcs())
        {
            mine.append(i);
        }
        if (!distributor.valid()) distributor.reset(new particleDistributor(model()));
        particleHolders holders(distributor->distribute(all.reordered(mine), particles));
        Info<< "Particles held: at most "
            << returnReduce(particles.size(), maxOp<label>()) << " of " << all.size()
            << " on a rank" << endl;
        return holders;
    };

    if (args.found("previous"))
    {
        model->update
        (
            particleData::readLiggghtsDump(args.get<fileName>("previous").expand())
        );
    }

    const fileNameList files(dumpFiles(args.get<fileName>("dump").expand()));
    const scalar deltaT = args.getOrDefault<scalar>("deltaT", 1);
    const scalarRanges times
    (
        args.found("time") ? scalarRanges::parse(args["time"]) : scalarRanges()
    );
    const bool latest = args.found("latest");

    // one read ahead: a single snapshot goes into the start time, and
    // -latest knows the last when nothing follows it
    snapshotQueue ahead(files);
    ahead.readAhead();
    ahead.readAhead();
    Info<< "Read " << ahead.front().particles.size() << " particles from " << files[0];
    if (files.size() > 1) Info<< " (first of " << files.size() << " files)";
    Info<< " in " << clock.timeIncrement() << " s" << endl;

    if (ahead.size() == 1)
    {
        particleData particles;
        const particleHolders holders(hold(std::move(ahead.front().particles), particles));
        mapAndWrite(particles, holders);
        Info<< "End" << endl;
        return 0;
    }

    label nSeen = 0, nMapped = 0;
    while (ahead.size())
    {
        snapshot now(ahead.pop());
        ++nSeen;
        const scalar t = now.timestep*deltaT;
        if ((latest && ahead.size()) || (times.size() && !times.match(t))) continue;
        runTime.setTime(t, nSeen);
        particleData particles;
        const particleHolders holders(hold(std::move(now.particles), particles));
        printProgress(nSeen, now, runTime.timeName(), clock.elapsedTime());
        mapAndWrite(particles, holders);
        ++nMapped;
    }
    if (nMapped == 0)
    {
        FatalErrorInFunction
            << "none of the " << nSeen << " snapshots of " << args["dump"]
            << " is at a time -time selects (times are TIMESTEP x deltaT " << deltaT << ")"
            << exit(FatalError);
    }
    Info<< nl << "Mapped " << nMapped << " of " << nSeen << " snapshots in "
        << clock.elapsedTime() << " s" << nl << "End" << endl;
    return 0;
}
