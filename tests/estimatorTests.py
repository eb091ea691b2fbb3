#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Tests of the voxel, hybrid, kernel and diffusion models on real meshes.
References: sums of sphere volumes, the analytical model's exact overlap
(itself tested against closed forms and numerical integration), an
independent Python evaluation of the Gaussian kernel (Kalderon et al.'s Eq. 8),
of their explicit diffusion step (Eq. 20) and of a voxel count, the centroid
split, and the serial run for the parallel one."""
import math
import os
import random
import re
import sys

import checks
from checks import WORK, check, field_checks, near, parallel_cases, run_model, serial_vs_parallel
from foamCase import (box_block_mesh, cell_centres, cell_volumes, new_case, parse_report,
                      random_spheres, read_scalar_field, set_coupling, sh, sphere_volume,
                      tet_case, write_dump)

L = 0.03
LO, HI = (0, 0, 0), (L, L, L)
MODELS = ("voxel", "hybrid", "kernel", "diffusion")


def solid_of(case, V):
    alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    return [(1 - a) * v for a, v in zip(alpha, V)]


def model_solid(case, dump, model, V, coeffs=""):
    """Solid volume per cell of model with the given coefficient entries."""
    set_coupling(case, "voidFractionModel %s;\nalphaMin 0.01;\n%sCoeffs { %s }\n" % (model, model, coeffs))
    rc, out = run_model(case, dump, model)
    if rc != 0:
        raise RuntimeError("%s {%s} failed" % (model, coeffs))
    return solid_of(case, V)


def relative_l1(a, b):
    return sum(abs(x - y) for x, y in zip(a, b)) / sum(abs(y) for y in b)


def test_conservation():
    print("conservation and bounds on a Cartesian, a graded and a tetrahedral mesh")
    spheres = random_spheres(1500, 0.0004, 0.0012, LO, HI, seed=11)
    cases = {
        "cartesian": new_case(os.path.join(WORK, "est-cartesian"), box_block_mesh(LO, HI, (10, 10, 10))),
        "graded": new_case(os.path.join(WORK, "est-graded"),
                           box_block_mesh(LO, HI, (12, 9, 10), grading=(4, 0.3, 2))),
        "tetrahedral": tet_case(os.path.join(WORK, "est-tet")),
    }
    for name, case in cases.items():
        for model in MODELS:
            field_checks(name, case, *spheres, model, alpha_min=0.05)


def test_convergence():
    print("voxel and hybrid converge to analytical as the resolution grows")
    case = new_case(os.path.join(WORK, "est-converge"), box_block_mesh(LO, HI, (8, 8, 8)))
    c, r = random_spheres(400, 0.0008, 0.0016, LO, HI, seed=12)   # many spheres cut by two or three planes
    write_dump(os.path.join(case, "p.dump"), c, r)
    V = cell_volumes(case)
    exact = model_solid(case, "p.dump", "analytical", V)
    for model, key in (("voxel", "voxelsPerDiameter"), ("hybrid", "subGridResolution")):
        ns = (5, 10, 20, 40)
        errs = [relative_l1(model_solid(case, "p.dump", model, V, "%s %d;" % (key, n)), exact) for n in ns]
        slope = math.log(errs[0] / errs[-1]) / math.log(ns[-1] / ns[0])
        print("    %s: L1 error %s at %s per diameter, order %.2f" %
              (model, " ".join("%.2e" % e for e in errs), ns, slope))
        # a cell face through the lattice miscounts up to a layer of voxels:
        # first order in the voxel size
        check("%s error falls with resolution at order >= 0.9" % model, slope >= 0.9, "(order %.2f)" % slope)
        check("%s error at 40 per diameter below 1.5 %%" % model, errs[-1] < 1.5e-2, "(%.2e)" % errs[-1])
        check("%s error falls at every refinement" % model,
              all(b < a for a, b in zip(errs, errs[1:])), str(["%.2e" % e for e in errs]))


def test_grid_against_walk():
    print("tensor-grid paths against the walk: the same box mesh with its far corner point moved in")
    full = new_case(os.path.join(WORK, "est-grid"), box_block_mesh(LO, HI, (10, 10, 10)))
    part = new_case(os.path.join(WORK, "est-walk"), box_block_mesh(LO, HI, (10, 10, 10)))
    # the corner cell, no longer a box, makes the mesh a general one (a missing
    # cell would not: grids with holes take the grid paths too)
    points = os.path.join(part, "constant", "polyMesh", "points")
    lines = open(points).read().split("\n")
    pattern = re.compile(r"^\((\S+) (\S+) (\S+)\)$")
    corner = max((i for i, l in enumerate(lines) if pattern.match(l)),
                 key=lambda i: sum(float(v) for v in pattern.match(lines[i]).groups()))
    lines[corner] = "(0.0295 0.0295 0.0295)"
    open(points, "w").write("\n".join(lines))
    c, r = random_spheres(800, 0.0004, 0.0012, LO, (0.024, 0.024, 0.024), seed=17)
    write_dump(os.path.join(full, "p.dump"), c, r)
    logs = [run_model(case, os.path.join(full, "p.dump"), "voxel")[1] for case in (full, part)]
    check("the full box is a tensor grid, the box with a corner moved in is not",
          "tensor-product" in logs[0] and "tensor-product" not in logs[1])
    # the kernel also at the factorised Gaussians' bound: cutoff 6, a cell 12
    # bandwidths wide, particles on the cell faces x = 3 mm k (and on the
    # cells' centres in y and z): windows of two cells in x, the second's
    # factor exp(144) times the first's Gaussian term, which prepareBlock's
    # clamp must leave exact; the two cells get half the volume each
    h = 0.003
    faces = [(h * (1 + i % 7) + 1e-10, h * (0.5 + (i // 7) % 8), h * (0.5 + (i // 56) % 8))
             for i in range(100)]
    fields = {}
    for name, case in (("grid", full), ("walk", part)):
        write_dump(os.path.join(case, "p.dump"), c, r)
        write_dump(os.path.join(case, "faces.dump"), faces, r[:100])
        V = cell_volumes(case)
        C = cell_centres(case)
        for model, dump, coeffs in (("analytical", "p.dump", ""), ("voxel", "p.dump", ""),
                                    ("hybrid", "p.dump", ""), ("kernel", "p.dump", ""),
                                    ("kernel cutoff 6", "faces.dump", "cutoff 6; bandwidthOverCellSize 0.0834;")):
            s = model_solid(case, dump, model.split()[0], V, coeffs)
            fields[(name, model)] = {tuple(round(x / 1e-6) for x in cc): v for cc, v in zip(C, s)}
    for model in ("analytical", "voxel", "hybrid", "kernel", "kernel cutoff 6"):
        g, w = fields[("grid", model)], fields[("walk", model)]
        diff = max(abs(g[k] - w[k]) for k in w if k in g) / max(g.values())
        near("%s: tensor-grid path = walk on the same cells (max rel to the largest)" % model, diff, 0, 1e-12)


def test_convex_cells_against_boxes():
    print("voxel and hybrid counts in tetrahedra (row by row through the face planes) against boxes")
    hexes = new_case(os.path.join(WORK, "est-hex6"), box_block_mesh(LO, HI, (6, 6, 6)))
    tets = tet_case(os.path.join(WORK, "est-tet6"), n=6, jitter=0.0)   # each box split into 6 tetrahedra
    c, r = random_spheres(100, 0.0008, 0.0020, LO, HI, seed=18)   # sparse: no alphaMin moves
    Vh, Vt, Ct = cell_volumes(hexes), cell_volumes(tets), cell_centres(tets)
    h = L / 6
    box_of = [int(x / h) + 6 * (int(y / h) + 6 * int(z / h)) for x, y, z in Ct]
    for model, coeffs in (("voxel", "voxelsPerDiameter 12;"), ("hybrid", "subGridResolution 12;")):
        fields = {}
        for name, case, V in (("hex", hexes, Vh), ("tet", tets, Vt)):
            write_dump(os.path.join(case, "p.dump"), c, r)
            fields[name] = model_solid(case, "p.dump", model, V, coeffs)
        sums = [0.0] * len(Vh)
        for b, v in zip(box_of, fields["tet"]):
            sums[b] += v
        if model == "hybrid":
            # the exact branch differs by cell shape; compare the voxel-split share only
            check("hybrid on tetrahedra conserves", abs(sum(fields["tet"]) / sum(fields["hex"]) - 1) < 1e-12)
            continue
        near("voxel: each box's six tetrahedra hold what the box holds (max rel)",
             max(abs(a - b) for a, b in zip(sums, fields["hex"])) / max(fields["hex"]), 0, 1e-12)


def test_vanishing_bandwidth():
    print("kernel and diffusion with a vanishing bandwidth become the centroid split")
    case = new_case(os.path.join(WORK, "est-vanish"), box_block_mesh(LO, HI, (10, 10, 10)))
    c, r = random_spheres(800, 0.0004, 0.0012, LO, HI, seed=13)
    write_dump(os.path.join(case, "p.dump"), c, r)
    V = cell_volumes(case)
    pcm = model_solid(case, "p.dump", "centroid", V)
    for model, coeffs, tol in (("kernel", "bandwidth 1e-5;", 1e-12),
                               ("diffusion", "bandwidth 1e-9;", 1e-12)):
        got = model_solid(case, "p.dump", model, V, coeffs)
        near("%s { %s }: = centroid (L1 rel)" % (model, coeffs), relative_l1(got, pcm), 0, tol)
    # and they move towards it as b shrinks
    for model, key in (("kernel", "bandwidthOverCellSize"), ("diffusion", "coefficient")):
        errs = [relative_l1(model_solid(case, "p.dump", model, V, "%s %g;" % (key, b)), pcm)
                for b in (0.4, 0.2, 0.1)]
        check("%s approaches centroid as %s shrinks" % (model, key),
              errs[0] > errs[1] > errs[2], str(["%.2e" % e for e in errs]))


def gaussian_reference(centres, V, c, b, rc, walls):
    """Seed Eq. 8 evaluated independently: V_cell exp(-|x - c|^2/b^2) in
    the cells whose centres lie within rc of c, plus there the Gaussians of
    the mirror images across the given axis planes (axis, position) within
    rc, normalised."""
    images = [tuple(c)]
    for axis, pos in walls:
        if abs(c[axis] - pos) < rc:
            images += [tuple(2 * pos - p[axis] if k == axis else p[k] for k in range(3)) for p in images]
    w = []
    for x, v in zip(centres, V):
        s = 0.0
        if sum((x[k] - c[k]) ** 2 for k in range(3)) <= rc * rc:
            for im in images:
                s += math.exp(-sum((x[k] - im[k]) ** 2 for k in range(3)) / b ** 2)
        w.append(v * s)
    total = sum(w)
    return [x / total for x in w]


def test_kernel_reference():
    print("kernel against an independent evaluation of Kalderon et al.'s Gaussian, walls reflected")
    R = 0.0005
    b, cutoff = 0.004, 3
    # a side whose far faces' normals come out of the face areas a few ulp
    # off the axes (the face centre, a mean of four equal coordinates, is
    # not the coordinate): their mirrors must count as exact ones do
    Lodd = 0.10988439379638951
    for name, case, side in (
        ("cartesian (1D factors)", new_case(os.path.join(WORK, "est-kref"),
                                            box_block_mesh(LO, HI, (10, 10, 10), grading=(2, 1, 1))), L),
        ("cartesian, inexact far normals", new_case(os.path.join(WORK, "est-kref-odd"),
                                                    box_block_mesh(LO, (Lodd,) * 3, (18, 18, 18))), Lodd),
        ("tetrahedral (walk)", tet_case(os.path.join(WORK, "est-kref-tet")), L)):
        walls = [(0, 0.0), (0, side), (1, 0.0), (1, side), (2, 0.0), (2, side)]
        V = cell_volumes(case)
        C = cell_centres(case)
        corner = (0.002, 0.0035, side - 0.001)
        for where, c in (("by a corner", corner), ("inside", (0.014, 0.016, 0.015))):
            write_dump(os.path.join(case, "one.dump"), [c], [R])
            got = model_solid(case, "one.dump", "kernel", V, "bandwidth %r; cutoff %d;" % (b, cutoff))
            want = gaussian_reference(C, V, c, b, cutoff * b, walls)
            Vp = sphere_volume(R)
            near("%s, particle %s: cell volumes = reference (max rel to particle)" % (name, where),
                 max(abs(g / Vp - w) for g, w in zip(got, want)), 0, 1e-12)
        if side == Lodd:
            # the default bandwidth on uniform planes: windows of two and
            # three cells (their fixed loops), serial Gaussians factorised
            # for the particles away from the walls, direct by them
            rng = random.Random(23)
            cs = [tuple(rng.uniform(0.0001, side - 0.0001) for _ in range(3)) for _ in range(40)]
            write_dump(os.path.join(case, "many.dump"), cs, [R] * len(cs))
            got = model_solid(case, "many.dump", "kernel", V, "bandwidthOverCellSize 0.4;")
            want = [0.0] * len(V)
            for c in cs:
                cell = min(range(len(C)), key=lambda i: sum((C[i][k] - c[k]) ** 2 for k in range(3)))
                bc = 0.4 * V[cell] ** (1 / 3)
                for i, w in enumerate(gaussian_reference(C, V, c, bc, 3 * bc, walls)):
                    want[i] += w * sphere_volume(R)
            near("%s, 40 particles at b/ds 0.4 (windows of 2 and 3 cells): = reference (max rel to particle)"
                 % name, max(abs(g - w) for g, w in zip(got, want)) / sphere_volume(R), 0, 1e-12)
        # without reflection the wall cells get less
        write_dump(os.path.join(case, "one.dump"), [corner], [R])
        flat = model_solid(case, "one.dump", "kernel", V, "bandwidth %r; reflectAtWalls false;" % b)
        want_flat = gaussian_reference(C, V, corner, b, cutoff * b, [])
        near("%s, no reflection: = reference without images" % name,
             max(abs(g / sphere_volume(R) - w) for g, w in zip(flat, want_flat)), 0, 1e-12)


def test_diffusion_is_gaussian():
    print("diffusion over pseudo-time T = kernel with b = sqrt(4 D T), one particle in a large box")
    n, h = 41, 0.001
    case = new_case(os.path.join(WORK, "est-gauss"), box_block_mesh((0, 0, 0), (n * h,) * 3, (n, n, n)))
    c = 20.5 * h
    write_dump(os.path.join(case, "one.dump"), [(c, c, c)], [0.0004])
    V = cell_volumes(case)
    C = cell_centres(case)
    devs = []
    kernels = {}
    for cells in (3, 6):
        b = cells * h
        kern = kernels[cells] = model_solid(case, "one.dump", "kernel", V, "bandwidth %r; cutoff 5;" % b)
        # implicit Euler converges to the heat kernel as 1/nSteps
        diff = model_solid(case, "one.dump", "diffusion", V, "bandwidth %r; nSteps 800;" % b)
        devs.append(max(abs(x - y) for x, y in zip(kern, diff)) / max(kern))
        print("    b = %d cells: max |diffusion - kernel| / peak = %.4f" % (cells, devs[-1]))
        # the second moment of exp(-r^2/b^2) is 3 b^2 / 2, for both
        for name, s in (("kernel", kern), ("diffusion", diff)):
            m2 = sum(v * ((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2) for v, (x, y, z) in zip(s, C)) / sum(s)
            near("b = %d cells: %s second moment / (3 b^2 / 2)" % (cells, name), m2 / (1.5 * b * b), 1, 0.01)
    # the grid's heat kernel differs from the sampled Gaussian by O((h/b)^2)
    check("diffusion = Gaussian kernel within 4 % of the peak at b = 6 cells", devs[1] < 0.04, "(%.4f)" % devs[1])
    check("the difference falls like (h/b)^2 (ratio >= 3 from b = 3 to 6 cells)",
          devs[0] / devs[1] >= 3, "(%.2f)" % (devs[0] / devs[1]))
    # Gaussians compose: the kernel split of bandwidth b1 smoothed with b2 is
    # the kernel of sqrt(b1^2 + b2^2); the second moments add exactly
    b1 = b2 = 6 * h / math.sqrt(2)
    comp = model_solid(case, "one.dump", "diffusion", V, "initial kernel; kernelCoeffs { bandwidth %r; cutoff 5; }"
                       " bandwidth %r; nSteps 800;" % (b1, b2))
    m2 = sum(v * ((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2) for v, (x, y, z) in zip(comp, C)) / sum(comp)
    near("diffusion from a kernel split: second moment / (3 (b1^2 + b2^2) / 2)", m2 / (1.5 * (b1 * b1 + b2 * b2)), 1, 0.01)
    dev = max(abs(x - y) for x, y in zip(kernels[6], comp)) / max(kernels[6])
    check("diffusion (b2) of a kernel split (b1) = kernel of sqrt(b1^2 + b2^2) within 4 %% of the peak (b1 = b2 = %.2f cells)"
          % (b1 / h), dev < 0.04, "(%.4f)" % dev)


def test_cyclic():
    print("cyclic wrap: spheres and kernels beyond one side land on the other")
    cyc = {"xmin": "type cyclic; neighbourPatch xmax;", "xmax": "type cyclic; neighbourPatch xmin;"}
    case = new_case(os.path.join(WORK, "est-cyclic"), box_block_mesh(LO, HI, (10, 10, 10), patches=cyc))
    c, r = random_spheres(1500, 0.0004, 0.0012, LO, HI, seed=14, periodic_axes=(0,))
    for model in MODELS:
        field_checks("cyclic", case, c, r, model)
    # a particle on the periodic plane: the first and last layers mirror each other
    V = cell_volumes(case)
    write_dump(os.path.join(case, "one.dump"), [(0.0, 0.0145, 0.0155)], [0.001])
    coeffs = {"diffusion": "initial analytical;",   # the centroid puts it on one side
              "voxel": "voxelsPerDiameter 40;"}
    for model in MODELS:
        s = model_solid(case, "one.dump", model, V, coeffs.get(model, ""))
        layer = lambda i: sum(s[i + 10 * (j + 10 * k)] for j in range(10) for k in range(10))
        if model == "voxel":
            # its lattice is not symmetric about the plane: equal to the voxel size
            near("voxel: a particle on the cyclic plane puts half on each side (ratio, 40 per diameter)",
                 layer(0) / layer(9), 1, 0.1)
        else:
            near("%s: a particle on the cyclic plane puts equal volume on both sides (rel)" % model,
                 layer(0) / layer(9), 1, 1e-9)


def test_parallel():
    print("serial against mpirun -np 2")
    # the diffusion solve converges to 1e-12, not to round-off
    parallel_cases("est-parallel-", 15, MODELS, lambda model: 1e-9 if model == "diffusion" else 1e-12)


def test_parallel_periodic():
    print("serial against mpirun -np 2 on a periodic box split across its periodic direction")
    cyc = {a + b: "type cyclic; neighbourPatch %s%s;" % (a, "max" if b == "min" else "min")
           for a in "xyz" for b in ("min", "max")}
    case = new_case(os.path.join(WORK, "est-parallel-periodic"), box_block_mesh(LO, HI, (10, 10, 10), patches=cyc))
    c, r = random_spheres(1500, 0.0004, 0.0012, LO, HI, seed=16, periodic_axes=(0, 1, 2))
    write_dump(os.path.join(case, "p.dump"), c, r)
    for model in ("centroid", "analytical") + MODELS:
        # conservation through images across processorCyclic patches, then the serial field
        field_checks("periodic box", case, c, r, model)
        serial_vs_parallel("periodic box", case, "p.dump", model, 1e-9 if model == "diffusion" else 1e-12)
    # a split with images and combinations of its own over the ranks, smoothed
    set_coupling(case, "voidFractionModel diffusion;\nalphaMin 0.05;\ndiffusionCoeffs { initial kernel; }\n")
    field_checks("periodic box, from a kernel split", case, c, r, "diffusion")
    serial_vs_parallel("periodic box, from a kernel split", case, "p.dump", "diffusion", 1e-9)
    # periodic in y only, split in x: each rank's grid spans y, so analytical
    # wraps the particles centred on the rank by grid index, and the others
    # (centred on the other rank) take images
    cyc = {"y" + b: "type cyclic; neighbourPatch y%s;" % ("max" if b == "min" else "min") for b in ("min", "max")}
    case = new_case(os.path.join(WORK, "est-parallel-periodic-y"), box_block_mesh(LO, HI, (10, 10, 10), patches=cyc))
    c, r = random_spheres(1500, 0.0004, 0.0012, LO, HI, seed=17, periodic_axes=(1,))
    write_dump(os.path.join(case, "p.dump"), c, r)
    field_checks("box periodic in y", case, c, r, "analytical")
    serial_vs_parallel("box periodic in y, split in x", case, "p.dump", "analytical", 1e-12)


def grid_index(point, h, n):
    return tuple(min(int(point[d] // h), n - 1) for d in range(3))


def test_explicit_diffusion_is_eq20():
    print("diffusion, integration explicit: Kalderon et al.'s Eq. 20 applied to the centroid field")
    n, h = 8, L / 8
    cyc = {a + b: "type cyclic; neighbourPatch %s%s;" % (a, "max" if b == "min" else "min")
           for a in "xyz" for b in ("min", "max")}
    case = new_case(os.path.join(WORK, "est-eq20"), box_block_mesh(LO, HI, (n, n, n), patches=cyc))
    c, r = random_spheres(600, 0.0004, 0.0012, LO, HI, seed=21, periodic_axes=(0, 1, 2))
    write_dump(os.path.join(case, "p.dump"), c, r)
    V, C = cell_volumes(case), cell_centres(case)
    # the centroid split, by grid index (independent of the C++)
    solid = {}
    for x, rad in zip(c, r):
        key = grid_index(x, h, n)
        solid[key] = solid.get(key, 0.0) + sphere_volume(rad) / h ** 3
    field = [[[solid.get((i, j, k), 0.0) for k in range(n)] for j in range(n)] for i in range(n)]

    def eq20(f, a):
        return [[[f[i][j][k] + a * (f[(i + 1) % n][j][k] + f[i - 1][j][k] + f[i][(j + 1) % n][k] + f[i][j - 1][k]
                                    + f[i][j][(k + 1) % n] + f[i][j][k - 1] - 6 * f[i][j][k])
                  for k in range(n)] for j in range(n)] for i in range(n)]

    for a, steps in ((0.12, 1), (0.3, 2)):
        ref = field
        for _ in range(steps):
            ref = eq20(ref, a / steps)
        got = model_solid(case, "p.dump", "diffusion", V, "integration explicit; coefficient %r; nSteps %d;" % (a, steps))
        worst = max(abs(g / v - ref[i][j][k])
                    for g, v, (i, j, k) in zip(got, V, (grid_index(x, h, n) for x in C)))
        near("a = %g in %d step(s): solid fraction = Eq. 20 applied %d time(s), max |difference|" % (a, steps, steps),
             worst, 0, 1e-13)
        near("a = %g in %d step(s): total solid volume conserved (rel)" % (a, steps),
             sum(got) / sum(sphere_volume(x) for x in r), 1, 1e-13)
    set_coupling(case, "voidFractionModel diffusion;\nalphaMin 0.01;\n"
                 "diffusionCoeffs { integration explicit; coefficient 0.3; }\n")
    rc, out = run_model(case, "p.dump", "diffusion")
    check("a = 0.3 in one explicit step (6 a > 1) is refused and names the stable nSteps (2)",
          rc != 0 and "unstable" in out and "Use nSteps 2 or more" in out and "diffusionCoeffs" in out,
          out[-300:] if rc == 0 else "")


def test_voxels_per_cell():
    print("voxel, voxelsPerCell: each cell divided evenly, against a Python voxel count")
    n, per = 6, 4
    h = L / (n * per)
    case = new_case(os.path.join(WORK, "est-voxel-cell"), box_block_mesh(LO, HI, (n, n, n)))
    c, r = random_spheres(400, 0.0004, 0.0015, LO, HI, seed=22)
    write_dump(os.path.join(case, "p.dump"), c, r)
    V, C = cell_volumes(case), cell_centres(case)
    ref = {}
    for x, rad in zip(c, r):
        counts = {}
        lo = [max(int((x[d] - rad) / h - 0.5), 0) for d in range(3)]
        hi = [min(int((x[d] + rad) / h + 0.5), n * per - 1) for d in range(3)]
        for i in range(lo[0], hi[0] + 1):
            for j in range(lo[1], hi[1] + 1):
                for k in range(lo[2], hi[2] + 1):
                    p = ((i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h)
                    if sum((p[d] - x[d]) ** 2 for d in range(3)) <= rad * rad:
                        key = (i // per, j // per, k // per)
                        counts[key] = counts.get(key, 0) + 1
        total = sum(counts.values())
        if total == 0:      # no voxel centre in it: the cell of its centre
            counts, total = {grid_index(x, L / n, n): 1}, 1
        for key, m in counts.items():
            ref[key] = ref.get(key, 0.0) + sphere_volume(rad) * m / total
    got = model_solid(case, "p.dump", "voxel", V, "voxelsPerCell %d;" % per)
    worst = max(abs(g - ref.get(grid_index(x, L / n, n), 0.0)) for g, x in zip(got, C))
    near("%d voxels per cell edge: solid volume per cell = Python count, max |difference| / sphere volume"
         % per, worst / sphere_volume(0.0004), 0, 1e-9)
    for name, mesh, needle in (
            ("tetrahedral", None, "equal axis-aligned box cells"),
            ("graded", box_block_mesh(LO, HI, (6, 6, 6), grading=(2, 1, 1)), "cells of one size")):
        bad = tet_case(os.path.join(WORK, "est-voxel-cell-tet")) if mesh is None else \
            new_case(os.path.join(WORK, "est-voxel-cell-graded"), mesh)
        write_dump(os.path.join(bad, "p.dump"), c[:5], r[:5])
        set_coupling(bad, "voidFractionModel voxel;\nvoxelCoeffs { voxelsPerCell 4; }\n")
        rc, out = run_model(bad, "p.dump", "voxel")
        check("%s mesh: voxelsPerCell is refused with '%s'" % (name, needle), rc != 0 and needle in out,
              out[-300:] if rc == 0 else "")


def test_bad_coefficients():
    print("bad coefficients: clear errors")
    case = new_case(os.path.join(WORK, "est-bad"), box_block_mesh(LO, HI, (4, 4, 4)))
    write_dump(os.path.join(case, "ok.dump"), [(0.01, 0.01, 0.01)], [0.001])
    bad = [
        ("kernel", "bandwidth -1e-3;", "bandwidth must be a positive number"),
        ("kernel", "bandwidth 1e-3; bandwidthOverCellSize 0.4;", "not both"),
        ("kernel", "cutoff 0;", "cutoff must be a positive number"),
        ("voxel", "voxelsPerSide 0;", "voxelsPerSide must be a positive number"),
        ("voxel", "voxelSize 1e-4; voxelsPerDiameter 10;", "not several"),
        ("voxel", "voxelsPerCell 2.5;", "voxelsPerCell must be a whole number"),
        ("hybrid", "subGridResolution 0;", "subGridResolution must be a positive number"),
        ("hybrid", "subGridResolution 2.5;", "whole number"),
        ("diffusion", "initial pcm;", "initial pcm is not one of"),
        ("diffusion", "initial diffusion;", "initial diffusion is not one of"),
        ("diffusion", "initial kernel; kernelCoeffs { cutoff 0; }", "diffusionCoeffs.kernelCoeffs"),
        ("diffusion", "coefficient -0.1;", "coefficient must be a positive number"),
        ("diffusion", "nSteps 0;", "nSteps must be a positive number"),
        ("diffusion", "integration rk4;", "integration rk4 is not one of"),
        ("diffusion", "laplacianScheme \"Gauss cubicSpline corrected\";", "cubicSpline"),
    ]
    for model, coeffs, needle in bad:
        set_coupling(case, "voidFractionModel %s;\n%sCoeffs { %s }\n" % (model, model, coeffs))
        rc, out = sh("demVoidFraction -dump ok.dump", case, check=False)
        ours = "laplacianScheme" not in coeffs    # that message is OpenFOAM's own
        check("%s { %s }: error says '%s'%s" % (model, coeffs, needle, " and names the dictionary" if ours else ""),
              rc != 0 and needle in out and (not ours or model + "Coeffs" in out)
              and "Segmentation" not in out)


def main():
    checks.run([test_conservation, test_grid_against_walk, test_convex_cells_against_boxes, test_convergence, test_vanishing_bandwidth, test_kernel_reference,
                test_diffusion_is_gaussian, test_explicit_diffusion_is_eq20, test_voxels_per_cell, test_cyclic, test_parallel, test_parallel_periodic,
                test_bad_coefficients], sys.argv[1:])
    return checks.summary("estimators")


if __name__ == "__main__":
    sys.exit(main())
