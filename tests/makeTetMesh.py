#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Writes a tetrahedral OpenFOAM polyMesh of a box: a grid of n^3 hexahedra,
interior points jittered, each hexahedron split into 6 tetrahedra around its
main diagonal (a conforming split). One wall patch 'walls'.

usage: makeTetMesh.py CASE n L [jitter] [seed]
"""
import itertools
import os
import random
import sys

case, n, L = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
jitter = float(sys.argv[4]) if len(sys.argv) > 4 else 0.2
rng = random.Random(int(sys.argv[5]) if len(sys.argv) > 5 else 7)
h = L / n

def pid(i, j, k):
    return i + (n + 1) * (j + (n + 1) * k)

pts = []
for k, j, i in itertools.product(range(n + 1), repeat=3):
    p = [i * h, j * h, k * h]
    for d, idx in enumerate((i, j, k)):
        if 0 < idx < n:
            p[d] += rng.uniform(-jitter, jitter) * h
    pts.append(p)

# the six tetrahedra of a hexahedron along the diagonal 0 -> 7 (corner bits x,y,z)
paths = [(1, 2, 4), (1, 4, 2), (2, 1, 4), (2, 4, 1), (4, 1, 2), (4, 2, 1)]
tets = []
for k, j, i in itertools.product(range(n), repeat=3):
    for a, b, c in paths:
        corners = [0, a, a | b, 7]
        tets.append([pid(i + (q & 1), j + ((q >> 1) & 1), k + ((q >> 2) & 1)) for q in corners])

def sub(u, v): return [u[0] - v[0], u[1] - v[1], u[2] - v[2]]
def cross(u, v): return [u[1]*v[2]-u[2]*v[1], u[2]*v[0]-u[0]*v[2], u[0]*v[1]-u[1]*v[0]]
def dot(u, v): return u[0]*v[0] + u[1]*v[1] + u[2]*v[2]

faces = {}
for t, tet in enumerate(tets):
    for q in range(4):
        tri = [tet[m] for m in range(4) if m != q]
        key = tuple(sorted(tri))
        faces.setdefault(key, []).append((t, tri, tet[q]))

internal, boundary = [], []
for key, users in faces.items():
    t, tri, opposite = users[0]
    if len(users) == 2 and users[1][0] < t:
        t, tri, opposite = users[1]
    a, b, c = (pts[v] for v in tri)
    centre = [(a[d] + b[d] + c[d]) / 3 for d in range(3)]
    if dot(cross(sub(b, a), sub(c, a)), sub(centre, pts[opposite])) < 0:
        tri = [tri[0], tri[2], tri[1]]
    if len(users) == 2:
        other = users[1][0] if users[0][0] == t else users[0][0]
        internal.append((t, other, tri))
    else:
        boundary.append((t, tri))
internal.sort(key=lambda f: (f[0], f[1]))
boundary.sort(key=lambda f: f[0])

d = os.path.join(case, "constant", "polyMesh")
os.makedirs(d, exist_ok=True)
def header(cls, obj, note=""):
    return ('FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n%s'
            '    location "constant/polyMesh";\n    object %s;\n}\n' % (cls, note, obj))
note = '    note "nPoints:%d nCells:%d nFaces:%d nInternalFaces:%d";\n' % (
    len(pts), len(tets), len(internal) + len(boundary), len(internal))
with open(os.path.join(d, "points"), "w") as f:
    f.write(header("vectorField", "points") + "%d\n(\n" % len(pts))
    f.writelines("(%.17g %.17g %.17g)\n" % tuple(p) for p in pts)
    f.write(")\n")
allFaces = [tri for _, _, tri in internal] + [tri for _, tri in boundary]
with open(os.path.join(d, "faces"), "w") as f:
    f.write(header("faceList", "faces") + "%d\n(\n" % len(allFaces))
    f.writelines("3(%d %d %d)\n" % tuple(tri) for tri in allFaces)
    f.write(")\n")
owners = [o for o, _, _ in internal] + [o for o, _ in boundary]
with open(os.path.join(d, "owner"), "w") as f:
    f.write(header("labelList", "owner", note) + "%d\n(\n" % len(owners))
    f.writelines("%d\n" % o for o in owners)
    f.write(")\n")
with open(os.path.join(d, "neighbour"), "w") as f:
    f.write(header("labelList", "neighbour", note) + "%d\n(\n" % len(internal))
    f.writelines("%d\n" % nb for _, nb, _ in internal)
    f.write(")\n")
with open(os.path.join(d, "boundary"), "w") as f:
    f.write(header("polyBoundaryMesh", "boundary") + "1\n(\n")
    f.write("walls\n{\n    type wall;\n    nFaces %d;\n    startFace %d;\n}\n)\n"
            % (len(boundary), len(internal)))
