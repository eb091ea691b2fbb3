/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "liggghtsCoupling.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "IFstream.H"
#include "OFstream.H"
#include "ListListOps.H"
#include "mathematicalConstants.H"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mpi.h>
#include "lammps.h"
#include "input.h"
#include "atom.h"
#include "update.h"
#include "domain.h"
#include "modify.h"
#include "fix_property_atom.h"
#include "fix_property_global.h"

namespace
{
    //- The screen file and the work of the LIGGGHTS call under way, for the
    //  exit handler: LIGGGHTS ends the process with exit() on an input
    //  error, and says why only on its screen
    std::string activeScreen;
    std::string activeWork;

    void reportLiggghtsExit()
    {
        if (activeScreen.empty()) return;
        std::fflush(nullptr);
        std::cerr << "\n--> LIGGGHTS stopped the run while " << activeWork
            << "; its message (from " << activeScreen << "):\n";
        std::ifstream screen(activeScreen);
        std::string line, last;
        bool found = false;
        while (std::getline(screen, line))
        {
            if (line.find("ERROR") != std::string::npos)
            {
                std::cerr << "    " << line << "\n";
                found = true;
            }
            last = line;
        }
        if (!found) std::cerr << "    " << last << "\n";
        std::cerr << std::flush;
    }
}


template<class F>
void Foam::liggghtsCoupling::inDemDir(const F& f, const std::string& work) const
{
    static const bool registered = (std::atexit(reportLiggghtsExit) == 0);
    (void)registered;
    const fileName here(cwd());
    chDir(demDir_);
    activeScreen = demDir_/screen_;
    activeWork = work;
    f();
    activeScreen.clear();
    chDir(here);
}


Foam::liggghtsCoupling::liggghtsCoupling(const Time& runTime, const dictionary& dict)
:
    lmp_(nullptr),
    ownMpi_(false),
    setUpNextRun_(false),
    restart_(restartFile(runTime)),
    heat_(false)
{
    // a run starting from a time the solver wrote continues the DEM from
    // the restart file written with it
    const fileName& restart = restart_;
    const bool restarting = !restart.empty();
    // a restart runs demRestartScript where there is one, else demScript
    // (whose 'variable demRestart index <initial state>' the command line
    // overrides)
    keywordSchema::checkKind(dict, "demScript", keywordSchema::fileOrWord);
    keywordSchema::checkKind(dict, "demRestartScript", keywordSchema::fileOrWord);
    keywordSchema::checkKind(dict, "demScreen", keywordSchema::fileOrWord);
    const word scriptKey
    (
        restarting && dict.found("demRestartScript") ? "demRestartScript" : "demScript"
    );
    const fileName script(dict.get<fileName>(scriptKey).expand());
    const fileName path(script.isAbsolute() ? script : runTime.globalPath()/script);
    if (!isFile(path))
    {
        FatalIOErrorInFunction(dict)
            << scriptKey << ": no LIGGGHTS input script " << path
            << exit(FatalIOError);
    }
    demDir_ = path.path();
    screen_ = dict.getOrDefault<fileName>("demScreen", "log.liggghtsScreen");
    const fileName& screen = screen_;

    int started = 0;
    MPI_Initialized(&started);
    if (!started)
    {
        MPI_Init(nullptr, nullptr);
        ownMpi_ = true;
    }

    // a continued run tells the script where from (demRestart) and that it
    // continues (demContinue 1: outputs append instead of starting anew)
    std::string args[] =
    {
        "liggghts", "-screen", screen, "-log", "none",
        "-var", "demRestart", restart, "-var", "demContinue", "1"
    };
    char* argv[11];
    for (label i = 0; i < 11; ++i) argv[i] = &args[i][0];
    const int argc = restarting ? 11 : 5;
    // said first: an error LIGGGHTS ends with MPI_Abort leaves no exit
    // handler a chance, and its reason is on this screen only
    Info<< "liggghtsCoupling: running " << path << " (LIGGGHTS screen output in "
        << demDir_/screen << ")" << endl;
    inDemDir
    (
        [&]()
        {
            // its own communicator: its messages never meet OpenFOAM's
            MPI_Comm comm;
            MPI_Comm_dup(MPI_COMM_WORLD, &comm);
            lmp_ = new LAMMPS_NS::LAMMPS(argc, argv, comm);
            lmp_->input->file(path.name().c_str());
        },
        "running " + path
    );
    if (restarting) restoreForces(restart);
    Info<< "liggghtsCoupling: " << nParticles() << " particles" << endl;
}


Foam::fileName Foam::liggghtsCoupling::restartFile(const Time& runTime)
{
    const fileName dir(runTime.globalPath()/runTime.timeName());
    const fileName restart(dir/"DEM.restart");
    const fileName forces(dir/"DEM.forces");
    // the solver wrote this time: it wrote alpha there, or the case has
    // earlier times (a run starts from its first)
    bool written = isFile(runTime.timePath()/"alpha") || isFile(runTime.timePath()/"alpha.gz");
    for (const instant& t : runTime.times())
    {
        if (t.name() != runTime.constant() && t.value() < runTime.value()) written = true;
    }
    written = returnReduce(written || isFile(restart), orOp<bool>());
    if (!written) return fileName();

    string problem;
    if (!isFile(restart) || !isFile(forces))
    {
        problem = "has no " + word(isFile(restart) ? "DEM.forces" : "DEM.restart");
    }
    else
    {
        IFstream is(forces, IOstream::BINARY);
        word key;
        scalar bytes = -1;
        is >> key >> bytes;
        const scalar found(fileSize(restart));
        if (key != "restartBytes" || bytes != found)
        {
            problem = "has a DEM.restart of " + Foam::name(found) + " bytes where the run wrote "
                + Foam::name(bytes);
        }
    }
    if (!problem.empty())
    {
        FatalErrorInFunction
            << "the run starts from time " << runTime.timeName() << ", whose directory " << dir
            << " " << problem.c_str() << ": it was written incompletely (a run stopped"
            << " while writing?). Remove it to continue from the time before, or set"
            << " startFrom/startTime in system/controlDict" << exit(FatalError);
    }
    return restart;
}


void Foam::liggghtsCoupling::restoreForces(const fileName& restart)
{
    const fileName path(restart.path()/"DEM.forces");
    IFstream is(path, IOstream::BINARY);
    word key;
    scalar bytes, step = -1;
    labelList ids;
    vectorField forces;
    const bool throwing = FatalIOError.throwExceptions();
    try
    {
        is >> key >> bytes >> key >> step >> ids >> forces;
    }
    catch (const Foam::IOerror&)
    {
        ids.clear();
    }
    FatalIOError.throwExceptions(throwing);
    if (is.bad() || ids.size() != nParticles() || forces.size() != ids.size())
    {
        FatalErrorInFunction
            << path << " holds " << ids.size() << " ids and " << forces.size()
            << " forces for the " << nParticles() << " particles of " << restart
            << ": it is damaged; remove " << restart.path()
            << " to continue from the time before" << exit(FatalError);
    }
    if (step != scalar(lmp_->update->ntimestep))
    {
        FatalErrorInFunction
            << "the DEM script " << demDir_ << " did not continue from " << restart
            << " (the DEM is at step " << label(lmp_->update->ntimestep) << ", the file at "
            << step << "): read it with 'read_restart ${demRestart}' (the initial state"
            << " given by 'variable demRestart index <file>' before it), or name a"
            << " script that does in demRestartScript" << exit(FatalError);
    }
    setForces(ids, forces);
    setUpNextRun_ = true;
}


void Foam::liggghtsCoupling::writeRestart(const fileName& dir)
{
    if (Pstream::master()) mkDir(dir);
    command("write_restart " + (dir/"DEM.restart"));

    // the fluid force the DEM applies until the next coupling, by id
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    double** f = forceArray();
    const label me = Pstream::myProcNo();
    List<labelList> ids(Pstream::nProcs());
    List<vectorField> forces(Pstream::nProcs());
    // and the velocities kept for the accelerations, with their flags
    double** previous = previousVelocityArray();
    List<vectorField> previousV(Pstream::nProcs());
    List<scalarField> previousSet(Pstream::nProcs());
    ids[me].setSize(atom.nlocal);
    forces[me].setSize(atom.nlocal);
    previousV[me].setSize(previous ? atom.nlocal : 0);
    previousSet[me].setSize(previous ? atom.nlocal : 0);
    for (label i = 0; i < atom.nlocal; ++i)
    {
        ids[me][i] = label(atom.tag[i]);
        forces[me][i] = vector(f[i][0], f[i][1], f[i][2]);
        if (previous)
        {
            previousV[me][i] = vector(previous[i][0], previous[i][1], previous[i][2]);
            previousSet[me][i] = previous[i][3];
        }
    }
    // the heat the particles were handed for the next interval, in
    // DEM.heat, written before DEM.forces whose presence says all is there
    if (heat_) writeHeat(dir);

    // a restart sets LIGGGHTS up (neighbour lists, contact histories)
    // before its first step, which a run going on does not: the next run
    // from here is set up alike, so that the two continue identically
    setUpNextRun_ = true;
    Pstream::gatherList(ids);
    Pstream::gatherList(forces);
    Pstream::gatherList(previousV);
    Pstream::gatherList(previousSet);
    if (!Pstream::master()) return;

    // written last and renamed when complete: its presence says the
    // directory is whole
    const fileName tmpPath(dir/"DEM.forces.tmp");
    {
        OFstream os(tmpPath, IOstream::BINARY);
        os.precision(17);
        os  << word("restartBytes") << token::SPACE << scalar(fileSize(dir/"DEM.restart")) << nl
            << word("demStep") << token::SPACE << scalar(lmp_->update->ntimestep) << nl
            << ListListOps::combine<labelList>(ids, accessOp<labelList>()) << nl
            << ListListOps::combine<vectorField>(forces, accessOp<vectorField>()) << nl;
        if (previous)
        {
            os  << ListListOps::combine<vectorField>(previousV, accessOp<vectorField>()) << nl
                << ListListOps::combine<scalarField>(previousSet, accessOp<scalarField>()) << nl;
        }
    }
    mv(tmpPath, dir/"DEM.forces");
}


void Foam::liggghtsCoupling::writeHeat(const fileName& dir) const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const double* q = heatArray("convectiveHeatFlux");
    const label me = Pstream::myProcNo();
    List<labelList> ids(Pstream::nProcs());
    List<scalarField> heat(Pstream::nProcs());
    ids[me].setSize(atom.nlocal);
    heat[me].setSize(atom.nlocal);
    for (label i = 0; i < atom.nlocal; ++i)
    {
        ids[me][i] = label(atom.tag[i]);
        heat[me][i] = q[i];
    }
    Pstream::gatherList(ids);
    Pstream::gatherList(heat);
    if (!Pstream::master()) return;
    OFstream os(dir/"DEM.heat", IOstream::BINARY);
    os.precision(17);
    os  << ListListOps::combine<labelList>(ids, accessOp<labelList>()) << nl
        << ListListOps::combine<scalarField>(heat, accessOp<scalarField>()) << nl;
}


Foam::liggghtsCoupling::~liggghtsCoupling()
{
    delete lmp_;
    if (ownMpi_) MPI_Finalize();
}


void Foam::liggghtsCoupling::command(const string& line)
{
    std::string copy(line);
    inDemDir([&]() { lmp_->input->one(copy.c_str()); }, "executing '" + copy + "'");
}


void Foam::liggghtsCoupling::run(const label nSteps)
{
    command("run " + Foam::name(nSteps) + (setUpNextRun_ ? " pre yes" : " pre no") + " post no");
    setUpNextRun_ = false;
}


void Foam::liggghtsCoupling::deleteParticles(const labelUList& ids)
{
    if (ids.empty()) return;
    string list;
    for (const label id : ids) list += " " + Foam::name(id);
    command("group vfmDelete id" + list);
    command("delete_atoms group vfmDelete");
    command("group vfmDelete delete");
}


Foam::labelList Foam::liggghtsCoupling::idOrder() const
{
    LAMMPS_NS::Atom& atom = *lmp_->atom;
    const label n = atom.nlocal;
    labelList order(n);
    // ids up to about the count (the usual 1..N): walk them through the
    // DEM's own id map, no sort
    label k = 0;
    if (atom.map_style && atom.map_tag_max <= 2*n + 16)
    {
        for (label id = 1; id <= atom.map_tag_max && k < n; ++id)
        {
            const label i = atom.map(id);
            if (i >= 0 && i < n) order[k++] = i;
        }
    }
    if (k != n)
    {
        labelList ids(n);
        for (label i = 0; i < n; ++i) ids[i] = label(atom.tag[i]);
        sortedOrder(ids, order);
    }
    return order;
}


Foam::label Foam::liggghtsCoupling::ownedAtom(const label id) const
{
    LAMMPS_NS::Atom& atom = *lmp_->atom;
    if (id < 1 || id > atom.map_tag_max) return -1;
    // map() also knows ghost atoms: only the owner's copy counts
    const label i = atom.map(id);
    return (i < atom.nlocal) ? i : -1;
}


Foam::particleData Foam::liggghtsCoupling::particles(const bool inIdOrder) const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    LAMMPS_NS::Domain& domain = *lmp_->domain;
    const label n = atom.nlocal;
    const labelList order(inIdOrder ? idOrder() : labelList());
    List<point> x(n);
    List<vector> v(n);
    List<scalar> r(n);
    List<label> id(n), type(n);
    // an orthogonal box leaves a position within its periodic bounds as it
    // is: only the others go through remap
    const int periodic[3] = {domain.xperiodic, domain.yperiodic, domain.zperiodic};
    auto inBox = [&](const double* xi)
    {
        for (direction d = 0; d < 3; ++d)
        {
            if (periodic[d] && !(xi[d] >= domain.boxlo[d] && xi[d] < domain.boxhi[d]))
            {
                return false;
            }
        }
        return !domain.triclinic;
    };
    for (label k = 0; k < n; ++k)
    {
        const label i = inIdOrder ? order[k] : k;
        // between re-neighbourings LIGGGHTS lets atoms drift past a
        // periodic side; the mesh sees them wrapped into the box
        double xi[3] = {atom.x[i][0], atom.x[i][1], atom.x[i][2]};
        if (!inBox(xi)) domain.remap(xi);
        x[k] = point(xi[0], xi[1], xi[2]);
        v[k] = vector(atom.v[i][0], atom.v[i][1], atom.v[i][2]);
        r[k] = atom.radius[i];
        id[k] = label(atom.tag[i]);
        type[k] = label(atom.type[i]);
    }
    particleData result(pointField(std::move(x)), scalarField(std::move(r)), std::move(id));
    result.setVelocities(vectorField(std::move(v)));
    result.setTypes(std::move(type));
    if (heat_)
    {
        const double* T = heatArray("Temp");
        const scalarList cp(thermalCapacities());
        scalarField temperature(n), capacity(n);
        for (label k = 0; k < n; ++k)
        {
            const label i = inIdOrder ? order[k] : k;
            temperature[k] = T[i];
            capacity[k] = atom.rmass[i]*cp[atom.type[i] - 1];
        }
        result.set("temperature", std::move(temperature));
        result.set("heatCapacity", std::move(capacity));
    }
    return result;
}


double** Foam::liggghtsCoupling::previousVelocityArray() const
{
    LAMMPS_NS::Fix* fix = lmp_->modify->find_fix_property
    (
        "vfmPreviousVelocity", "property/atom", "vector", 0, 0, "pimpleDEMFoam", false
    );
    return fix ? static_cast<LAMMPS_NS::FixPropertyAtom*>(fix)->array_atom : nullptr;
}


void Foam::liggghtsCoupling::trackAccelerations()
{
    if (previousVelocityArray()) return;
    command
    (
        "fix vfmPreviousVelocity all property/atom vfmPreviousVelocity"
        " vector no no no 0 0 0 0"
    );
    if (restart_.empty()) return;

    // a continued run: the velocities written with DEM.forces (LIGGGHTS
    // drops a restart file's per-atom data at the script's first run)
    const fileName path(restart_.path()/"DEM.forces");
    IFstream is(path, IOstream::BINARY);
    word key;
    scalar bytes, step;
    labelList ids;
    vectorField forces, previousV;
    scalarField previousSet;
    const bool throwing = FatalIOError.throwExceptions();
    try
    {
        is >> key >> bytes >> key >> step >> ids >> forces >> previousV >> previousSet;
    }
    catch (const Foam::IOerror&)
    {
        previousV.clear();
    }
    FatalIOError.throwExceptions(throwing);
    if (previousV.size() != ids.size() || previousSet.size() != ids.size())
    {
        WarningInFunction
            << path << " holds no particle velocities (written without"
            << " virtualMass): the first interval takes the particles as"
            << " not accelerating" << endl;
        return;
    }
    // LIGGGHTS sets a new fix's values to their defaults at its first
    // run: they go in after it (meanAccelerations)
    restoredIds_.transfer(ids);
    restoredVelocities_.transfer(previousV);
    restoredFlags_.transfer(previousSet);
}


Foam::vectorField Foam::liggghtsCoupling::meanAccelerations
(
    const scalar interval,
    const bool inIdOrder
)
{
    double** previous = previousVelocityArray();
    if (!previous)
    {
        FatalErrorInFunction
            << "trackAccelerations() was not called" << abort(FatalError);
    }
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    forAll(restoredIds_, k)
    {
        const label i = ownedAtom(restoredIds_[k]);
        if (i < 0) continue;
        for (direction d = 0; d < 3; ++d) previous[i][d] = restoredVelocities_[k][d];
        previous[i][3] = restoredFlags_[k];
    }
    restoredIds_.clear();
    const label n = atom.nlocal;
    const labelList order(inIdOrder ? idOrder() : labelList());
    vectorField a(n, Zero);
    for (label k = 0; k < n; ++k)
    {
        const label i = inIdOrder ? order[k] : k;
        double* p = previous[i];
        const vector v(atom.v[i][0], atom.v[i][1], atom.v[i][2]);
        if (p[3] > 0.5) a[k] = (v - vector(p[0], p[1], p[2]))/interval;
        p[0] = v.x();
        p[1] = v.y();
        p[2] = v.z();
        p[3] = 1;
    }
    return a;
}


Foam::scalar Foam::liggghtsCoupling::lightestDensity() const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const bool disks = (dimension() == 2);
    scalar lightest = GREAT;
    for (label i = 0; i < atom.nlocal; ++i)
    {
        const scalar r = atom.radius[i];
        const scalar size = disks ? constant::mathematical::pi*r*r
                                  : 4.0/3.0*constant::mathematical::pi*r*r*r;
        lightest = min(lightest, atom.rmass[i]/size);
    }
    return returnReduce(lightest, minOp<scalar>());
}


Foam::label Foam::liggghtsCoupling::nParticles() const
{
    return label(lmp_->atom->natoms);
}


Foam::label Foam::liggghtsCoupling::nTypes() const
{
    return label(lmp_->atom->ntypes);
}


Foam::scalar Foam::liggghtsCoupling::timeStep() const
{
    return lmp_->update->dt;
}


Foam::label Foam::liggghtsCoupling::dimension() const
{
    return lmp_->domain->dimension;
}


double** Foam::liggghtsCoupling::forceArray() const
{
    LAMMPS_NS::Fix* fix = lmp_->modify->find_fix_property
    (
        "dragforce", "property/atom", "vector", 0, 0, "pimpleDEMFoam", false
    );
    if (!fix)
    {
        FatalErrorInFunction
            << "the DEM script " << demDir_ << " has no 'fix couple/cfd/force'"
            << " (with 'fix couple/cfd couple_every N mpi' and 'atom_modify"
            << " map array'): the fluid forces cannot reach the particles"
            << exit(FatalError);
    }
    return static_cast<LAMMPS_NS::FixPropertyAtom*>(fix)->array_atom;
}


template<class Set, class Clear>
void Foam::liggghtsCoupling::setOwned
(
    const labelList& ids,
    const Set& set,
    const Clear& clear
) const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    // the atoms as particles() listed them (no DEM step since): no id
    // lookup
    bool inLocalOrder = (ids.size() == atom.nlocal);
    for (label i = 0; inLocalOrder && i < atom.nlocal; ++i)
    {
        inLocalOrder = (ids[i] == label(atom.tag[i]));
    }
    if (inLocalOrder)
    {
        for (label i = 0; i < atom.nlocal; ++i) set(i, i);
        return;
    }
    for (label i = 0; i < atom.nlocal; ++i) clear(i);
    forAll(ids, k)
    {
        const label i = ownedAtom(ids[k]);
        if (i >= 0) set(i, k);
    }
}


void Foam::liggghtsCoupling::setForces
(
    const labelList& ids,
    const vectorField& forces
)
{
    double** f = forceArray();
    setOwned
    (
        ids,
        [&](const label i, const label k)
        {
            f[i][0] = forces[k].x();
            f[i][1] = forces[k].y();
            f[i][2] = forces[k].z();
        },
        [&](const label i) { f[i][0] = f[i][1] = f[i][2] = 0; }
    );
}


double* Foam::liggghtsCoupling::heatArray(const word& name) const
{
    LAMMPS_NS::Fix* fix = lmp_->modify->find_fix_property
    (
        name.c_str(), "property/atom", "scalar", 0, 0, "pimpleDEMFoam", false
    );
    if (!fix)
    {
        FatalErrorInFunction
            << "heatTransfer: the DEM script " << demDir_ << " has no per-particle "
            << name << ": it needs 'fix couple/cfd/convection T0 <initial K>',"
            << " which gives the particles a temperature and the gas's heat"
            << exit(FatalError);
    }
    return static_cast<LAMMPS_NS::FixPropertyAtom*>(fix)->vector_atom;
}


Foam::scalarList Foam::liggghtsCoupling::thermalCapacities() const
{
    const label nTypes = lmp_->atom->ntypes;
    LAMMPS_NS::Fix* fix = lmp_->modify->find_fix_property
    (
        "thermalCapacity", "property/global", "peratomtype", nTypes, 0,
        "pimpleDEMFoam", false
    );
    if (!fix)
    {
        FatalErrorInFunction
            << "heatTransfer: the DEM script " << demDir_ << " has no"
            << " 'fix ... property/global thermalCapacity peratomtype c1 c2 ...'"
            << exit(FatalError);
    }
    scalarList cp(nTypes);
    forAll(cp, t)
    {
        cp[t] = static_cast<LAMMPS_NS::FixPropertyGlobal*>(fix)->compute_vector(t);
        if (!(cp[t] > 0))
        {
            FatalErrorInFunction
                << "heatTransfer: the DEM script's thermalCapacity of atom type "
                << t + 1 << " is " << cp[t] << ": it must be positive"
                << exit(FatalError);
        }
    }
    return cp;
}


void Foam::liggghtsCoupling::enableHeat()
{
    heat_ = true;
    // every piece the exchange needs, or an error naming it, now
    heatArray("Temp");
    heatArray("convectiveHeatFlux");
    thermalCapacities();
    if (restart_.empty()) return;

    // a continued run: the heat each particle had been handed for the
    // interval after the written time (LIGGGHTS's restart file lacks it)
    const fileName path(restart_.path()/"DEM.heat");
    labelList ids;
    scalarField heat;
    if (isFile(path))
    {
        IFstream is(path, IOstream::BINARY);
        const bool throwing = FatalIOError.throwExceptions();
        try
        {
            is >> ids >> heat;
        }
        catch (const Foam::IOerror&)
        {
            ids.clear();
        }
        FatalIOError.throwExceptions(throwing);
    }
    if (ids.size() != nParticles() || heat.size() != ids.size())
    {
        FatalErrorInFunction
            << path << " holds " << ids.size() << " ids and " << heat.size()
            << " heat fluxes for the " << nParticles() << " particles of " << restart_
            << ": a run with heatTransfer continues only from a time it wrote"
            << " (remove " << restart_.path() << " to continue from the time before)"
            << exit(FatalError);
    }
    setHeatFluxes(ids, heat);
}


void Foam::liggghtsCoupling::setHeatFluxes
(
    const labelList& ids,
    const scalarField& Q
)
{
    double* q = heatArray("convectiveHeatFlux");
    setOwned
    (
        ids,
        [&](const label i, const label k) { q[i] = Q[k]; },
        [&](const label i) { q[i] = 0; }
    );
}


void Foam::liggghtsCoupling::addKeywords(keywordSchema& schema)
{
    schema.add("demScript", keywordSchema::fileOrWord);
    schema.add("demRestartScript", keywordSchema::fileOrWord);
    schema.add("demScreen", keywordSchema::fileOrWord);
}
