/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleHeatTransfer.H"
#include "voidFractionModel.H"
#include "parcelScaling.H"
#include "particleData.H"
#include "fvm.H"
#include "IOdictionary.H"

namespace
{
    Foam::scalar readPositive
    (
        const Foam::dictionary& dict,
        const Foam::word& name,
        const Foam::dimensionSet& dims
    )
    {
        const Foam::scalar value = Foam::dimensionedScalar(name, dims, dict).value();
        if (!(value > 0))
        {
            FatalIOErrorInFunction(dict)
                << "heatTransfer: " << name << " must be positive, not " << value
                << Foam::exit(Foam::FatalIOError);
        }
        return value;
    }
}


Foam::particleHeatTransfer::particleHeatTransfer
(
    const fvMesh& mesh,
    const dictionary& couplingDict,
    const scalar rho
)
:
    mesh_(mesh),
    correlation_
    (
        heatTransferCorrelation::New(couplingDict.subDict("heatTransfer"), "correlation")
    ),
    rho_(rho),
    Cp_(0),
    kappa_(0),
    T_
    (
        IOobject
        (
            "T",
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    ),
    Kh_
    (
        IOobject("Kh", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(inv(dimTime), Zero)
    ),
    KhTp_
    (
        IOobject("KhTp", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimTemperature/dimTime, Zero)
    ),
    totalHeat_(0),
    worstBalance_(0)
{
    const IOdictionary transport
    (
        IOobject
        (
            "transportProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    Cp_ = readPositive(transport, "Cp", dimensionSet(0, 2, -2, -1, 0));
    kappa_ = readPositive(transport, "kappa", dimensionSet(1, 1, -3, -1, 0));
    Info<< "particleHeatTransfer: gas Cp " << Cp_ << " J/kg/K, kappa " << kappa_
        << " W/m/K" << endl;
}


void Foam::particleHeatTransfer::addKeywords(keywordSchema& schema)
{
    keywordSchema heat("heatTransfer");
    heat.add("correlation", keywordSchema::oneWord);
    schema.add("heatTransfer", heat);
}


Foam::dimensionedScalar Foam::particleHeatTransfer::diffusivity() const
{
    return dimensionedScalar("DT", dimViscosity, kappa_/(rho_*Cp_));
}


void Foam::particleHeatTransfer::beginInterval(const particleForce::state& s)
{
    const particleData& particles = s.particles;
    const vectorField& v = s.velocities;
    const scalarField& Tp = particles.field<scalar>("temperature");
    const scalarField& mcp = particles.field<scalar>("heatCapacity");
    const scalar Pr = s.nu*rho_*Cp_/kappa_;
    const scalar dt = s.interval;
    hA_.setSize(particles.size());
    Tp_ = Tp;
    scalarField cellHA;
    scalarField cellHATp;
    s.voidFraction.gatherApplySpread
    (
        s.voidFraction.voidFraction().primitiveField(), s.U.primitiveField(),
        cellHA, cellHATp,
        [&](const label i, const scalar alphaP, const vector& Up, scalar& a, scalar& aT)
        {
            const scalar w = s.weightSum[i];
            scalar& hA = hA_[i];
            if (w <= SMALL)
            {
                hA = 0;
            }
            else
            {
                const label type = s.type(i);
                const scalar d = s.parcels.particleDiameter(2*particles.radii()[i], type);
                const scalar alpha = alphaP/w;
                const scalar Re = alpha*mag(Up/w - v[i])*d/s.nu;
                const scalar h = correlation_->Nu(Re, Pr, alpha)*kappa_/d;
                // a parcel: one particle's conductance times their number
                const scalar hA0 =
                    s.parcels.dragFactor(type)*h*constant::mathematical::pi*d*d;
                // the particle's lumped solution over the interval
                hA = mcp[i]/dt*(-std::expm1(-hA0*dt/mcp[i]));
            }
            a = hA;
            aT = hA*Tp[i];
        }
    );
    const scalarField& V = mesh_.V();
    const scalar rhoCp = rho_*Cp_;
    Kh_.field() = cellHA/(rhoCp*V);
    KhTp_.field() = cellHATp/(rhoCp*V);
    heatSum_ = scalarField(particles.size(), Zero);
}


Foam::tmp<Foam::fvScalarMatrix> Foam::particleHeatTransfer::exchange
(
    volScalarField& T
) const
{
    return KhTp_ - fvm::Sp(Kh_, T);
}


void Foam::particleHeatTransfer::endStep
(
    const particleForce::state& s,
    const bool last,
    const label fluidSteps
)
{
    scalarField Tf;
    s.voidFraction.gather(T_.primitiveField(), Tf);
    const particleHolders& holders = s.voidFraction.holders();
    // the balance relative to the heat flows the exchange is the
    // difference of (hA T_p): a bed near its gas's temperature exchanges
    // little, and round-off is relative to those flows
    scalar gained = 0, flows = 0;
    forAll(Tf, i)
    {
        const scalar Q = hA_[i]*(Tf[i] - s.weightSum[i]*Tp_[i]);
        heatSum_[i] += Q;
        if (holders.counted(i))
        {
            gained += Q;
            flows += mag(hA_[i]*s.weightSum[i]*Tp_[i]);
        }
    }
    const scalar rhoCp = rho_*Cp_;
    scalarField sums(3);
    sums[0] = gained;
    sums[1] = rhoCp*sum(mesh_.V().field()*(Kh_.field()*T_.primitiveField() - KhTp_.field()));
    sums[2] = flows;
    reduce(sums, sumOp<scalarField>());
    worstBalance_ = max(worstBalance_, mag(sums[1] - sums[0])/max(sums[2], VSMALL));
    if (last)
    {
        heatMean_ = heatSum_/scalar(fluidSteps);
        totalHeat_ = 0;
        forAll(heatMean_, i)
        {
            if (holders.counted(i)) totalHeat_ += heatMean_[i];
        }
        reduce(totalHeat_, sumOp<scalar>());
    }
}


Foam::scalar Foam::particleHeatTransfer::takeWorstBalance()
{
    const scalar worst = worstBalance_;
    worstBalance_ = 0;
    return worst;
}
