# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""A cylindrical column meshed by snappyHexMesh instead of blockMesh: a
background box of cubic cells cut to a cylinder given as an STL surface
(written here), the cells at the wall split once and snapped to it. Patches:
inlet (the box's bottom), outlet (its top), walls (the cylinder); the box's
sides lie outside the column, and snappyHexMesh drops them."""
import math
import os

from foamCase import sh


def write_cylinder_stl(path, radius, z0, z1, n=96):
    """The side of a cylinder on the z axis from z0 to z1, n facets round, as ASCII STL."""
    def facet(a, b, c):
        normal = (0.5*(a[0] + b[0]), 0.5*(a[1] + b[1]), 0.0)
        return ("  facet normal %g %g 0\n    outer loop\n" % normal[:2] +
                "".join("      vertex %.9g %.9g %.9g\n" % v for v in (a, b, c)) + "    endloop\n  endfacet\n")
    ring = [(radius*math.cos(2*math.pi*k/n), radius*math.sin(2*math.pi*k/n)) for k in range(n + 1)]
    with open(path, "w") as f:
        f.write("solid walls\n")
        for (xa, ya), (xb, yb) in zip(ring[:-1], ring[1:]):
            f.write(facet((xa, ya, z0), (xb, yb, z0), (xb, yb, z1)))
            f.write(facet((xa, ya, z0), (xb, yb, z1), (xa, ya, z1)))
        f.write("endsolid walls\n")


BACKGROUND = """FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
scale 1;
vertices ( (%(lo)g %(lo)g %(z0)g) (%(hi)g %(lo)g %(z0)g) (%(hi)g %(hi)g %(z0)g) (%(lo)g %(hi)g %(z0)g)
           (%(lo)g %(lo)g %(z1)g) (%(hi)g %(lo)g %(z1)g) (%(hi)g %(hi)g %(z1)g) (%(lo)g %(hi)g %(z1)g) );
blocks ( hex (0 1 2 3 4 5 6 7) (%(nxy)d %(nxy)d %(nz)d) simpleGrading (1 1 1) );
boundary
(
    inlet { type patch; faces ( (0 3 2 1) ); }
    outlet { type patch; faces ( (4 5 6 7) ); }
    sides { type patch; faces ( (0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7) ); }
);
"""

SNAPPY = """FoamFile { version 2.0; format ascii; class dictionary; object snappyHexMeshDict; }
castellatedMesh true;
snap            true;
addLayers       false;
geometry { column.stl { type triSurfaceMesh; name walls; } }
castellatedMeshControls
{
    maxLocalCells 2000000; maxGlobalCells 4000000; minRefinementCells 0; maxLoadUnbalance 0.1;
    nCellsBetweenLevels 2;
    features ();
    refinementSurfaces { walls { level (%(level)d %(level)d); patchInfo { type wall; } } }
    resolveFeatureAngle 30;
    refinementRegions {}
    locationInMesh (0.00011 0.00013 %(zin)g);
    allowFreeStandingZoneFaces true;
}
snapControls
{
    nSmoothPatch 3; tolerance 2.0; nSolveIter 50; nRelaxIter 5;
    nFeatureSnapIter 10; implicitFeatureSnap false; explicitFeatureSnap false; multiRegionFeatureSnap false;
}
addLayersControls
{
    relativeSizes true; layers {}; expansionRatio 1; finalLayerThickness 0.3; minThickness 0.1;
    nGrow 0; featureAngle 60; nRelaxIter 3; nSmoothSurfaceNormals 1; nSmoothNormals 3;
    nSmoothThickness 10; maxFaceThicknessRatio 0.5; maxThicknessToMedialRatio 0.3;
    minMedialAxisAngle 90; nBufferCellsNoExtrude 0; nLayerIter 50;
}
meshQualityControls
{
    maxNonOrtho 65; maxBoundarySkewness 20; maxInternalSkewness 4; maxConcave 80;
    minVol 1e-15; minTetQuality 1e-15; minArea -1; minTwist 0.02; minDeterminant 0.001;
    minFaceWeight 0.05; minVolRatio 0.01; minTriangleTwist -1; nSmoothScale 4; errorReduction 0.75;
    relaxed { maxNonOrtho 75; }
}
mergeTolerance 1e-6;
"""


def mesh_column(case, radius, z0, z1, cell, level=1):
    """Mesh case (its system/ and 0.orig/ as for a blockMesh column with patches inlet,
    outlet and walls) with snappyHexMesh: background cells of size cell, split level times
    at the wall. Returns (return code, output)."""
    half = radius + cell
    nxy = int(math.ceil(2*half/cell))
    half = 0.5*nxy*cell
    surface = os.path.join(case, "constant", "triSurface")
    os.makedirs(surface, exist_ok=True)
    write_cylinder_stl(os.path.join(surface, "column.stl"), radius, z0 - cell, z1 + cell)
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write(BACKGROUND % dict(lo=-half, hi=half, z0=z0, z1=z1, nxy=nxy, nz=int(round((z1 - z0)/cell))))
    with open(os.path.join(case, "system", "snappyHexMeshDict"), "w") as f:
        f.write(SNAPPY % dict(level=level, zin=0.5*(z0 + z1) + 1.7e-4))
    return sh("blockMesh > log.blockMesh 2>&1 && snappyHexMesh -overwrite > log.snappyHexMesh 2>&1 && "
              "checkMesh > log.checkMesh 2>&1", case, check=False)
