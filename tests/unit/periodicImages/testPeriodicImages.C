/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    testPeriodicImages

Description
    periodicImages on a box of 4 x 3 x 2 mm, cyclic in x and y, walls in z
    (blockMesh, written under build/unit/): the translations are the eight
    combinations of (4 0 0) and (0 3 0) mm; a particle clear of the
    periodic sides has no image, one by an x side has one across it, one by
    a corner has three (x, y, xy), at the positions translated by hand; the
    entries keep each particle before its images; a model that wraps x
    itself gets the images along y only, and one that always wraps x tests
    the y sides only. Ends with 'periodicImages: N passed, M failed'.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "periodicImages.H"
#include "testHarness.H"
#include "blockMeshCase.H"

using namespace Foam;
using testHarness::near;

namespace
{
    //- The rules of a model that wraps nothing itself
    struct noWrap
    {
        scalar reach(const scalar r) const { return r; }
        unsigned wrappedDirections(const point&, scalar, label) const { return 0; }
        unsigned wrappedAlways() const { return 0; }
        scalar wrappedRadius() const { return -1; }
    };

    //- Wraps x for every particle (wrappedDirections), or only for those
    //  centred in the mesh up to a radius (wrappedAlways)
    struct wrapsX
    {
        const bool always;
        const scalar radius;
        wrapsX(const bool always, const scalar radius) : always(always), radius(radius) {}
        scalar reach(const scalar r) const { return r; }
        unsigned wrappedDirections(const point&, scalar, label) const
        {
            return always ? 0 : 1u;
        }
        unsigned wrappedAlways() const { return always ? 1u : 0; }
        scalar wrappedRadius() const { return always ? radius : -1; }
    };

    //- The shifts of particle p's images (in mm), sorted by x then y
    List<vector> imageShiftsOf(const periodicImages& images, const label p)
    {
        DynamicList<vector> found;
        const labelList& first = images.firstEntry();
        for (label i = first[p] + 1; i < first[p + 1]; ++i)
        {
            found.append(images.shift(i)*1000);
        }
        std::sort(found.begin(), found.end(), [](const vector& a, const vector& b)
        {
            return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
        });
        return List<vector>(found);
    }

    void checkShifts(const std::string& what, const List<vector>& got, const List<vector>& want)
    {
        near((what + ": number of images").c_str(), got.size(), want.size(), 0);
        if (got.size() != want.size()) return;
        forAll(got, i)
        {
            near((what + ": image shift (mm)").c_str(), mag(got[i] - want[i]), 0, 1e-12);
        }
    }
}


int main(int argc, char *argv[])
{
    const testHarness::blockMeshCase unitCase
    (
        "periodicImagesCase",
        "scale 0.001;\n"
        "vertices ((0 0 0) (4 0 0) (4 3 0) (0 3 0) (0 0 2) (4 0 2) (4 3 2) (0 3 2));\n"
        "blocks (hex (0 1 2 3 4 5 6 7) (4 3 2) simpleGrading (1 1 1));\n"
        "boundary (\n"
        " left { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }\n"
        " right { type cyclic; neighbourPatch left; faces ((1 2 6 5)); }\n"
        " front { type cyclic; neighbourPatch back; faces ((0 1 5 4)); }\n"
        " back { type cyclic; neighbourPatch front; faces ((3 7 6 2)); }\n"
        " walls { type wall; faces ((0 3 2 1) (4 5 6 7)); });"
    );
    periodicImages images(unitCase.mesh());

    // the translations
    near("eight shifts: every combination of x and y but none", images.shifts().size(), 8, 0);
    near("periodic directions x and y (bits)", images.directions(), 3, 0);
    label nX = 0, nY = 0, nXY = 0;
    forAll(images.shifts(), s)
    {
        const vector S = images.shifts()[s]*1000;
        const unsigned dirs = images.shiftDirections()[s];
        near("shift has no z component (mm)", S.z(), 0, 1e-12);
        near("shift along x is 0 or 4 mm", mag(S.x())*(mag(S.x()) - 4), 0, 1e-9);
        near("shift along y is 0 or 3 mm", mag(S.y())*(mag(S.y()) - 3), 0, 1e-9);
        near("shift directions match its components", dirs, (mag(S.x()) > 1 ? 1 : 0) + (mag(S.y()) > 1 ? 2 : 0), 0);
        nX += dirs == 1;
        nY += dirs == 2;
        nXY += dirs == 3;
    }
    near("two shifts along x only", nX, 2, 0);
    near("two shifts along y only", nY, 2, 0);
    near("four shifts along x and y", nXY, 4, 0);

    // particles: clear of the sides, by the left side, by the corner x = y = 0
    const scalar r = 0.5e-3;
    const pointField x({point(2e-3, 1.5e-3, 1e-3), point(0.3e-3, 1.5e-3, 1e-3), point(0.2e-3, 0.2e-3, 1e-3)});
    const scalarField radii(3, r);
    const labelList centres({0, 1, 2});   // inside the mesh (the value is not read)

    near("clear of the sides: not near", images.nearSide(x[0], r), 0, 0);
    near("by the left side: near", images.nearSide(x[1], r), 1, 0);
    near("by the left side, x not tested: not near", images.nearSide(x[1], r, ~1u), 0, 0);

    {
        const pointField clear({x[0]});
        near("no particle by a side: no entries", images.make(clear, scalarField(1, r), labelList(1, 0), noWrap()), 0, 0);
        near("no particle by a side: no images", images.any(), 0, 0);
        near("no images: an entry is its own particle", images.parent(0), 0, 0);
    }

    near("images made", images.make(x, radii, centres, noWrap()), 1, 0);
    near("entries: 3 particles and 4 images", images.entries().size(), 7, 0);
    near("particle 1 starts at entry 1", images.firstEntry()[1], 1, 0);
    near("particle 2 starts at entry 3", images.firstEntry()[2], 3, 0);
    near("entry 3 is particle 2 itself", images.isParticle(3), 1, 0);
    near("entry 4 is an image of particle 2", images.isParticle(4) == 0 && images.parent(4) == 2, 1, 0);
    near("an image keeps its particle's radius (mm)", images.radii()[4]*1000, 0.5, 0);
    near("an image lies at its particle + its shift (mm)",
         mag(images.entries()[2] - x[1] - images.shift(2))*1000, 0, 1e-15);
    checkShifts("clear of the sides", imageShiftsOf(images, 0), List<vector>());
    checkShifts("by the left side", imageShiftsOf(images, 1), List<vector>({vector(4, 0, 0)}));
    checkShifts("by the corner", imageShiftsOf(images, 2),
                List<vector>({vector(0, 3, 0), vector(4, 0, 0), vector(4, 3, 0)}));

    // a second object's entries after a swap are the first's, and back
    {
        periodicImages other(unitCase.mesh());
        images.swapEntries(other);
        near("after a swap: the other holds the 7 entries", other.entries().size(), 7, 0);
        near("after a swap: this one holds none and has no images", images.entries().size() + images.any(), 0, 0);
        near("after a swap: the other's entry 4 is an image of particle 2", other.parent(4), 2, 0);
        images.swapEntries(other);
        near("swapped back: entry 4 is an image of particle 2 again", images.parent(4), 2, 0);
        checkShifts("swapped back, by the corner", imageShiftsOf(images, 2),
                    List<vector>({vector(0, 3, 0), vector(4, 0, 0), vector(4, 3, 0)}));
    }

    // the model wraps x itself: shifts along x only are its own
    images.make(x, radii, centres, wrapsX(false, 0));
    checkShifts("x wrapped, by the left side", imageShiftsOf(images, 1), List<vector>());
    checkShifts("x wrapped, by the corner", imageShiftsOf(images, 2),
                List<vector>({vector(0, 3, 0), vector(4, 3, 0)}));

    // x always wrapped up to a radius: only the y sides are tested for the
    // particles it covers
    images.make(x, radii, centres, wrapsX(true, 1e-3));
    checkShifts("x always wrapped, by the left side", imageShiftsOf(images, 1), List<vector>());
    checkShifts("x always wrapped, by the corner", imageShiftsOf(images, 2),
                List<vector>({vector(0, 3, 0), vector(4, 0, 0), vector(4, 3, 0)}));
    images.make(x, radii, centres, wrapsX(true, 0.4e-3));
    checkShifts("x wrapped below the radius only, by the left side", imageShiftsOf(images, 1),
                List<vector>({vector(4, 0, 0)}));

    return testHarness::summary("periodicImages");
}
