/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "particleData.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "UIndirectList.H"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

Foam::particleData::particleData
(
    pointField&& positions,
    scalarField&& radii,
    labelList&& ids
)
:
    positions_(std::move(positions)),
    radii_(std::move(radii)),
    ids_(std::move(ids))
{
    if (positions_.size() != radii_.size() || positions_.size() != ids_.size())
    {
        FatalErrorInFunction
            << "positions (" << positions_.size() << "), radii ("
            << radii_.size() << ") and ids (" << ids_.size()
            << ") differ in size" << exit(FatalError);
    }
}


void Foam::particleData::setVelocities(vectorField&& velocities)
{
    if (velocities.size() != positions_.size())
    {
        FatalErrorInFunction
            << velocities.size() << " velocities for " << positions_.size()
            << " particles" << exit(FatalError);
    }
    velocities_ = std::move(velocities);
}


Foam::particleData Foam::particleData::reordered(const labelUList& order) const
{
    particleData result
    (
        pointField(positions_, order),
        scalarField(radii_, order),
        labelList(UIndirectList<label>(ids_, order))
    );
    if (velocities_.size()) result.setVelocities(vectorField(velocities_, order));
    return result;
}


Foam::scalar Foam::particleData::totalVolume() const
{
    scalar v = 0;
    forAll(radii_, i)
    {
        v += 4.0/3.0*constant::mathematical::pi*pow3(radii_[i]);
    }
    return v;
}


namespace
{
    [[noreturn]] void dumpError
    (
        const Foam::fileName& file,
        long line,
        const std::string& what
    )
    {
        FatalErrorInFunction
            << "LIGGGHTS dump " << file;
        if (line > 0) Foam::FatalError << ", line " << Foam::label(line);
        Foam::FatalError << ": " << what.c_str() << Foam::exit(Foam::FatalError);
        std::abort();   // not reached
    }

    double parseNumber
    (
        const std::string& word,
        const Foam::fileName& file,
        long line,
        const std::string& column
    )
    {
        const char* s = word.c_str();
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(s, &end);
        if (end == s || *end != '\0' || errno == ERANGE)
        {
            dumpError(file, line, "malformed number '" + word + "' in column " + column);
        }
        if (!std::isfinite(v))
        {
            dumpError(file, line, "non-finite value '" + word + "' in column " + column);
        }
        return v;
    }
}


Foam::particleData Foam::particleData::readLiggghtsDump(const fileName& file)
{
    std::ifstream is(file.c_str());
    if (!is.good())
    {
        dumpError(file, 0, "cannot open the file");
    }

    std::string text;
    long lineNo = 0;
    long nAtoms = -1;
    std::vector<std::string> columns;
    long atomsLine = 0;
    while (std::getline(is, text))
    {
        ++lineNo;
        if (text.rfind("ITEM: NUMBER OF ATOMS", 0) == 0)
        {
            if (!std::getline(is, text))
            {
                dumpError(file, lineNo, "missing the number of atoms");
            }
            ++lineNo;
            const double n = parseNumber(text, file, lineNo, "NUMBER OF ATOMS");
            if (n < 0 || n != std::floor(n))
            {
                dumpError(file, lineNo, "the number of atoms must be a whole number >= 0");
            }
            nAtoms = long(n);
        }
        else if (text.rfind("ITEM: ATOMS", 0) == 0)
        {
            std::istringstream hdr(text.substr(11));
            std::string c;
            while (hdr >> c) columns.push_back(c);
            atomsLine = lineNo;
            break;
        }
    }
    if (atomsLine == 0)
    {
        dumpError(file, 0, lineNo ? "no 'ITEM: ATOMS' section" : "the file is empty");
    }
    if (nAtoms < 0)
    {
        dumpError(file, atomsLine, "no 'ITEM: NUMBER OF ATOMS' before the atoms");
    }

    const std::vector<std::string> needed = {"id", "x", "y", "z", "radius"};
    std::vector<int> col(needed.size(), -1);
    for (std::size_t k = 0; k < needed.size(); ++k)
    {
        for (std::size_t j = 0; j < columns.size(); ++j)
        {
            if (columns[j] == needed[k]) col[k] = int(j);
        }
        if (col[k] < 0)
        {
            dumpError(file, atomsLine, "missing column '" + needed[k] + "' in the ATOMS header");
        }
    }

    pointField positions(nAtoms);
    scalarField radii(nAtoms);
    labelList ids(nAtoms);
    std::vector<std::string> words;
    for (long i = 0; i < nAtoms; ++i)
    {
        if (!std::getline(is, text))
        {
            dumpError
            (
                file, lineNo, "expected " + std::to_string(nAtoms)
              + " atoms, found " + std::to_string(i)
            );
        }
        ++lineNo;
        words.clear();
        std::istringstream ls(text);
        std::string w;
        while (ls >> w) words.push_back(w);
        if (words.size() != columns.size())
        {
            dumpError
            (
                file, lineNo, "expected " + std::to_string(columns.size())
              + " columns, found " + std::to_string(words.size())
            );
        }
        double v[5];
        for (std::size_t k = 0; k < needed.size(); ++k)
        {
            v[k] = parseNumber(words[col[k]], file, lineNo, needed[k]);
        }
        if (v[4] <= 0)
        {
            dumpError(file, lineNo, "radius must be positive, got " + words[col[4]]);
        }
        ids[i] = label(v[0]);
        positions[i] = point(v[1], v[2], v[3]);
        radii[i] = v[4];
    }
    return particleData(std::move(positions), std::move(radii), std::move(ids));
}
