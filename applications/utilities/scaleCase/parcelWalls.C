/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "parcelWalls.H"
#include "caseFiles.H"
#include "Time.H"
#include "pointIOField.H"
#include "polyMesh.H"
#include "DynamicList.H"
#include <regex>
#include <sstream>

// the beads' slot against their bulk (docs/coarseGraining.md, "Parcels
// against walls: the packing")
const Foam::scalar Foam::parcelWalls::beadsWallVoid = 0.166;


Foam::parcelWalls::parcelWalls
(
    const fileName& dir,
    const scalar h,
    const scalar diameter,
    const scalar wallVoid
)
:
    dir_(dir),
    shift_(wallVoid*(h - 1)*diameter),
    tolerance_(0.5*diameter)
{
    // equal-style variables given a number, ${other} or -${other}, in
    // in.parameters first, then the scripts in name order
    const std::regex assign("^\\s*variable\\s+(\\w+)\\s+equal\\s+(\\S+)\\s*(#.*)?$");
    fileNameList files(readDir(dir_/"DEM", fileName::FILE));
    Foam::sort(files);
    DynamicList<fileName> scripts(1, fileName("in.parameters"));
    for (const fileName& f : files)
    {
        if (f.startsWith("in.") && f != "in.parameters") scripts.append(f);
    }
    for (const fileName& f : scripts)
    {
        if (!isFile(dir_/"DEM"/f)) continue;
        std::istringstream in(caseFiles::readText(dir_/"DEM"/f));
        std::string line;
        std::smatch m;
        while (std::getline(in, line))
        {
            scalar v;
            if (std::regex_match(line, m, assign) && value(m[2].str(), v))
            {
                variables_.set(word(m[1].str()), v);
            }
        }
    }
}


bool Foam::parcelWalls::value(const std::string& token, scalar& v) const
{
    static const std::regex reference("^(-?)\\$\\{(\\w+)\\}$");
    std::smatch m;
    if (std::regex_match(token, m, reference))
    {
        const word name(m[2].str());
        if (!variables_.found(name)) return false;
        v = (m[1].length() ? -1 : 1)*variables_[name];
        return true;
    }
    try
    {
        size_t used = 0;
        v = std::stod(token, &used);
        return used == token.size();
    }
    catch (...)
    {
        return false;
    }
}


Foam::boundBox Foam::parcelWalls::meshBounds(const fileName& dir)
{
    if (isFile(dir/"constant"/"polyMesh"/"points"))
    {
        Time runTime(Time::controlDictName, dir.path(), dir.name(), "system", "constant", false, false);
        const pointIOField points
        (
            IOobject("points", "constant", polyMesh::meshSubDir, runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false)
        );
        return boundBox(points, false);
    }
    // a tutorial's template has the vertices, an Allrun the cell counts
    fileName block(dir/"system"/"blockMeshDict");
    if (!isFile(block)) block = block + ".template";
    if (!isFile(block)) return boundBox::invertedBox;
    // the vertices and the arcs' points (an O-grid's vertices lie inside
    // its circle)
    const dictionary dict(caseFiles::readDict(block));
    pointField points(dict.get<pointField>("vertices"));
    if (dict.found("edges"))
    {
        ITstream& is = dict.lookup("edges");
        token t;
        while (is.read(t).good())
        {
            if (t.isWord() && t.wordToken() == "arc")
            {
                label a, b;
                point p;
                is >> a >> b >> p;
                points.append(p);
            }
        }
    }
    points *= dict.getOrDefault<scalar>("scale", dict.getOrDefault<scalar>("convertToMeters", 1));
    return boundBox(points, false);
}


std::string Foam::parcelWalls::moved
(
    const fileName& file,
    const boundBox& mesh,
    label& nMoved
)
{
    std::istringstream in(caseFiles::readText(file));
    std::ostringstream out;
    std::string line;
    const std::string shift(caseFiles::number(shift_));
    while (std::getline(in, line))
    {
        std::istringstream words(line.substr(0, line.find('#')));
        std::vector<std::string> w;
        for (std::string s; words >> s; ) w.push_back(s);
        const auto at = [&w](const std::string& s)
        {
            return label(std::find(w.begin(), w.end(), s) - w.begin());
        };
        if (w.size() < 4 || w[0] != "fix" || w[3].find("wall/gran") != 0)
        {
            out << line << '\n';
            continue;
        }
        const word id(w[1]);
        const label type = at("type");
        const label shape = type + 2;
        if (at("primitive") >= label(w.size()) || shape >= label(w.size()))
        {
            Info<< "    wall " << id << " (" << file.name() << "): not a primitive plane or"
                << " cylinder, left" << nl;
            out << line << '\n';
            continue;
        }
        const std::string kind(w[shape]);
        const bool plane = kind.size() == 6 && kind.substr(1) == "plane";
        const bool cylinder = kind.size() == 9 && kind.substr(1) == "cylinder";
        const label axis = kind[0] - 'x';
        scalar v[3] = {0, 0, 0};
        const label nValues = plane ? 1 : 3;
        bool read = (plane || cylinder) && axis >= 0 && axis < 3 && shape + nValues < label(w.size());
        for (label i = 0; read && i < nValues; ++i) read = value(w[shape + 1 + i], v[i]);
        if (!read)
        {
            Info<< "    wall " << id << " (" << file.name() << "): " << kind.c_str()
                << (plane || cylinder ? " at a position not read (a number or ${name})"
                    : ": only planes and cylinders are moved") << ", left" << nl;
            out << line << '\n';
            continue;
        }
        scalar sign = 0;
        if (plane)
        {
            if (mag(v[0] - mesh.min()[axis]) <= tolerance_) sign = -1;
            else if (mag(v[0] - mesh.max()[axis]) <= tolerance_) sign = 1;
        }
        else
        {
            // the other two axes in order, centre (c1, c2), radius v[0]
            const label a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            const label lo = min(a1, a2), hi = max(a1, a2);
            const bool touches =
                mag(v[1] - v[0] - mesh.min()[lo]) <= tolerance_
             && mag(v[1] + v[0] - mesh.max()[lo]) <= tolerance_
             && mag(v[2] - v[0] - mesh.min()[hi]) <= tolerance_
             && mag(v[2] + v[0] - mesh.max()[hi]) <= tolerance_;
            if (touches) sign = 1;
        }
        if (sign == 0)
        {
            Info<< "    wall " << id << " (" << file.name() << "): " << kind.c_str() << " "
                << w[shape + 1].c_str() << " is not on the mesh's side, left" << nl;
            out << line << '\n';
            continue;
        }
        const std::string name(id + "MovedOut");
        const std::string token(w[shape + 1]);
        out << "# scaleCase -parcels: moved out by c (h - 1) d (see parcelWalls)\n"
            << "variable " << name << " equal " << token << (sign > 0 ? "+" : "-") << shift << '\n';
        // the token replaced where it stands, the rest of the line kept
        const std::regex first
        (
            "(\\s" + kind + "\\s+)"
          + std::regex_replace(token, std::regex("[$.+{}\\-]"), "\\$&")
        );
        out << std::regex_replace(line, first, "$1$${" + name + "}", std::regex_constants::format_first_only)
            << '\n';
        Info<< "    wall " << id << " (" << file.name() << "): " << kind.c_str() << " "
            << (plane ? "" : "radius ") << token.c_str() << " moved out by " << shift_ << " m" << nl;
        ++nMoved;
    }
    return out.str();
}


Foam::label Foam::parcelWalls::move()
{
    const boundBox mesh(meshBounds(dir_));
    if (!mesh.valid())
    {
        Info<< "    no mesh (constant/polyMesh or system/blockMeshDict): walls left" << nl;
        return 0;
    }
    label nMoved = 0;
    for (const fileName& f : readDir(dir_/"DEM", fileName::FILE))
    {
        if (!f.startsWith("in.") || f == "in.parameters") continue;
        const std::string text(moved(dir_/"DEM"/f, mesh, nMoved));
        caseFiles::writeText(dir_/"DEM"/f, text);
    }
    return nMoved;
}
