#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The model tests on real OpenFOAM meshes. Every check compares a number with
an independent reference (sums of sphere volumes, closed forms, the serial
run for the parallel one) and a tolerance. Ends with 'N passed, N failed'."""
import bisect
import math
import os
import random
import re
import shutil
import sys

import checks
from checks import WORK, check, field_checks, near, parallel_cases, run_model, serial_vs_parallel
from foamCase import (ROOT, box_block_mesh, cell_centres, cell_volumes, new_case, parse_report,
                      random_spheres, read_scalar_field, set_coupling, sh, sphere_volume,
                      tet_case, void_fraction_models, write_dump)

L = 0.03
LO, HI = (0, 0, 0), (L, L, L)


def test_meshes():
    print("conservation on five kinds of mesh, polydisperse random spheres")
    spheres = random_spheres(1500, 0.0004, 0.0012, LO, HI, seed=3)
    meshes = {
        "cartesian": box_block_mesh(LO, HI, (10, 10, 10)),
        "graded": box_block_mesh(LO, HI, (12, 9, 10), grading=(4, 0.3, 2)),
    }
    for name, bm in meshes.items():
        case = new_case(os.path.join(WORK, name), bm)
        for model in ("centroid", "analytical"):
            field_checks(name, case, *spheres, model)

    graded_centroid_reference()

    # sheared hexahedra: an affine map of the box, particles mapped alike
    case = new_case(os.path.join(WORK, "sheared"), box_block_mesh(LO, HI, (9, 9, 9)))
    shear = lambda p: (p[0] + 0.3 * p[1], p[1], p[2] + 0.2 * p[0])
    pts_file = os.path.join(case, "constant", "polyMesh", "points")
    point_line = re.compile(r"^\([ \t]*(\S+)[ \t]+(\S+)[ \t]+(\S+)[ \t]*\)$", re.M)
    text = open(pts_file).read()
    text = point_line.sub(lambda m: "(%.17g %.17g %.17g)" % shear([float(v) for v in m.groups()]), text)
    open(pts_file, "w").write(text)
    c, r = random_spheres(1500, 0.0004, 0.0012, LO, HI, seed=4)
    # a margin of 1.6 r in the unsheared box keeps every sphere inside
    c = [shear([min(max(ci[d], 1.6 * ri), L - 1.6 * ri) for d in range(3)]) for ci, ri in zip(c, r)]
    for model in ("centroid", "analytical"):
        field_checks("sheared", case, c, r, model)

    case = tet_case(os.path.join(WORK, "tet"))
    for model in ("centroid", "analytical"):
        field_checks("tetrahedral", case, *spheres, model)

    # polyhedral cells with warped faces: the dual of the tet mesh
    poly = os.path.join(WORK, "polyhedral")
    shutil.rmtree(poly, ignore_errors=True)
    shutil.copytree(case, poly)
    shutil.rmtree(os.path.join(poly, "0"), ignore_errors=True)
    sh("polyDualMesh 80 -overwrite", poly)
    for model in ("centroid", "analytical"):
        field_checks("polyhedral", poly, *spheres, model)


def test_closed_forms():
    print("closed forms on a mesh: a sphere on a grid vertex, edge and face")
    case = new_case(os.path.join(WORK, "closed"), box_block_mesh(LO, HI, (10, 10, 10)))
    h = L / 10
    R = 0.001
    V = cell_volumes(case)
    cases = {"vertex": ((5 * h, 5 * h, 5 * h), 8), "edge": ((5 * h, 5 * h, 4.5 * h), 4),
             "face": ((5 * h, 4.5 * h, 4.5 * h), 2)}
    for name, (c, k) in cases.items():
        write_dump(os.path.join(case, "one.dump"), [c], [R])
        rc, _ = run_model(case, "one.dump", "analytical")
        alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
        solids = sorted(((1 - a) * v for a, v in zip(alpha, V)), reverse=True)
        near("sphere on a %s: %d cells hold V/%d each (rel)" % (name, k, k),
             max(abs(s / (sphere_volume(R) / k) - 1) for s in solids[:k]), 0, 1e-12)
        near("sphere on a %s: no other cell holds any" % name, solids[k], 0, 1e-20)
    # centred on the wall x = 0: half inside, half reported outside
    write_dump(os.path.join(case, "one.dump"), [(0.0, 4.5 * h, 4.5 * h)], [R])
    rc, out = run_model(case, "one.dump", "analytical")
    alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    near("sphere centred on a wall: the mesh holds V/2 (rel)",
         sum((1 - a) * v for a, v in zip(alpha, V)) / (sphere_volume(R) / 2), 1, 1e-12)
    m = re.search(r"volume outside ([^,\s]+)", out)
    near("sphere centred on a wall: V/2 reported outside (rel, to the 4 digits printed)",
         float(m.group(1)) / (sphere_volume(R) / 2) if m else None, 1, 5e-4)


def cap_volume(r, depth):
    """Volume of a spherical cap of the given depth (closed form)"""
    return math.pi * depth ** 2 * (3 * r - depth) / 3


def spheres_through_walls(n, seed):
    """Spheres of 0.8 to 1.2 mm centred inside the box, each reaching
    through at most one of its walls (L/10 cells of 3 mm: none through an
    edge), and the part of each beyond the wall (a cap)"""
    rng = random.Random(seed)
    centres, radii, caps = [], [], []
    while len(radii) < n:
        r = rng.uniform(0.0008, 0.0012)
        c = [rng.uniform(0, L) for _ in range(3)]
        gaps = sorted(min(x, L - x) for x in c)
        if gaps[1] < r:
            continue
        centres.append(c)
        radii.append(r)
        caps.append(cap_volume(r, r - gaps[0]) if gaps[0] < r else 0.0)
    return centres, radii, caps


def test_keep_volume_beyond_mesh():
    print("keepVolumeBeyondMesh: the part of a sphere beyond a wall kept in its cells")
    case = new_case(os.path.join(WORK, "keepBeyond"), box_block_mesh(LO, HI, (10, 10, 10)))
    c, r, caps = spheres_through_walls(400, seed=11)
    check("spheres through the walls: some reach out", sum(1 for v in caps if v > 0) > 50)
    V = cell_volumes(case)
    whole = sum(sphere_volume(ri) for ri in r)
    dump = os.path.join(case, "particles.dump")
    write_dump(dump, c, r)
    # without: the field holds the spheres less their caps beyond the walls
    for model in ("analytical", "voxel", "hybrid"):
        rc, out = run_model(case, dump, model)
        alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
        near("without: %s holds the spheres less their caps (rel)" % model,
             sum((1 - a) * v for a, v in zip(alpha, V)) / (whole - sum(caps)), 1,
             1e-12 if model == "analytical" else 2e-3)
    set_coupling(case, "voidFractionModel analytical;\nalphaMin 0.05;\nkeepVolumeBeyondMesh on;\n")
    for model in void_fraction_models():
        field_checks("kept", case, c, r, model)
        _, out = run_model(case, dump, model)
        report = parse_report(out)
        m = re.search(r"kept in the mesh (\S+)", out)
        kept = float(m.group(1)) if m else None
        if model == "analytical":
            near("kept: analytical reports the caps as kept (rel, 4 digits)", kept and kept / sum(caps), 1, 5e-4)
        elif model in ("voxel", "hybrid"):
            near("kept: %s reports the caps as kept (rel to the spheres' volume)" % model,
                 kept and (kept - sum(caps)) / whole, 0, 2e-3)
        near("kept: %s conservation error" % model, report["conservation"], 0, 1e-12)
        serial_vs_parallel("kept", case, "particles.dump", model, 1e-9 if model == "diffusion" else 1e-12)
    # one sphere 0.4 R from the wall x = 0 on the edge of four cells: each
    # holds a quarter of the whole sphere
    h = L / 10
    R = 0.001
    write_dump(dump, [(0.4 * R, 5 * h, 5 * h)], [R])
    run_model(case, dump, "analytical")
    alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    solids = sorted(((1 - a) * v for a, v in zip(alpha, V)), reverse=True)
    near("sphere through a wall on four cells: each holds V/4 (rel)",
         max(abs(s / (sphere_volume(R) / 4) - 1) for s in solids[:4]), 0, 1e-12)
    near("sphere through a wall on four cells: no other cell holds any", solids[4], 0, 1e-20)


def graded_centroid_reference():
    """On a graded grid (non-uniform planes in all three directions) each
    sphere's volume lies in the cell holding its centre, that cell found
    here from the mesh's own points by bisection."""
    import bisect
    case = new_case(os.path.join(WORK, "gradedCentroid"), box_block_mesh(LO, HI, (12, 9, 10), grading=(4, 0.3, 2)),
                    coupling="voidFractionModel centroid;\nalphaMin 1e-6;\n")
    text = open(os.path.join(case, "constant", "polyMesh", "points")).read()
    points = [[float(v) for v in m] for m in
              re.findall(r"^\([ \t]*(\S+)[ \t]+(\S+)[ \t]+(\S+)[ \t]*\)$", text, re.M)]
    planes = [sorted(set(round(p[d], 12) for p in points)) for d in range(3)]
    check("graded planes: 13 x 10 x 11, not uniform",
          [len(g) for g in planes] == [13, 10, 11]
          and max(b - a for a, b in zip(planes[0], planes[0][1:])) > 2 * min(b - a for a, b in zip(planes[0], planes[0][1:])))

    def ijk(x):
        return tuple(min(bisect.bisect_right(planes[d], x[d]) - 1, len(planes[d]) - 2) for d in range(3))
    cell_of = {ijk(x): i for i, x in enumerate(cell_centres(case))}
    c, r = random_spheres(400, 0.0002, 0.0005, LO, HI, seed=21)
    alpha = field_checks("graded (reference)", case, c, r, "centroid", alpha_min=1e-6)
    if alpha is None:
        return
    V = cell_volumes(case)
    want = [0.0] * len(V)
    for x, ri in zip(c, r):
        want[cell_of[ijk(x)]] += sphere_volume(ri)
    near("graded centroid: per-cell solid = volume of the spheres centred in it, max rel to a sphere",
         max(abs((1 - a) * v - w) for a, v, w in zip(alpha, V, want)) / sphere_volume(0.0002), 0, 1e-9)


def test_thin_neighbour():
    print("graded grid: a sphere that crosses a thin neighbour cell whole, against spherical slabs")
    # widths grow 20-fold over 10 cells in x (0.44 mm to 8.8 mm); y and z uniform, 3 mm
    case = new_case(os.path.join(WORK, "thinNeighbour"), box_block_mesh(LO, HI, (10, 10, 10), grading=(20, 1, 1)))
    V = cell_volumes(case)
    C = cell_centres(case)
    layer = {}                          # cell centres' x, grouped per layer (full precision kept)
    for x in C:
        layer.setdefault(round(x[0], 9), x[0])
    keys = sorted(layer)
    planes = [0.0]
    for k in keys:
        planes.append(2 * layer[k] - planes[-1])
    R = 0.001
    # centre 0.05 mm above plane 3: its piece below crosses cell 2 (0.86 mm) into cell 1
    c = (planes[3] + 0.00005, 0.0165, 0.0165)
    write_dump(os.path.join(case, "one.dump"), [c], [R])
    rc, _ = run_model(case, "one.dump", "analytical")
    alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))

    def slab(a, b):
        a, b = max(a - c[0], -R), min(b - c[0], R)
        return 0.0 if b <= a else math.pi * ((R * R * b - b ** 3 / 3) - (R * R * a - a ** 3 / 3))
    got = [0.0] * 10
    for a, v, x in zip(alpha, V, C):
        got[keys.index(round(x[0], 9))] += (1 - a) * v
    want = [slab(planes[i], planes[i + 1]) for i in range(10)]
    check("the sphere reaches three x-layers", sum(w > 0 for w in want) == 3)
    near("per x-layer solid = spherical slab volume (max rel to the sphere)",
         max(abs(g - w) for g, w in zip(got, want)) / sphere_volume(R), 0, 1e-12)


def test_fast_against_general():
    print("axis-aligned fast path against the general path on a rotated mesh")
    c, r = random_spheres(800, 0.0005, 0.002, LO, HI, seed=5)   # cells smaller and larger than spheres
    base = new_case(os.path.join(WORK, "unrotated"), box_block_mesh(LO, HI, (8, 8, 8)))
    a0 = field_checks("unrotated", base, c, r, "analytical")
    rot = new_case(os.path.join(WORK, "rotated"), box_block_mesh(LO, HI, (8, 8, 8)))
    sh("transformPoints -rotate '((1 0 0) (0.8 0.6 0))'", rot)
    cr = [(0.8 * p[0] - 0.6 * p[1], 0.6 * p[0] + 0.8 * p[1], p[2]) for p in c]
    a1 = field_checks("rotated", rot, cr, r, "analytical")
    if a0 and a1:
        near("rotated (general path) = unrotated (box path), max |d alpha|",
             max(abs(x - y) for x, y in zip(a0, a1)), 0, 1e-11)
    # hexahedra each split into 6 tetrahedra (cells numbered hexahedron by
    # hexahedron), tetrahedra being volumes through the face caps: their
    # solid sums to the box path's in their hexahedron. Spheres small enough
    # that no volume is moved by alphaMin.
    c, r = random_spheres(600, 0.0003, 0.0008, LO, HI, seed=8)
    coupling = "voidFractionModel analytical;\nalphaMin 1e-6;\n"
    hexes = new_case(os.path.join(WORK, "hexSplit"), box_block_mesh(LO, HI, (8, 8, 8)), coupling=coupling)
    tets = tet_case(os.path.join(WORK, "tetSplit"), n=8, length=L, jitter=0.0, coupling=coupling)
    a0 = field_checks("hexahedra", hexes, c, r, "analytical", alpha_min=1e-6)
    a2 = field_checks("their tetrahedra", tets, c, r, "analytical", alpha_min=1e-6)
    if a0 and a2:
        V0, V2 = cell_volumes(hexes), cell_volumes(tets)
        solid0 = [(1 - a) * v for a, v in zip(a0, V0)]
        solid2 = [sum((1 - a2[6 * h + q]) * V2[6 * h + q] for q in range(6)) for h in range(len(V0))]
        near("6 tetrahedra (cap path) = their hexahedron (box path), max |d solid| / cell volume",
             max(abs(x - y) / v for x, y, v in zip(solid0, solid2, V0)), 0, 1e-11)
        check("tetrahedra: some cells hold parts of spheres (the test compares something)",
              sum(1 for a in a2 if 1e-9 < 1 - a < 0.999) > 100)


def step_mesh(n, cut):
    """blockMesh body of the cube [0, L]^3 in n^3 cells without the cells
    x < cut[0] L/n, z < cut[1] L/n (all y): three blocks whose planes are
    one tensor grid with cut[0] x n x cut[1] holes; walls all round."""
    h = L/n
    xs, zs = cut[0]*h, cut[1]*h
    boxes = [((0, 0, zs), (xs, L, L)), ((xs, 0, 0), (L, L, zs)), ((xs, 0, zs), (L, L, L))]
    vertices, blocks = [], []
    for lo, hi in boxes:
        corners = [(lo[0], lo[1], lo[2]), (hi[0], lo[1], lo[2]), (hi[0], hi[1], lo[2]), (lo[0], hi[1], lo[2]),
                   (lo[0], lo[1], hi[2]), (hi[0], lo[1], hi[2]), (hi[0], hi[1], hi[2]), (lo[0], hi[1], hi[2])]
        ids = []
        for c in corners:
            if c not in vertices:
                vertices.append(c)
            ids.append(vertices.index(c))
        cells = [round((hi[d] - lo[d])/h) for d in range(3)]
        blocks.append("hex (%s) (%d %d %d) simpleGrading (1 1 1)" % ((" ".join(map(str, ids)),) + tuple(cells)))
    return ("scale 1;\nvertices (%s);\nblocks ( %s );\nboundary ( );\ndefaultPatch { name walls; type wall; }\n"
            % (" ".join("(%.17g %.17g %.17g)" % v for v in vertices), " ".join(blocks)))


def test_grid_with_holes():
    print("a tensor grid with holes (a step cut out of a box) against the general path")
    n, cut = 8, (4, 3)
    xs, zs = cut[0]*L/n, cut[1]*L/n
    holes = cut[0]*n*cut[1]

    def to_step(x):
        """distance from the centre to the cut-out block (0 inside it)"""
        return math.hypot(max(x[0] - xs, 0), max(x[2] - zs, 0))
    c, r = random_spheres(900, 0.0005, 0.0016, LO, HI, seed=12)
    inside = [(x, ri) for x, ri in zip(c, r) if to_step(x) >= ri]
    crossing = [(x, ri) for x, ri in zip(c, r) if 0 < to_step(x) < ri]
    check("spheres wholly in the stepped mesh and spheres crossing the step",
          len(inside) > 300 and len(crossing) > 30, "(%d and %d)" % (len(inside), len(crossing)))
    grid = new_case(os.path.join(WORK, "stepGrid"), step_mesh(n, cut))
    rot = new_case(os.path.join(WORK, "stepRotated"), step_mesh(n, cut))
    sh("transformPoints -rotate '((1 0 0) (0.8 0.6 0))'", rot)
    rotate = lambda p: (0.8*p[0] - 0.6*p[1], 0.6*p[0] + 0.8*p[1], p[2])
    write_dump(os.path.join(grid, "one.dump"), [inside[0][0]], [inside[0][1]])
    rc, out = run_model(grid, "one.dump", "analytical")
    check("the stepped mesh is taken as an 8 x 8 x 8 grid with %d holes" % holes,
          "tensor-product mesh 8 x 8 x 8 with %d holes" % holes in out,
          "" if rc else "(%s)" % [l for l in out.splitlines() if "particleCellLocator" in l])
    spheres = [x for x, _ in inside], [ri for _, ri in inside]
    for model in ("analytical", "centroid", "voxel", "hybrid", "kernel", "diffusion"):
        field_checks("stepped grid", grid, *spheres, model)
    for name, group in (("wholly inside", inside), ("crossing the step", crossing)):
        fields = []
        for case, move in ((grid, lambda p: p), (rot, rotate)):
            write_dump(os.path.join(case, "step.dump"), [move(x) for x, _ in group], [ri for _, ri in group])
            rc, _ = run_model(case, "step.dump", "analytical")
            fields.append(read_scalar_field(os.path.join(case, "0", "voidfraction")) if rc == 0 else None)
        if None not in fields:
            near("analytical, spheres %s: grid with holes = general path (rotated), max |d alpha|" % name,
                 max(abs(a - b) for a, b in zip(*fields)), 0, 1e-11)
    # scotch parts of the step: grids with holes of their own, or general meshes
    with open(os.path.join(grid, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod scotch;\n")
    write_dump(os.path.join(grid, "p.dump"), *spheres)
    for model in ("analytical", "kernel"):
        serial_vs_parallel("stepped grid, scotch", grid, "p.dump", model, 1e-12)


def test_cyclic():
    print("cyclic patches: spheres beyond one side land on the other")
    cyc = {"xmin": "type cyclic; neighbourPatch xmax;", "xmax": "type cyclic; neighbourPatch xmin;"}
    case = new_case(os.path.join(WORK, "cyclic"), box_block_mesh(LO, HI, (10, 10, 10), patches=cyc))
    c, r = random_spheres(1500, 0.0004, 0.0012, LO, HI, seed=6, periodic_axes=(0,))
    for model in ("centroid", "analytical"):
        field_checks("cyclic", case, c, r, model)
    h = L / 10
    R = 0.001
    write_dump(os.path.join(case, "one.dump"), [(0.0, 4.5 * h, 4.5 * h)], [R])
    run_model(case, "one.dump", "analytical")
    alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    V = cell_volumes(case)
    first, last = 0 + 10 * (4 + 10 * 4), 9 + 10 * (4 + 10 * 4)
    for name, i in (("first", first), ("last", last)):
        near("sphere centred on the cyclic plane: %s cell holds V/2 (rel)" % name,
             (1 - alpha[i]) * V[i] / (sphere_volume(R) / 2), 1, 1e-12)


def test_parallel():
    print("serial against mpirun -np 2")
    parallel_cases("parallel-", 7, ("centroid", "analytical"))


def test_alpha_min():
    print("alphaMin: excess volume moved to neighbours, not deleted")
    case = new_case(os.path.join(WORK, "alphaMin"), box_block_mesh(LO, HI, (10, 10, 10)),
                    coupling="voidFractionModel centroid;\nalphaMin 0.4;\n")
    h = L / 10
    c, r = random_spheres(60, 0.0008, 0.0009, (4 * h,) * 3, (5 * h,) * 3, seed=8, gap=False)
    for model in void_fraction_models():
        alpha = field_checks("crowded cell", case, c, r, model, alpha_min=0.4)
        _, out = run_model(case, "particles.dump", model)
        check("crowded cell %s reports moved volume" % model, (parse_report(out)["moved"] or 0) > 0)
        # the crowded cell touches the processor boundary of the 2-way split
        serial_vs_parallel("crowded cell", case, "particles.dump", model,
                           1e-9 if model == "diffusion" else 1e-12)


def test_list_models():
    print("demVoidFraction -listModels: the papers' six in their order, each selectable")
    papers = ("centroid", "analytical", "voxel", "hybrid", "kernel", "diffusion")
    listed = void_fraction_models()
    check("the list starts with the papers' six in their order", listed[:6] == papers, "(%s)" % " ".join(listed))
    case = new_case(os.path.join(WORK, "listModels"), box_block_mesh(LO, HI, (4, 4, 4)))
    c, r = random_spheres(5, 0.0008, 0.0009, LO, HI, seed=3)
    write_dump(os.path.join(case, "particles.dump"), c, r)
    for model in listed:
        rc, _ = run_model(case, "particles.dump", model)
        check("-model %s is accepted" % model, rc == 0)
    rc, out = sh("demVoidFraction -dump particles.dump -model nonsense", case, check=False)
    refused = rc != 0 and all(m in out for m in listed)
    check("-model nonsense is refused with the list", refused, "" if refused else out[-300:])


def test_liggghts_in_process():
    print("LIGGGHTS as a library: demVoidFraction -liggghts equals the same state read from a dump")
    case = new_case(os.path.join(WORK, "liggghts"), box_block_mesh(LO, (0.02, 0.02, 0.02), (5, 5, 5)),
                    coupling='voidFractionModel analytical;\ndemScript "DEM/in.settle";\n')
    os.makedirs(os.path.join(case, "DEM"), exist_ok=True)
    shutil.copy(os.path.join(ROOT, "tests", "cases", "liggghts", "in.settle"), os.path.join(case, "DEM"))
    rc, out = sh("demVoidFraction -liggghts -name vf_library", case, check=False)
    check("in-process LIGGGHTS runs and reports 150 particles", rc == 0 and "Read 150 particles" in out,
          out[-500:] if rc else "")
    rc2, _ = sh("demVoidFraction -dump DEM/post/settled.dump -name vf_dump", case, check=False)
    if rc == 0 and rc2 == 0:
        a = read_scalar_field(os.path.join(case, "0", "vf_library"))
        b = read_scalar_field(os.path.join(case, "0", "vf_dump"))
        near("library field = dump field (max |d alpha|)", max(abs(x - y) for x, y in zip(a, b)), 0, 1e-14)
    # on 2 ranks (LIGGGHTS inserts differently per process count: compare
    # with the dump that run writes)
    sh("rm -rf processor* 0 && decomposePar -force", case)
    rc, out = sh("mpirun -np 2 demVoidFraction -parallel -liggghts -name vf_library", case, check=False)
    check("in-process LIGGGHTS on 2 ranks runs and reports 150 particles",
          rc == 0 and "Read 150 particles" in out, out[-500:] if rc else "")
    rc2, _ = sh("mpirun -np 2 demVoidFraction -parallel -dump DEM/post/settled.dump -name vf_dump", case, check=False)
    if rc == 0 and rc2 == 0:
        sh("reconstructPar -withZero -fields '(vf_library vf_dump)'", case)
        a = read_scalar_field(os.path.join(case, "0", "vf_library"))
        b = read_scalar_field(os.path.join(case, "0", "vf_dump"))
        near("2 ranks: library field = dump field (max |d alpha|)", max(abs(x - y) for x, y in zip(a, b)), 0, 1e-14)
    sh("rm -rf processor*", case)
    set_coupling(case, 'voidFractionModel analytical;\ndemScript "DEM/missing.in";\n')
    rc, out = sh("demVoidFraction -liggghts", case, check=False)
    check("missing demScript: error names it", rc != 0 and "missing.in" in out and "demScript" in out)


def test_bad_input():
    print("bad input: clear errors")
    case = new_case(os.path.join(WORK, "bad"), box_block_mesh(LO, HI, (4, 4, 4)))
    write_dump(os.path.join(case, "ok.dump"), [(0.01, 0.01, 0.01)], [0.001])
    set_coupling(case, "voidFractionModel nonsense;\n")
    rc, out = sh("demVoidFraction -dump ok.dump", case, check=False)
    check("unknown model: error lists the valid names",
          rc != 0 and "nonsense" in out and "analytical" in out and "centroid" in out)
    set_coupling(case, "voidFractionModel analytical;\nalphaMin 2;\n")
    rc, out = sh("demVoidFraction -dump ok.dump", case, check=False)
    check("alphaMin out of range: error names it", rc != 0 and "alphaMin" in out)
    set_coupling(case, "voidFractionModel analytical;\n")
    good = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n"
    bad = {
        "missing column": (good + "ITEM: ATOMS id x y z\n1 0.01 0.01 0.01\n2 0.01 0.01 0.01\n", "radius"),
        "malformed number": (good + "ITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 0.001\n2 0.01 0.0.1 0.01 0.001\n", "line 11"),
        "NaN": (good + "ITEM: ATOMS id x y z radius\n1 0.01 0.01 nan 0.001\n2 0.01 0.01 0.01 0.001\n", "line 10"),
        "negative radius": (good + "ITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 -0.001\n2 0.01 0.01 0.01 0.001\n", "radius"),
        "zero radius": (good + "ITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 0.001\n2 0.01 0.01 0.01 0\n", "line 11"),
        "truncated": (good + "ITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 0.001\n", "found 1"),
        "short row": (good + "ITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 0.001\n2 0.01 0.01\n", "line 11"),
        "empty file": ("", "empty"),
        "repeated id": (good + "ITEM: ATOMS id x y z radius\n7 0.01 0.01 0.01 0.001\n7 0.02 0.01 0.01 0.001\n",
                        "line 11: atom id 7 again (first at line 10)"),
        "snapshot without atoms": (good + "ITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 0.001\n"
                                   "2 0.02 0.01 0.01 0.001\nITEM: TIMESTEP\n5\n", "line 12"),
    }
    for name, (text, needle) in bad.items():
        path = os.path.join(case, "bad.dump")
        open(path, "w").write(text)
        rc, out = sh("demVoidFraction -dump bad.dump", case, check=False)
        check("dump with %s: error names file and cause" % name,
              rc != 0 and "bad.dump" in out and needle in out and "Segmentation" not in out)
    rc, out = sh("demVoidFraction -dump missing.dump", case, check=False)
    check("missing dump file: error", rc != 0 and "missing.dump" in out)


def test_dump_series():
    print("a dump of several snapshots: each into its own time directory")
    case = new_case(os.path.join(WORK, "series"), box_block_mesh(LO, HI, (6, 6, 6)))
    snaps = []
    for k in range(3):
        c, r = random_spheres(200, 0.0005, 0.0015, LO, HI, seed=40 + k)
        snaps.append((100 * k, c, r))
    # the references: each snapshot alone, written into the start time
    want = []
    for step, c, r in snaps:
        write_dump(os.path.join(case, "one.dump"), c, r)
        rc, _ = sh("rm -rf 0 && demVoidFraction -dump one.dump", case, check=False)
        want.append(read_scalar_field(os.path.join(case, "0", "voidfraction")) if rc == 0 else None)
    text = ""
    for step, c, r in snaps:
        write_dump(os.path.join(case, "one.dump"), c, r)
        text += open(os.path.join(case, "one.dump")).read().replace("TIMESTEP\n0\n", "TIMESTEP\n%d\n" % step)
    open(os.path.join(case, "all.dump"), "w").write(text)
    for step, c, r in snaps:
        write_dump(os.path.join(case, "dump.%d" % step), c, r)
        t = open(os.path.join(case, "dump.%d" % step)).read()
        open(os.path.join(case, "dump.%d" % step), "w").write(t.replace("TIMESTEP\n0\n", "TIMESTEP\n%d\n" % step))

    def fields(times):
        return [read_scalar_field(os.path.join(case, t, "voidfraction"))
                if os.path.exists(os.path.join(case, t, "voidfraction")) else None for t in times]

    def same(a, b):
        return a is not None and b is not None and max(abs(x - y) for x, y in zip(a, b)) < 1e-15

    for label, cmd, times, expect in (
            ("one file, every snapshot", "demVoidFraction -dump all.dump -deltaT 1e-5",
             ("0", "0.001", "0.002"), [0, 1, 2]),
            ("files dump.*, every snapshot", "demVoidFraction -dump 'dump.*' -deltaT 1e-5",
             ("0", "0.001", "0.002"), [0, 1, 2]),
            ("-latest", "demVoidFraction -dump all.dump -latest", ("200",), [2]),
            ("-time 100", "demVoidFraction -dump all.dump -time 100", ("100",), [1]),
            ("-time 50:150", "demVoidFraction -dump all.dump -time 50:150", ("100",), [1]),
            ("-time :50,150:", "demVoidFraction -dump all.dump -time :50,150:", ("0", "200"), [0, 2])):
        sh("rm -rf 0 0.00* 100 200", case)
        rc, out = sh(cmd, case, check=False)
        got = fields(times)
        check("%s: each time = that snapshot mapped alone" % label,
              rc == 0 and all(same(g, want[k]) for g, k in zip(got, expect)), out[-400:] if rc else "")
        others = [t for t in ("0", "100", "200", "0.001", "0.002") if t not in times]
        check("%s: no other time written" % label,
              not any(os.path.exists(os.path.join(case, t, "voidfraction")) for t in others))
        check("%s: progress per snapshot" % label, out.count("Snapshot ") == len(times))
    rc, out = sh("demVoidFraction -dump all.dump -time 50", case, check=False)
    check("-time selecting nothing: error", rc != 0 and "none of the 3 snapshots" in out)
    for option, needle in (("-deltaT nan", "-deltaT 'nan': not a finite number"),
                           ("-deltaT 1e999", "-deltaT '1e999': out of the range"),
                           ("-deltaT 1e-5s", "-deltaT '1e-5s': not a number"),
                           ("-deltaT 0", "-deltaT 0: must be positive"),
                           ("-repeat inf", "-repeat 'inf': not a finite number"),
                           ("-repeat 2.5", "-repeat '2.5': not a whole number"),
                           ("-repeat -1", "-repeat '-1': not a whole number"),
                           ("-time nan", "-time 'nan': not a finite number"),
                           ("-time 0:abc", "-time 'abc': not a number"),
                           ("-time :", "without bounds")):
        rc, out = sh("demVoidFraction -dump all.dump %s" % option, case, check=False)
        ok = rc == 1 and needle in out and "printStack" not in out
        check("%s: error says \"%s\", no stack trace" % (option, needle), ok, "" if ok else out[-400:])
    # on 2 ranks, each keeping the particles near its cells (one distributor
    # for the whole series)
    sh("rm -rf 0 0.00* 100 200 processor*", case)
    rc, out = sh("decomposePar -force > log.decomposePar && mpirun -np 2 demVoidFraction -parallel -distribute "
                 "-dump all.dump -deltaT 1e-5 && reconstructPar -withZero > log.reconstructPar", case, check=False)
    got = fields(("0", "0.001", "0.002"))
    close = rc == 0 and all(g is not None and max(abs(x - y) for x, y in zip(g, w)) < 1e-12
                            for g, w in zip(got, want))
    check("2 ranks, -distribute, every snapshot: each time = that snapshot mapped alone in serial (1e-12)",
          close, out[-400:] if rc else "")


def test_previous_step():
    print("-previous: the search starts from each particle's cell one step before; the field is the dump's alone")
    cyc = {"xmin": "type cyclic; neighbourPatch xmax;", "xmax": "type cyclic; neighbourPatch xmin;"}
    case = new_case(os.path.join(WORK, "previous"), box_block_mesh(LO, HI, (10, 10, 10), patches=cyc))
    c, r = random_spheres(1000, 0.0004, 0.0012, LO, HI, seed=8, periodic_axes=(0,))
    # half the particles move by 1e-7 m, the others by 2e-4 m, some across the cyclic sides
    moved = [((p[0] + (1e-7 if i % 2 else 2e-4)) % L, p[1], p[2]) for i, p in enumerate(c)]
    write_dump(os.path.join(case, "before.dump"), c, r)
    write_dump(os.path.join(case, "after.dump"), moved, r)
    for model in ("analytical", "hybrid", "kernel"):
        set_coupling(case, "voidFractionModel %s;\nalphaMin 0.05;\n" % model)
        rc, out = sh("demVoidFraction -previous before.dump -dump after.dump -name withPrevious", case, check=False)
        rc2, _ = sh("demVoidFraction -dump after.dump -name alone", case, check=False)
        check("%s: runs with -previous" % model, rc == 0 and rc2 == 0, out[-400:] if rc else "")
        if rc == 0 and rc2 == 0:
            a = read_scalar_field(os.path.join(case, "0", "withPrevious"))
            b = read_scalar_field(os.path.join(case, "0", "alone"))
            near("%s: field after -previous = the dump mapped alone, max |d alpha|" % model,
                 max(abs(x - y) for x, y in zip(a, b)), 0, 1e-14)


def grid_planes(case):
    """The sorted distinct point coordinates per direction of a box-block mesh."""
    text = open(os.path.join(case, "constant", "polyMesh", "points")).read()
    pts = [tuple(float(v) for v in t.split()) for t in re.findall(r"\(([-0-9.eE+ ]+)\)", text)]
    planes = []
    for d in range(3):
        vals = sorted(set(round(p[d], 15) for p in pts))
        planes.append(vals)
    return planes


def test_centre_search():
    print("centre search: a particle's cell from its previous cell, against the grid planes")
    n = (8, 6, 5)
    case = new_case(os.path.join(WORK, "centreSearch"), box_block_mesh(LO, HI, n, grading=(4, 0.3, 2)))
    set_coupling(case, "voidFractionModel centroid;\nalphaMin 0.05;\n")
    planes = grid_planes(case)
    check("graded grid has %d x %d x %d cells" % n, [len(p) - 1 for p in planes] == list(n))
    rng = random.Random(21)
    before, after = [], []
    for k in range(1200):
        c = [rng.uniform(1e-4, L - 1e-4) for _ in range(3)]
        kind = k % 4
        if kind == 0:      # a small move, mostly within its cell
            m = [x + rng.uniform(-1e-5, 1e-5) for x in c]
        elif kind == 1:    # far away
            m = [rng.uniform(1e-4, L - 1e-4) for _ in range(3)]
        else:              # just either side of a plane of its own or the next cell
            d = rng.randrange(3)
            inner = planes[d][1:-1]
            plane = min(inner, key=lambda g: abs(g - c[d]))
            m = list(c)
            m[d] = plane + (1 if kind == 2 else -1) * 1e-9 * L
        before.append(tuple(c))
        after.append(tuple(min(max(x, 1e-6), L - 1e-6) for x in m))
    r = [5e-5] * len(after)
    write_dump(os.path.join(case, "before.dump"), before, r)
    write_dump(os.path.join(case, "after.dump"), after, r)
    V = cell_volumes(case)
    solid = [0.0] * len(V)
    for p in after:
        i, j, k = (bisect.bisect_right(planes[d], p[d]) - 1 for d in range(3))
        solid[i + n[0] * (j + n[1] * k)] += sphere_volume(r[0])
    want = [1 - s / v for s, v in zip(solid, V)]
    for label, cmd in (("from the previous cells", "-previous before.dump -dump after.dump"),
                       ("searched afresh", "-dump after.dump")):
        rc, out = sh("demVoidFraction %s -name searched" % cmd, case, check=False)
        check("centroid %s runs" % label, rc == 0, out[-600:] if rc else "")
        if rc == 0:
            got = read_scalar_field(os.path.join(case, "0", "searched"))
            near("centroid %s: alpha = the grid planes' cells, max |d alpha|" % label,
                 max(abs(a - b) for a, b in zip(got, want)), 0, 1e-12)


def main():
    checks.run([test_list_models, test_closed_forms, test_keep_volume_beyond_mesh, test_thin_neighbour, test_meshes, test_fast_against_general, test_grid_with_holes, test_cyclic,
                test_alpha_min, test_parallel, test_dump_series, test_previous_step, test_centre_search, test_liggghts_in_process,
                test_bad_input], sys.argv[1:])
    return checks.summary("models")


if __name__ == "__main__":
    sys.exit(main())
