#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Every void fraction model on every kind of decomposition against the serial
field: tetrahedral, Cartesian and polyhedral meshes, each decomposed by scotch
(3 ranks), by simple across two directions (4 ranks) and by a manual
decomposition whose subdomains are in several pieces. The field
must equal the serial one to round-off, and the volume reported outside the
mesh must equal the serial run's. Ends with 'N passed, N failed'."""
import os
import re
import shutil
import sys

import checks
from checks import WORK, check, near, run_model
from foamCase import (box_block_mesh, cell_centres, new_case, random_spheres,
                      read_scalar_field, sh, sphere_volume, tet_case, void_fraction_models, write_dump)

MODELS = void_fraction_models()
TOL = {"diffusion": 1e-9}


def read_label_list(path):
    text = open(path).read()
    body = text[text.index("}") + 1:] if text.lstrip().startswith("FoamFile") else text
    m = re.search(r"(\d+)\s*\((.*?)\)", body, re.S)
    vals = [int(v) for v in m.group(2).split()]
    assert len(vals) == int(m.group(1)), path
    return vals


def parallel_field(case, n_ranks, n_cells):
    """The decomposed field put back together from the processor folders."""
    alpha = [None] * n_cells
    for rank in range(n_ranks):
        proc = os.path.join(case, "processor%d" % rank)
        local = read_scalar_field(os.path.join(proc, "0", "voidfraction"))
        for a, cell in zip(local, read_label_list(
                os.path.join(proc, "constant", "polyMesh", "cellProcAddressing"))):
            alpha[cell] = a
    assert all(a is not None for a in alpha)
    return alpha


def volume_outside(out):
    """The volume outside the mesh and the count of spheres reaching out."""
    m = re.search(r"reaching outside (\d+), volume outside ([^,\s]+)", out)
    return (int(m.group(1)), float(m.group(2))) if m else (None, None)


def write_decomposition(case, n, method, body):
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains %d;\nmethod %s;\n%s\n" % (n, method, body))


def pieces_decomposition(case, block):
    """Three ranks, cells dealt by blocks of side block in a repeating
    pattern: each rank's cells lie in several separate pieces, and on
    tetrahedra the blocks cut through hexahedra."""
    centres = cell_centres(case)
    ranks = []
    for x, y, z in centres:
        i, j, k = (int(v // block) for v in (x, y, z))
        ranks.append((i + 2 * j + k) % 3)
    path = os.path.join(case, "constant", "cellRanks")
    with open(path, "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class labelList; object cellRanks; }\n")
        f.write("%d\n(\n%s\n)\n" % (len(ranks), "\n".join(map(str, ranks))))
    shutil.rmtree(os.path.join(case, "0"), ignore_errors=True)
    write_decomposition(case, 3, "manual", 'coeffs { dataFile "cellRanks"; }')
    return len(set(ranks))


def serial_runs(case, dump):
    """Serial field and outside volume per model."""
    ref = {}
    for model in MODELS:
        rc, out = run_model(case, dump, model)
        check("%s serial runs" % model, rc == 0)
        ref[model] = (read_scalar_field(os.path.join(case, "0", "voidfraction")), volume_outside(out))
    return ref


def compare(label, case, dump, n_ranks, ref, volume):
    sh("rm -rf 0 processor*", case)
    rc, out = sh("decomposePar -force", case, check=False)
    check("%s: decomposePar" % label, rc == 0, out[-600:] if rc else "")
    if rc:
        return
    n_cells = len(next(iter(ref.values()))[0])
    for model in MODELS:
        # 3 and 4 ranks on machines with 2 cores
        rc, out = sh("mpirun --oversubscribe -np %d demVoidFraction -parallel -distribute -dump %s -model %s"
                     % (n_ranks, dump, model), case, check=False)
        check("%s %s runs on %d ranks" % (label, model, n_ranks), rc == 0, out[-600:] if rc else "")
        if rc:
            continue
        # scotch's compact subdomains: each rank holds the particles near its
        # cells only (subdomains dealt in small pieces are near every particle)
        if model == "analytical" and "scotch" in label:
            m = re.search(r"Particles held: at most (\d+) of (\d+) on a rank", out)
            held, total = (int(m.group(1)), int(m.group(2))) if m else (None, None)
            check("%s %s: no rank holds every particle" % (label, model),
                  held is not None and held < total, "(at most %s of %s)" % (held, total))
        serial, (cut, outside) = ref[model]
        par = parallel_field(case, n_ranks, n_cells)
        near("%s %s: serial = parallel, max |d alpha|" % (label, model),
             max(abs(a - b) for a, b in zip(serial, par)), 0, TOL.get(model, 1e-12))
        pcut, poutside = volume_outside(out)
        check("%s %s: spheres reaching outside as serial" % (label, model), pcut == cut,
              "(%s, serial %s)" % (pcut, cut))
        near("%s %s: volume outside the mesh as serial" % (label, model),
             poutside if poutside is not None else float("nan"), outside, 1e-13 * volume)


def decompositions(case, block):
    """(label, ranks, method, coefficients) of the decompositions tested."""
    return [
        ("scotch 3", 3, "scotch", ""),
        ("simple (2 2 1)", 4, "simple", "coeffs { n (2 2 1); }"),
        ("manual in pieces", 3, None, block),
    ]


def test_mesh(name, case, spheres, block):
    print("%s mesh: %d spheres" % (name, len(spheres[1])))
    dump = "p.dump"
    write_dump(os.path.join(case, dump), *spheres)
    ref = serial_runs(case, dump)
    cut = ref["analytical"][1][0]
    check("%s: some spheres reach outside the mesh (the count is tested)" % name, cut and cut > 0,
          "(%s)" % cut)
    for label, n, method, coeffs in decompositions(case, block):
        if method is None:
            n = pieces_decomposition(case, coeffs)
        else:
            write_decomposition(case, n, method, coeffs)
        compare("%s, %s" % (name, label), case, dump, n, ref, sum(sphere_volume(r) for r in spheres[1]))


def main():
    only = set(sys.argv[1:])
    os.makedirs(WORK, exist_ok=True)
    meshes = ("tetrahedral", "cartesian", "polyhedral")
    if only - set(meshes):
        checks.check("mesh names given exist (%s)" % ", ".join(sorted(only - set(meshes))), False,
                     "valid: " + " ".join(meshes))
        return checks.summary("decomposition")
    L = 0.03
    lo, hi = (0, 0, 0), (L, L, L)

    # tetrahedra of 6^3 jittered hexahedra; spheres up to 1.2 hexahedra across,
    # some through the walls
    if not only or "tetrahedral" in only:
        case = tet_case(os.path.join(WORK, "decomp-tetrahedral"), n=6, length=L)
        spheres = random_spheres(150, 0.0005, 0.003, lo, hi, seed=11, gap=False)
        test_mesh("tetrahedral", case, spheres, L / 6 * 1.5)

    # Cartesian 12 x 10 x 8, spheres up to 0.8 cells across
    if not only or "cartesian" in only:
        case = new_case(os.path.join(WORK, "decomp-cartesian"),
                        box_block_mesh(lo, (0.012, 0.010, 0.008), (12, 10, 8)))
        spheres = random_spheres(200, 0.0001, 0.0004, lo, (0.012, 0.010, 0.008), seed=12, gap=False)
        test_mesh("cartesian", case, spheres, 0.002)

    # polyhedra with warped faces: the dual of a tetrahedral mesh
    if not only or "polyhedral" in only:
        case = tet_case(os.path.join(WORK, "decomp-polyhedral"), n=5, length=L)
        sh("polyDualMesh 80 -overwrite", case)
        spheres = random_spheres(150, 0.0005, 0.003, lo, hi, seed=13, gap=False)
        test_mesh("polyhedral", case, spheres, L / 5 * 1.5)
    return checks.summary("decomposition")


if __name__ == "__main__":
    sys.exit(main())
