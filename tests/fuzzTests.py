#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Fuzz tests of bad input: seeded random damage to the couplingProperties of
the settling sphere (plain and as h = 2 parcels), each damaged file run for one
coupling. This file's own reading of what is valid (written from the
documented entries, not from the solver's code) says whether each run must
stop with a clear error that names the damaged entry or run to the end; a
crash, a hang, an error that does not name the entry, or a run on input that
is wrong fails, and prints the seed and the damage so that it can be replayed:

    /usr/bin/python3 fuzzTests.py test_coupling_fuzz --seed S --runs N
"""
import os
import random
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import checks
from checks import WORK, check
from foamCase import ROOT, sh

SEED = 20261207
RUNS = 240
TIMEOUT = 60

# What couplingProperties may hold, by the documentation (docs/solver.md)
SWITCHES = {"false", "true", "no", "yes", "off", "on", "none", "any", "f", "n", "t", "y"}
CHOICES = {
    "formulation": {"A", "B"},
    "dragModel": {"Gidaspow", "DiFelice", "Beetstra"},
    "particlesOutside": {"error", "remove"},
    "particleOutput": {"binary", "ascii"},
    "voidFractionModel": {"centroid", "analytical", "voxel", "hybrid", "kernel", "diffusion"},
}
FORCES = {"pressureGradient", "buoyancy", "SaffmanMeiLift", "virtualMass"}
MODEL_COEFFS = {m + "Coeffs" for m in CHOICES["voidFractionModel"]}
KEYWORDS = set(CHOICES) | MODEL_COEFFS | {
    "demScript", "demRestartScript", "demScreen", "couplingInterval", "forces", "alphaMin",
    "reportExchange", "twoDimensional", "virtualMassCoefficient", "coarseGraining",
    "keepVolumeBeyondMesh"}
REQUIRED = {"demScript", "couplingInterval", "dragModel", "voidFractionModel"}
# the case: one DEM type, deltaT 5e-4 s, DEM step 5e-5 s, a 3D mesh
DEM_SCRIPT = "DEM/in.liggghts"
N_TYPES = 1
COUPLING_STEPS_OK = {1, 2, 5, 10}   # DEM steps whose coupling time divides deltaT

# replacement values, of every kind, valid for some entries and not others
POOL = ["foo", "Gidaspow", "Beetstra", "A", "B", "remove", "ascii", "kernel", "centroid",
        "cubic", "exact", "0", "1", "2", "-1", "10", "0.5", "3.7", "1e30", "1.5", "yes", "off",
        '"DEM/in.liggghts"', "DEM/in.liggghts", '"nothing"', "(pressureGradient buoyancy)",
        "(buoyancy buoyancy)", "(virtualMass)", "(lift)", "()", "(1 2)", "(2)", "{ factor 2; }",
        "{}", "{ type Gidaspow; }"]
# valid alternatives, so that both outcomes are exercised
VALID = {
    "formulation": ["A"], "dragModel": ["DiFelice", "Beetstra"], "particlesOutside": ["remove"],
    "voidFractionModel": ["centroid", "kernel", "diffusion", "voxel", "hybrid"],
    "couplingInterval": ["1", "2", "5", "20"], "alphaMin": ["0", "0.2"],
    "forces": ["()", "(buoyancy)", "(virtualMass buoyancy pressureGradient)"],
    "reportExchange": ["yes", "0"], "particleOutput": ["ascii"], "twoDimensional": ["false", "off"],
    "keepVolumeBeyondMesh": ["on", "off"],
    "virtualMassCoefficient": ["0.5", "0"], "demScreen": ['"log.screen"'],
    "demRestartScript": ['"DEM/in.other"'], "demScript": ['"./DEM/in.liggghts"'],
    "kernelCoeffs": ["{ cutoff 2; reflectAtWalls off; }"], "diffusionCoeffs": ["{ nSteps 2; }"],
    "coarseGraining": ["{ factor 1.5; }", "{ factor (3); forceScaling exact; }"],
}
# each model's coefficients and their kinds
MODEL_KEYS = {
    "kernelCoeffs": {"bandwidth": "n", "bandwidthOverCellSize": "n", "cutoff": "n", "reflectAtWalls": "s"},
    "diffusionCoeffs": {"bandwidth": "n", "coefficient": "n", "nSteps": "n", "initial": "w",
                        "integration": "w", "laplacianScheme": "t", "solver": "d"},
    "voxelCoeffs": {"voxelSize": "n", "voxelsPerSide": "n", "voxelsPerDiameter": "n", "voxelsPerCell": "n"},
    "hybridCoeffs": {"subGridResolution": "n"}, "centroidCoeffs": {}, "analyticalCoeffs": {},
}
OPTIONAL_TO_ADD = ["alphaMin", "reportExchange", "particleOutput", "twoDimensional", "keepVolumeBeyondMesh",
                   "virtualMassCoefficient", "coarseGraining", "demScreen", "kernelCoeffs",
                   "diffusionCoeffs", "formulation", "forces", "particlesOutside"]


def kind(value):
    """word, string, number, whole, list (with its items) or dict"""
    v = value.strip()
    if v.startswith("{"):
        return "dict", None
    if v.startswith("("):
        return "list", v[1:-1].split()
    if v.startswith('"'):
        return "string", v.strip('"')
    if re.fullmatch(r"[-+]?\d+", v):
        return "whole", int(v)
    if re.fullmatch(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?", v):
        return "number", float(v)
    return ("word", v) if v else ("empty", None)


def is_number(k):
    return k in ("whole", "number")


def value_problem(key, value, entries):
    """The needle an error about key = value must contain, None if valid"""
    k, v = kind(value) if isinstance(value, str) else ("dict", value)
    if key in ("demScript", "demRestartScript", "demScreen"):
        # '/' outside quotes is an operator to OpenFOAM's parser, not a word
        if k not in ("word", "string") or (k == "word" and "/" in v):
            return key
        return key if key == "demScript" and os.path.normpath(v) != DEM_SCRIPT else None
    if key in CHOICES:
        return None if k == "word" and v in CHOICES[key] else key
    if key == "couplingInterval":
        if k != "whole":
            return key
        return None if v in COUPLING_STEPS_OK or (v > 0 and v % 10 == 0) else key
    if key == "forces":
        if k != "list" or len(set(v)) != len(v) or any(re.match(r"[-\d]", w) for w in v):
            return key
        unknown = [w for w in v if w not in FORCES]
        return unknown[0] if unknown else None
    if key == "alphaMin":
        return None if is_number(k) and 0 <= v < 1 else key
    if key in ("reportExchange", "twoDimensional", "keepVolumeBeyondMesh"):
        ok = (k == "word" and v in SWITCHES) or (k == "whole" and v in (0, 1))
        if not ok:
            return key
        true = (v in ("true", "yes", "on", "any", "t", "y")) or v == 1
        return key if key == "twoDimensional" and true else None
    if key == "virtualMassCoefficient":
        return None if is_number(k) and v >= 0 else key
    if key == "coarseGraining":
        if k != "dict":
            return key
        return coarse_problem(value if isinstance(value, list) else parse_dict(value))
    if key in MODEL_COEFFS:
        if k != "dict":
            return key
        # the model in use takes its defaults: only unknown keywords and kinds fail
        for k2, v2 in (value if isinstance(value, list) else parse_dict(value)):
            want = MODEL_KEYS[key].get(k2)
            got = kind(v2)[0]
            if want is None or (want == "n") != is_number(got) or (want == "s" and got != "word"):
                return k2
        return None
    return key


def coarse_problem(entries):
    keys = [e[0] for e in entries]
    for key in keys:
        if keys.count(key) > 1:
            return key
    for key, value in entries:
        if key not in ("factor", "forceScaling"):
            return key
        k, v = kind(value)
        if key == "forceScaling" and not (k == "word" and v in ("cubic", "exact")):
            return key
        if key == "factor":
            if is_number(k):
                h = [v]
            elif k == "list" and v and all(kind(x)[0] in ("whole", "number") for x in v):
                h = [float(x) for x in v]
            else:
                return "factor"
            if len(h) not in (1, N_TYPES) or any(not 1 <= x < 1e6 for x in h):
                return "factor"
    return None if "factor" in keys else "factor"


def parse_dict(text):
    """{ k v; ... } of one level, as [key, value] pairs"""
    body = text.strip()[1:-1]
    return [[m.group(1), m.group(2).strip()] for m in re.finditer(r"(\w+)\s+([^;]*);", body)]


def expected(entries):
    """The needle of the first problem of a couplingProperties, None if valid"""
    keys = [e[0] for e in entries]
    for key in keys:
        if keys.count(key) > 1:
            return "duplicate entry: " + key
    for key, value in entries:
        if key not in KEYWORDS:
            return key
        problem = value_problem(key, value, entries)
        if problem:
            return problem
    missing = REQUIRED - set(keys)
    if missing:
        return tuple(sorted(missing))   # any one of them
    values = dict((k, v) for k, v in entries)
    if values.get("formulation") == "B" and "pressureGradient" in values.get("forces", ""):
        return "pressureGradient"
    return None


def render(entries):
    lines = ["FoamFile { version 2.0; format ascii; class dictionary; object couplingProperties; }", ""]
    for key, value in entries:
        if isinstance(value, list):
            value = "{ " + " ".join("%s %s;" % (k, v) for k, v in value) + " }"
        lines.append("%-19s %s%s" % (key, value, "" if value.startswith("{") else ";"))
    return "\n".join(lines) + "\n"


BASE = [["demScript", '"DEM/in.liggghts"'], ["demRestartScript", '"DEM/in.restart"'],
        ["couplingInterval", "10"], ["formulation", "A"], ["dragModel", "Gidaspow"],
        ["forces", "(pressureGradient buoyancy)"], ["particlesOutside", "error"],
        ["voidFractionModel", "analytical"]]
PARCELS = BASE + [["coarseGraining", [["factor", "2"], ["forceScaling", "cubic"]]]]


def pick(key, rng):
    """A replacement value: one of the key's valid ones, or any of the pool"""
    if key in VALID and rng.random() < 0.5:
        return rng.choice(VALID[key])
    return rng.choice(POOL)


def misspell(word, rng):
    i = rng.randrange(len(word))
    how = rng.choice(["drop", "double", "swap", "case"])
    if how == "drop":
        return word[:i] + word[i + 1:]
    if how == "double":
        return word[:i] + word[i] + word[i:]
    if how == "swap" and i + 1 < len(word) and word[i] != word[i + 1]:
        return word[:i] + word[i + 1] + word[i] + word[i + 2:]
    return word[:i] + word[i].swapcase() + word[i + 1:]


def damage(base, rng):
    """(what was done, file text, needle or None)"""
    entries = [[k, [list(e) for e in v] if isinstance(v, list) else v] for k, v in base]
    how = rng.choice(["drop", "replace", "add", "duplicate", "misspell", "truncate", "nested"])
    if how == "nested" and not any(isinstance(v, list) for _, v in entries):
        how = "replace"
    if how == "drop":
        i = rng.randrange(len(entries))
        what = "dropped %s" % entries.pop(i)[0]
    elif how == "replace":
        i = rng.randrange(len(entries))
        entries[i][1] = pick(entries[i][0], rng)
        what = "%s replaced by %s" % tuple(entries[i])
    elif how == "add":
        key = rng.choice(OPTIONAL_TO_ADD)
        entries.append([key, pick(key, rng)])
        what = "added %s %s" % tuple(entries[-1])
    elif how == "duplicate":
        key, value = rng.choice(entries)
        entries.append([key, rng.choice([value, rng.choice(POOL)])])
        what = "%s given again as %s" % (key, entries[-1][1])
    elif how == "misspell":
        e = rng.choice(entries)
        old, e[0] = e[0], misspell(e[0], rng)
        if e[0] in KEYWORDS:
            e[0] = old + "x"
        what = "keyword %s misspelt %s" % (old, e[0])
    elif how == "nested":
        sub = next(v for _, v in entries if isinstance(v, list))
        op = rng.choice(["drop", "replace", "misspell", "duplicate"])
        j = rng.randrange(len(sub))
        if op == "drop":
            what = "coarseGraining: dropped %s" % sub.pop(j)[0]
        elif op == "replace":
            sub[j][1] = rng.choice(POOL + ["1", "0.9", "(2 3)", "4"])
            what = "coarseGraining: %s replaced by %s" % tuple(sub[j])
        elif op == "duplicate":
            sub.append(list(sub[j]))
            what = "coarseGraining: %s given twice" % sub[j][0]
        else:
            old, sub[j][0] = sub[j][0], misspell(sub[j][0], rng)
            if sub[j][0] in ("factor", "forceScaling"):
                sub[j][0] = old + "x"
            what = "coarseGraining: keyword %s misspelt %s" % (old, sub[j][0])
        if not sub:
            entries = [e for e in entries if e[1] is not sub] + [["coarseGraining", "{}"]]
    if how != "truncate":
        return what, render(entries), expected(entries)
    return truncate(entries, rng)


def truncate(entries, rng):
    """Cut the file after an entry (the rest lost) or inside one (an error)"""
    text = render(entries)
    header = text.index("\n\n") + 2
    ends = [m.end() for m in re.finditer(r";\n|}\n", text) if m.end() > header]
    if rng.random() < 0.5:
        i = rng.randrange(len(ends))
        kept = entries[:i + 1]
        return ("cut after %s (%d of %d entries kept)" % (kept[-1][0], len(kept), len(entries)),
                text[:ends[i]], expected(kept))
    cut = rng.randrange(header + 1, len(text) - 2)
    while text[cut - 1] in "\n" or any(cut == e for e in ends):
        cut += 1
    line = text[:cut].rsplit("\n", 1)[-1]
    return "cut inside '%s'" % line, text[:cut], "FOAM FATAL"


def classify(rc, out, needle):
    """'' when the run is as the input deserves, else why not"""
    if rc == 124:
        return "hung (killed after %d s)" % TIMEOUT
    if rc in (134, 136, 139) or rc < 0 or "printStack" in out or "Segmentation" in out:
        return "crashed (status %d)" % rc
    if needle is None:
        return "" if rc == 0 and "\nEnd" in out else "valid input did not run (status %d)" % rc
    if rc == 0:
        return "wrong input ran (status 0): expected an error naming '%s'" % needle
    # OpenFOAM's own command-line errors ('Invalid option') are not FOAM FATAL
    error = out[out.find("FOAM FATAL"):] if "FOAM FATAL" in out else out[-2000:]
    needles = needle if isinstance(needle, tuple) else (needle,)
    if not any(n in error for n in needles):
        return "error does not name '%s'" % "' or '".join(needles)
    return ""


def prepare(name):
    base = os.path.join(WORK, name)
    shutil.rmtree(base, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "tutorials", "settlingSphere"), base)
    sh("./Allclean > /dev/null; cp -r 0.orig 0 && blockMesh > /dev/null", base)
    control = os.path.join(base, "system", "controlDict")
    text = re.sub(r"^endTime\s+\S+;", "endTime 0.0005;", open(control).read(), flags=re.M)
    open(control, "w").write(text)
    return base


def run_one(base, index, text):
    case = "%s-run%d" % (base, index)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base, case)
    with open(os.path.join(case, "constant", "couplingProperties"), "w") as f:
        f.write(text)
    rc, out = sh("timeout %d pimpleDEMFoam" % TIMEOUT, case, check=False)
    return rc, out, case


def option(name, default):
    args = sys.argv[1:]
    return int(args[args.index(name) + 1]) if name in args else default


def test_coupling_fuzz():
    seed, runs = option("--seed", SEED), option("--runs", RUNS)
    print("couplingProperties of the settling sphere, %d damaged files (seed %d)" % (runs, seed))
    rng = random.Random(seed)
    cases = []
    for i in range(runs):
        base = PARCELS if i % 3 == 2 else BASE
        cases.append(("parcels" if base is PARCELS else "plain",) + damage(base, rng))
    base = prepare("fuzz")
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda ic: run_one(base, ic[0], ic[1][2]), enumerate(cases)))
    counts = {"error": 0, "ran": 0}
    bad = []
    for i, ((which, what, text, needle), (rc, out, case)) in enumerate(zip(cases, results)):
        why = classify(rc, out, needle)
        counts["ran" if needle is None else "error"] += 1
        if why:
            bad.append("run %d (%s, seed %d): %s: %s\n%s" % (i, which, seed, what, why, out[-500:]))
        else:
            shutil.rmtree(case, ignore_errors=True)
    documented(seed, runs, RUNS, "%d errors naming the entry, %d runs to the end" % (counts["error"], counts["ran"]))
    check("%d damaged couplingProperties: %d clean errors naming the entry, %d valid runs, "
          "no crash, hang or wrong input run" % (runs, counts["error"], counts["ran"]),
          not bad, "%d not as expected; the first:\n" % len(bad) + "\n".join(bad[:5]) if bad else "")
    check("the damage reaches both outcomes (at least a fifth each)",
          min(counts.values()) >= runs // 5, str(counts))


def write_particles(case, n=12, seed=3):
    """A dump of n spheres well inside the settling sphere's box"""
    rng = random.Random(seed)
    lines = ["ITEM: TIMESTEP", "0", "ITEM: NUMBER OF ATOMS", str(n), "ITEM: BOX BOUNDS ff ff ff",
             "0 0.04", "0 0.04", "0 0.096", "ITEM: ATOMS id type x y z vx vy vz radius"]
    for i in range(n):
        lines.append("%d 1 %.6g %.6g %.6g 0 0 0 %.6g" % (i + 1, rng.uniform(0.005, 0.035),
                     rng.uniform(0.005, 0.035), rng.uniform(0.005, 0.09), rng.uniform(5e-4, 1e-3)))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(case, "p.dump"), "w") as f:
        f.write(text)
    return text


ATOMS_FROM = 9          # the first atom line (0-based) of write_particles' dump
COLUMNS = "id type x y z vx vy vz radius".split()


def damage_dump(text, rng):
    """(what was done, dump text, needle or None): a LIGGGHTS dump must hold its
    count of atom lines, each with one finite number per column, unique whole
    ids and positive radii"""
    lines = text.splitlines()
    atoms = len(lines) - ATOMS_FROM
    i = ATOMS_FROM + rng.randrange(atoms)
    col = rng.randrange(len(COLUMNS))
    how = rng.choice(["drop", "twice", "token", "radius", "id", "count", "header", "truncate",
                      "velocity", "shuffle", "timestep", "empty"])
    bad = "LIGGGHTS dump"
    if how == "drop":
        del lines[i]
        return "atom line %d dropped" % i, lines, bad
    if how == "twice":
        lines.insert(i, lines[i])
        return "atom line %d twice" % i, lines, bad
    words = lines[i].split()
    if how == "token":
        words[col] = rng.choice(["nan", "inf", "-inf", "abc", "1e999", "0x", "", "1 2"])
        lines[i] = " ".join(words)
        return "%s of atom line %d replaced by '%s'" % (COLUMNS[col], i, words[col]), lines, bad
    if how == "radius":
        words[-1] = rng.choice(["0", "-1e-3", "-0"])
        lines[i] = " ".join(words)
        return "radius of line %d %s" % (i, words[-1]), lines, bad
    if how == "id":
        words[0] = rng.choice(["2.5", lines[ATOMS_FROM + (i - ATOMS_FROM + 1) % atoms].split()[0]])
        lines[i] = " ".join(words)
        return "id of line %d %s" % (i, words[0]), lines, bad
    if how == "count":
        lines[3] = rng.choice([str(atoms + 1), str(atoms - 1), "-1", "x", "1e3"])
        return "atom count %s" % lines[3], lines, bad
    if how == "header":
        cols = COLUMNS[:]
        del cols[rng.choice([0, 2, 3, 4, 8])]
        lines[ATOMS_FROM - 1] = "ITEM: ATOMS " + " ".join(cols)
        return "ATOMS header without a column", lines, bad
    if how == "truncate":
        cut = rng.randrange(1, len(text) - 1)
        if text[cut - 1] == "\n" and text.count("\n", 0, cut) >= len(lines):
            cut -= 2
        return "cut at character %d" % cut, text[:cut].splitlines(), bad
    if how == "empty":
        return "empty file", [], bad
    if how == "velocity":
        words[5 + rng.randrange(3)] = rng.choice(["-0.3", "12", "1e-9"])
        lines[i] = " ".join(words)
        return "a velocity of line %d changed" % i, lines, None
    if how == "shuffle":
        body = lines[ATOMS_FROM:]
        rng.shuffle(body)
        return "atom lines shuffled", lines[:ATOMS_FROM] + body, None
    lines[1] = str(rng.randrange(0, 10**6))
    return "timestep %s" % lines[1], lines, None


def test_dump_fuzz():
    seed, runs = option("--seed", SEED), option("--runs", RUNS) // 4
    print("demVoidFraction on %d damaged LIGGGHTS dumps (seed %d)" % (runs, seed))
    rng = random.Random(seed)
    base = prepare("fuzz-dump")
    text = write_particles(base)
    cases = []
    for i in range(runs):
        what, lines, needle = damage_dump(text, rng)
        cases.append((what, "\n".join(lines) + ("\n" if lines else ""), needle))

    def run(ic):
        i, (what, dump, needle) = ic
        case = "%s-run%d" % (base, i)
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(base, case)
        with open(os.path.join(case, "p.dump"), "w") as f:
            f.write(dump)
        rc, out = sh("timeout %d demVoidFraction -dump p.dump" % TIMEOUT, case, check=False)
        return rc, out, case
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(run, enumerate(cases)))
    counts = report("damaged dumps", seed, cases, results)
    documented(seed, runs, RUNS // 4, "%d errors naming the dump, %d runs" % (counts["error"], counts["ran"]))


NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")
ARG_POOL = ["foo", "2", "1", "0", "-1", "0.5", "1.5", "1e30", "1e999", "nan", "inf", "", "a b",
            "kernel", "centroid", "cubic", "exact", "0:1", ":", "0,2", "1:2", "p.dump",
            "missing.dump", "(z 12 0.05)", "(q 3)", "vf2", "x,y"]


def finite(text):
    return bool(NUMBER.match(text)) and abs(float(text)) < 1.7e308


def word_like(text):
    return bool(text) and not any(c.isspace() or c in "\"'/;{}" for c in text)


def selects_zero(text):
    """-time's ranges: comma-separated numbers, a:b, a: or :b; do they match 0?"""
    hit = False
    for item in text.split(","):
        lo, colon, hi = item.partition(":")
        if not colon:
            if not finite(item):
                return None
            hit |= float(item) == 0
            continue
        if (lo and not finite(lo)) or (hi and not finite(hi)) or not (lo or hi):
            return None
        hit |= (not lo or float(lo) <= 0) and (not hi or 0 <= float(hi))
    return hit


def dem_void_fraction_problem(opts):
    """demVoidFraction in a case with p.dump (one snapshot, TIMESTEP 0)"""
    if "dump" not in opts:
        return "-dump"
    for name, value in opts.items():
        if name in ("dump", "previous") and value != "p.dump":
            return value or "dump"
        if name == "model" and value not in CHOICES["voidFractionModel"]:
            return value or "model"
        if name == "repeat" and not (finite(value) and float(value) >= 0 and float(value).is_integer()):
            return "-repeat"
        if name == "deltaT" and not (finite(value) and float(value) > 0):
            return "-deltaT"
        if name == "time" and not selects_zero(value):
            return "-time" if selects_zero(value) is None else "none of the 1 snapshots"
        if name == "name" and not word_like(value):
            return "-name"
    return None


def scale_case_problem(opts):
    """scaleCase in the settling sphere's case"""
    parcels = "parcels" in opts
    if "factor" not in opts or not finite(opts["factor"]):
        return "-factor"
    if "wallVoid" in opts:
        if not parcels or not finite(opts["wallVoid"]) or not 0 <= float(opts["wallVoid"]) < 0.5:
            return "-wallVoid"
    if "courant" in opts and not (finite(opts["courant"]) and 0 < float(opts["courant"]) <= 1):
        return "-courant"
    for name in ("minCells", "relativeSmoothing", "courant"):
        if name in opts and (not parcels or "keepMesh" in opts):
            return "-" + name
    if "keepMesh" in opts and not parcels:
        return "-keepMesh"
    h = float(opts["factor"])
    if not h > 0:
        return "-factor"
    if "output" not in opts:
        return "-output"
    if opts["output"] in ("", ".") or any(c.isspace() or c in "\"'" for c in opts["output"]):
        return "-output"
    if parcels:
        if h < 1:
            return "-factor"
        if opts["parcels"] not in ("cubic", "exact"):
            return "-parcels"
        rules = opts.get("minCells")
        if rules is not None and not re.fullmatch(r"(\s*\([xyz] \d+( [\d.]+)?\))+\s*", rules):
            return "-minCells"
        if "courant" in opts:
            return "-courant: no inlet velocity"    # the settling sphere has none
    return None


def benchmark_problem(opts):
    """voidFractionBenchmark in a case with p.dump and a benchmark dictionary"""
    if "dump" not in opts:
        return "-dump"
    if opts["dump"] != "p.dump":
        return opts["dump"] or "dump"
    if "sample" in opts and (not word_like(opts["sample"]) or "," in opts["sample"]):
        return "-sample"
    return None


UTILITIES = {
    # name: (the valid command's options, optional ones, flags, oracle)
    "demVoidFraction": ({"dump": "p.dump"}, ["model", "repeat", "deltaT", "time", "name", "previous"],
                        ["latest", "distribute"], dem_void_fraction_problem),
    "scaleCase": ({"factor": "2", "output": "OUT"}, ["parcels", "minCells", "wallVoid", "courant"],
                  ["keepMesh", "relativeSmoothing", "overwrite"], scale_case_problem),
    "voidFractionBenchmark": ({"dump": "p.dump"}, ["sample"], [], benchmark_problem),
}


def damage_arguments(rng):
    """(utility, what was done, argument list, needle or None)"""
    utility = rng.choice(sorted(UTILITIES))
    base, optional, flags, problem = UTILITIES[utility]
    opts = dict(base)
    extra = []
    how = rng.choice(["replace", "add", "add", "flag", "drop", "unknown", "no value", "twice"])
    if how == "replace":
        name = rng.choice(sorted(opts))
        opts[name] = rng.choice(ARG_POOL)
        what = "-%s '%s'" % (name, opts[name])
    elif how == "add":
        name = rng.choice(optional)
        opts[name] = rng.choice(ARG_POOL)
        what = "added -%s '%s'" % (name, opts[name])
    elif how == "flag" and flags:
        name = rng.choice(flags)
        opts[name] = None
        what = "added -%s" % name
    elif how == "drop":
        name = rng.choice(sorted(opts))
        del opts[name]
        what = "dropped -%s" % name
    elif how == "unknown":
        name = rng.choice(["bogus", misspell(rng.choice(sorted(base) + optional), rng)])
        extra = ["-" + name, "1"]
        what = "unknown option -%s" % name
    elif how == "no value":
        name = rng.choice(optional)
        extra = ["-" + name]
        what = "-%s without its value" % name
    else:
        how = "twice"
        name = rng.choice(sorted(opts))
        extra = ["-" + name, opts[name]]
        what = "-%s given twice" % name
    args = []
    for key, value in opts.items():
        args += ["-" + key] + ([] if value is None else [value])
    args += extra
    if how in ("unknown", "no value", "twice"):
        needle = name
    else:
        needle = problem({k: ("" if v is None else v) for k, v in opts.items()})
    return utility, what, args, needle


BENCHMARK_DICT = """FoamFile { version 2.0; format ascii; class dictionary; object voidFractionBenchmarkDict; }
reference { voidFractionModel analytical; }
repeat 1;
csv "bench.csv";
runs { centroid { voidFractionModel centroid; } }
"""


def test_argument_fuzz():
    seed, runs = option("--seed", SEED), option("--runs", RUNS) // 3
    print("demVoidFraction, scaleCase and voidFractionBenchmark on %d damaged command lines (seed %d)"
          % (runs, seed))
    rng = random.Random(seed)
    base = prepare("fuzz-args")
    write_particles(base)
    with open(os.path.join(base, "system", "voidFractionBenchmarkDict"), "w") as f:
        f.write(BENCHMARK_DICT)
    cases = [damage_arguments(rng) for _ in range(runs)]

    def run(ic):
        i, (utility, what, args, needle) = ic
        case = "%s-run%d" % (base, i)
        shutil.rmtree(case, ignore_errors=True)
        shutil.rmtree(case + "-out", ignore_errors=True)
        shutil.copytree(base, case)
        words = [case + "-out" if a == "OUT" else a for a in args]
        command = "timeout %d %s %s" % (TIMEOUT, utility, " ".join("'%s'" % w for w in words))
        rc, out = sh(command, case, check=False)
        if rc == 0 or needle:
            shutil.rmtree(case + "-out", ignore_errors=True)
        return rc, out, case
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(run, enumerate(cases)))
    counts = report("damaged command lines", seed,
                    [(u + " " + what, " ".join(a), n) for u, what, a, n in cases], results)
    documented(seed, runs, RUNS // 3,
               "%d errors naming the option or value, %d runs" % (counts["error"], counts["ran"]))


def test_utilities_check_coupling_properties():
    print("the utilities that read couplingProperties check it as the solver does")
    base = prepare("fuzz-utilities")
    write_particles(base)
    with open(os.path.join(base, "system", "voidFractionBenchmarkDict"), "w") as f:
        f.write(BENCHMARK_DICT)
    damages = [("coarseGraining 2;", "coarseGraining in couplingProperties is not a dictionary"),
               ("virtualMassCoeficient 0.3;", "unknown keyword virtualMassCoeficient"),
               ("formulation B;", "duplicate entry: formulation")]
    commands = {"demVoidFraction": "demVoidFraction -dump p.dump",
                "scaleCase": "scaleCase -factor 2 -output ../fuzz-utilities-out",
                "voidFractionBenchmark": "voidFractionBenchmark -dump p.dump"}
    props = os.path.join(base, "constant", "couplingProperties")
    original = open(props).read()
    for line, needle in damages:
        with open(props, "w") as f:
            f.write(original + line + "\n")
        for name, command in sorted(commands.items()):
            shutil.rmtree(base + "-out", ignore_errors=True)
            rc, out = sh("timeout %d %s" % (TIMEOUT, command), base, check=False)
            why = classify(rc, out, needle)
            check("%s with '%s': %s" % (name, line, why or "error says '%s'" % needle), not why,
                  "" if not why else out[-400:])
            check("%s with '%s': nothing written" % (name, line),
                  not os.path.exists(base + "-out") and not os.path.exists(os.path.join(base, "bench.csv"))
                  and not os.path.exists(os.path.join(base, "0", "voidfraction")))


def documented(seed, runs, default_runs, text):
    """With the default seed and count, docs/validation.md must state these counts"""
    if seed != SEED or runs != default_runs:
        return
    docs = open(os.path.join(ROOT, "docs", "validation.md")).read()
    check("docs/validation.md states the counts: '%s'" % text, text in docs)


def report(what, seed, cases, results):
    """One check over the runs: each as its input deserves"""
    counts = {"error": 0, "ran": 0}
    bad = []
    for i, (case, (rc, out, path)) in enumerate(zip(cases, results)):
        damage_done, needle = case[-3], case[-1]
        why = classify(rc, out, needle)
        counts["ran" if needle is None else "error"] += 1
        if why:
            bad.append("run %d (seed %d): %s: %s\n%s" % (i, seed, damage_done, why, out[-500:]))
        else:
            shutil.rmtree(path, ignore_errors=True)
    check("%d %s: %d clean errors naming what is wrong, %d valid runs, no crash, hang or "
          "wrong input run" % (len(cases), what, counts["error"], counts["ran"]), not bad,
          "%d not as expected; the first:\n" % len(bad) + "\n".join(bad[:5]) if bad else "")
    return counts


def main():
    tests = [test_coupling_fuzz, test_dump_fuzz, test_argument_fuzz,
             test_utilities_check_coupling_properties]
    names = [a for a in sys.argv[1:] if a.startswith("test_")]
    checks.run(tests, names)
    return checks.summary("fuzz")


if __name__ == "__main__":
    sys.exit(main())
