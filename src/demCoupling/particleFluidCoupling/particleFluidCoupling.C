/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleFluidCoupling.H"
#include "readChoice.H"
#include "couplingKeywords.H"
#include "fvc.H"
#include "particleVtkWriter.H"
#include "StringStream.H"
#include "zeroGradientFvPatchFields.H"
#include "ListListOps.H"
#include "UIndirectList.H"

namespace
{
    Foam::IOobject couplingDictIO(const Foam::fvMesh& mesh)
    {
        return Foam::IOobject
        (
            "couplingProperties",
            mesh.time().constant(),
            mesh,
            Foam::IOobject::MUST_READ_IF_MODIFIED,
            Foam::IOobject::NO_WRITE
        );
    }

    //- The dictionary, once every entry is known and of its kind
    const Foam::dictionary& checked(const Foam::IOdictionary& dict)
    {
        Foam::checkCouplingProperties(dict, dict.filePath());
        return dict;
    }

    //- Each rank's values, joined on the master (empty elsewhere)
    template<class Type>
    Foam::Field<Type> onMaster(const Foam::Field<Type>& mine)
    {
        Foam::List<Foam::Field<Type>> all(Foam::Pstream::nProcs());
        all[Foam::Pstream::myProcNo()] = mine;
        Foam::Pstream::gatherList(all);
        return Foam::ListListOps::combine<Foam::Field<Type>>(all, Foam::accessOp<Foam::Field<Type>>());
    }

    //- Into all, every named field of the counted particles, joined on
    //  the master
    template<class Type>
    void allOnMaster
    (
        const Foam::particleFields<Type>& fields,
        const Foam::labelUList& counted,
        Foam::particleData& all
    )
    {
        for (const Foam::word& name : fields.sortedToc())
        {
            Foam::Field<Type> joined(onMaster(Foam::Field<Type>(fields[name], counted)));
            if (Foam::Pstream::master()) all.set(name, std::move(joined));
        }
    }

    //- Every named field of the particles into the particle file
    template<class Type>
    void writeFields(Foam::particleVtkWriter& vtp, const Foam::particleFields<Type>& fields)
    {
        for (const Foam::word& name : fields.sortedToc()) vtp.write(name, fields[name]);
    }

    Foam::scalar readDensity(const Foam::fvMesh& mesh)
    {
        const Foam::IOdictionary transport
        (
            Foam::IOobject
            (
                "transportProperties",
                mesh.time().constant(),
                mesh,
                Foam::IOobject::MUST_READ,
                Foam::IOobject::NO_WRITE,
                false
            )
        );
        const Foam::scalar rho =
            Foam::dimensionedScalar("rho", Foam::dimDensity, transport).value();
        if (!(rho > 0))
        {
            FatalIOErrorInFunction(transport)
                << "rho must be positive, not " << rho << Foam::exit(Foam::FatalIOError);
        }
        return rho;
    }
}


const Foam::Enum<Foam::particleFluidCoupling::formulation>
Foam::particleFluidCoupling::formulationNames
({
    { formulation::A, "A" },
    { formulation::B, "B" },
});


const Foam::Enum<Foam::particleFluidCoupling::outsideAction>
Foam::particleFluidCoupling::outsideActionNames
({
    { outsideAction::error, "error" },
    { outsideAction::remove, "remove" },
});


const Foam::Enum<Foam::vtk::formatType>
Foam::particleFluidCoupling::particleOutputNames
({
    { vtk::formatType::INLINE_BASE64, "binary" },
    { vtk::formatType::INLINE_ASCII, "ascii" },
});


Foam::particleFluidCoupling::particleFluidCoupling
(
    const fvMesh& mesh,
    const uniformDimensionedVectorField& g
)
:
    mesh_(mesh),
    dict_(couplingDictIO(mesh)),
    // the first member after dict_: the whole file is checked before any read
    rho_((checked(dict_), readDensity(mesh))),
    g_(g.value()),
    formulation_(formulation::A),
    removeOutside_(false),
    parcels_(dict_, dict_.getOrDefault<bool>("twoDimensional", false)),
    nu_(0),
    demForceScale_(1),
    alpha_
    (
        IOobject
        (
            "alpha",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        zeroGradientFvPatchScalarField::typeName
    ),
    Ksl_
    (
        IOobject
        (
            "Ksl",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("zero", inv(dimTime), 0.0),
        zeroGradientFvPatchScalarField::typeName
    ),
    explicitSource_
    (
        IOobject("explicitSource", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector("zero", dimAcceleration, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    reportExchange_(dict_.getOrDefault<bool>("reportExchange", false)),
    particleOutput_
    (
        readChoice(dict_, "particleOutput", particleOutputNames, vtk::formatType::INLINE_BASE64)
    )
{
    // bad names fail before the DEM starts
    readForces();
    voidFraction_ = voidFractionModel::New(dict_, mesh);
    if (dict_.found("heatTransfer"))
    {
        heat_.reset(new particleHeatTransfer(mesh, dict_, rho_));
    }
    distributor_.reset(new particleDistributor(voidFraction_()));
    dem_.reset(new liggghtsCoupling(mesh.time(), dict_));
    if (forces_->needsAccelerations()) dem_->trackAccelerations();
    checkDimensions();
    if (heat_.valid())
    {
        if (voidFraction_->twoDimensional())
        {
            FatalIOErrorInFunction(dict_)
                << "heatTransfer is not available in 2D (twoDimensional)"
                << exit(FatalIOError);
        }
        dem_->enableHeat();
    }
    schedule_.reset(new couplingSchedule(mesh.time(), dict_, dem_->timeStep()));

    // the initial state: the field the first interval starts from
    mapParticles();
    alpha_ = voidFraction_->voidFraction();
    alpha_.oldTime();
    checkParcels();
    Info<< "particleFluidCoupling: formulation " << formulationNames[formulation_] << ", "
        << voidFraction_->stats().nParticles << " particles" << endl;
}


void Foam::particleFluidCoupling::addKeywords(keywordSchema& schema)
{
    couplingSchedule::addKeywords(schema);
    schema.add("formulation", keywordSchema::oneWord);
    particleForceList::addKeywords(schema);
    particleHeatTransfer::addKeywords(schema);
    schema.add("particlesOutside", keywordSchema::oneWord);
    schema.add("reportExchange", keywordSchema::onOff);
    schema.add("particleOutput", keywordSchema::oneWord);
}


void Foam::particleFluidCoupling::readForces()
{
    formulation_ = readChoice(dict_, "formulation", formulationNames, formulation::A);
    forces_.reset
    (
        new particleForceList(dict_, {mesh_, formulation_ == formulation::B})
    );
    removeOutside_ =
        readChoice(dict_, "particlesOutside", outsideActionNames, outsideAction::error)
     == outsideAction::remove;
}


void Foam::particleFluidCoupling::checkDimensions()
{
    const bool twoD = voidFraction_->twoDimensional();
    if (twoD != (dem_->dimension() == 2))
    {
        FatalIOErrorInFunction(dict_)
            << (twoD ? "twoDimensional is set but the DEM script is 3D: 2D"
                       " coupling needs 'dimension 2' (disks in the x-y plane)"
                     : "the DEM script is 2D ('dimension 2') but twoDimensional"
                       " is not set: 2D coupling needs it, on a one-cell-thick mesh")
            << exit(FatalIOError);
    }
    if (!twoD) return;
    if (voidFraction_->emptyDirection() != vector::Z)
    {
        FatalIOErrorInFunction(dict_)
            << "the mesh is one cell thick in "
            << vector::componentNames[voidFraction_->emptyDirection()]
            << ", but a 2D DEM moves its disks in the x-y plane: the mesh must be"
            << " one cell thick in z" << exit(FatalIOError);
    }
    // the disks' masses are per metre of depth, the forces over the slab
    demForceScale_ = 1/voidFraction_->slabThickness();
    Info<< "particleFluidCoupling: 2D, forces to the DEM per metre of depth (slab "
        << voidFraction_->slabThickness() << " m)" << endl;
}


void Foam::particleFluidCoupling::checkParcels() const
{
    if (!parcels_.active()) return;
    parcels_.checkTypes(dem_->nTypes());
    const scalarList& h = parcels_.factors();
    Info<< "particleFluidCoupling: coarse-grained parcels, factor "
        << (h.size() == 1 ? Foam::name(h[0]) : "per DEM type " + Foam::name(h.size()) + " values")
        << " " << h << ", forces scaled "
        << parcelScaling::lawNames[parcels_.forceScaling()] << endl;
    // centroid puts a parcel's whole volume into one cell
    const scalar widest = 2*gMax(particles_.radii());
    const scalar narrowest = gMin(cbrt(mesh_.V().field()));
    if (voidFraction_->type() == "centroid" && widest > narrowest)
    {
        WarningInFunction
            << "parcels up to " << widest << " m wide on cells from "
            << narrowest << " m: centroid puts each parcel's volume into"
            << " one cell; analytical, kernel or diffusion spread it" << endl;
    }
}


void Foam::particleFluidCoupling::mapParticles()
{
    diagnostics_.mark();
    // a serial run reads them in the id order it holds them in
    particleData owned(dem_->particles(!Pstream::parRun()));
    if (Pstream::parRun()) ownedIds_ = owned.ids();
    particleHolders holders(distributor_->distribute(std::move(owned), particles_));
    diagnostics_.charge(couplingDiagnostics::exchange);
    voidFraction_->update(particles_, std::move(holders));
    diagnostics_.charge(couplingDiagnostics::voidFraction);
    handleOutside();
}


void Foam::particleFluidCoupling::handleOutside()
{
    const label nOutside = voidFraction_->stats().nOutside;
    if (nOutside == 0) return;

    // a particle is outside when no rank holds its centre
    const particleHolders& holders = voidFraction_->holders();
    labelList found(particles_.size(), 0);
    forAll(found, i)
    {
        if (voidFraction_->centreCells()[i] >= 0) found[i] = 1;
    }
    holders.combine(found, maxEqOp<label>());
    List<labelList> outside(Pstream::nProcs());
    DynamicList<label> mine;
    forAll(found, i)
    {
        if (!found[i] && holders.counted(i)) mine.append(particles_.ids()[i]);
    }
    outside[Pstream::myProcNo()] = mine;
    Pstream::gatherList(outside);
    Pstream::scatterList(outside);
    const labelList ids(ListListOps::combine<labelList>(outside, accessOp<labelList>()));
    if (!removeOutside_)
    {
        OStringStream first;
        for (label i = 0; i < min(ids.size(), label(20)); ++i) first << " " << ids[i];
        FatalErrorInFunction
            << nOutside << " particles have left the mesh at time "
            << mesh_.time().timeName() << " (ids" << first.str().c_str()
            << (ids.size() > 20 ? " ..." : "")
            << "); set particlesOutside remove in couplingProperties to"
            << " delete them from the DEM instead" << exit(FatalError);
    }
    Info<< "particleFluidCoupling: removing " << nOutside
        << " particles that left the mesh from the DEM" << endl;
    dem_->deleteParticles(ids);
}


Foam::particleForce::state Foam::particleFluidCoupling::forceState
(
    const volVectorField& U
)
{
    return
    {
        U, rho_, nu_, g_, schedule_->interval(), particles_, particles_.velocities(),
        particles_.types(), voidFraction_->particleVolumes(), weightSum_, parcels_,
        voidFraction_(), dem_()
    };
}


Foam::particleData Foam::particleFluidCoupling::particlesOnMaster() const
{
    const particleHolders& holders = voidFraction_->holders();
    DynamicList<label> counted;
    forAll(particles_.ids(), i)
    {
        if (holders.counted(i)) counted.append(i);
    }
    particleData all
    (
        onMaster(pointField(particles_.positions(), counted)),
        onMaster(scalarField(particles_.radii(), counted)),
        onMaster(labelField(UIndirectList<label>(particles_.ids(), counted)))
    );
    // the named fields: the same names on every rank
    allOnMaster(particles_.fields<scalar>(), counted, all);
    allOnMaster(particles_.fields<vector>(), counted, all);
    allOnMaster(particles_.fields<label>(), counted, all);
    if (!Pstream::master()) return particleData();
    labelList order;
    sortedOrder(all.ids(), order);
    return all.reordered(order);
}


void Foam::particleFluidCoupling::beginStep
(
    const volVectorField& U,
    const scalar nu
)
{
    nu_ = nu;
    if (schedule_->startsInterval())
    {
        alphaStart_ = alpha_.primitiveField();
        diagnostics_.mark();
        dem_->run(schedule_->demSteps());
        diagnostics_.charge(couplingDiagnostics::dem);
        mapParticles();
        setMomentumExchange(U);
        if (heat_.valid())
        {
            heat_->beginInterval(forceState(U));
            diagnostics_.charge(couplingDiagnostics::forces);
        }
    }

    const scalar f = schedule_->beginFluidStep();
    alpha_.primitiveFieldRef() =
        (1 - f)*alphaStart_ + f*voidFraction_->voidFraction().primitiveField();
    alpha_.correctBoundaryConditions();
    diagnostics_.mark();
}


void Foam::particleFluidCoupling::setMomentumExchange(const volVectorField& U)
{
    voidFraction_->weightSums(weightSum_);
    scalarField cellBeta;
    vectorField cellExplicit;
    forces_->beginInterval(forceState(U), cellBeta, cellExplicit);
    const scalarField& V = mesh_.V();
    // the equations read the cell values only: the boundaries (and
    // their processor exchange) wait for a write time, see endStep
    Ksl_.primitiveFieldRef() = cellBeta/(rho_*V);
    explicitSource_.primitiveFieldRef() = cellExplicit/(rho_*V);
    forceSum_ = vectorField(particles_.size(), Zero);
    diagnostics_.charge(couplingDiagnostics::forces);
}


void Foam::particleFluidCoupling::addFluidForces
(
    const volVectorField& U,
    const volScalarField& p,
    const bool last,
    vector& dragSum,
    vector& meanSum
)
{
    // the exchanged force with the same weights as the fluid's, and the
    // others; the sums over the particles (each once) in the same pass:
    // this step's exchanged force, and at the end of the interval the mean
    const particleForce::state s(forceState(U));
    vectorField Up;
    forces_->prepareStep(s, p, Up);
    const scalar perStep = 1/scalar(schedule_->fluidSteps());
    const particleHolders& holders = voidFraction_->holders();
    vectorField& F = forceSum_;
    if (last) forceMean_.setSize(F.size());
    forAll(Up, i)
    {
        const vector exchanged(forces_->exchanged(s, i, Up[i]));
        vector f(F[i] + exchanged);
        forces_->addOnParticle(s, i, f);
        F[i] = f;
        const bool counted = holders.counted(i);
        if (counted) dragSum += exchanged;
        if (last)
        {
            forceMean_[i] = f*perStep;
            if (counted) meanSum += forceMean_[i];
        }
    }
}


void Foam::particleFluidCoupling::checkMomentumBalance
(
    const volVectorField& U,
    const bool last,
    const vector& dragSum,
    const vector& meanSum
)
{
    // what the particles gained and what the fluid lost to them in this
    // step's equations; at the end of the interval also the total force
    // and the particles each rank holds, for the log: one reduction
    const label nProcs = Pstream::nProcs();
    scalarField sums(6 + (last ? 3 + nProcs : 0), Zero);
    auto put = [&](const label at, const vector& v)
    {
        for (direction d = 0; d < 3; ++d) sums[at + d] = v[d];
    };
    auto get = [&](const label at)
    {
        return vector(sums[at], sums[at + 1], sums[at + 2]);
    };
    put(0, dragSum);
    put(3, rho_*sum
    (
        mesh_.V().field()*(Ksl_.primitiveField()*U.primitiveField()
      - explicitSource_.primitiveField())
    ));
    if (last)
    {
        put(6, meanSum);
        sums[9 + Pstream::myProcNo()] = particles_.size();
    }
    reduce(sums, sumOp<scalarField>());
    diagnostics_.momentumBalance(get(0), get(3));
    if (last)
    {
        diagnostics_.interval(get(6), label(max(SubList<scalar>(sums, nProcs, 9))));
    }
}


void Foam::particleFluidCoupling::endStep
(
    const volVectorField& U,
    const volScalarField& p
)
{
    diagnostics_.charge(couplingDiagnostics::fluid);

    // at the end of the interval the mean force goes to the DEM
    const bool last = schedule_->endsInterval();
    vector dragSum(Zero), meanSum(Zero);
    addFluidForces(U, p, last, dragSum, meanSum);
    checkMomentumBalance(U, last, dragSum, meanSum);
    if (heat_.valid()) heat_->endStep(forceState(U), last, schedule_->fluidSteps());
    if (mesh_.time().writeTime())
    {
        Ksl_.correctBoundaryConditions();
        explicitSource_.correctBoundaryConditions();
    }
    diagnostics_.charge(couplingDiagnostics::forces);

    if (last)
    {
        pushForces();
    }
}


void Foam::particleFluidCoupling::pushForces()
{
    diagnostics_.mark();
    vectorField& F = forceMean_;
    if (demForceScale_ != 1) F *= demForceScale_;
    const particleHolders& holders = voidFraction_->holders();
    // the holders agree on each value: one copy goes to its owner
    const labelList& ids = holders.distributed() ? ownedIds_ : particles_.ids();
    holders.toOwners(F);
    dem_->setForces(ids, F);
    if (heat_.valid())
    {
        gasEnergyBalance& energy = heat_->energy();
        Info<< "heat exchange " << schedule_->nCouplings() << ": to the particles "
            << heat_->totalHeat() << " W, balance " << heat_->takeWorstBalance()
            << "; gas energy balance " << energy.worstBalance()
            << ", continuity errors' heat " << energy.worstContinuity() << endl;
        energy.reset();
        scalarField& Q = heat_->heatMean();
        holders.toOwners(Q);
        dem_->setHeatFluxes(ids, Q);
    }
    diagnostics_.charge(couplingDiagnostics::exchange);

    diagnostics_.log(schedule_->nCouplings(), voidFraction_->stats());
    if (reportExchange_) distributor_->writeExchange(Info);
    schedule_->endInterval();
}


void Foam::particleFluidCoupling::write()
{
    const Time& runTime = mesh_.time();
    const fileName dir(runTime.globalPath()/runTime.timeName());
    // in parallel the time directories are the processors'; LIGGGHTS writes
    // one file from the master
    dem_->writeRestart(dir);
    const particleData all(particlesOnMaster());
    if (!Pstream::master()) return;

    const fileName file("particles_" + Foam::name(runTime.timeIndex()) + ".vtp");
    particleVtkWriter vtp(particleOutput_, runTime.globalPath()/"VTK"/file);
    vtp.writeGeometry(all.positions(), "time='" + runTime.timeName() + "'");
    vtp.write("radius", all.radii());
    vtp.write("id", all.ids());
    writeFields(vtp, all.fields<scalar>());
    writeFields(vtp, all.fields<vector>());
    writeFields(vtp, all.fields<label>());
    vtp.close();

    // a restarted run continues the series: later entries are dropped
    const fileName series(runTime.globalPath()/"VTK"/"particles.vtp");
    if (particleSeries_.empty()) particleSeries_.load(series, true, runTime.value());
    particleSeries_.append(runTime.value(), file);
    particleSeries_.write(series);
}
