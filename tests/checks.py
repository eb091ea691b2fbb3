# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Assertion counters and the checks the model test files share."""
import math
import os
import time

from foamCase import ROOT, cell_volumes, read_scalar_field, sh, sphere_volume, write_dump

WORK = os.path.join(ROOT, "build", "tests")
passed = failed = 0


def check(name, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
        print("  ok   %s %s" % (name, detail))
    else:
        failed += 1
        print("  FAIL %s %s" % (name, detail))


def near(name, got, want, tol):
    ok = got is not None and math.isfinite(got) and abs(got - want) <= tol
    check(name, ok, "(got %.17g, want %.17g, tol %.3g)" % (got if got is not None else float("nan"), want, tol))


def run_model(case, dump, model, extra=""):
    rc, out = sh("demVoidFraction -dump %s -model %s %s" % (dump, model, extra), case, check=False)
    if rc != 0:
        print(out[-600:])
    return rc, out


def field_checks(label, case, centres, radii, model, alpha_min=0.05):
    """Run the model; the field's solid volume must equal the sum of the
    sphere volumes (all spheres lie wholly inside the mesh or wrap through
    cyclic patches), and the void fraction lie in [alphaMin, 1]."""
    dump = os.path.join(case, "particles.dump")
    write_dump(dump, centres, radii)
    rc, out = run_model(case, dump, model)
    check("%s %s runs" % (label, model), rc == 0)
    if rc != 0:
        return None
    alpha = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    V = cell_volumes(case)
    solid = sum((1 - a) * v for a, v in zip(alpha, V))
    want = sum(sphere_volume(r) for r in radii)
    near("%s %s solid volume = sum of sphere volumes (rel)" % (label, model), solid / want, 1.0, 1e-12)
    # (at most 1 by construction: the field is min(1 - solid/V, 1))
    check("%s %s void fraction finite and at least alphaMin" % (label, model),
          all(math.isfinite(a) and a >= alpha_min - 1e-12 for a in alpha),
          "(min %.6f max %.6f)" % (min(alpha), max(alpha)))
    return alpha



def serial_vs_parallel(label, case, dump, model, tol):
    """The model's field in serial and on 2 ranks (decomposed as the case's
    decomposeParDict says): equal within tol."""
    sh("rm -rf processor* 0", case)
    run_model(case, dump, model)
    serial = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    sh("rm -rf 0 && decomposePar -force", case)
    rc, out = sh("mpirun -np 2 demVoidFraction -parallel -dump %s -model %s" % (dump, model),
                 case, check=False)
    check("%s %s runs on 2 ranks" % (label, model), rc == 0)
    if rc != 0:
        print(out[-600:])
        return
    sh("reconstructPar -withZero -fields '(voidfraction)'", case)
    par = read_scalar_field(os.path.join(case, "0", "voidfraction"))
    near("%s %s serial = parallel, max |d alpha|" % (label, model),
         max(abs(x - y) for x, y in zip(serial, par)), 0, tol)


def parallel_cases(prefix, seed, models, tol_of=lambda model: 1e-12):
    """Serial against 2 ranks for the models, on a 10^3 Cartesian and a
    tetrahedral mesh of the 3 cm cube holding 1,500 random spheres."""
    from foamCase import box_block_mesh, new_case, random_spheres, tet_case
    lo, hi = (0, 0, 0), (0.03, 0.03, 0.03)
    for name in ("cartesian", "tetrahedral"):
        case = os.path.join(WORK, prefix + name)
        if name == "cartesian":
            new_case(case, box_block_mesh(lo, hi, (10, 10, 10)))
        else:
            tet_case(case)
        c, r = random_spheres(1500, 0.0004, 0.0012, lo, hi, seed=seed)
        write_dump(os.path.join(case, "p.dump"), c, r)
        for model in models:
            serial_vs_parallel(name, case, "p.dump", model, tol_of(model))


def run(tests, only):
    """Run the test functions (those named in only, when given); a test that
    raises counts as failed."""
    os.makedirs(WORK, exist_ok=True)
    unknown = sorted(set(only) - {t.__name__ for t in tests})
    if unknown:
        check("test names given exist (%s)" % ", ".join(unknown), False,
              "valid: " + " ".join(t.__name__ for t in tests))
        return
    for t in tests:
        if only and t.__name__ not in only:
            continue
        start = time.time()
        try:
            t()
        except Exception as e:
            check(t.__name__ + " completed", False, str(e)[-2000:])
        print("  (%s: %.0f s)" % (t.__name__, time.time() - start))


def summary(name):
    print("%s: %d passed, %d failed" % (name, passed, failed))
    return 1 if failed else 0
