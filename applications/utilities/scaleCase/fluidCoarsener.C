/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "fluidCoarsener.H"
#include "caseFiles.H"
#include "OSspecific.H"
#include "primitiveEntry.H"
#include "modelCoefficients.H"
#include "pointField.H"
#include <cmath>
#include <regex>
#include <sstream>

namespace
{
    bool timeStepControlled(const Foam::dictionary& dict)
    {
        return dict.getOrDefault<Foam::word>("writeControl", "timeStep") == "timeStep"
            && dict.found("writeInterval");
    }
}


Foam::fluidCoarsener::fluidCoarsener
(
    const fileName& dir,
    const scalar h,
    const List<minCellRule>& minCells,
    const bool relativeSmoothing
)
:
    h_(h),
    dir_(dir),
    minCells_(minCells),
    relativeSmoothing_(relativeSmoothing)
{}


Foam::List<Foam::fluidCoarsener::minCellRule> Foam::fluidCoarsener::readMinCells
(
    const string& spec,
    const word& option
)
{
    // (dir count [length]) ...
    const std::regex rule("\\(\\s*([xyz])\\s+(\\S+?)(?:\\s+(\\S+?))?\\s*\\)");
    const std::regex whole("^\\s*(\\(\\s*[xyz][^()]*\\)\\s*)+$");
    auto fail = [&](const std::string& why)
    {
        FatalErrorInFunction
            << "-" << option << " '" << spec.c_str() << "': " << why.c_str()
            << "; write rules as '(z 12 0.2) (x 20)': at least 12 cells across"
            << " 0.2 m in z, 20 across the mesh in x" << exit(FatalError);
    };
    if (!std::regex_match(spec, whole)) fail("not a list of (direction count [length])");
    List<minCellRule> rules;
    for (std::sregex_iterator r(spec.begin(), spec.end(), rule), end; r != end; ++r)
    {
        const std::smatch& m = *r;
        minCellRule c{direction(m[1].str()[0] - 'x'), -1, 0};
        size_t used = 0;
        try { c.count = std::stol(m[2].str(), &used); } catch (...) {}
        if (used != m[2].str().size() || c.count < 1)
        {
            fail("'" + m[2].str() + "' is not a positive whole number of cells");
        }
        if (m[3].matched)
        {
            used = 0;
            try { c.length = std::stod(m[3].str(), &used); } catch (...) {}
            if (used != m[3].str().size() || !(c.length > 0))
            {
                fail("'" + m[3].str() + "' is not a positive length in metres");
            }
        }
        for (const minCellRule& other : rules)
        {
            if (other.dir == c.dir) fail("two rules for " + m[1].str());
        }
        rules.append(c);
    }
    return rules;
}


Foam::label Foam::fluidCoarsener::coarsened(const label n, const scalar h, const label split)
{
    if (n <= 1) return n;
    if (split > 1 && n % split == 0)
    {
        const label m = label(std::round(n/(h*split)));
        return m >= 1 ? m*split : -1;
    }
    const label m = label(std::round(n/h));
    return m >= 1 ? m : -1;
}


Foam::labelVector Foam::fluidCoarsener::decompositionSplits() const
{
    labelVector n(1, 1, 1);
    const fileName file(dir_/"system"/"decomposeParDict");
    if (!isFile(file)) return n;
    const dictionary dict(caseFiles::readDict(file));
    const word method(dict.getOrDefault<word>("method", word::null));
    if (method != "simple" && method != "hierarchical") return n;
    for (const word& coeffs : {word("coeffs"), word(method + "Coeffs")})
    {
        const dictionary* d = dict.findDict(coeffs);
        if (d && d->found("n")) return d->get<labelVector>("n");
    }
    return n;
}


Foam::fluidCoarsener::meshGrowth Foam::fluidCoarsener::coarsenBlocks() const
{
    const fileName file(dir_/"system"/"blockMeshDict");
    const std::string keep
    (
        "; -keepMesh keeps the mesh (and the fluid and coupling steps) as they are"
    );
    if (!isFile(file))
    {
        FatalErrorInFunction
            << "cannot coarsen the fluid: " << file << " does not exist"
            << (isFile(dir_/"system"/"blockMeshDict.template")
                ? " (blockMeshDict.template's cell counts are filled in by an Allrun:"
                  " write the blockMeshDict first)" : "")
            << (isDir(dir_/"constant"/"polyMesh") ? " and constant/polyMesh has no block"
                " description" : "")
            << keep.c_str() << exit(FatalError);
    }
    std::string text(caseFiles::readText(file));
    // the vertices in metres, for the rules' cell widths
    pointField vertices;
    vector widest(Zero);
    if (minCells_.size())
    {
        const dictionary dict(caseFiles::readDict(file));
        vertices = dict.get<pointField>("vertices");
        vertices *= dict.getOrDefault<scalar>
        (
            "scale", dict.getOrDefault<scalar>("convertToMeters", 1)
        );
        widest = max(vertices) - min(vertices);
    }
    vector maxWidth(GREAT, GREAT, GREAT);
    for (const minCellRule& r : minCells_)
    {
        maxWidth[r.dir] = (r.length > 0 ? r.length : widest[r.dir])/r.count;
    }
    // hex (vertices) [zone] (nx ny nz)
    const std::regex block
    (
        "(hex\\s*\\(([^()]*)\\)\\s*(?:[A-Za-z_]\\w*\\s*)?\\()([^()]*)(\\))"
    );
    std::string out;
    auto from = text.cbegin();
    label index = 0;
    const labelVector splits(decompositionSplits());
    bool rounded = false;
    meshGrowth growth{h_, 1, GREAT};
    bool held = false;
    scalar fineSize = 0, coarseSize = 0;
    for (std::sregex_iterator b(text.begin(), text.end(), block), end; b != end; ++b, ++index)
    {
        const std::smatch& m = *b;
        auto numbers = [&](const std::string& words, const size_t count, const char* what)
        {
            std::istringstream is(words);
            std::vector<long> n;
            for (std::string w; is >> w;)
            {
                size_t used = 0;
                long v = -1;
                try { v = std::stol(w, &used); } catch (...) {}
                if (used != w.size() || v < 0) n.push_back(-1);
                else n.push_back(v);
            }
            bool ok = (n.size() == count);
            for (const long v : n) ok = ok && v >= 0;
            if (!ok)
            {
                FatalErrorInFunction
                    << "cannot coarsen the fluid: " << file << " block " << index
                    << " has " << what << " (" << words.c_str() << "), not " << (count == 3 ? "three" : "eight")
                    << " whole numbers" << keep.c_str() << exit(FatalError);
            }
            return n;
        };
        const std::vector<long> n(numbers(m[3].str(), 3, "cell counts"));
        // the block's edges from vertex 0 along its x, y and z (OpenFOAM's
        // hex numbering)
        vector edge[3];
        if (minCells_.size())
        {
            const std::vector<long> v(numbers(m[2].str(), 8, "vertices"));
            for (const long i : v)
            {
                if (i >= vertices.size())
                {
                    FatalErrorInFunction
                        << file << " block " << index << ": vertex " << label(i)
                        << " of " << vertices.size() << exit(FatalError);
                }
            }
            edge[0] = vertices[v[1]] - vertices[v[0]];
            edge[1] = vertices[v[3]] - vertices[v[0]];
            edge[2] = vertices[v[4]] - vertices[v[0]];
        }
        std::ostringstream counts, before, why;
        label fineCells = 1, coarseCells = 1;
        for (direction d = 0; d < 3; ++d)
        {
            if (n[d] < 1)
            {
                FatalErrorInFunction
                    << "cannot coarsen the fluid: " << file << " block " << index
                    << " has no cells in direction " << label(d) << keep.c_str()
                    << exit(FatalError);
            }
            label c = coarsened(label(n[d]), h_, splits[d]);
            rounded = rounded || (c != coarsened(label(n[d]), h_) && c > 0);
            if (c < 1)
            {
                FatalErrorInFunction
                    << "cannot coarsen the fluid by " << h_ << ": " << file << " block "
                    << index << " has " << label(n[d]) << " cells in direction " << label(d)
                    << ", which would round to none" << keep.c_str() << exit(FatalError);
            }
            const scalar length = mag(edge[d]);
            const direction axis =
                cmptMax(cmptMag(edge[d])) == mag(edge[d].x()) ? 0
              : cmptMax(cmptMag(edge[d])) == mag(edge[d].y()) ? 1 : 2;
            if (n[d] > 1 && length > 0 && maxWidth[axis] < GREAT)
            {
                label need = label(std::ceil(length/maxWidth[axis] - 1e-9));
                const label split = splits[d];
                if (split > 1 && n[d] % split == 0)
                {
                    need = ((need + split - 1)/split)*split;
                }
                need = min(need, label(n[d]));
                if (need > c)
                {
                    why << "; " << "xyz"[axis] << ": " << need << " cells, widths of at most "
                        << maxWidth[axis] << " m, not " << c;
                    c = need;
                    held = true;
                }
            }
            if (n[d] > 1) growth.time = min(growth.time, scalar(n[d])/c);
            if (length > 0) growth.narrowestCell = min(growth.narrowestCell, length/c);
            fineCells *= label(n[d]);
            coarseCells *= c;
            counts << (d ? " " : "") << c;
            before << (d ? " " : "") << n[d];
        }
        if (minCells_.size())
        {
            const scalar volume = mag(edge[0] & (edge[1] ^ edge[2]));
            fineSize = max(fineSize, cbrt(volume/fineCells));
            coarseSize = max(coarseSize, cbrt(volume/coarseCells));
        }
        Info<< "    block " << index << ": cells (" << before.str().c_str() << ") -> ("
            << counts.str().c_str() << ")" << why.str().c_str() << nl;
        out.append(from, m[1].second);
        out += counts.str();
        from = m[4].first;
    }
    if (rounded)
    {
        Info<< "    (counts rounded to multiples of decomposeParDict's n " << splits
            << ": each rank's part stays whole cell layers, as the fine mesh's)" << nl;
    }
    if (!index)
    {
        FatalErrorInFunction
            << "cannot coarsen the fluid: " << file << " has no hex block"
            << keep.c_str() << exit(FatalError);
    }
    // without rules the cells grow by h, as the steps do
    if (!held) growth.time = h_;
    growth.cellSize = fineSize > 0 ? coarseSize/fineSize : h_;
    out.append(from, text.cend());
    caseFiles::writeText(file, out);
    if (isDir(dir_/"constant"/"polyMesh"))
    {
        rmDir(dir_/"constant"/"polyMesh");
        Info<< "    constant/polyMesh removed: run blockMesh in the coarse case" << nl;
    }
    return growth;
}


void Foam::fluidCoarsener::requireUniformFields() const
{
    for (const word t : {"0", "0.orig"})
    {
        for (const fileName& f : readDir(dir_/t, fileName::FILE))
        {
            const std::string text(caseFiles::readText(dir_/t/f));
            if (std::regex_search(text, std::regex("\\bnonuniform\\b")))
            {
                FatalErrorInFunction
                    << "cannot coarsen the fluid: " << dir_/t/f << " holds nonuniform"
                    << " values of the fine mesh; start from uniform fields or keep the"
                    << " mesh with -keepMesh" << exit(FatalError);
            }
        }
    }
}


Foam::scalar Foam::fluidCoarsener::stepGrowth
(
    const fluidStepRule& rule,
    const meshGrowth& cells,
    const scalar couplingSteps,
    std::string& why
) const
{
    const dictionary dict(caseFiles::readDict(dir_/"system"/"controlDict"));
    const scalar deltaT = dict.get<scalar>("deltaT");
    const scalar allowed = rule.maxStep(cells.narrowestCell, couplingSteps);
    const label most = label(std::floor(allowed/deltaT + 1e-9));
    label g = most;
    if (timeStepControlled(dict))
    {
        // written at the fine case's times where a divisor allows
        const label n = dict.get<label>("writeInterval");
        label k = most;
        while (k > 1 && n % k) --k;
        if (k > 1) g = k;
    }
    if (!(g > cells.time))
    {
        why += std::string("; the rule's ") + Foam::name(allowed) + " s is no longer";
        return cells.time;
    }
    why = std::string("the rule's ") + Foam::name(allowed) + " s in a whole number of fine steps"
        + (g < most ? " that divides the writeInterval" : "");
    return g;
}


void Foam::fluidCoarsener::coarsenControl
(
    const scalar growth,
    const std::string& why
) const
{
    const fileName file(dir_/"system"/"controlDict");
    dictionary dict(caseFiles::readDict(file));
    const scalar deltaT = dict.get<scalar>("deltaT");
    dict.set("deltaT", deltaT*growth);
    Info<< "    deltaT: " << deltaT << " -> " << deltaT*growth << " s (" << why.c_str() << ")"
        << nl;
    auto keepPeriod = [&](dictionary& d, const string& where)
    {
        if (!timeStepControlled(d)) return;
        const label n = d.get<label>("writeInterval");
        const label m = max(label(std::round(n/growth)), label(1));
        d.set("writeInterval", m);
        Info<< "    " << where.c_str() << "writeInterval: " << n << " -> " << m
            << " time steps (" << n*deltaT << " -> " << m*deltaT*growth << " s)" << nl;
    };
    keepPeriod(dict, "");
    dictionary* functions = dict.findDict("functions");
    if (functions)
    {
        for (entry& fo : *functions)
        {
            if (fo.isDict()) keepPeriod(fo.dict(), "functions/" + fo.keyword() + " ");
        }
    }
    caseFiles::writeDict(file, dict, "scaleCase -parcels: fluid coarsened by " + name(h_));
}


void Foam::fluidCoarsener::coarsenLengths(const scalar cellGrowth) const
{
    const dictionary coupling(caseFiles::readDict(dir_/"constant"/"couplingProperties"));
    const bool twoD = coupling.getOrDefault<bool>("twoDimensional", false);
    for (const word& model : modelCoefficients::models())
    {
        const word name(model + "Coeffs");
        coarsenCoefficients(model, coupling.findDict(name), {name}, cellGrowth, twoD);
    }
}


void Foam::fluidCoarsener::coarsenCoefficients
(
    const word& model,
    const dictionary* coeffs,
    const wordList& path,
    const scalar cellGrowth,
    const bool twoD
) const
{
    // voxels follow the parcels; the smoothing keeps its length in metres
    // (relative to the cells when asked)
    const fileName file(dir_/"constant"/"couplingProperties");
    std::string where;
    for (const word& w : path) where += w + "/";
    for (const modelCoefficients::coefficient& c : modelCoefficients::of(model))
    {
        const bool given = coeffs && coeffs->found(c.keyword);
        wordList at(path);
        at.append(c.keyword);
        scalar f = 1, value = 0;
        std::string why;
        switch (c.what)
        {
            case modelCoefficients::particleLength:
                if (!given) continue;
                f = h_;
                why = " m (with the parcels)";
                break;
            case modelCoefficients::smoothingLength:
                if (!given) continue;
                f = relativeSmoothing_ ? cellGrowth : 1;
                why = relativeSmoothing_ ? " m (with the cells)" : " m (the fine case's smoothing length)";
                break;
            case modelCoefficients::perCellSize:
            case modelCoefficients::perCellArea:
                // a length in metres given instead is kept as it is
                if (relativeSmoothing_ || (!given && !c.fallback)) continue;
                if (coeffs && c.replacedBy.size() && coeffs->found(c.replacedBy)) continue;
                f = c.what == modelCoefficients::perCellSize ? 1/cellGrowth : 1/sqr(cellGrowth);
                why = " (the largest cell " + Foam::name(cellGrowth) + " times the fine one's size:"
                    " the fine case's smoothing length)";
                break;
            case modelCoefficients::splitModel:
                if (given)
                {
                    const word inner(coeffs->get<word>(c.keyword));
                    wordList innerPath(path);
                    innerPath.append(inner + "Coeffs");
                    coarsenCoefficients(inner, coeffs->findDict(inner + "Coeffs"), innerPath, cellGrowth, twoD);
                }
                continue;
            case modelCoefficients::number:
            case modelCoefficients::flag:
            case modelCoefficients::choice:
            case modelCoefficients::text:
            case modelCoefficients::settings:
                continue;
        }
        value = given ? coeffs->get<scalar>(c.keyword) : c.fallback(twoD);
        Info<< "    couplingProperties " << where.c_str() << c.keyword << ": " << value << " -> "
            << value*f << why.c_str() << nl;
        if (f != 1) caseFiles::setEntry(file, at, caseFiles::number(value*f), "scaleCase -parcels");
    }
}


Foam::fluidCoarsener::meshGrowth Foam::fluidCoarsener::coarsen
(
    const fluidStepRule* rule,
    const scalar couplingSteps
) const
{
    Info<< "The fluid coarsened with the parcels (factor " << h_ << "):" << nl;
    requireUniformFields();
    meshGrowth growth(coarsenBlocks());
    std::string why
    (
        std::string("the narrowest cells ") + Foam::name(growth.time)
      + " times wider at the same velocities: the fine case's Courant number"
    );
    if (rule) growth.time = stepGrowth(*rule, growth, couplingSteps, why);
    coarsenControl(growth.time, why);
    coarsenLengths(growth.cellSize);
    return growth;
}
