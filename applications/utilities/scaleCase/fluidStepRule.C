/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "fluidStepRule.H"
#include "caseFiles.H"
#include "Function1.H"
#include "vector.H"
#include "error.H"
#include "OSspecific.H"
#include "particleForceList.H"
#include "dragModel.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidStepRule::fluidStepRule
(
    const fileName& dir,
    const scalar courant,
    const scalar diameter,
    const scalar density,
    const scalar slower
)
:
    courant_(courant),
    gasSpeed_(0),
    responseTime_(GREAT)
{
    fileName Ufile(dir/"0"/"U");
    if (!isFile(Ufile)) Ufile = dir/"0.orig"/"U";
    const scalar inlet = inletSpeed(Ufile);
    if (!(inlet > 0))
    {
        FatalErrorInFunction
            << "-courant: no inlet velocity in " << Ufile << " (a fixedValue patch with a"
            << " uniform value, or uniformFixedValue) to bound the gas's speed"
            << exit(FatalError);
    }
    gasSpeed_ = inlet/packedVoidFraction;
    if (!(diameter > 0 && density > 0))
    {
        FatalErrorInFunction
            << "-courant: DEM/in.parameters names no {particle} radius or diameter and"
            << " density (kg/m^3) for the parcels' drag response time" << exit(FatalError);
    }
    const fileName transport(dir/"constant"/"transportProperties");
    const dictionary gas(caseFiles::readDict(transport));
    const scalar rho = gas.get<scalar>("rho");
    const scalar mu = gas.get<scalar>("nu")*rho;
    // the case's own drag law, as the solver reads it
    const dictionary coupling(caseFiles::readDict(dir/"constant"/"couplingProperties"));
    dictionary shortForm;
    const dictionary& drag =
        particleForceList::forcesDict(coupling, shortForm).subDict("drag");
    const autoPtr<dragModel> law(dragModel::New(drag, "model"));
    dragModel::particleState p;
    p.d = diameter;
    p.Vp = constant::mathematical::pi*pow3(diameter)/6;
    p.alpha = packedVoidFraction;
    p.magUr = gasSpeed_;
    p.rho = rho;
    p.mu = mu;
    responseTime_ = slower*density*p.Vp/law->beta(p);
    Info<< "    the gas's speed: at most " << gasSpeed_ << " m/s (the inlet's " << inlet
        << " m/s through the densest packing, void fraction " << packedVoidFraction << ")" << nl
        << "    the parcels' drag response time there: " << responseTime_ << " s ("
        << drag.get<word>("model") << ", particles of " << diameter << " m, " << density
        << " kg/m^3, gas " << rho << " kg/m^3, " << mu << " Pa s"
        << (slower > 1 ? ", times h for the exact law)" : ")") << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fluidStepRule::inletSpeed(const fileName& file)
{
    const dictionary field(caseFiles::readDict(file));
    const dictionary* patches = field.findDict("boundaryField");
    if (!patches) return 0;
    const fileName control(file.path().path()/"system"/"controlDict");
    const dictionary times(isFile(control) ? caseFiles::readDict(control) : dictionary());
    const scalar start = times.getOrDefault<scalar>("startTime", 0);
    const scalar end = times.getOrDefault<scalar>("endTime", start);
    scalar fastest = 0;
    for (const entry& patch : *patches)
    {
        if (!patch.isDict()) continue;
        const dictionary& d = patch.dict();
        const word type(d.getOrDefault<word>("type", word::null));
        if (type == "fixedValue" && d.found("value"))
        {
            ITstream& is = d.lookup("value");
            const token kind(is);
            if (kind.isWord() && kind.wordToken() == "uniform")
            {
                fastest = max(fastest, mag(vector(is)));
            }
        }
        else if (type == "uniformFixedValue")
        {
            // any Function1 (constant, table, ...), sampled over the run
            autoPtr<Function1<vector>> value(Function1<vector>::New("uniformValue", d));
            const label samples = 10000;
            for (label i = 0; i <= samples; ++i)
            {
                fastest = max(fastest, mag(value->value(start + (end - start)*i/samples)));
            }
        }
    }
    return fastest;
}


Foam::scalar Foam::fluidStepRule::maxStep
(
    const scalar narrowestCell,
    const scalar couplingSteps
) const
{
    const scalar byCourant = courant_*narrowestCell/gasSpeed_;
    const scalar byResponse = 0.1*responseTime_/couplingSteps;
    Info<< "    fluid step by the Courant number " << courant_ << " on cells of "
        << narrowestCell << " m: " << byCourant << " s; by the coupling time at most a"
        << " tenth of the response time: " << byResponse << " s" << nl;
    return min(byCourant, byResponse);
}


// ************************************************************************* //
