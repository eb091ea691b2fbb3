#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Carry a spouted bed run from one machine to another: a run longer than a
machine lives (the fine bed takes hours) continues elsewhere from its last
written time.

  carry.py save CASE ARCHIVE      the last written time of the run in CASE
  carry.py restore ARCHIVE CASE   makes CASE a run that continues from it

The archive (tar.xz) holds the case's dictionaries and scripts, its last
written time (fluid fields of every rank, DEM.forces), its outputs so far
(the pressure and wall-force histories, the logs' time and timing lines,
snapshotProfiles.npz: the speed sums of every snapshot after the start-up)
and the particles' state in a portable form. LIGGGHTS's binary restart files
are not portable and are large (485 bytes a particle); the archive keeps
what LIGGGHTS's write_data gives (positions, velocities and spins in double
precision, diameters, densities) and restore makes a DEM.restart of it with
read_data and write_restart. What a restored run loses is the contacts'
tangential history (the springs of the sliding contacts restart from zero,
as for a new contact); everything else continues exactly.
"""
import glob
import io
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TUTORIAL = os.path.join(ROOT, "tutorials", "spoutedBed")
ENV = dict(os.environ, VFM_PROJECT_DIR=ROOT)
STATE = "carriedParticles.npz"
# LIGGGHTS's set-up of every spoutedBed script (DEM/in.liggghts)
HEAD = "units si\natom_style granular\natom_modify map array\nboundary f f f\nnewton off\n" \
       "communicate single vel yes\n"
# the log lines run.py and record.py read
LOG_LINES = re.compile(r"^(Time = |ExecutionTime|End$|coupling |particleFluidCoupling: formulation )")


def time_names(root):
    """The numbered directories under root: each one's time and name."""
    names = {}
    for d in os.listdir(root):
        try:
            names[float(d)] = d
        except ValueError:
            pass
    return names


def numbered(root):
    return set(time_names(root))


def latest_time(case):
    """The last time the run wrote whole (the DEM's state, written last, and
    every rank's fields), 0 if none."""
    if not os.path.isdir(case):
        return 0.0
    times = {t for t in numbered(case) if t > 0 and os.path.isfile(os.path.join(case, "%g" % t, "DEM.forces"))}
    for root in glob.glob(os.path.join(case, "processor*")):
        times &= numbered(root)
    return max(times) if times else 0.0


def time_dir(root, t):
    """The directory of time t under root, as OpenFOAM named it."""
    return next((d for v, d in time_names(root).items() if abs(v - t) < 1e-12), None)


def liggghts(case, script):
    """Run a LIGGGHTS script in the case's DEM folder, stopping with its
    ERROR line if it fails."""
    dem = os.path.join(case, "DEM")
    with tempfile.NamedTemporaryFile("w", suffix=".in", dir=dem, delete=False) as f:
        f.write(script)
    try:
        out = subprocess.run(["liggghts", "-in", os.path.basename(f.name), "-log", "none"], cwd=dem, env=ENV,
                             capture_output=True, text=True)
    finally:
        os.remove(f.name)
    errors = [l for l in out.stdout.splitlines() if l.startswith("ERROR")]
    if out.returncode != 0 or errors:
        sys.exit("carry.py: LIGGGHTS failed in %s: %s" % (dem, "; ".join(errors) or out.stderr.strip()[-300:]))


def read_data(path):
    """The box and the per-particle columns of a LIGGGHTS data file."""
    text = open(path).read()
    box = [float(v) for v in re.findall(r"(?m)^(\S+) (\S+) [xyz]lo [xyz]hi$", text) for v in v]
    sections = {}
    for name in ("Atoms", "Velocities"):
        block = re.search(r"(?ms)^%s\s*\n\n(.*?)(?:\n\n|\Z)" % name, text).group(1)
        sections[name] = np.loadtxt(io.StringIO(block), ndmin=2)
    atoms = sections["Atoms"][np.argsort(sections["Atoms"][:, 0])]
    spins = sections["Velocities"][np.argsort(sections["Velocities"][:, 0])]
    if not np.array_equal(atoms[:, 0], spins[:, 0]):
        sys.exit("carry.py: %s: Atoms and Velocities list different particles" % path)
    return np.array(box), atoms, spins


def write_data(path, box, atoms, spins):
    with open(path, "w") as out:
        out.write("particles carried from another machine\n\n%d atoms\n%d atom types\n\n" %
                  (len(atoms), int(atoms[:, 1].max())))
        for i, axis in enumerate("xyz"):
            out.write("%.17g %.17g %slo %shi\n" % (box[2*i], box[2*i + 1], axis, axis))
        out.write("\nAtoms\n\n")
        for a in atoms:
            out.write("%d %d %.17g %.17g %.17g %.17g %.17g %d %d %d\n" % tuple(a))
        out.write("\nVelocities\n\n")
        for s in spins:
            out.write("%d %.17g %.17g %.17g %.17g %.17g %.17g\n" % tuple(s))


def forces_header(path):
    """(restartBytes, demStep, the header's length in bytes) of a DEM.forces"""
    raw = open(path, "rb").read(200)
    m = re.match(rb"restartBytes (\d+)\ndemStep (\d+)\n", raw)
    if not m:
        sys.exit("carry.py: %s does not start with restartBytes and demStep" % path)
    return int(m.group(1)), int(m.group(2)), m.end()


def kept(case, t_name, path):
    """Whether the archive keeps this file of the case (path relative to it)."""
    parts = path.split(os.sep)
    # not the snapshots, restart files, pictures or LIGGGHTS's screen output
    if parts[0] == "VTK" or path.endswith(".restart") or parts[-1].endswith(".png") or \
            parts[-1] == "log.liggghtsScreen":
        return False
    for i, p in enumerate(parts[:-1]):
        try:
            float(p)
        except ValueError:
            continue
        # time directories: the last written one and the initial one
        if p != t_name and float(p) != 0 and (i == 0 or parts[0].startswith("processor")):
            return False
    return True


def log_until(path, t):
    """The log's kept lines up to the end of the step to time t: a run
    continued from t runs the later steps again, and counts their time."""
    for line in open(path):
        if line.startswith("Time = ") and float(line.split()[2]) > t + 1e-9:
            return
        if LOG_LINES.match(line):
            yield line


def save(case, archive):
    t = latest_time(case)
    if t == 0:
        sys.exit("carry.py: %s has no written time to carry" % case)
    name = time_dir(case, t)
    # the speed sums of the snapshots so far (the snapshots themselves stay behind)
    subprocess.run(["/usr/bin/python3", os.path.join(TUTORIAL, "plotSpoutedBed.py"), "1.0"], cwd=case, env=ENV,
                   capture_output=True)
    data = os.path.join(case, "DEM", "carried.data")
    liggghts(case, HEAD + "read_restart ../%s/DEM.restart\ninclude in.parameters\ninclude in.settings\n"
             "write_data %s\n" % (name, os.path.basename(data)))
    box, atoms, spins = read_data(data)
    os.remove(data)
    _, step, _ = forces_header(os.path.join(case, name, "DEM.forces"))
    state = io.BytesIO()
    np.savez(state, box=box, atoms=atoms, spins=spins, step=step, time=t)
    tmp = archive + ".part"
    with tarfile.open(tmp, "w:xz") as tar:
        for root, _, files in os.walk(case):
            for f in sorted(files):
                full = os.path.join(root, f)
                rel = os.path.relpath(full, case)
                if not kept(case, name, rel):
                    continue
                if re.match(r"log\.pimpleDEMFoam", f):
                    lines = "".join(log_until(full, t)).encode()
                    info = tarfile.TarInfo(rel)
                    info.size = len(lines)
                    tar.addfile(info, io.BytesIO(lines))
                else:
                    tar.add(full, rel)
        info = tarfile.TarInfo(STATE)
        info.size = state.getbuffer().nbytes
        state.seek(0)
        tar.addfile(info, state)
    os.replace(tmp, archive)
    print("carry.py: %s at t = %g s (%d particles, DEM step %d) saved in %s, %.1f MB"
          % (case, t, len(atoms), step, archive, os.path.getsize(archive)/1e6))


def restore(archive, case):
    if os.path.exists(case):
        sys.exit("carry.py: %s exists; restore makes a new case" % case)
    os.makedirs(case)
    with tarfile.open(archive, "r:xz") as tar:
        tar.extractall(case)
    state = np.load(os.path.join(case, STATE))
    t = float(state["time"])
    name = time_dir(case, t)
    data = os.path.join(case, "DEM", "carried.data")
    write_data(data, state["box"], state["atoms"], state["spins"])
    liggghts(case, HEAD + "read_data %s\nreset_timestep %d\nwrite_restart ../%s/DEM.restart\n"
             % (os.path.basename(data), int(state["step"]), name))
    os.remove(data)
    os.remove(os.path.join(case, STATE))
    # DEM.forces names the size of the DEM.restart written beside it
    forces = os.path.join(case, name, "DEM.forces")
    _, step, length = forces_header(forces)
    raw = open(forces, "rb").read()
    size = os.path.getsize(os.path.join(case, name, "DEM.restart"))
    open(forces, "wb").write(b"restartBytes %d\ndemStep %d\n" % (size, step) + raw[length:])
    print("carry.py: %s continues from t = %g s (%d particles; their tangential contact history restarts)"
          % (case, t, len(state["atoms"])))


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ("save", "restore"):
        sys.exit(__doc__)
    if sys.argv[1] == "save":
        save(sys.argv[2], sys.argv[3])
    else:
        restore(sys.argv[2], sys.argv[3])


if __name__ == "__main__":
    main()
