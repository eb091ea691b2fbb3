#include "liggghtsCoupling.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "ListListOps.H"

#include <mpi.h>
#include "lammps.h"
#include "input.h"
#include "atom.h"

template<class F>
void Foam::liggghtsCoupling::inDemDir(const F& f) const
{
    const fileName here(cwd());
    chDir(demDir_);
    f();
    chDir(here);
}


Foam::liggghtsCoupling::liggghtsCoupling(const Time& runTime, const dictionary& dict)
:
    lmp_(nullptr),
    ownMpi_(false)
{
    const fileName script(dict.get<fileName>("demScript").expand());
    const fileName path(script.isAbsolute() ? script : runTime.globalPath()/script);
    if (!isFile(path))
    {
        FatalIOErrorInFunction(dict)
            << "demScript: no LIGGGHTS input script " << path << exit(FatalIOError);
    }
    demDir_ = path.path();
    const fileName screen(dict.getOrDefault<fileName>("demScreen", "log.liggghtsScreen"));

    int started = 0;
    MPI_Initialized(&started);
    if (!started)
    {
        MPI_Init(nullptr, nullptr);
        ownMpi_ = true;
    }

    std::string arg0("liggghts"), arg1("-screen"), arg2(screen), arg3("-log"), arg4("none");
    char* argv[] = {&arg0[0], &arg1[0], &arg2[0], &arg3[0], &arg4[0]};
    inDemDir
    (
        [&]()
        {
            // its own communicator: its messages never meet OpenFOAM's
            MPI_Comm comm;
            MPI_Comm_dup(MPI_COMM_WORLD, &comm);
            lmp_ = new LAMMPS_NS::LAMMPS(5, argv, comm);
            lmp_->input->file(path.name().c_str());
        }
    );
    Info<< "liggghtsCoupling: ran " << path << ": " << particles().size()
        << " particles (LIGGGHTS screen output in " << demDir_/screen << ")" << endl;
}


Foam::liggghtsCoupling::~liggghtsCoupling()
{
    delete lmp_;
    if (ownMpi_) MPI_Finalize();
}


void Foam::liggghtsCoupling::command(const string& line)
{
    std::string copy(line);
    inDemDir([&]() { lmp_->input->one(copy.c_str()); });
}


void Foam::liggghtsCoupling::run(const label nSteps)
{
    command("run " + Foam::name(nSteps) + " pre no post no");
}


Foam::particleData Foam::liggghtsCoupling::particles() const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const label n = atom.nlocal;
    List<pointField> positions(Pstream::nProcs());
    List<scalarField> radii(Pstream::nProcs());
    List<labelList> ids(Pstream::nProcs());
    pointField& x = positions[Pstream::myProcNo()];
    scalarField& r = radii[Pstream::myProcNo()];
    labelList& id = ids[Pstream::myProcNo()];
    x.setSize(n);
    r.setSize(n);
    id.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        x[i] = point(atom.x[i][0], atom.x[i][1], atom.x[i][2]);
        r[i] = atom.radius[i];
        id[i] = label(atom.tag[i]);
    }
    if (Pstream::parRun())
    {
        Pstream::gatherList(positions);
        Pstream::scatterList(positions);
        Pstream::gatherList(radii);
        Pstream::scatterList(radii);
        Pstream::gatherList(ids);
        Pstream::scatterList(ids);
    }
    // in id order, whatever the DEM's decomposition
    labelList all(ListListOps::combine<labelList>(ids, accessOp<labelList>()));
    pointField allX(ListListOps::combine<pointField>(positions, accessOp<pointField>()));
    scalarField allR(ListListOps::combine<scalarField>(radii, accessOp<scalarField>()));
    labelList order;
    sortedOrder(all, order);
    pointField sortedX(allX.size());
    scalarField sortedR(allR.size());
    labelList sortedIds(all.size());
    forAll(order, i)
    {
        sortedX[i] = allX[order[i]];
        sortedR[i] = allR[order[i]];
        sortedIds[i] = all[order[i]];
    }
    return particleData(std::move(sortedX), std::move(sortedR), std::move(sortedIds));
}
