/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    scaleCase

Description
    Writes the exactly scaled copy of a coupled CFD-DEM case: lengths and
    times by h, densities by 1, so that a quantity of dimensions M^a L^b T^c
    scales by h^(3a+b+c) (Zhang, Huang and Zhao, "Comparison of coarse
    graining DEM models based on exact scaling laws", CMES 2021, Table 1).
    The scaled case, run, reproduces the original mapped back: positions
    and times divided by h, velocities and pressures (kinematic) as they
    are, forces divided by h^2.

    Copied: everything but results (time directories other than 0,
    processor*, postProcessing, VTK, DEM/post, log.*). Scaled: the mesh
    (blockMeshDict's scale and constant/polyMesh/points), the fields of 0
    and 0.orig by their dimensions, constant/g, constant/transportProperties,
    controlDict's times and probe locations, the void fraction models'
    lengths, and the DEM parameters of DEM/in.parameters:

        variable dp     equal 0.001     # [0 1 0]    diameter
        variable E      equal 5e6       # [1 -1 -2]  Young's modulus

    The DEM scripts take every dimensional number from these variables.
    Hertz contacts with an unchanged modulus are consistent under the
    scaling as they stand; a Hooke stiffness is declared [1 0 -2] and
    scales by h.

    With -parcels cubic|exact it writes instead the same case with the
    DEM's spheres made parcels of h^3 particles: a coarseGraining
    dictionary in couplingProperties, the DEM parameters marked {particle},
    {count} or {timestep} in DEM/in.parameters scaled by the law (see
    caseScaler), and the fluid coarsened with them: blockMeshDict's cell
    counts divided by at most h (less where -minCells asks for more cells
    across the bed), the fluid step and the coupling time times the least
    growth of a cell, the smoothing of kernel and diffusion kept in metres
    unless -relativeSmoothing (see fluidCoarsener), every change printed.
    -keepMesh keeps the fluid's mesh and steps (the parcels then see h
    times fewer cells each).
    A 2D case (twoDimensional true in couplingProperties) gets parcels of
    h^2 disks. The DEM's primitive walls on the mesh's sides move out by
    c (h - 1) d, so that the parcels' looser layer at a wall holds the
    particles' solids, and keepVolumeBeyondMesh keeps the parcels' part
    beyond the mesh, with -wallVoid c (parcelWalls; c = 0.166 for beads at
    a flat wall). Without it the walls stay. -courant Co sets the coarse
    fluid step and coupling time by the coarse bed's needs instead of the
    fine case's Courant number: Co on the coarse cells and a tenth of the
    parcels' drag response time (fluidStepRule), where that is longer.

Usage
    scaleCase -factor 2 -output ../bed-h2
    scaleCase -factor 2 -parcels cubic -output ../bed-parcels
    scaleCase -factor 2 -parcels cubic -keepMesh -output ../bed-parcels-fine
    scaleCase -factor 4 -parcels cubic -minCells '(z 12 0.042)' -output ../bed-h4
    scaleCase -factor 3 -parcels cubic -wallVoid 0.166 -output ../bed-h3-walls
    scaleCase -factor 4 -parcels cubic -minCells '(z 12 0.042)' -courant 0.5 -output ../bed-h4-step

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "OSspecific.H"
#include "caseScaler.H"
#include "numericOption.H"
#include "caseFiles.H"
#include "couplingKeywords.H"
#include <algorithm>

using namespace Foam;

namespace
{
    bool isResult(const fileName& name)
    {
        // a time directory; textNumber, as a folder "nan" would trip the trap
        const char* notTime = nullptr;
        textNumber(name, notTime);
        return (!notTime && name != "0")
            || name.startsWith("processor") || name.startsWith("log.")
            || name == "postProcessing" || name == "VTK";
    }

    // Foam::cp copies contents only: give each copied file its source's
    // permissions, so that Allrun and Allclean stay executable
    void keepModes(const fileName& source, const fileName& copy)
    {
        for (const fileName& f : readDir(source, fileName::FILE, false))
        {
            if (isFile(copy/f, false)) chMod(copy/f, mode(source/f, false));
        }
        for (const fileName& d : readDir(source, fileName::DIRECTORY, false))
        {
            if (isDir(copy/d)) keepModes(source/d, copy/d);
        }
    }
}

int main(int argc, char *argv[])
{
    argList::addNote("Writes the exactly scaled copy of a coupled case");
    argList::noParallel();
    argList::addOption("factor", "h", "length and time scale, > 0");
    argList::addOption("output", "dir", "the scaled case, a new directory");
    argList::addBoolOption("overwrite", "replace the output directory");
    argList::addOption
    (
        "parcels", "law",
        "instead: the same case with the DEM's spheres parcels of h^3"
        " particles, forces scaled cubic or exact, the fluid coarsened by h"
    );
    argList::addBoolOption
    (
        "keepMesh",
        "with -parcels: keep the fluid's mesh, time step and coupling interval"
    );
    argList::addOption
    (
        "minCells", "rules",
        "with -parcels: at least so many cells across a length, e.g."
        " '(z 12 0.2) (x 20)': 12 across the 0.2 m settled bed in z, 20 across"
        " the mesh in x (cells grow by h at most, and less where a rule says)"
    );
    argList::addOption
    (
        "wallVoid", "c",
        "with -parcels: the DEM's walls on the mesh's sides move out by"
        " c (h - 1) d, c the particles' extra void at a wall per wall area in"
        " diameters (0.166: beads at a flat wall); without, they stay"
    );
    argList::addOption
    (
        "courant", "Co",
        "with -parcels and a coarsened fluid: the fluid step the coarse bed"
        " needs, the Courant number Co on its cells (the gas's speed bounded by"
        " the inlet's through the densest packing) and the coupling time at"
        " most a tenth of the parcels' drag response time; without, the fine"
        " case's Courant number"
    );
    argList::addBoolOption
    (
        "relativeSmoothing",
        "with -parcels: kernel's and diffusion's smoothing grows with the cells"
        " (default: the fine case's length in metres)"
    );
    noRepeatedOptions(argc, argv);
    #include "setRootCase.H"

    const scalar h = finiteOption(args, "factor");
    if (args.found("wallVoid") && !args.found("parcels"))
    {
        FatalErrorInFunction
            << "-wallVoid goes with -parcels" << exit(FatalError);
    }
    const scalar wallVoid =
        args.found("wallVoid") ? finiteOption(args, "wallVoid") : scalar(0);
    if (!(wallVoid >= 0 && wallVoid < 0.5))
    {
        // a parcel's centre stays inside the mesh while c (h - 1) < h/2
        FatalErrorInFunction
            << "-wallVoid " << wallVoid << ": must lie in [0, 0.5) particle diameters"
            << exit(FatalError);
    }
    const scalar courant =
        args.found("courant") ? finiteOption(args, "courant") : scalar(0);
    if (args.found("courant") && !(courant > 0 && courant <= 1))
    {
        // PISO's pressure-velocity coupling asks for Co below 1
        FatalErrorInFunction
            << "-courant " << courant << ": must lie in (0, 1]" << exit(FatalError);
    }
    for (const word option : {"minCells", "relativeSmoothing", "courant"})
    {
        if (args.found(option) && (!args.found("parcels") || args.found("keepMesh")))
        {
            FatalErrorInFunction
                << "-" << option << " goes with -parcels and a coarsened fluid"
                << " (not -keepMesh)" << exit(FatalError);
        }
    }
    if (args.found("keepMesh") && !args.found("parcels"))
    {
        FatalErrorInFunction
            << "-keepMesh goes with -parcels: the exact scaling scales the mesh"
            << exit(FatalError);
    }
    if (!(h > 0))
    {
        FatalErrorInFunction << "-factor " << h << ": must be positive" << exit(FatalError);
    }
    const fileName source(args.path());
    // a damaged file stops here, before anything is written
    const fileName couplingFile(source/"constant"/"couplingProperties");
    checkCouplingProperties(caseFiles::readDict(couplingFile), couplingFile);
    if (!args.found("output"))
    {
        FatalErrorInFunction
            << "option -output is required (the scaled case, a new directory)"
            << exit(FatalError);
    }
    const std::string given(args["output"]);
    if (given.empty() || !std::all_of(given.begin(), given.end(), [](char c) { return fileName::valid(c); }))
    {
        FatalErrorInFunction
            << "-output '" << given.c_str() << "': not a directory name OpenFOAM takes"
            << " (no spaces or quotes)" << exit(FatalError);
    }
    const fileName output(args.get<fileName>("output").expand());
    const fileName outputAbs(output.isAbsolute() ? output : cwd()/output);
    const fileName sourceAbs(source.isAbsolute() ? source : cwd()/source);
    if (outputAbs.clean() == sourceAbs.clean())
    {
        FatalErrorInFunction
            << "-output " << output << " is the case itself" << exit(FatalError);
    }
    if (exists(output))
    {
        if (!args.found("overwrite"))
        {
            FatalErrorInFunction
                << output << " exists; choose another -output or add -overwrite"
                << exit(FatalError);
        }
        rmDir(output);
    }
    mkDir(output);
    for (const fileName::Type type : {fileName::FILE, fileName::DIRECTORY})
    {
        for (const fileName& name : readDir(source, type, false))
        {
            // (the output may lie inside the case)
            const fileName entry(sourceAbs/name);
            if (!isResult(name) && entry.clean() != outputAbs.clean())
            {
                cp(source/name, outputAbs/name);
            }
        }
    }
    keepModes(sourceAbs, outputAbs);
    if (isDir(outputAbs/"DEM"/"post")) rmDir(outputAbs/"DEM"/"post");

    if (args.found("parcels"))
    {
        if (!(h >= 1))
        {
            FatalErrorInFunction
                << "-factor " << h << ": a parcel stands for h^3 >= 1 particles"
                << exit(FatalError);
        }
        caseScaler(outputAbs, h).makeParcels
        (
            args.get<word>("parcels"),
            !args.found("keepMesh"),
            args.found("minCells")
              ? fluidCoarsener::readMinCells(args["minCells"], "minCells")
              : List<fluidCoarsener::minCellRule>(),
            args.found("relativeSmoothing"),
            wallVoid,
            courant
        );
    }
    else
    {
        caseScaler(outputAbs, h).scaleAll();
    }
    Info<< "scaleCase: " << source << " scaled by " << h << " into " << outputAbs
        << nl << "End" << nl << endl;
    return 0;
}
