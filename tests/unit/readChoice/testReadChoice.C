/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testReadChoice

Description
    readChoice on dictionaries written in the test: a keyword's word gives
    its Enum value, an absent keyword the default, and a word not among
    the Enum's a FatalIOError naming the keyword, the word and the valid
    words. Ends with 'readChoice: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "readChoice.H"
#include "IStringStream.H"
#include "testHarness.H"

using namespace Foam;
using testHarness::near;

namespace
{
    enum class shape { sphere, disk, cube };

    const Enum<shape> shapeNames
    ({
        { shape::sphere, "sphere" },
        { shape::disk, "disk" },
        { shape::cube, "cube" },
    });

    dictionary read(const char* text)
    {
        IStringStream is(text);
        return dictionary(is);
    }
}


int main()
{
    FatalIOError.throwExceptions();

    near("a listed word gives its value",
         int(readChoice(read("form disk;"), "form", shapeNames, shape::sphere)), int(shape::disk), 0);
    near("another listed word",
         int(readChoice(read("form cube;"), "form", shapeNames, shape::sphere)), int(shape::cube), 0);
    near("an absent keyword gives the default",
         int(readChoice(read("other disk;"), "form", shapeNames, shape::cube)), int(shape::cube), 0);

    bool named = false;
    try
    {
        readChoice(read("form cone;"), "form", shapeNames, shape::sphere);
    }
    catch (const Foam::IOerror& e)
    {
        const std::string m(e.message());
        named = m.find("form cone is not one of") != std::string::npos
             && m.find("sphere") != std::string::npos && m.find("cube") != std::string::npos;
    }
    near("an unlisted word: FatalIOError naming keyword, word and the valid words", named, 1, 0);

    return testHarness::summary("readChoice");
}
