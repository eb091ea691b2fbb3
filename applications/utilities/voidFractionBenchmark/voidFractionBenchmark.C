/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    voidFractionBenchmark

Description
    Accuracy, smoothness and cost of void fraction models on one case and
    one particle sample. For every run of system/voidFractionBenchmarkDict:
    the error against the reference model (Kalderon et al., Eq. 21: the mean over
    cells of |n - n_ref|/n_ref, in %), the smoothness (its Eq. 22: the mean
    over cells of |grad n|, in 1/m), the conservation error, and the median
    time per call after a warm-up call, and the peak memory of the process
    so far. One CSV row per run, appended to the file the dictionary names
    (a header is written when the file is new).

    Each run's entries are merged over constant/couplingProperties, so
    alphaMin and twoDimensional come from there.

Usage
    voidFractionBenchmark -dump FILE [-sample NAME] [-parallel]

    system/voidFractionBenchmarkDict:
    \verbatim
    reference   { voidFractionModel analytical; }
    repeat      10;
    csv         "voidFractionBenchmark.csv";
    runs
    {
        centroid    { voidFractionModel centroid; }
        kernel0.4
        {
            voidFractionModel kernel;
            kernelCoeffs { bandwidthOverCellSize 0.4; }
            parameter   0.4;        // for the plots; optional
        }
    }
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "voidFractionModel.H"
#include "medianCallTime.H"
#include "OFstream.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "couplingKeywords.H"
#include "numericOption.H"
#include <algorithm>

using namespace Foam;

namespace
{
    //- Checks voidFractionBenchmarkDict; returns what a run may hold
    keywordSchema benchmarkKeywords(const IOdictionary& benchDict)
    {
        keywordSchema run("a run of voidFractionBenchmarkDict");
        voidFractionModel::addKeywords(run);
        run.add("parameter", keywordSchema::oneNumber);
        keywordSchema bench("voidFractionBenchmarkDict");
        bench.add("reference", run);
        bench.add("repeat", keywordSchema::wholeNumber);
        bench.add("csv", keywordSchema::fileOrWord);
        bench.add("runs", keywordSchema::subDictionary);
        keywordSchema::checkRepeats(benchDict.filePath());
        bench.check(benchDict);
        return run;
    }

    //- Peak resident memory of this process so far (MB; 0 if unknown)
    scalar peakMemoryMB()
    {
        IFstream is("/proc/self/status");
        string line;
        while (is.good() && is.getLine(line))
        {
            if (line.find("VmHWM:") == 0)
            {
                IStringStream ls(line.substr(6));
                const scalar kB = readScalar(ls);
                return kB/1024;
            }
        }
        return 0;
    }

    struct metrics
    {
        scalar error = 0;
        scalar smoothness = 0;
        scalar conservation = 0;
        scalar time = 0;
    };

    metrics measure
    (
        const dictionary& dict,
        const fvMesh& mesh,
        const particleData& particles,
        const scalarField& reference,
        const label repeat,
        scalarField* field = nullptr
    )
    {
        autoPtr<voidFractionModel> model(voidFractionModel::New(dict, mesh));
        model->update(particles);     // warm-up: first-call allocations
        metrics m;
        m.time = medianCallTime(model(), particles, repeat);

        const volScalarField& n = model->voidFraction();
        if (field) *field = n.primitiveField();
        const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
        if (reference.size())
        {
            m.error = 100*gSum(mag(n.primitiveField() - reference)/reference)/nCells;
        }
        m.smoothness = gSum(mag(fvc::grad(n))().primitiveField())/nCells;
        const mappingStatistics& s = model->stats();
        m.conservation = s.conservationError();
        return m;
    }

    //- Kalderon et al.'s X: the mean cell size (in 2D from the area in the
    //  plane) over the largest particle diameter
    scalar sizeRatioX(const fvMesh& mesh, const bool twoD, const scalar rMax)
    {
        const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
        const scalar meanV = gSum(mesh.V().field())/nCells;
        scalar thickness = 0;
        for (direction d = 0; d < 3; ++d)
        {
            if (mesh.solutionD()[d] == -1) thickness = mesh.bounds().span()[d];
        }
        const scalar ds =
            (twoD && thickness > 0) ? Foam::sqrt(meanV/thickness) : Foam::cbrt(meanV);
        return ds/(2*rMax);
    }

    //- One line per run on the terminal, and one row of the CSV (appended,
    //  with a header when the file is new), written by the master only
    class benchmarkCsv
    {
        autoPtr<OFstream> os_;
        const word sample_;
        const label nParticles_;
        const label nCells_;
        const scalar X_;

    public:

        benchmarkCsv
        (
            const fileName& name,
            const word& sample,
            const label nParticles,
            const label nCells,
            const scalar X
        )
        :
            sample_(sample),
            nParticles_(nParticles),
            nCells_(nCells),
            X_(X)
        {
            if (!Pstream::master()) return;
            const bool isNew = !isFile(name);
            os_.reset(new OFstream(name, IOstream::ASCII, IOstream::currentVersion,
                                   IOstream::UNCOMPRESSED, true));
            if (!os_().good())
            {
                FatalErrorInFunction
                    << "cannot write the CSV file " << name << exit(FatalError);
            }
            if (isNew)
            {
                os_()<< "sample,nParticles,nCells,X,nProcs,run,model,parameter,"
                     << "error_percent,smoothness,conservation,median_s,particles_per_s,"
                     << "peak_memory_MB" << nl;
            }
            os_().precision(8);
        }

        void row(const word& run, const dictionary& dict, const metrics& m)
        {
            // the largest rank's peak so far (every run adds to the same process)
            const scalar memory = returnReduce(peakMemoryMB(), maxOp<scalar>());
            Info<< "    " << run << ": error " << m.error << " %, smoothness " << m.smoothness
                << " 1/m, conservation " << m.conservation << ", median " << m.time << " s"
                << endl;
            if (!os_.valid()) return;
            // only the master writes: nothing collective here
            os_()<< sample_ << ',' << nParticles_ << ',' << nCells_ << ',' << X_ << ','
                 << Pstream::nProcs() << ',' << run << ','
                 << dict.get<word>("voidFractionModel") << ','
                 << dict.getOrDefault<scalar>("parameter", 0) << ',' << m.error << ','
                 << m.smoothness << ',' << m.conservation << ',' << m.time << ','
                 << nParticles_/max(m.time, VSMALL) << ',' << memory << endl;
        }
    };
}


int main(int argc, char *argv[])
{
    argList::addNote("Error, smoothness, conservation and time of void fraction models");
    argList::addOption("dump", "file", "LIGGGHTS text dump (id x y z radius)");
    argList::addOption("sample", "name", "sample name for the CSV (default: the dump's)");

    noRepeatedOptions(argc, argv);
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    if (!args.found("dump"))
    {
        FatalErrorInFunction
            << "missing -dump FILE (a LIGGGHTS text dump)" << exit(FatalError);
    }
    if (args["dump"].empty())
    {
        FatalErrorInFunction << "-dump '': no file name" << exit(FatalError);
    }
    const fileName dumpFile(args.get<fileName>("dump").expand());
    // the sample names a CSV column: a word, without the comma of the CSV
    const std::string sample(args.found("sample") ? args["sample"] : dumpFile.nameLessExt());
    if
    (
        sample.empty() || sample.find(',') != std::string::npos
     || !std::all_of(sample.begin(), sample.end(), [](char c) { return word::valid(c); })
    )
    {
        FatalErrorInFunction
            << "-sample '" << sample.c_str() << "': not a name for the CSV (a word without commas)"
            << exit(FatalError);
    }

    const IOdictionary coupling
    (
        IOobject("couplingProperties", runTime.constant(), mesh, IOobject::MUST_READ)
    );
    const IOdictionary benchDict
    (
        IOobject("voidFractionBenchmarkDict", runTime.system(), mesh, IOobject::MUST_READ)
    );
    checkCouplingProperties(coupling, coupling.filePath());
    const keywordSchema runKeywords(benchmarkKeywords(benchDict));
    const label repeat = benchDict.getOrDefault<label>("repeat", 10);
    fileName csvName(benchDict.getOrDefault<fileName>("csv", "voidFractionBenchmark.csv").expand());
    if (!csvName.isAbsolute()) csvName = runTime.globalPath()/csvName;
    const dictionary& runs = benchDict.subDict("runs");

    const particleData particles(particleData::readLiggghtsDump(dumpFile));
    const scalar rMax = gMax(particles.radii());

    dictionary referenceDict(coupling);
    referenceDict.merge(benchDict.subDict("reference"));
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    const scalar X =
        sizeRatioX(mesh, referenceDict.getOrDefault<bool>("twoDimensional", false), rMax);

    Info<< "Sample " << sample << ": " << particles.size() << " particles, "
        << nCells << " cells, X = " << X << nl << endl;

    scalarField reference;
    const metrics ref = measure(referenceDict, mesh, particles, scalarField(), repeat, &reference);
    if (gMin(reference) <= 0)
    {
        FatalErrorInFunction
            << "the reference field has a void fraction <= 0: Eq. 21 divides by it"
            << exit(FatalError);
    }

    benchmarkCsv csv(csvName, word(sample), particles.size(), nCells, X);
    csv.row("reference", referenceDict, ref);

    for (const entry& e : runs)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(runs)
                << "runs: entry " << e.keyword() << " is not a dictionary"
                << exit(FatalIOError);
        }
        runKeywords.check(e.dict());
        dictionary runDict(coupling);
        runDict.merge(e.dict());
        csv.row(e.keyword(), runDict, measure(runDict, mesh, particles, reference, repeat));
    }

    Info<< nl << "Appended to " << csvName << nl << "End" << endl;
    return 0;
}
