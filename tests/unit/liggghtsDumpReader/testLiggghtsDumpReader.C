/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testLiggghtsDumpReader

Description
    liggghtsDumpReader on dumps written by the test (under build/unit/): two
    snapshots whose ATOMS columns are in another order with extra columns
    are read back value by value with their TIMESTEPs, the progress rises
    to 1 and a third read says the end; bad dumps (an id twice, a missing
    column, a radius <= 0, fewer atoms than announced, a malformed number,
    an empty file) stop with an error that names the line and the fault.
    Ends with 'liggghtsDumpReader: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "liggghtsDumpReader.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "testHarness.H"

using namespace Foam;
using testHarness::near;

namespace
{
    fileName dir() { return getEnv("VFM_PROJECT_DIR")/"build"/"unit"/"dumpReader"; }

    fileName writeDump(const word& name, const std::string& text)
    {
        const fileName f(dir()/name);
        OFstream os(f);
        os << text.c_str();
        return f;
    }

    const std::string header(const label step, const label n, const std::string& columns)
    {
        return "ITEM: TIMESTEP\n" + std::to_string(step) + "\nITEM: NUMBER OF ATOMS\n"
            + std::to_string(n) + "\nITEM: BOX BOUNDS pp pp ff\n0 1\n0 1\n0 1\n"
            + "ITEM: ATOMS " + columns + "\n";
    }

    //- Reading the dump stops with an error holding every one of the needles
    void refused(const char* what, const std::string& text, const std::vector<std::string>& needles)
    {
        const fileName f(writeDump("bad.dump", text));
        bool ok = false;
        std::string message;
        try
        {
            liggghtsDumpReader dump(f);
            particleData p;
            while (dump.read(p)) {}
        }
        catch (const Foam::error& e)
        {
            message = e.message();
            ok = true;
            for (const std::string& n : needles) ok = ok && message.find(n) != std::string::npos;
        }
        if (!ok) Info<< "    message: " << message.c_str() << endl;
        near(what, ok, 1, 0);
    }
}


int main()
{
    mkDir(dir());
    FatalError.throwExceptions();

    // 9 header lines per snapshot: the atoms of the first are lines 10-12
    const std::string cols("radius type id z y x vx");
    const fileName two
    (
        writeDump
        (
            "two.dump",
            header(100, 3, cols)
          + "0.5e-3 1 7 0.3 0.2 0.1 0\n"
            "0.25e-3 1 3 0.6 0.5 0.4 0\n"
            "1e-3 2 11 0.9 0.8 0.7 0\n"
          + header(200, 2, cols)
          + "0.5e-3 1 7 0.35 0.25 0.15 0\n"
            "1e-3 2 11 0.95 0.85 0.75 0\n"
        )
    );
    liggghtsDumpReader dump(two);
    particleData p;
    near("first snapshot read", dump.read(p), 1, 0);
    near("its TIMESTEP", dump.timestep(), 100, 0);
    near("its atom count", p.size(), 3, 0);
    if (p.size() == 3)
    {
        near("id of the second atom", p.ids()[1], 3, 0);
        near("radius of the second atom (m)", p.radii()[1], 0.25e-3, 0);
        near("x of the third atom (x is the sixth column)", p.positions()[2].x(), 0.7, 0);
        near("y of the third atom", p.positions()[2].y(), 0.8, 0);
        near("z of the third atom", p.positions()[2].z(), 0.9, 0);
    }
    const scalar halfway = dump.progress();
    near("progress after the first of two snapshots within (0, 1)", halfway > 0 && halfway < 1, 1, 0);
    near("second snapshot read", dump.read(p), 1, 0);
    near("its TIMESTEP", dump.timestep(), 200, 0);
    near("its atom count", p.size(), 2, 0);
    if (p.size() == 2) near("x of its second atom", p.positions()[1].x(), 0.75, 0);
    near("no third snapshot", dump.read(p), 0, 0);
    near("progress at the end", dump.progress(), 1, 0);

    const std::string atoms("id x y z radius");
    refused
    (
        "an id twice: error names its line and the first",
        header(0, 3, atoms) + "1 0 0 0 1e-3\n2 0 0 0 1e-3\n1 0 0 0 1e-3\n",
        {"line 12", "atom id 1 again (first at line 10)"}
    );
    refused
    (
        "a missing radius column: error names it",
        header(0, 1, "id x y z") + "1 0 0 0\n", {"line 9", "missing column 'radius'"}
    );
    refused
    (
        "a radius <= 0: error names the line",
        header(0, 2, atoms) + "1 0 0 0 1e-3\n2 0 0 0 -1e-3\n", {"line 11", "radius must be positive"}
    );
    refused
    (
        "fewer atoms than announced: error names the line",
        header(0, 3, atoms) + "1 0 0 0 1e-3\n2 0 0 0 1e-3\n", {"line 11", "expected 3 atoms"}
    );
    refused
    (
        "a malformed number: error names the column",
        header(0, 1, atoms) + "1 0 0.x 0 1e-3\n", {"line 10", "'0.x' in column y: not a number"}
    );
    refused
    (
        "an overflowing number: error names it (no floating-point trap)",
        header(0, 1, atoms) + "1 0 1e999 0 1e-3\n", {"line 10", "'1e999' in column y: out of the range"}
    );
    refused
    (
        "a non-number in a column not kept: the file is damaged",
        header(0, 1, "id type x y z vx radius") + "1 1 0 0 0 nan 1e-3\n",
        {"line 10", "'nan' in column vx: not a finite number"}
    );
    refused("an empty file: error says so", "", {"the file is empty"});

    return testHarness::summary("liggghtsDumpReader");
}
