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


Foam::fluidCoarsener::fluidCoarsener(const fileName& dir, const scalar h)
:
    h_(h),
    dir_(dir)
{}


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
    for (const word coeffs : {word("coeffs"), word(method + "Coeffs")})
    {
        const dictionary* d = dict.findDict(coeffs);
        if (d && d->found("n")) return d->get<labelVector>("n");
    }
    return n;
}


void Foam::fluidCoarsener::coarsenBlocks() const
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
    // hex (vertices) [zone] (nx ny nz)
    const std::regex block("(hex\\s*\\([^()]*\\)\\s*(?:[A-Za-z_]\\w*\\s*)?\\()([^()]*)(\\))");
    std::string out;
    auto from = text.cbegin();
    label index = 0;
    const labelVector splits(decompositionSplits());
    bool rounded = false;
    for (std::sregex_iterator b(text.begin(), text.end(), block), end; b != end; ++b, ++index)
    {
        const std::smatch& m = *b;
        std::istringstream is(m[2].str());
        std::vector<std::string> words;
        for (std::string w; is >> w;) words.push_back(w);
        std::ostringstream counts, before;
        for (size_t d = 0; d < words.size(); ++d)
        {
            size_t used = 0;
            long n = -1;
            try { n = std::stol(words[d], &used); } catch (...) {}
            if (words.size() != 3 || used != words[d].size() || n < 1)
            {
                FatalErrorInFunction
                    << "cannot coarsen the fluid: " << file << " block " << index
                    << " has cell counts (" << m[2].str().c_str() << "), not three whole"
                    << " numbers" << keep.c_str() << exit(FatalError);
            }
            const label c = coarsened(label(n), h_, splits[d]);
            rounded = rounded || (c != coarsened(label(n), h_) && c > 0);
            if (c < 1)
            {
                FatalErrorInFunction
                    << "cannot coarsen the fluid by " << h_ << ": " << file << " block "
                    << index << " has " << n << " cells in direction " << label(d)
                    << ", which would round to none" << keep.c_str() << exit(FatalError);
            }
            counts << (d ? " " : "") << c;
            before << (d ? " " : "") << n;
        }
        Info<< "    block " << index << ": cells (" << before.str().c_str() << ") -> ("
            << counts.str().c_str() << ")" << nl;
        out.append(from, m[1].second);
        out += counts.str();
        from = m[3].first;
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
    out.append(from, text.cend());
    caseFiles::writeText(file, out);
    if (isDir(dir_/"constant"/"polyMesh"))
    {
        rmDir(dir_/"constant"/"polyMesh");
        Info<< "    constant/polyMesh removed: run blockMesh in the coarse case" << nl;
    }
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


void Foam::fluidCoarsener::coarsenControl() const
{
    const fileName file(dir_/"system"/"controlDict");
    dictionary dict(caseFiles::readDict(file));
    const scalar deltaT = dict.get<scalar>("deltaT");
    dict.set("deltaT", deltaT*h_);
    Info<< "    deltaT: " << deltaT << " -> " << deltaT*h_ << " s (cells " << h_
        << " times wider at the same velocities: the fine case's Courant number)" << nl;
    auto keepPeriod = [&](dictionary& d, const string& where)
    {
        if (!timeStepControlled(d)) return;
        const label n = d.get<label>("writeInterval");
        const label m = max(label(std::round(n/h_)), label(1));
        d.set("writeInterval", m);
        Info<< "    " << where.c_str() << "writeInterval: " << n << " -> " << m
            << " time steps (" << n*deltaT << " -> " << m*deltaT*h_ << " s)" << nl;
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


void Foam::fluidCoarsener::coarsenLengths() const
{
    // line by line, the part before a // comment, so that the file keeps
    // its layout and comments
    const fileName file(dir_/"constant"/"couplingProperties");
    std::istringstream in(caseFiles::readText(file));
    std::ostringstream out;
    const std::regex length("\\b(bandwidth|voxelSize)(\\s+)([-+0-9.eE]+)(\\s*;)");
    for (std::string line; std::getline(in, line);)
    {
        const size_t comment = line.find("//");
        std::string code(line.substr(0, comment));
        std::string done;
        std::smatch m;
        while (std::regex_search(code, m, length))
        {
            const scalar v = std::stod(m[3].str());
            std::ostringstream num;
            num.precision(15);
            num << v*h_;
            done += m.prefix().str() + m[1].str() + m[2].str() + num.str() + m[4].str();
            code = m.suffix().str();
            Info<< "    couplingProperties " << m[1].str().c_str() << ": " << v << " -> "
                << v*h_ << " m" << nl;
        }
        out << done << code << (comment == std::string::npos ? "" : line.substr(comment)) << '\n';
    }
    caseFiles::writeText(file, out.str());
}


void Foam::fluidCoarsener::coarsen() const
{
    Info<< "The fluid coarsened with the parcels (factor " << h_ << "):" << nl;
    requireUniformFields();
    coarsenBlocks();
    coarsenControl();
    coarsenLengths();
}
