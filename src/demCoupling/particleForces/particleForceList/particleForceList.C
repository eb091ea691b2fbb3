/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleForceList.H"
#include "voidFractionModel.H"

namespace
{
    //- The short form's forces, in the order their sums were always taken
    const Foam::wordList shortFormOrder
    ({
        "pressureGradient", "buoyancy", "SaffmanMeiLift", "virtualMass"
    });
}


void Foam::particleForceList::addKeywords(keywordSchema& schema)
{
    schema.add("forces", keywordSchema::wordsOrDictionary);
    schema.add("dragModel", keywordSchema::oneWord);
    schema.add("virtualMassCoefficient", keywordSchema::oneNumber);
}


const Foam::dictionary& Foam::particleForceList::forcesDict
(
    const dictionary& couplingDict,
    dictionary& shortForm
)
{
    const entry* given = couplingDict.findEntry("forces", keyType::LITERAL);
    if (given && given->isDict())
    {
        for (const word shortOnly : {"dragModel", "virtualMassCoefficient"})
        {
            if (couplingDict.found(shortOnly, keyType::LITERAL))
            {
                FatalIOErrorInFunction(couplingDict)
                    << shortOnly << " is given with forces as a dictionary, which"
                    << " holds the forces' entries: drag { model Gidaspow; },"
                    << " virtualMass { Cvm 0.5; }; give each once"
                    << exit(FatalIOError);
            }
        }
        return given->dict();
    }

    // the short form: dragModel, and the other forces by name
    if (!couplingDict.found("dragModel", keyType::LITERAL))
    {
        FatalIOErrorInFunction(couplingDict)
            << "no drag law: give dragModel Gidaspow; (or DiFelice, Beetstra),"
            << " or forces as a dictionary with drag { model Gidaspow; }"
            << exit(FatalIOError);
    }
    dictionary& forces = shortForm;
    forces.name() = couplingDict.name()/"forces";
    dictionary drag;
    drag.add("model", couplingDict.get<word>("dragModel"));
    forces.add("drag", drag);
    const wordList named(couplingDict.getOrDefault<wordList>("forces", wordList()));
    for (const word& f : named)
    {
        if (f == "drag")
        {
            FatalIOErrorInFunction(couplingDict)
                << "drag in forces: with the list form, dragModel gives the drag"
                << exit(FatalIOError);
        }
        const auto& table = *particleForce::dictionaryConstructorTablePtr_;
        if (!table.found(f))
        {
            const word near(keywordSchema::closest(f, table.sortedToc()));
            FatalIOErrorInFunction(couplingDict)
                << "unknown entry " << f << " in forces"
                << (near.size() ? " (did you mean " + near + "?)" : std::string()).c_str()
                << "; valid: " << table.sortedToc() << exit(FatalIOError);
        }
    }
    const scalar Cvm = couplingDict.getOrDefault<scalar>("virtualMassCoefficient", 0.5);
    if (!(Cvm >= 0))
    {
        FatalIOErrorInFunction(couplingDict)
            << "virtualMassCoefficient must be zero or positive, not " << Cvm
            << exit(FatalIOError);
    }
    if (couplingDict.found("virtualMassCoefficient") && !named.found("virtualMass"))
    {
        WarningInFunction
            << "virtualMassCoefficient is given but forces has no virtualMass:"
            << " it is not used" << endl;
    }
    // the known ones in their order, then any others as listed
    wordList ordered;
    for (const word& f : shortFormOrder) if (named.found(f)) ordered.append(f);
    for (const word& f : named) if (!shortFormOrder.found(f)) ordered.append(f);
    for (const word& f : ordered)
    {
        dictionary coeffs;
        if (f == "virtualMass") coeffs.add("Cvm", Cvm);
        forces.add(f, coeffs);
    }
    return forces;
}


Foam::particleForceList::particleForceList
(
    const dictionary& couplingDict,
    const particleForce::setup& s
)
{
    dictionary shortForm;
    const dictionary& forces = forcesDict(couplingDict, shortForm);
    if (!forces.found("drag", keyType::LITERAL))
    {
        FatalIOErrorInFunction(forces)
            << "forces has no drag entry: drag { model Gidaspow; }"
            << " (or DiFelice, Beetstra)" << exit(FatalIOError);
    }
    for (const entry& e : forces)
    {
        const word& name = e.keyword();
        if (!e.isDict() && !e.stream().empty())
        {
            FatalIOErrorInFunction(forces)
                << name << " in forces must be a dictionary { ... } or empty ("
                << name << ";), at line " << e.startLineNumber() << exit(FatalIOError);
        }
        const auto& table = *particleForce::dictionaryConstructorTablePtr_;
        if (!table.found(name))
        {
            const word near(keywordSchema::closest(name, table.sortedToc()));
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__,
                forces.name(), e.startLineNumber(), e.endLineNumber()
            )   << "unknown entry " << name << " in forces"
                << (near.size() ? " (did you mean " + near + "?)" : std::string()).c_str()
                << "; valid: " << table.sortedToc() << exit(FatalIOError);
        }
        dictionary none;
        none.name() = forces.name()/name;
        forces_.append(particleForce::New(name, e.isDict() ? e.dict() : none, s));
    }
    Info<< "particleForceList: forces";
    for (const particleForce& f : forces_) Info<< " " << f.name();
    Info<< endl;
}


bool Foam::particleForceList::needsAccelerations() const
{
    for (const particleForce& f : forces_)
    {
        if (f.needsAccelerations()) return true;
    }
    return false;
}


void Foam::particleForceList::beginInterval
(
    const particleForce::state& s,
    scalarField& cellBeta,
    vectorField& cellExplicit
)
{
    exchange_.force.clear();
    exchange_.added = false;
    for (particleForce& f : forces_) f.beginInterval(s, exchange_);
    cellBeta = exchange_.cellBeta;
    cellExplicit = exchange_.cellBetaV;
    // the same on every rank: the spread may smooth across them
    if (!exchange_.added) return;

    // the cells lose the constant forces themselves: spread per unit of
    // each particle's weights
    const vectorField& F = exchange_.force;
    vectorField perWeight(F.size(), Zero);
    forAll(F, i)
    {
        if (s.weightSum[i] > SMALL) perWeight[i] = F[i]/s.weightSum[i];
    }
    vectorField cellForce;
    s.voidFraction.spread(perWeight, cellForce);
    cellExplicit -= cellForce;
}


void Foam::particleForceList::prepareStep
(
    const particleForce::state& s,
    const volScalarField& p,
    vectorField& Up
)
{
    const vectorField& U = s.U.primitiveField();
    bool joined = false;
    for (particleForce& f : forces_)
    {
        tmp<vectorField> field(f.stepField(p));
        if (!field.valid()) continue;
        vectorField perParticle;
        if (joined)
        {
            s.voidFraction.gather(field(), perParticle);
        }
        else
        {
            // the first such field shares the velocity's pass
            s.voidFraction.gather(U, Up, field(), perParticle);
            joined = true;
        }
        f.setGathered(std::move(perParticle));
    }
    if (!joined) s.voidFraction.gather(U, Up);
}
