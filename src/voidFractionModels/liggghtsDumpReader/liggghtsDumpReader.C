/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "liggghtsDumpReader.H"
#include "error.H"
#include "textNumber.H"
#include <algorithm>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_map>
#include <vector>


const std::vector<std::string> Foam::liggghtsDumpReader::neededColumns =
    {"id", "x", "y", "z", "radius"};


Foam::liggghtsDumpReader::liggghtsDumpReader(const fileName& file)
:
    file_(file),
    is_(file.c_str()),
    lineNo_(0),
    timestep_(-1),
    nRead_(0),
    size_(0)
{
    if (!is_.good()) error(0, "cannot open the file");
    is_.seekg(0, std::ios::end);
    size_ = is_.tellg();
    is_.seekg(0, std::ios::beg);
}


Foam::scalar Foam::liggghtsDumpReader::progress()
{
    if (size_ <= 0) return 1;
    const std::streamoff at = is_.good() ? std::streamoff(is_.tellg()) : size_;
    return scalar(at)/scalar(size_);
}


void Foam::liggghtsDumpReader::error(const long line, const std::string& what) const
{
    FatalErrorInFunction << "LIGGGHTS dump " << file_;
    if (line > 0) FatalError << ", line " << label(line);
    FatalError << ": " << what.c_str() << exit(FatalError);
    std::abort();   // not reached
}


double Foam::liggghtsDumpReader::number
(
    const std::string& word,
    const long line,
    const std::string& column
) const
{
    const char* why = nullptr;
    const double v = textNumber(word, why);
    if (why)
    {
        error(line, "'" + word + "' in column " + column + ": " + why);
    }
    return v;
}


bool Foam::liggghtsDumpReader::nextLine(std::string& text)
{
    if (!std::getline(is_, text)) return false;
    ++lineNo_;
    return true;
}


bool Foam::liggghtsDumpReader::readHeader
(
    long& nAtoms,
    std::vector<std::string>& columns
)
{
    std::string text;
    nAtoms = -1;
    long headerLine = 0;
    timestep_ = -1;
    bool atoms = false;
    while (!atoms && nextLine(text))
    {
        if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
        if (!headerLine) headerLine = lineNo_;
        const bool isCount = text.rfind("ITEM: NUMBER OF ATOMS", 0) == 0;
        if (isCount || text.rfind("ITEM: TIMESTEP", 0) == 0)
        {
            const std::string what = isCount ? "NUMBER OF ATOMS" : "TIMESTEP";
            if (!nextLine(text)) error(lineNo_, "missing the value of ITEM: " + what);
            const double n = number(text, lineNo_, what);
            if (n < 0 || n != std::floor(n))
            {
                error(lineNo_, "ITEM: " + what + " must be a whole number >= 0");
            }
            if (isCount) nAtoms = long(n);
            else timestep_ = label(n);
        }
        else if (text.rfind("ITEM: ATOMS", 0) == 0)
        {
            std::istringstream hdr(text.substr(11));
            std::string c;
            while (hdr >> c) columns.push_back(c);
            atoms = true;
        }
    }
    if (!atoms)
    {
        if (headerLine == 0 && nRead_ > 0) return false;
        if (headerLine == 0) error(0, "the file is empty");
        error(headerLine, "no 'ITEM: ATOMS' section in the snapshot starting here");
    }
    if (nAtoms < 0) error(lineNo_, "no 'ITEM: NUMBER OF ATOMS' before the atoms");
    return true;
}


std::vector<int> Foam::liggghtsDumpReader::findColumns
(
    const std::vector<std::string>& columns
) const
{
    std::vector<int> col(neededColumns.size(), -1);
    for (std::size_t k = 0; k < neededColumns.size(); ++k)
    {
        for (std::size_t j = 0; j < columns.size(); ++j)
        {
            if (columns[j] == neededColumns[k]) col[k] = int(j);
        }
        if (col[k] < 0)
        {
            error(lineNo_, "missing column '" + neededColumns[k] + "' in the ATOMS header");
        }
    }
    return col;
}


bool Foam::liggghtsDumpReader::read(particleData& particles)
{
    long nAtoms;
    std::vector<std::string> columns;
    if (!readHeader(nAtoms, columns)) return false;
    const long atomsLine = lineNo_;
    const std::vector<int> col = findColumns(columns);

    pointField positions(nAtoms);
    scalarField radii(nAtoms);
    labelList ids(nAtoms);
    std::unordered_map<label, long> idLine;
    idLine.reserve(nAtoms);
    std::string text;
    std::vector<std::string> words;
    for (long i = 0; i < nAtoms; ++i)
    {
        if (!nextLine(text))
        {
            error
            (
                lineNo_, "expected " + std::to_string(nAtoms)
              + " atoms after line " + std::to_string(atomsLine)
              + ", found " + std::to_string(i)
            );
        }
        words.clear();
        std::istringstream ls(text);
        std::string w;
        while (ls >> w) words.push_back(w);
        if (words.size() != columns.size())
        {
            error
            (
                lineNo_, "expected " + std::to_string(columns.size())
              + " columns, found " + std::to_string(words.size())
            );
        }
        double v[5];
        for (std::size_t k = 0; k < neededColumns.size(); ++k)
        {
            v[k] = number(words[col[k]], lineNo_, neededColumns[k]);
        }
        // a column not kept that is no number still means a damaged file
        for (std::size_t j = 0; j < words.size(); ++j)
        {
            if (std::find(col.begin(), col.end(), int(j)) == col.end())
            {
                number(words[j], lineNo_, columns[j]);
            }
        }
        if (v[4] <= 0) error(lineNo_, "radius must be positive, got " + words[col[4]]);
        if (v[0] != std::floor(v[0])) error(lineNo_, "id must be a whole number, got " + words[col[0]]);
        ids[i] = label(v[0]);
        const auto seen = idLine.emplace(ids[i], lineNo_);
        if (!seen.second)
        {
            error
            (
                lineNo_, "atom id " + words[col[0]] + " again (first at line "
              + std::to_string(seen.first->second) + ")"
            );
        }
        positions[i] = point(v[1], v[2], v[3]);
        radii[i] = v[4];
    }
    ++nRead_;
    particles = particleData(std::move(positions), std::move(radii), std::move(ids));
    return true;
}
