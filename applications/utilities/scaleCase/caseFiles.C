/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "caseFiles.H"
#include "IFstream.H"
#include "OFstream.H"
#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

namespace
{
    // A dictionary file's text as tokens: words (keywords, values), the
    // punctuation that shapes entries, and where each lies; comments and
    // strings skipped
    struct piece
    {
        char kind;          // 'w' a word or number, '"' a string, else the character
        size_t begin, end;
        int depth;          // of braces enclosing it
    };

    std::vector<piece> pieces(const std::string& t)
    {
        std::vector<piece> out;
        int depth = 0;
        for (size_t i = 0; i < t.size();)
        {
            const char c = t[i];
            if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
            if (t.compare(i, 2, "//") == 0) { i = t.find('\n', i); if (i == std::string::npos) break; continue; }
            if (t.compare(i, 2, "/*") == 0)
            {
                const size_t e = t.find("*/", i + 2);
                i = (e == std::string::npos) ? t.size() : e + 2;
                continue;
            }
            if (c == '"')
            {
                size_t e = i + 1;
                while (e < t.size() && t[e] != '"') e += (t[e] == '\\') ? 2 : 1;
                out.push_back({'"', i, std::min(e + 1, t.size()), depth});
                i = e + 1;
                continue;
            }
            if (c == '{' || c == '}' || c == ';' || c == '(' || c == ')')
            {
                if (c == '}') --depth;
                out.push_back({c, i, i + 1, depth});
                if (c == '{') ++depth;
                ++i;
                continue;
            }
            size_t e = i;
            while
            (
                e < t.size() && !std::isspace(static_cast<unsigned char>(t[e]))
             && std::string("{};()\"").find(t[e]) == std::string::npos
             && t.compare(e, 2, "//") != 0 && t.compare(e, 2, "/*") != 0
            ) ++e;
            out.push_back({'w', i, e, depth});
            i = e;
        }
        return out;
    }

    // The index of the keyword word at depth within [from, to): one that
    // starts an entry (after '{', ';', '}' or at the start)
    size_t findKeyword
    (
        const std::string& t,
        const std::vector<piece>& p,
        size_t from,
        size_t to,
        int depth,
        const std::string& keyword
    )
    {
        for (size_t k = from; k < to; ++k)
        {
            const bool starts = (k == 0 || p[k - 1].kind == '{' || p[k - 1].kind == ';' || p[k - 1].kind == '}');
            if
            (
                p[k].kind == 'w' && p[k].depth == depth && starts
             && t.compare(p[k].begin, p[k].end - p[k].begin, keyword) == 0
             && p[k].end - p[k].begin == keyword.size()
            )
            {
                return k;
            }
        }
        return std::string::npos;
    }

    // The closing piece of the block opened at k (a '{')
    size_t closing(const std::vector<piece>& p, size_t k)
    {
        for (size_t j = k + 1; j < p.size(); ++j)
        {
            if (p[j].kind == '}' && p[j].depth == p[k].depth) return j;
        }
        return p.size();
    }

    // The text with a line added at its end
    std::string withLine(const std::string& text, const std::string& line)
    {
        std::string out(text);
        if (out.size() && out.back() != '\n') out += '\n';
        return out + line + "\n";
    }
}


Foam::dictionary Foam::caseFiles::readDict(const fileName& file)
{
    IFstream is(file);
    if (!is.good())
    {
        FatalErrorInFunction << "cannot read " << file << exit(FatalError);
    }
    return dictionary(is, true);
}


void Foam::caseFiles::writeDict
(
    const fileName& file,
    const dictionary& dict,
    const std::string& by
)
{
    OFstream os(file);
    os.precision(15);
    os  << "// written by " << by.c_str() << nl << nl;
    dict.write(os, false);
}


std::string Foam::caseFiles::readText(const fileName& file)
{
    std::ifstream in(file);
    if (!in.good())
    {
        FatalErrorInFunction << "cannot read " << file << exit(FatalError);
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}


void Foam::caseFiles::writeText(const fileName& file, const std::string& text)
{
    std::ofstream out(file);
    out << text;
    if (!out.good())
    {
        FatalErrorInFunction << "cannot write " << file << exit(FatalError);
    }
}


std::string Foam::caseFiles::number(const double value)
{
    std::ostringstream s;
    s.precision(15);
    s << value;
    return s.str();
}


std::string Foam::caseFiles::setEntry
(
    const std::string& text,
    const wordList& path,
    const std::string& value,
    const std::string& note
)
{
    if (path.empty())
    {
        FatalErrorInFunction << "no entry to set" << exit(FatalError);
    }
    const std::vector<piece> p(pieces(text));
    const std::string comment(note.empty() ? "" : "   // " + note);
    const std::string& key = path.last();
    size_t from = 0, to = p.size();
    int depth = 0;
    for (; depth + 1 < path.size(); ++depth)
    {
        const size_t block = findKeyword(text, p, from, to, depth, path[depth]);
        if (block == std::string::npos || block + 1 >= to || p[block + 1].kind != '{')
        {
            // the missing sub-dictionaries, inside the last one found
            std::string entry(key + " " + value + ";");
            for (label d = path.size() - 2; d >= depth; --d) entry = path[d] + " { " + entry + " }";
            if (depth == 0) return withLine(text, entry + comment);
            return text.substr(0, p[to].begin) + entry + " " + text.substr(p[to].begin);
        }
        from = block + 2;
        to = closing(p, block + 1);
        if (to == p.size())
        {
            FatalErrorInFunction
                << path[depth] << " has no closing brace" << exit(FatalError);
        }
    }
    const size_t k = findKeyword(text, p, from, to, depth, key);
    if (k == std::string::npos)
    {
        if (depth > 0)
        {
            // before the block's closing brace
            const size_t at = p[to].begin;
            return text.substr(0, at) + key + " " + value + "; " + text.substr(at);
        }
        return withLine(text, key + " " + value + ";" + comment);
    }
    size_t end = k + 1;
    while (end < p.size() && p[end].kind != ';') ++end;
    if (end == p.size() || end == k + 1)
    {
        FatalErrorInFunction
            << "entry " << key << " has no value ending in ';'" << exit(FatalError);
    }
    // the note ends the line, in place of its comment (which spoke of the
    // old value); not where other entries follow on the line
    const size_t after = p[end].end;
    const size_t lineEnd = std::min(text.find('\n', after), text.size());
    const std::string rest(text.substr(after, lineEnd - after));
    const size_t first = rest.find_first_not_of(" \t");
    std::string line(rest);
    if (!note.empty() && first == std::string::npos) line = comment;
    else if (!note.empty() && rest.compare(first, 2, "//") == 0) line = comment;
    return text.substr(0, p[k + 1].begin) + value + ";" + line + text.substr(lineEnd);
}


void Foam::caseFiles::setEntry
(
    const fileName& file,
    const wordList& path,
    const std::string& value,
    const std::string& note
)
{
    writeText(file, setEntry(readText(file), path, value, note));
}
