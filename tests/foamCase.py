# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Helpers for the tests and benchmarks: make small OpenFOAM cases, write
LIGGGHTS-style dumps, run the project's applications and read fields back."""
import math
import os
import random
import re
import shutil
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TEMPLATE = os.path.join(HERE, "cases", "template")


def void_fraction_models():
    """The void fraction models' names as `demVoidFraction -listModels` gives
    them: the papers' six in their order, then any other registered model."""
    out = subprocess.run(["demVoidFraction", "-listModels"], capture_output=True, text=True)
    if out.returncode != 0 or not out.stdout.split():
        raise SystemExit("foamCase: demVoidFraction -listModels failed (source etc/bashrc and build "
                         "first): %s" % out.stderr.strip()[-300:])
    return tuple(out.stdout.split())


def sh(cmd, cwd, check=True):
    """Run a shell command with the project environment; return (rc, output)."""
    full = ". %s/etc/bashrc >/dev/null && %s" % (ROOT, cmd)
    p = subprocess.run(["bash", "-c", full], cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, errors="replace",
                       stdin=subprocess.DEVNULL)
    if check and p.returncode != 0:
        raise RuntimeError("'%s' failed in %s:\n%s" % (cmd, cwd, p.stdout[-3000:]))
    return p.returncode, p.stdout


def set_dem(case, **values):
    """Set variables of the case's DEM/in.parameters (dimensions kept)"""
    path = os.path.join(case, "DEM", "in.parameters")
    text = open(path).read()
    for name, value in values.items():
        text, n = re.subn(r"(?m)^(variable\s+%s\s+equal\s+)\S+" % name, r"\g<1>%r" % value, text)
        if n != 1:
            raise RuntimeError("%s: no variable %s" % (path, name))
    with open(path, "w") as f:
        f.write(text)


def new_case(path, block_mesh=None, coupling="voidFractionModel analytical;\nalphaMin 0.05;\n"):
    """Copy the template case to path; write a blockMeshDict and run blockMesh
    when block_mesh (the dictionary body) is given."""
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(TEMPLATE, path)
    set_coupling(path, coupling)
    if block_mesh is not None:
        with open(os.path.join(path, "system", "blockMeshDict"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }\n")
            f.write(block_mesh)
        sh("blockMesh", path)
    return path


def tet_case(path, n=6, length=0.03, jitter=0.2, coupling=None):
    """A case on the cube [0, length]^3 meshed with jittered tetrahedra."""
    new_case(path, coupling=coupling) if coupling else new_case(path)
    shutil.rmtree(os.path.join(path, "constant", "polyMesh"), ignore_errors=True)
    sh("/usr/bin/python3 %s/tests/makeTetMesh.py . %d %r %r" % (ROOT, n, length, jitter), path)
    return path


def set_coupling(path, body):
    with open(os.path.join(path, "constant", "couplingProperties"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object couplingProperties; }\n")
        f.write(body)


def box_block_mesh(lo, hi, n, grading=(1, 1, 1), patches=None):
    """blockMesh dictionary body of one box block (lengths in metres)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = {"xmin": "(0 4 7 3)", "xmax": "(1 2 6 5)", "ymin": "(0 1 5 4)",
             "ymax": "(3 7 6 2)", "zmin": "(0 3 2 1)", "zmax": "(4 5 6 7)"}
    patches = patches or {}
    body = "scale 1;\nvertices (%s);\n" % " ".join("(%.17g %.17g %.17g)" % p for p in v)
    body += "blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (%g %g %g) );\n" % (tuple(n) + tuple(grading))
    body += "boundary (\n"
    walls = [k for k in faces if k not in patches]
    for name, entry in patches.items():
        body += "%s { %s faces ( %s ); }\n" % (name, entry, faces[name])
    body += "walls { type wall; faces ( %s ); }\n" % " ".join(faces[k] for k in walls)
    body += ");\n"
    return body


def write_dump(path, centres, radii, columns="id type x y z vx vy vz radius"):
    cols = columns.split()
    with open(path, "w") as f:
        f.write("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\n" % len(radii))
        f.write("ITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n")
        f.write("ITEM: ATOMS %s\n" % columns)
        for i, (c, r) in enumerate(zip(centres, radii)):
            val = {"id": "%d" % (i + 1), "type": "1", "x": "%.17g" % c[0], "y": "%.17g" % c[1],
                   "z": "%.17g" % c[2], "radius": "%.17g" % r}
            f.write(" ".join(val.get(k, "0") for k in cols) + "\n")


def random_spheres(n, rmin, rmax, lo, hi, seed, gap=True, periodic_axes=()):
    """Random polydisperse spheres in the box; with gap, clear of every wall
    (periodic axes excepted: there centres lie anywhere in [lo, hi))."""
    rng = random.Random(seed)
    centres, radii = [], []
    for _ in range(n):
        r = rng.uniform(rmin, rmax)
        c = []
        for d in range(3):
            m = 0.0 if (d in periodic_axes or not gap) else r
            c.append(rng.uniform(lo[d] + m, hi[d] - m))
        centres.append(c)
        radii.append(r)
    return centres, radii


def sphere_volume(r):
    return 4.0 / 3.0 * math.pi * r ** 3


def read_scalar_field(path):
    """internalField of an ascii volScalarField as a list of floats."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)\s*;", text, re.S)
    if m:
        vals = [float(x) for x in m.group(2).split()]
        assert len(vals) == int(m.group(1))
        return vals
    m = re.search(r"internalField\s+uniform\s+(\S+);", text)
    raise ValueError("uniform field in %s (%s); expected nonuniform" % (path, m.group(1) if m else "?"))


def cell_volumes(case):
    os.makedirs(os.path.join(case, "0"), exist_ok=True)
    sh("postProcess -func writeCellVolumes -time 0", case)
    return read_scalar_field(os.path.join(case, "0", "V"))


def cell_centres(case):
    """Cell centres (list of (x, y, z)) from postProcess writeCellCentres."""
    os.makedirs(os.path.join(case, "0"), exist_ok=True)
    sh("postProcess -func writeCellCentres -time 0", case)
    return read_vector_field(os.path.join(case, "0", "C"))


def read_vector_field(path):
    """internalField of an ascii volVectorField as a list of (x, y, z)."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<vector>\s*(\d+)\s*\((.*?)\)\s*;", text, re.S)
    if not m:
        raise ValueError("no nonuniform vector internalField in %s" % path)
    vals = [tuple(float(v) for v in t.split()) for t in re.findall(r"\(([^()]*)\)", m.group(2))]
    assert len(vals) == int(m.group(1))
    return vals


def parse_report(out):
    """Numbers demVoidFraction prints."""
    def num(pattern):
        m = re.search(pattern, out)
        return float(m.group(1)) if m else None
    return {
        "solid": num(r"solid volume in the field (\S+),"),
        "meshed": num(r"of the particles inside the mesh (\S+),"),
        "outside": num(r"centre outside the mesh (\S+),"),
        "moved": num(r"volume moved by alphaMin (\S+)"),
        "conservation": num(r"conservation error (\S+)"),
        "min": num(r"void fraction min (\S+)"),
        "rate": num(r"s, (\S+) particles/s"),
        "median": num(r"median of \d+ (\S+) s"),
    }
