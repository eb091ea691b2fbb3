/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "keywordSchema.H"
#include "Switch.H"
#include "HashSet.H"
#include "StringStream.H"
#include "IFstream.H"
#include <algorithm>
#include <sstream>

namespace
{
    bool isOpen(const Foam::token& t)
    {
        return t.isPunctuation() && t.pToken() == Foam::token::BEGIN_LIST;
    }

    bool isClose(const Foam::token& t)
    {
        return t.isPunctuation() && t.pToken() == Foam::token::END_LIST;
    }

    //- The tokens between ( and ), with an optional leading count, or
    //  false when the stream is not one such list
    bool listItems(const Foam::ITstream& is, Foam::label& first, Foam::label& last)
    {
        first = (is.size() && is[0].isLabel()) ? 1 : 0;
        last = is.size() - 1;
        if (is.size() < first + 2 || !isOpen(is[first]) || !isClose(is[last])) return false;
        ++first;
        if (is[0].isLabel() && is[0].labelToken() != last - first) return false;
        return true;
    }

    std::string shown(const Foam::ITstream& is)
    {
        std::ostringstream os;
        for (Foam::label i = 0; i < is.size() && i < 8; ++i)
        {
            Foam::OStringStream one;
            one << is[i];
            os << (i ? " " : "") << one.str();
        }
        if (is.size() > 8) os << " ...";
        return os.str();
    }

    std::string joined(const Foam::wordList& words)
    {
        std::string all;
        for (const Foam::word& w : words) all += (all.empty() ? "" : " ") + w;
        return all;
    }

    Foam::label editDistance(const std::string& a, const std::string& b)
    {
        std::vector<Foam::label> row(b.size() + 1);
        for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
        for (size_t i = 1; i <= a.size(); ++i)
        {
            Foam::label diagonal = row[0];
            row[0] = i;
            for (size_t j = 1; j <= b.size(); ++j)
            {
                const Foam::label above = row[j];
                const bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
                diagonal = above;
            }
        }
        return row[b.size()];
    }
}


const char* Foam::keywordSchema::describe(const kind k)
{
    switch (k)
    {
        case subDictionary: return "a dictionary { ... }";
        case oneWord: return "one word";
        case fileOrWord: return "one word or \"quoted string\"";
        case oneNumber: return "one number";
        case wholeNumber: return "one whole number";
        case onOff: return "a switch (true/false, on/off, yes/no)";
        case listOfWords: return "a list of words, each once (w1 w2 ...)";
        case wordsOrDictionary:
            return "a list of words, each once (w1 w2 ...), or a dictionary { ... }";
        case numberOrList: return "one number or a list of numbers (n1 n2 ...)";
    }
    return "";
}


Foam::keywordSchema::keywordSchema(const Foam::word& name)
:
    name_(name)
{}


void Foam::keywordSchema::add(const Foam::word& keyword, const kind k)
{
    const auto iter = kinds_.cfind(keyword);
    if (iter.found() && *iter != k)
    {
        FatalErrorInFunction
            << keyword << " declared as " << describe(*iter) << " and as "
            << describe(k) << " in " << name_ << abort(FatalError);
    }
    kinds_.set(keyword, k);
}


void Foam::keywordSchema::add(const Foam::word& keyword, const keywordSchema& sub)
{
    add(keyword, subDictionary);
    nested_.set(keyword, sub);
}


std::string Foam::keywordSchema::problem(const entry& e, const kind k)
{
    if (k == subDictionary) return e.isDict() ? "" : "is not a dictionary";
    if (k == wordsOrDictionary && e.isDict()) return "";
    if (e.isDict()) return "is a dictionary";
    const ITstream& is = e.stream();
    if (is.empty()) return "has no value";
    const bool one = is.size() == 1;
    label first = 0, last = 0;
    switch (k)
    {
        case oneWord:
            return one && is[0].isWord() ? "" : "is not one word";
        case fileOrWord:
            return one && is[0].isStringType() ? "" : "is not one word or string";
        case oneNumber:
            return one && is[0].isNumber() ? "" : "is not one number";
        case wholeNumber:
            return one && is[0].isLabel() ? "" : "is not one whole number";
        case onOff:
            if (one && is[0].isWord() && Switch(is[0].wordToken(), true).valid()) return "";
            if (one && is[0].isLabel() && (is[0].labelToken() == 0 || is[0].labelToken() == 1))
            {
                return "";
            }
            return "is not a switch";
        case listOfWords:
        case wordsOrDictionary:
        {
            if (!listItems(is, first, last)) return "is not a list (w1 w2 ...)";
            wordHashSet seen;
            for (label i = first; i < last; ++i)
            {
                if (!is[i].isWord()) return "holds something other than words";
                if (!seen.insert(is[i].wordToken()))
                {
                    return "names " + is[i].wordToken() + " twice";
                }
            }
            return "";
        }
        case numberOrList:
        {
            if (one) return is[0].isNumber() ? "" : "is not a number";
            if (!listItems(is, first, last)) return "is not a number or a list (n1 n2 ...)";
            for (label i = first; i < last; ++i)
            {
                if (!is[i].isNumber()) return "holds something other than numbers";
            }
            return "";
        }
        default:
            return "";
    }
}


Foam::word Foam::keywordSchema::closest(const Foam::word& unknown, const wordList& known)
{
    Foam::word best;
    label bestDistance = max(label(3), label(unknown.size()/4));
    for (const Foam::word& k : known)
    {
        const label d = editDistance(unknown, k);
        if (d <= bestDistance)
        {
            best = k;
            bestDistance = d;
        }
    }
    return best;
}


void Foam::keywordSchema::fail(const dictionary& dict, const entry& e, const std::string& what)
{
    FatalIOError
    (
        "Foam::keywordSchema::check", __FILE__, __LINE__,
        dict.name(), e.startLineNumber(), e.endLineNumber()
    )   << what.c_str() << exit(FatalIOError);
    std::abort();
}


void Foam::keywordSchema::checkKind
(
    const dictionary& dict,
    const Foam::word& keyword,
    const kind k
)
{
    keywordSchema one(dict.dictName());
    one.add(keyword, k);
    one.checkKeyword(dict, keyword);
}


void Foam::keywordSchema::checkKeyword(const dictionary& dict, const Foam::word& keyword) const
{
    const entry* e = dict.findEntry(keyword, keyType::LITERAL);
    if (e) checkEntry(dict, *e);
}


void Foam::keywordSchema::checkEntry(const dictionary& dict, const entry& e) const
{
    const Foam::word key(e.keyword());
    const kind k = kinds_[key];
    const std::string wrong(problem(e, k));
    if (wrong.size())
    {
        fail
        (
            dict, e,
            key + (name_.size() ? " in " + name_ : std::string()) + " " + wrong
          + ": it must be " + describe(k)
          + (e.isDict() ? std::string() : ", not '" + shown(e.stream()) + "'")
        );
    }
    const auto sub = nested_.cfind(key);
    if (sub.found()) (*sub).check(e.dict());
}


void Foam::keywordSchema::checkRepeats(const fileName& file)
{
    // a top-level read resets the input mode: read the entries directly
    IFstream is(file);
    dictionary all;
    all.name() = file;
    const entry::inputMode mode = entry::globalInputMode;
    entry::globalInputMode = entry::inputMode::ERROR;
    all.read(is);
    entry::globalInputMode = mode;
}


void Foam::keywordSchema::check(const dictionary& dict) const
{
    const wordList known(keywords());
    for (const entry& e : dict)
    {
        const Foam::word key(e.keyword());
        if (key == "FoamFile") continue;
        const auto iter = kinds_.cfind(key);
        if (!iter.found())
        {
            const Foam::word near(closest(key, known));
            fail
            (
                dict, e,
                "unknown keyword " + key + " in " + name_
              + (near.size() ? " (did you mean " + near + "?)" : "")
              + "; valid: " + joined(known)
            );
        }
        checkEntry(dict, e);
    }
}
