#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The 2D (disk) variant on one-cell-thick meshes with empty front and back:
closed forms (disk on a vertex or an edge: sectors with the cells' corner
angles), conservation of the disk volumes pi r^2 T for all six models, the
kernel against an independent evaluation of Kalderon et al.'s 2D Gaussian, voxel and
hybrid converging to analytical, independence of the particles' out-of-plane
coordinate, serial against mpirun -np 2, and a 2D switch on a 3D mesh."""
import math
import os
import re
import sys

import checks
from checks import WORK, check, near, run_model, serial_vs_parallel
from estimatorTests import gaussian_reference, relative_l1
from foamCase import (box_block_mesh, cell_centres, cell_volumes, new_case, random_spheres,
                      read_scalar_field, set_coupling, sh, void_fraction_models, write_dump)

L, T, N = 0.03, 0.002, 10
MODELS = void_fraction_models()
EMPTY = {"zmin": "type empty;", "zmax": "type empty;"}
SHEAR = 0.3


def slab_case(name, shear=False, n=N):
    case = new_case(os.path.join(WORK, name), box_block_mesh((0, 0, 0), (L, L, T), (n, n, 1), patches=EMPTY))
    if shear:
        pts = os.path.join(case, "constant", "polyMesh", "points")
        line = re.compile(r"^\([ \t]*(\S+)[ \t]+(\S+)[ \t]+(\S+)[ \t]*\)$", re.M)
        text = line.sub(lambda m: "(%.17g %.17g %.17g)" % (float(m.group(1)) + SHEAR * float(m.group(2)),
                                                         float(m.group(2)), float(m.group(3))),
                        open(pts).read())
        open(pts, "w").write(text)
    return case


def solid2d(case, dump, model, V, coeffs=""):
    set_coupling(case, "voidFractionModel %s;\nalphaMin 0.01;\ntwoDimensional true;\n%sCoeffs { %s }\n"
                 % (model, model, coeffs))
    rc, out = run_model(case, dump, model)
    if rc != 0:
        raise RuntimeError("%s {%s} failed:\n%s" % (model, coeffs, out[-800:]))
    alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    return [(1 - a) * v for a, v in zip(alpha, V)], out


def random_disks(n, seed, shear=False):
    c, r = random_spheres(n, 0.0004, 0.0012, (0, 0, 0), (L, L, T), seed=seed)
    # disks clear of the walls; any out-of-plane coordinate
    c = [(min(max(x, ri), L - ri), min(max(y, ri), L - ri), z * 7) for (x, y, z), ri in zip(c, r)]
    if shear:
        c = [(x + SHEAR * y, y, z) for x, y, z in c]
    return c, r


def test_closed_forms():
    print("2D analytical: a disk on a vertex or an edge splits into sectors")
    h = L / N
    R = 0.0012
    A = math.pi * R * R * T
    for name, shear in (("rectangles", False), ("sheared quadrilaterals", True)):
        case = slab_case("2d-closed-" + ("shear" if shear else "rect"), shear)
        V = cell_volumes(case)
        vertex = (5 * h + (SHEAR * 5 * h if shear else 0), 5 * h, 0.0)
        write_dump(os.path.join(case, "one.dump"), [vertex], [R])
        s, _ = solid2d(case, "one.dump", "analytical", V)
        pieces = sorted(x for x in s if x > 0)
        # corner angles of the cells at the vertex: between (1, 0) and (shear, 1)
        theta = math.atan2(1, SHEAR) if shear else math.pi / 2
        want = sorted([R * R / 2 * theta * T] * 2 + [R * R / 2 * (math.pi - theta) * T] * 2)
        near("%s: disk on a vertex, four sectors with the corner angles (max rel)" % name,
             max(abs(p / w - 1) for p, w in zip(pieces, want)) if len(pieces) == 4 else None, 0, 1e-12)
        edge = (5 * h + (SHEAR * 4.5 * h if shear else 0), 4.5 * h, 0.0)
        write_dump(os.path.join(case, "one.dump"), [edge], [0.3 * h])
        s, _ = solid2d(case, "one.dump", "analytical", V)
        pieces = sorted(x for x in s if x > 0)
        near("%s: disk centred on an edge, two halves (rel)" % name,
             max(abs(p / (math.pi * (0.3 * h) ** 2 * T / 2) - 1) for p in pieces) if len(pieces) == 2 else None,
             0, 1e-12)


def test_conservation():
    print("2D conservation (sum of pi r^2 T) and bounds for all six models")
    for name, shear in (("rectangles", False), ("sheared quadrilaterals", True)):
        case = slab_case("2d-cons-" + ("shear" if shear else "rect"), shear)
        c, r = random_disks(300, seed=21, shear=shear)
        write_dump(os.path.join(case, "p.dump"), c, r)
        V = cell_volumes(case)
        want = sum(math.pi * ri * ri * T for ri in r)
        for model in MODELS:
            s, out = solid2d(case, "p.dump", model, V)
            near("%s %s: solid = sum of disk volumes (rel)" % (name, model), sum(s) / want, 1, 1e-12)
            alpha = [1 - x / v for x, v in zip(s, V)]
            check("%s %s: void fraction finite and at least alphaMin" % (name, model),
                  all(math.isfinite(a) and a >= 0.01 - 1e-12 for a in alpha), "(min %.4f)" % min(alpha))


def test_out_of_plane_coordinate():
    print("2D: the particles' out-of-plane coordinate does not matter")
    case = slab_case("2d-z")
    c, r = random_disks(200, seed=22)
    V = cell_volumes(case)
    for model in ("analytical", "kernel"):
        fields = []
        for z in (0.0, T / 2, 5.0):
            write_dump(os.path.join(case, "p.dump"), [(x, y, z) for x, y, _ in c], r)
            fields.append(solid2d(case, "p.dump", model, V)[0])
        near("%s: z = 0, T/2, 5 give the same field (L1 rel)" % model,
             max(relative_l1(fields[0], fields[1]), relative_l1(fields[2], fields[1])), 0, 1e-14)


def test_kernel_reference():
    print("2D kernel against an independent evaluation of Kalderon et al.'s Eq. 7, walls reflected")
    case = slab_case("2d-kref", shear=True)
    V = cell_volumes(case)
    C = cell_centres(case)
    b, R = 0.002, 0.0005
    # far from the slanted x-walls (more than the cut-off 3b), near y = 0 or not
    for where, c in (("by a wall", (0.015, 0.002)), ("inside", (0.02, 0.015))):
        write_dump(os.path.join(case, "one.dump"), [(c[0], c[1], 0.0)], [R])
        got, _ = solid2d(case, "one.dump", "kernel", V, "bandwidth %r;" % b)
        # walls y = 0 and y = L are planes; the sheared x-walls too, but slanted: none near here
        want = gaussian_reference(C, V, (c[0], c[1], T / 2), b, 3 * b, [(1, 0.0), (1, L)])
        Vp = math.pi * R * R * T
        near("sheared 2D mesh, particle %s: cell volumes = reference (max rel to particle)" % where,
             max(abs(g / Vp - w) for g, w in zip(got, want)), 0, 1e-12)


def test_convergence():
    print("2D voxel and hybrid converge to analytical")
    case = slab_case("2d-conv", n=8)
    c, r = random_disks(60, seed=23)
    r = [1.6 * ri for ri in r]   # disks of 0.3 to 1 cell widths: many cut by two or more edges
    c = [(min(max(x, ri), L - ri), min(max(y, ri), L - ri), z) for (x, y, z), ri in zip(c, r)]
    write_dump(os.path.join(case, "p.dump"), c, r)
    V = cell_volumes(case)
    exact = solid2d(case, "p.dump", "analytical", V)[0]
    for model, key in (("voxel", "voxelsPerDiameter"), ("hybrid", "subGridResolution")):
        ns = (5, 20, 80)
        errs = [relative_l1(solid2d(case, "p.dump", model, V, "%s %d;" % (key, n))[0], exact) for n in ns]
        slope = math.log(errs[0] / errs[-1]) / math.log(ns[-1] / ns[0])
        print("    2D %s: L1 error %s at %s per diameter, order %.2f" %
              (model, " ".join("%.2e" % e for e in errs), ns, slope))
        check("2D %s error falls at order >= 0.9" % model, slope >= 0.9, "(order %.2f)" % slope)


def test_parallel():
    print("2D serial against mpirun -np 2")
    case = slab_case("2d-parallel", shear=True)
    # crowded: the alphaMin limiter moves volume across the processor boundary
    c, r = random_disks(300, seed=24, shear=True)
    write_dump(os.path.join(case, "p.dump"), c, r)
    for model in MODELS:
        set_coupling(case, "voidFractionModel %s;\nalphaMin 0.01;\ntwoDimensional true;\n" % model)
        serial_vs_parallel("2D sheared", case, "p.dump", model, 1e-9 if model == "diffusion" else 1e-12)


def test_bad_input():
    print("2D switch on a 3D mesh: clear error")
    case = new_case(os.path.join(WORK, "2d-bad"), box_block_mesh((0, 0, 0), (L, L, L), (4, 4, 4)))
    write_dump(os.path.join(case, "ok.dump"), [(0.01, 0.01, 0.01)], [0.001])
    set_coupling(case, "voidFractionModel analytical;\ntwoDimensional true;\n")
    rc, out = sh("demVoidFraction -dump ok.dump", case, check=False)
    check("twoDimensional on a 3D mesh: error names it and the cause",
          rc != 0 and "twoDimensional" in out and "one cell thick" in out)


def main():
    checks.run([test_closed_forms, test_conservation, test_out_of_plane_coordinate,
                test_kernel_reference, test_convergence, test_parallel, test_bad_input], sys.argv[1:])
    return checks.summary("twodim")


if __name__ == "__main__":
    sys.exit(main())
