/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "caseScaler.H"
#include "parcelWalls.H"
#include "caseFiles.H"
#include "fluidCoarsener.H"
#include "exactScaling.H"
#include "modelCoefficients.H"
#include "IOstreams.H"
#include "dimensionedScalar.H"
#include "primitiveEntry.H"
#include "Time.H"
#include "pointIOField.H"
#include "polyMesh.H"
#include "stringOps.H"
#include "dimensionSets.H"
#include <cctype>
#include <functional>
#include <vector>
#include <regex>
#include <sstream>

namespace
{
    bool holdsNumber(const Foam::entry& e)
    {
        if (!e.isStream()) return false;
        for (const Foam::token& t : e.stream())
        {
            if (t.isNumber()) return true;
        }
        return false;
    }

    bool timeBased(const Foam::dictionary& dict, const Foam::word& control)
    {
        const Foam::word c(dict.getOrDefault<Foam::word>(control, "timeStep"));
        return c == "runTime" || c == "adjustableRunTime";
    }
}


Foam::caseScaler::caseScaler(const fileName& dir, const scalar h)
:
    h_(h),
    dir_(dir)
{}


Foam::dictionary Foam::caseScaler::read(const fileName& file) const
{
    return caseFiles::readDict(file);
}


void Foam::caseScaler::write(const fileName& file, const dictionary& dict) const
{
    caseFiles::writeDict(file, dict, "scaleCase -factor " + name(h_));
}


void Foam::caseScaler::scaleEntry
(
    dictionary& dict,
    const word& key,
    const scalar f,
    const fileName& where
) const
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e || !e->isStream()) return;
    tokenList tokens(static_cast<const tokenList&>(e->stream()));
    const bool table = tokens.size() && tokens[0].isWord() && tokens[0].wordToken() == "table";
    label depth = 0;
    bool rowStart = false, listSize = false;
    for (token& t : tokens)
    {
        if (t.isPunctuation())
        {
            if (t.pToken() == token::BEGIN_LIST && ++depth == 2 && table) rowStart = true;
            if (t.pToken() == token::END_LIST) --depth;
            continue;
        }
        if (t.isWord())
        {
            const word& w = t.wordToken();
            if (w.startsWith("List<")) { listSize = true; continue; }
            if (w == "uniform" || w == "nonuniform" || w == "table" || w == "constant") continue;
            FatalErrorInFunction
                << where << ": entry " << key << " holds '" << w << "'; scaleCase"
                << " scales uniform and nonuniform values, tables and constants"
                << exit(FatalError);
        }
        if (!t.isNumber()) continue;
        if (listSize && t.isLabel()) { listSize = false; continue; }
        const scalar m = (table && rowStart) ? h_ : f;
        rowStart = false;
        t = token(doubleScalar(t.number()*m));
    }
    dict.set(new primitiveEntry(key, ITstream(key, tokens)));
}


void Foam::caseScaler::requireKnown
(
    const dictionary& dict,
    const wordList& scaled,
    const wordList& unchanged,
    const fileName& where
) const
{
    for (const entry& e : dict)
    {
        if (e.keyword() == "FoamFile" || !holdsNumber(e)) continue;
        if (!scaled.found(e.keyword()) && !unchanged.found(e.keyword()))
        {
            FatalErrorInFunction
                << where << ": entry " << e.keyword() << " holds a number whose"
                << " dimensions scaleCase does not know; it scales "
                << scaled << " and leaves " << unchanged << exit(FatalError);
        }
    }
}


void Foam::caseScaler::scaleField(const fileName& file) const
{
    dictionary dict(read(file));
    const word cls(dict.subDict("FoamFile").get<word>("class"));
    const dimensionSet dims(dict.lookup("dimensions"));
    const scalar f = exactScaling::factor(dims, h_, file.name());
    if (cls.startsWith("uniformDimensioned"))
    {
        scaleEntry(dict, "value", f, file);
        requireKnown(dict, {"value"}, {"dimensions"}, file);
        write(file, dict);
        return;
    }
    scaleEntry(dict, "internalField", f, file);
    const wordList values
        ({"value", "inletValue", "refValue", "uniformValue", "uniformInletValue", "freestreamValue"});
    const wordList gradients({"gradient", "refGradient", "uniformGradient"});
    dictionary& boundary = dict.subDict("boundaryField");
    for (entry& patch : boundary)
    {
        if (!patch.isDict()) continue;
        dictionary& pd = patch.dict();
        for (const word& k : values) scaleEntry(pd, k, f, file/patch.keyword());
        for (const word& k : gradients) scaleEntry(pd, k, f/h_, file/patch.keyword());
        wordList known(values);
        known.append(gradients);
        requireKnown(pd, known, {"valueFraction"}, file/patch.keyword());
    }
    write(file, dict);
}


void Foam::caseScaler::scaleControlDict() const
{
    const fileName file(dir_/"system"/"controlDict");
    dictionary dict(read(file));
    wordList times({"startTime", "endTime", "deltaT", "maxDeltaT"});
    wordList unchanged({"writePrecision", "timePrecision", "purgeWrite", "maxCo", "maxAlphaCo"});
    (timeBased(dict, "writeControl") ? times : unchanged).append("writeInterval");
    for (const word& k : times) scaleEntry(dict, k, h_, file);
    requireKnown(dict, times, unchanged, file);
    dictionary* functions = dict.findDict("functions");
    if (functions)
    {
        for (entry& fo : *functions)
        {
            if (!fo.isDict()) continue;
            dictionary& fd = fo.dict();
            wordList scaled({"timeStart", "timeEnd", "probeLocations"});
            wordList same;
            (timeBased(fd, "writeControl") ? scaled : same).append("writeInterval");
            (timeBased(fd, "executeControl") ? scaled : same).append("executeInterval");
            for (const word& k : scaled)
            {
                scaleEntry(fd, k, h_, file/"functions"/fo.keyword());
            }
            requireKnown(fd, scaled, same, file/"functions"/fo.keyword());
        }
    }
    write(file, dict);
}


void Foam::caseScaler::scaleTransport() const
{
    const fileName file(dir_/"constant"/"transportProperties");
    if (!isFile(file)) return;
    dictionary dict(read(file));
    const dimensionedScalar nu("nu", dimViscosity, dict);
    dict.set("nu", nu.value()*exactScaling::factor(dimViscosity, h_, "nu"));
    requireKnown(dict, {"nu"}, {"rho"}, file);
    write(file, dict);
}


void Foam::caseScaler::scaleCoefficients
(
    dictionary& coeffs,
    const word& model,
    const fileName& where
) const
{
    wordList lengths, unchanged;
    for (const modelCoefficients::coefficient& c : modelCoefficients::of(model))
    {
        const bool length =
            c.what == modelCoefficients::particleLength || c.what == modelCoefficients::smoothingLength;
        (length ? lengths : unchanged).append(c.keyword);
    }
    for (const word& k : lengths) scaleEntry(coeffs, k, h_, where);
    requireKnown(coeffs, lengths, unchanged, where);
    for (entry& e : coeffs)
    {
        if (!e.isDict()) continue;
        const fileName inner(where/e.keyword());
        scaleCoefficients(e.dict(), coefficientsModel(e.keyword(), inner), inner);
    }
}


Foam::word Foam::caseScaler::coefficientsModel(const word& dictName, const fileName& where)
{
    const word model(dictName.substr(0, max(label(dictName.size()) - 6, label(0))));
    if (!dictName.endsWith("Coeffs") || !modelCoefficients::registered(model))
    {
        FatalErrorInFunction
            << where << ": scaleCase knows the coefficients of the void fraction models "
            << modelCoefficients::models() << " (<model>Coeffs) and coarseGraining, not "
            << dictName << exit(FatalError);
    }
    return model;
}


void Foam::caseScaler::scaleCoupling() const
{
    const fileName file(dir_/"constant"/"couplingProperties");
    if (!isFile(file)) return;
    dictionary dict(read(file));
    requireKnown
    (
        dict, wordList(), {"couplingInterval", "alphaMin", "virtualMassCoefficient"}, file
    );
    for (entry& e : dict)
    {
        if (!e.isDict() || e.keyword() == "FoamFile") continue;
        const fileName where(file/e.keyword());
        if (e.keyword() == "coarseGraining")
        {
            requireKnown(e.dict(), wordList(), {"factor"}, where);
            continue;
        }
        if (e.keyword() == "forces" || e.keyword() == "heatTransfer")
        {
            // the forces' and the correlations' numbers are dimensionless
            // (the added mass's Cvm); a dimensional one is an error
            for (const entry& sub : e.dict())
            {
                if (sub.isDict()) requireKnown(sub.dict(), wordList(), {"Cvm"}, where/sub.keyword());
            }
            requireKnown(e.dict(), wordList(), wordList(), where);
            continue;
        }
        scaleCoefficients(e.dict(), coefficientsModel(e.keyword(), where), where);
    }
    write(file, dict);
}


void Foam::caseScaler::scaleMesh() const
{
    // a blockMeshDict, or the template a tutorial's Allrun fills in: only
    // the scale changes, the file keeps its layout and comments
    for (const word name : {"blockMeshDict", "blockMeshDict.template"})
    {
        const fileName block(dir_/"system"/name);
        if (!isFile(block)) continue;
        const dictionary dict(read(block));
        const word key(dict.found("convertToMeters") && !dict.found("scale") ? "convertToMeters" : "scale");
        caseFiles::setEntry
        (
            block, {key}, caseFiles::number(dict.getOrDefault<scalar>(key, 1)*h_),
            "scaleCase -factor " + caseFiles::number(h_)
        );
    }
    if (isFile(dir_/"constant"/"polyMesh"/"points"))
    {
        Time runTime(Time::controlDictName, dir_.path(), dir_.name(), "system", "constant", false, false);
        pointIOField points
        (
            IOobject("points", "constant", polyMesh::meshSubDir, runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false)
        );
        points *= h_;
        points.writeObject(IOstream::ASCII, IOstream::currentVersion, IOstream::UNCOMPRESSED, true);
    }
}


std::string Foam::caseScaler::demParametersText
(
    const std::function<scalar(const demParameter&)>& newValue
) const
{
    // variable NAME equal NUMBER  # ... [M L T] ... {role}
    const fileName file(dir_/"DEM"/"in.parameters");
    if (!isFile(file)) return std::string();
    std::istringstream in(caseFiles::readText(file));
    std::ostringstream out;
    const std::regex number
        ("^(\\s*variable\\s+)(\\S+)(\\s+equal\\s+)([-+0-9.eE]+)(\\s*)(#.*)?$");
    const std::regex dims("\\[([-0-9 ]+)\\]");
    const std::regex role("\\{(\\w+)\\}");
    std::string line;
    label lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        std::smatch m, d;
        if (!std::regex_match(line, m, number))
        {
            out << line << '\n';
            continue;
        }
        const std::string comment(m[6].matched ? m[6].str() : "");
        if (!std::regex_search(comment, d, dims))
        {
            FatalErrorInFunction
                << file << " line " << lineNo << ": " << word(m[2].str()) << " has no"
                << " dimensions; declare them after a #, e.g. # [1 -1 -2] for a"
                << " modulus, # [0 0 0] for a number" << exit(FatalError);
        }
        std::istringstream ds(d[1].str());
        scalar e[7] = {0, 0, 0, 0, 0, 0, 0};
        label n = 0;
        while (n < 7 && ds >> e[n]) ++n;
        if (n != 3 && n != 7)
        {
            FatalErrorInFunction
                << file << " line " << lineNo << ": the dimensions of "
                << word(m[2].str()) << " are [mass length time] or OpenFOAM's seven"
                << exit(FatalError);
        }
        demParameter p
        {
            word(m[2].str()), std::stod(m[4].str()),
            dimensionSet(e[0], e[1], e[2], e[3], e[4], e[5], e[6]), wordList()
        };
        for (std::sregex_iterator r(comment.begin(), comment.end(), role), end; r != end; ++r)
        {
            p.roles.append(word((*r)[1].str()));
        }
        std::ostringstream num;
        num.precision(15);
        num << newValue(p);
        out << m[1].str() << m[2].str() << m[3].str() << num.str() << m[5].str() << comment << '\n';
    }
    return out.str();
}


void Foam::caseScaler::rewriteDemParameters
(
    const std::function<scalar(const demParameter&)>& newValue
) const
{
    const fileName file(dir_/"DEM"/"in.parameters");
    if (isFile(file)) caseFiles::writeText(file, demParametersText(newValue));
}


std::vector<Foam::caseScaler::demParameter> Foam::caseScaler::demParameters() const
{
    // a vector: dimensionSet's assignment insists on equal dimensions, so
    // the parameters are copy-constructed, never assigned
    std::vector<demParameter> found;
    demParametersText([&found](const demParameter& p) { found.push_back(p); return p.value; });
    return found;
}


void Foam::caseScaler::scaleDemParameters() const
{
    rewriteDemParameters
    (
        [this](const demParameter& p)
        {
            return p.value*exactScaling::factor(p.dims, h_, p.name);
        }
    );
}


void Foam::caseScaler::scaleDemData(const fileName& file) const
{
    // atom_style granular: Atoms "id type diameter density x y z [ix iy iz]",
    // Velocities "id vx vy vz wx wy wz"; the box and tilt lines are lengths
    std::istringstream in(caseFiles::readText(file));
    std::ostringstream out;
    out.precision(17);
    std::string line, section;
    label lineNo = 0;
    auto fail = [&](const std::string& why)
    {
        FatalErrorInFunction
            << file << " line " << lineNo << ": " << why << exit(FatalError);
    };
    while (std::getline(in, line))
    {
        ++lineNo;
        std::istringstream is(line);
        std::vector<std::string> words;
        for (std::string w; is >> w;) words.push_back(w);
        if (lineNo == 1 || words.empty())
        {
            out << line << '\n';
            continue;
        }
        if (words.size() == 1 && std::isalpha(words[0][0]))
        {
            section = words[0];
            if (section != "Atoms" && section != "Velocities")
            {
                fail("section " + section + ": scaleCase scales Atoms and Velocities");
            }
            out << line << '\n';
            continue;
        }
        std::vector<scalar> f(words.size(), 1);
        if (section.empty())
        {
            const std::string& last = words.back();
            if (last == "xhi" || last == "yhi" || last == "zhi") f[0] = f[1] = h_;
            else if (last == "yz") f[0] = f[1] = f[2] = h_;
            else if (last != "atoms" && last != "types") fail("unknown header line");
        }
        else if (section == "Atoms")
        {
            if (words.size() != 7 && words.size() != 10)
            {
                fail("an atom of atom_style granular has 7 or 10 columns");
            }
            f[2] = f[4] = f[5] = f[6] = h_;
        }
        else
        {
            if (words.size() != 7) fail("a granular velocity has 7 columns");
            f[4] = f[5] = f[6] = 1/h_;
        }
        for (size_t i = 0; i < words.size(); ++i)
        {
            if (i) out << ' ';
            if (f[i] == 1) { out << words[i]; continue; }
            size_t used = 0;
            double v = 0;
            try { v = std::stod(words[i], &used); } catch (...) {}
            if (used != words[i].size()) fail("'" + words[i] + "' is not a number");
            out << v*f[i];
        }
        out << '\n';
    }
    caseFiles::writeText(file, out.str());
}


// the thinnest coarse bed measured to keep the fine bed's pressure drop
// and Umf: the wide bed at h = 4, 10.5 parcels tall (docs/coarseGraining.md);
// between walls, the fewer parcels fill a bed's depth the looser they pack:
// the spouted bed's spout slowed at 8, 5.3 and 4 parcels deep, the more the
// fewer, and kept the beads' within their noise at 10 (docs/spoutedBed.md)
const Foam::label Foam::caseScaler::minParcelsAcross = 10;


Foam::caseScaler::parcelSetting Foam::caseScaler::checkParcelCase
(
    const word& law,
    const bool coarsenFluid
) const
{
    if (law != "exact" && law != "cubic")
    {
        FatalErrorInFunction
            << "-parcels " << law << ": cubic or exact" << exit(FatalError);
    }
    const fileName coupling(dir_/"constant"/"couplingProperties");
    const dictionary dict(read(coupling));
    if (dict.found("coarseGraining"))
    {
        FatalErrorInFunction
            << coupling << " already has coarseGraining" << exit(FatalError);
    }
    // 2D: a parcel is a disk of h^2 disks, its mass (per depth) h^2
    const bool twoD = dict.getOrDefault<bool>("twoDimensional", false);
    const label interval = dict.get<label>("couplingInterval");
    parcelSetting s;
    s.exact = (law == "exact");
    s.twoD = twoD;
    s.perParcel = std::pow(h_, twoD ? 2 : 3);
    s.fineInterval = s.interval = interval;
    s.fluidDeltaT = read(dir_/"system"/"controlDict").get<scalar>("deltaT");
    s.timeGrowth = 0;
    return s;
}


Foam::scalar Foam::caseScaler::parcelTimeStep
(
    const scalar fine,
    const scalar allowed,
    parcelSetting& s
)
{
    // With the fluid coarsened the coupling time is the fine one times the
    // fluid step's growth, taken in as few DEM steps as the law allows.
    // On the fine mesh the step is lowered so that the coupling time stays
    // a whole multiple or fraction of the fluid step
    if (s.timeGrowth > 0)
    {
        const scalar couplingTime = s.fineInterval*fine*s.timeGrowth;
        s.interval = max(label(std::ceil(couplingTime/allowed - 1e-9)), label(1));
        return couplingTime/s.interval;
    }
    const scalar one = s.fluidDeltaT/s.fineInterval;
    return allowed >= one
        ? std::floor(allowed/one + 1e-9)*one
        : one/std::ceil(one/allowed - 1e-9);
}


Foam::scalar Foam::caseScaler::parcelValue
(
    const demParameter& p,
    parcelSetting& s
) const
{
    if (p.roles.found("count"))
    {
        return max(std::round(p.value/s.perParcel), scalar(1));
    }
    if (p.roles.found("timestep"))
    {
        // exact: h; the coarse grain model, contacts unscaled: sqrt of the
        // mass, h^3/2 (Zhang, Huang and Zhao 2021, Eq. 17), or h for disks
        return parcelTimeStep(p.value, p.value*(s.exact ? h_ : std::sqrt(s.perParcel)), s);
    }
    if (p.roles.found("particle"))
    {
        // exact: by its dimensions; the coarse grain model keeps the
        // particles' properties and scales their size
        return s.exact
            ? p.value*exactScaling::factor(p.dims, h_, p.name)
            : (p.dims == dimLength ? p.value*h_ : p.value);
    }
    return p.value;
}


void Foam::caseScaler::makeParcels
(
    const word& law,
    const bool coarsenFluid,
    const List<fluidCoarsener::minCellRule>& minCells,
    const bool relativeSmoothing,
    const scalar wallVoid,
    const scalar courant
) const
{
    parcelSetting s(checkParcelCase(law, coarsenFluid));
    // the mesh's sides before the fluid is coarsened (and its points removed)
    moveWalls(s, particleDiameter(), wallVoid);
    fluidCoarsener::meshGrowth growth{h_, h_, GREAT};
    if (coarsenFluid)
    {
        const autoPtr<fluidStepRule> rule(stepRule(s, courant));
        const scalar couplingSteps =
            s.fineInterval*demValue("timestep", dimTime)/s.fluidDeltaT;
        growth = fluidCoarsener(dir_, h_, minCells, relativeSmoothing)
            .coarsen(rule.get(), couplingSteps);
        s.timeGrowth = growth.time;
    }
    const fileName coupling(dir_/"constant"/"couplingProperties");
    caseFiles::setEntry(coupling, {"coarseGraining", "factor"}, caseFiles::number(h_), "scaleCase -parcels");
    caseFiles::setEntry(coupling, {"coarseGraining", "forceScaling"}, law);

    Info<< "DEM parameters for parcels of " << h_ << "^" << (s.twoD ? 2 : 3)
        << (s.twoD ? " disks (" : " particles (") << law << "):" << nl;
    rewriteDemParameters
    (
        [&](const demParameter& p)
        {
            const scalar v = parcelValue(p, s);
            Info<< "    " << p.name << ": " << p.value << " -> " << v << nl;
            return v;
        }
    );
    if (coarsenFluid)
    {
        caseFiles::setEntry
        (
            coupling, {"couplingInterval"}, Foam::name(s.interval), "scaleCase -parcels: DEM steps"
        );
        Info<< "    couplingInterval: " << s.fineInterval << " -> " << s.interval << " DEM steps"
            << " (the coupling time times " << growth.time << ", as the fluid step, in DEM"
            << " steps no longer than the law allows)" << nl;
    }
    Info<< endl;
    warnOfNarrowBeds(read(coupling), minCells, growth.narrowestCell);
}


void Foam::caseScaler::scaleAll() const
{
    scaleMesh();
    for (const word t : {"0", "0.orig"})
    {
        for (const fileName& f : readDir(dir_/t, fileName::FILE))
        {
            scaleField(dir_/t/f);
        }
    }
    const fileName g(dir_/"constant"/"g");
    if (isFile(g)) scaleField(g);
    scaleControlDict();
    scaleTransport();
    scaleCoupling();
    scaleDemParameters();
    for (const fileName& f : readDir(dir_/"DEM", fileName::FILE))
    {
        if (f.hasExt("data")) scaleDemData(dir_/"DEM"/f);
    }
}


Foam::scalar Foam::caseScaler::demValue
(
    const word& role,
    const dimensionSet& dims
) const
{
    for (const demParameter& p : demParameters())
    {
        if (p.roles.found(role) && p.dims == dims) return p.value;
    }
    return 0;
}


Foam::autoPtr<Foam::fluidStepRule> Foam::caseScaler::stepRule
(
    const parcelSetting& s,
    const scalar courant
) const
{
    if (!(courant > 0)) return nullptr;
    if (s.twoD)
    {
        FatalErrorInFunction
            << "-courant: the rule's packing and drag are of spheres, not disks"
            << exit(FatalError);
    }
    Info<< "The fluid step by the coarse bed's needs (-courant " << courant << "):" << nl;
    return autoPtr<fluidStepRule>::New
    (
        dir_, courant, particleDiameter(), demValue("particle", dimDensity), s.exact ? h_ : 1
    );
}


Foam::scalar Foam::caseScaler::particleDiameter() const
{
    scalar d = 0;
    for (const demParameter& p : demParameters())
    {
        if (p.roles.found("particle") && p.dims == dimLength)
        {
            if (p.name == "radius") d = 2*p.value;
            if (p.name == "diameter") d = p.value;
        }
    }
    return d;
}


void Foam::caseScaler::moveWalls
(
    const parcelSetting& s,
    const scalar diameter,
    const scalar wallVoid
) const
{
    if (!(wallVoid > 0) || h_ == 1)
    {
        Info<< "DEM walls left where they are (-wallVoid " << parcelWalls::beadsWallVoid
            << " moves those on the mesh's sides out, so that parcels pack at a wall"
            << " as beads do)" << nl << endl;
        return;
    }
    Info<< "DEM walls for parcels: out by c (h - 1) d, c = " << wallVoid
        << " particle diameters of extra void at a wall per wall area, so that the"
        << " parcels' layer at a wall holds the particles' solids:" << nl;
    if (s.twoD || !(diameter > 0))
    {
        Info<< "    walls left: " << (s.twoD ? "the rule is for spheres, not disks"
            : "no {particle} radius or diameter in DEM/in.parameters") << nl << endl;
        return;
    }
    if (parcelWalls(dir_, h_, diameter, wallVoid).move())
    {
        const fileName coupling(dir_/"constant"/"couplingProperties");
        caseFiles::setEntry(coupling, {"keepVolumeBeyondMesh"}, "on", "scaleCase -parcels: walls moved out");
        Info<< "    keepVolumeBeyondMesh: on (the parcels' part beyond the mesh's walls"
            << " stays in their cells)" << nl;
    }
    Info<< endl;
}


void Foam::caseScaler::warnOfNarrowBeds
(
    const dictionary& coupling,
    const List<fluidCoarsener::minCellRule>& minCells,
    const scalar narrowestCell
) const
{
    const scalar parcel = particleDiameter();
    if (!(parcel > 0)) return;
    const word model(coupling.getOrDefault<word>("voidFractionModel", word::null));
    if (model == "centroid" && parcel > narrowestCell)
    {
        WarningInFunction
            << "parcels of " << parcel << " m are wider than the narrowest cell ("
            << narrowestCell << " m): centroid puts each whole into one cell; kernel,"
            << " diffusion or analytical spread it" << endl;
    }
    for (const fluidCoarsener::minCellRule& r : minCells)
    {
        if (r.length > 0 && r.length/parcel < minParcelsAcross)
        {
            WarningInFunction
                << "the bed is " << r.length/parcel << " parcels across in "
                << "xyz"[r.dir] << " (" << r.length << " m over parcels of " << parcel
                << " m), fewer than " << minParcelsAcross << ": thinner than any coarse"
                << " bed measured to keep the fine bed's pressure drop and Umf"
                << " (docs/coarseGraining.md); between walls, parcels pack looser"
                << " within a diameter of them (a spouted bed 4 parcels deep: a"
                << " slower spout, docs/spoutedBed.md)"
                << endl;
        }
    }
}
