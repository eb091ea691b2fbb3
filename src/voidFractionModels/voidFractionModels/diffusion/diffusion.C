/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "diffusion.H"
#include "smoothingDefaults.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoefficients.H"
#include "laplacianScheme.H"
#include "snGradScheme.H"
#include "surfaceInterpolationScheme.H"
#include "fvm.H"
#include "fvc.H"
#include "zeroGradientFvPatchFields.H"
#include "IStringStream.H"
#include "readChoice.H"

namespace Foam
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(diffusion, 0);
    addToRunTimeSelectionTable(voidFractionModel, diffusion, dictionary);
    // what scaleCase needs to know of the coefficients
    const modelCoefficients::add diffusionCoefficients
    (
        diffusion::typeName,
        {
            {"bandwidth", modelCoefficients::smoothingLength, nullptr, ""},
            {
                "coefficient", modelCoefficients::perCellArea,
                smoothingDefaults::diffusionCoefficient, "bandwidth"
            },
            {"nSteps", modelCoefficients::number, nullptr, ""},
            {"initial", modelCoefficients::splitModel, nullptr, ""},
            {"integration", modelCoefficients::choice, nullptr, ""},
            {"laplacianScheme", modelCoefficients::text, nullptr, ""},
            {"solver", modelCoefficients::settings, nullptr, ""}
        }
    );
}
}


const Foam::Enum<Foam::voidFractionModels::diffusion::integration>
Foam::voidFractionModels::diffusion::integrationNames
({
    { integration::implicitEuler, "implicit" },
    { integration::explicitEuler, "explicit" },
});


Foam::dictionary Foam::voidFractionModels::diffusion::defaultSolver()
{
    dictionary d;
    d.add("solver", "PCG");
    d.add("preconditioner", "DIC");
    d.add("tolerance", 1e-12);
    d.add("relTol", 0.0);
    d.add("maxIter", 1000);
    return d;
}


Foam::voidFractionModels::diffusion::diffusion
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(modelType, dict, mesh),
    initial_(newInitialSplit(dict)),
    nSteps_(label(positiveCoeff("nSteps", 1))),
    integration_
    (
        readChoice(coeffs(), "integration", integrationNames, integration::implicitEuler)
    ),
    laplacianScheme_
    (
        coeffs().lookupOrDefault<string>("laplacianScheme", "Gauss linear uncorrected")
    ),
    solverDict_(coeffs().subOrEmptyDict("solver")),
    D_
    (
        IOobject("voidfractionDiffusivity", mesh.time().timeName(), mesh,
                 IOobject::NO_READ, IOobject::NO_WRITE, false),
        mesh,
        dimensionedScalar(dimViscosity, Zero)
    ),
    phi_
    (
        IOobject("voidfractionSmoothing", mesh.time().timeName(), mesh,
                 IOobject::NO_READ, IOobject::NO_WRITE, false),
        mesh,
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    )
{
    smoothSplitOf(initial_.ref());
    if (scalar(nSteps_) != coeffs().lookupOrDefault<scalar>("nSteps", 1))
    {
        FatalIOErrorInFunction(coeffs())
            << "nSteps must be a whole number in " << coeffs().name()
            << exit(FatalIOError);
    }
    if (coeffs().found("bandwidth") && coeffs().found("coefficient"))
    {
        FatalIOErrorInFunction(coeffs())
            << "give bandwidth or coefficient in " << coeffs().name()
            << ", not both" << exit(FatalIOError);
    }
    if (solverDict_.empty()) solverDict_ = defaultSolver();
    readDiffusivity();
    buildLaplacianScheme();
    if (integration_ == integration::explicitEuler) checkExplicitStability();
}


Foam::autoPtr<Foam::voidFractionModel>
Foam::voidFractionModels::diffusion::newInitialSplit(const dictionary& dict) const
{
    const word initial(coeffs().lookupOrDefault<word>("initial", "centroid"));
    if (initial == typeName || !dictionaryConstructorTablePtr_->found(initial))
    {
        DynamicList<word> valid;
        for (const word& w : dictionaryConstructorTablePtr_->sortedToc())
        {
            if (w != typeName) valid.append(w);
        }
        FatalIOErrorInFunction(coeffs())
            << "initial " << initial << " is not one of " << valid
            << " in " << coeffs().name() << exit(FatalIOError);
    }
    // the split is configured where it is named, inside this dictionary
    dictionary splitDict(dict);
    splitDict.set("voidFractionModel", initial);
    const word key(initial + "Coeffs");
    splitDict.set(key, coeffs().subOrEmptyDict(key));
    splitDict.subDict(key).name() = coeffs().name() + '.' + key;
    return voidFractionModel::New(splitDict, mesh());
}


void Foam::voidFractionModels::diffusion::readDiffusivity()
{
    if (coeffs().found("bandwidth"))
    {
        D_ = dimensionedScalar("D", dimViscosity, sqr(positiveCoeff("bandwidth"))/4);
    }
    else
    {
        const scalar a = positiveCoeff
        (
            "coefficient",
            smoothingDefaults::diffusionCoefficient(twoDimensional())
        );
        volScalarField D
        (
            IOobject("D", mesh().time().timeName(), mesh(),
                     IOobject::NO_READ, IOobject::NO_WRITE, false),
            mesh(),
            dimensionedScalar(dimViscosity, Zero),
            zeroGradientFvPatchScalarField::typeName
        );
        forAll(D, celli) D[celli] = a*sqr(cellSize(celli));
        D.correctBoundaryConditions();
        D_ = fvc::interpolate(D);
    }
}


void Foam::voidFractionModels::diffusion::buildLaplacianScheme()
{
    // check the scheme now, against OpenFOAM's tables (its own message for
    // a scheme read from a string names no file)
    IStringStream is(laplacianScheme_);
    const word gauss(is), interpolation(is), snGrad(is);
    if
    (
        gauss != "Gauss"
     || !surfaceInterpolationScheme<scalar>::MeshConstructorTablePtr_->found(interpolation)
     || !fv::snGradScheme<scalar>::MeshConstructorTablePtr_->found(snGrad)
    )
    {
        FatalIOErrorInFunction(coeffs())
            << "laplacianScheme \"" << laplacianScheme_.c_str() << "\" in "
            << coeffs().name() << " is not Gauss <interpolation> <snGrad>;"
            << " valid interpolations: "
            << surfaceInterpolationScheme<scalar>::MeshConstructorTablePtr_->sortedToc()
            << ", valid snGrad schemes: "
            << fv::snGradScheme<scalar>::MeshConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    IStringStream schemeStream(laplacianScheme_);
    scheme_ = fv::laplacianScheme<scalar, scalar>::New(mesh(), schemeStream);
}


void Foam::voidFractionModels::diffusion::checkExplicitStability() const
{
    surfaceScalarField transfer(D_*mesh().magSf()*mesh().nonOrthDeltaCoeffs()/nSteps_);
    // walls carry no flux: only coupled patches pass volume on
    for (fvsPatchScalarField& pf : transfer.boundaryFieldRef())
    {
        if (!pf.coupled()) pf = 0;
    }
    const scalarField given(fvc::surfaceSum(transfer)().primitiveField()/mesh().V());
    const scalar worst = returnReduce(gMax(given), maxOp<scalar>());
    if (worst > 1 + 1e-12)
    {
        FatalIOErrorInFunction(coeffs())
            << "integration explicit is unstable with nSteps " << nSteps_
            << " in " << coeffs().name() << ": a cell would give away "
            << worst << " times what it holds in one step (at most 1; the"
            << " paper's coefficient a at most 1/(2 dim)). Use nSteps "
            << label(std::ceil(worst*nSteps_ - 1e-12))
            << " or more, or integration implicit" << exit(FatalIOError);
    }
}


void Foam::voidFractionModels::diffusion::smoothVolumes(scalarField& cellVolumes)
{
    const scalarField& V = mesh().V();
    phi_.primitiveFieldRef() = cellVolumes/V;
    phi_.correctBoundaryConditions();

    fv::laplacianScheme<scalar, scalar>& scheme = scheme_.ref();
    const dimensionedScalar dTau("dTau", dimTime, 1.0/nSteps_);
    if (integration_ == integration::explicitEuler)
    {
        for (label step = 0; step < nSteps_; ++step)
        {
            phi_ = phi_ + dTau*scheme.fvcLaplacian(D_, phi_);
            phi_.correctBoundaryConditions();
        }
        cellVolumes = phi_.primitiveField()*V;
        return;
    }
    for (label step = 0; step < nSteps_; ++step)
    {
        const volScalarField phiOld("phiOld", phi_);
        fvScalarMatrix eq
        (
            fvm::Sp(1/dTau, phi_) - scheme.fvmLaplacian(D_, phi_)
         == phiOld/dTau
        );
        eq.solve(solverDict_);
        // the solution sets the fluxes; the update from them is conservative
        phi_ = phiOld + dTau*scheme.fvcLaplacian(D_, phi_);
    }
    cellVolumes = phi_.primitiveField()*V;
}
