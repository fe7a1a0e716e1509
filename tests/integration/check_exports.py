#!/usr/bin/python3
"""`suspend export` on a real run (cases/quickstart.yaml, adhesive frictional, sheared cell): the extended XYZ has a
frame per snapshot with the sheared Lattice, species, positions, radii and velocities of run.h5; the GSD (read back
with python3-gsd, as freud and OVITO read it) has the tilt offset / L_y, positions inside HOOMD's triclinic cell,
and every contact, measured with HOOMD's minimum image in that cell, has the separation run.h5 records. Bad
arguments exit 2 with one line. Usage: check_exports.py SUSPEND_BINARY SOURCE_DIR"""
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from script_checks import check, failures, run_quickstart

suspend_bin, source = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(source, "python"))
import suspend  # noqa: E402

def is_extxyz(path):
    with open(path) as f:
        return f.readline().strip().isdigit() and "Lattice=" in f.readline()


with tempfile.TemporaryDirectory() as work:
    run_dir = os.path.join(work, "run")
    run_quickstart(suspend_bin, source, run_dir, 0.4, 0.2)
    run = suspend.load_run(run_dir)
    snaps = list(run.snapshots())

    xyz = os.path.join(work, "run.xyz")
    r = subprocess.run([suspend_bin, "export", run_dir, "--format", "extxyz", "--out", xyz], capture_output=True,
                       text=True)
    check(r.returncode == 0, f"extxyz export exit {r.returncode}: {r.stderr}")
    lines = open(xyz).read().splitlines()
    at = 0
    for s in snaps:
        n = int(lines[at])
        header = lines[at + 1]
        rows = [line.split() for line in lines[at + 2:at + 2 + n]]
        at += 2 + n
        lx, ly, lz = s["box"]
        lattice = [float(v) for v in header.split('Lattice="')[1].split('"')[0].split()]
        check(np.allclose(lattice, [lx, 0, 0, s["shear_offset"], ly, 0, 0, 0, lz], rtol=0, atol=1e-12),
              f"extxyz lattice {lattice}")
        check("Properties=species:S:1:pos:R:3:radius:R:1:velo:R:3:omega:R:3" in header, "extxyz properties")
        check(f"strain={float(s['strain'])!r}" in header, "extxyz strain")
        table = np.array([[float(v) for v in row[1:]] for row in rows])
        check(n == len(s["radius"]), "extxyz particle count")
        check(np.array_equal(table[:, 0:3], s["position"]), "extxyz positions")
        check(np.array_equal(table[:, 3], s["radius"]), "extxyz radii")
        check(np.array_equal(table[:, 4:7], s["velocity"]), "extxyz velocities")
        check([row[0] for row in rows] == [["H", "He"][k] for k in s["species"]], "extxyz species")
    check(at == len(lines), f"extxyz: {len(snaps)} frames and nothing else")

    gsd_file = os.path.join(work, "run.gsd")
    r = subprocess.run([suspend_bin, "export", run_dir, "--format", "gsd", "--out", gsd_file], capture_output=True,
                       text=True)
    check(r.returncode == 0, f"gsd export exit {r.returncode}: {r.stderr}")
    import gsd.hoomd
    with gsd.hoomd.open(gsd_file, "rb") as trajectory:
        check(len(trajectory) == len(snaps), f"gsd frames {len(trajectory)}")
        contacts_checked = 0
        for frame, s in zip(trajectory, snaps):
            lx, ly, lz = s["box"]
            box = frame.configuration.box
            check(np.allclose(box, [lx, ly, lz, s["shear_offset"] / ly, 0, 0]), f"gsd box {box}")
            p = frame.particles.position.astype(float)
            xy = box[3]
            frac_x = (p[:, 0] - xy * p[:, 1]) / lx
            check(np.all(np.abs(frac_x) <= 0.5 + 1e-6) and np.all(np.abs(p[:, 1]) <= ly / 2 + 1e-6),
                  "gsd positions inside the triclinic cell")
            check(np.array_equal(frame.particles.typeid, s["species"]), "gsd typeid")
            check(np.allclose(frame.particles.diameter, 2 * s["radius"]), "gsd diameter")
            check(np.array_equal(frame.bonds.group, s["contact_pairs"]), "gsd bonds are the contacts")
            seg = s["contact_segments"].reshape(-1, 2, 3)
            for (i, j), (a, b) in zip(frame.bonds.group, seg):
                d = p[j] - p[i]
                d -= np.array([0, 0, lz]) * np.round(d[2] / lz)
                k = np.round(d[1] / ly)
                d -= k * np.array([xy * ly, ly, 0])
                d[0] -= lx * np.round(d[0] / lx)
                check(np.allclose(d, b - a, atol=1e-4), f"gsd contact {i}-{j}: {d} against {b - a}")
                contacts_checked += 1
        check(contacts_checked > 0, "some contacts compared")

    # No export overwrites what it did not make: the run's own files never (--force or not), another file only with
    # --force; an earlier export of the same format is replaced.
    notes = os.path.join(work, "notes.txt")
    with open(notes, "w") as f:
        f.write("my notes\n")
    own = {name: open(os.path.join(run_dir, name), "rb").read() for name in ("run.h5", "summary.json")}
    for args, fragment in [(["export", run_dir, "--format", "pdb"], "--format"),
                           (["export", os.path.join(work, "nowhere"), "--format", "gsd"], "not found"),
                           (["export", run_dir, "--format", "extxyz", "--out", os.path.join(run_dir, "run.h5")],
                            "own file"),
                           (["export", run_dir, "--format", "gsd", "--out", os.path.join(run_dir, "summary.json"),
                             "--force"], "own file"),
                           (["export", run_dir, "--format", "extxyz", "--out", notes], "--force"),
                           (["export", run_dir, "--format", "gsd", "--out", xyz], "not a gsd export"),
                           (["export", run_dir, "--format", "extxyz", "--out", work], "directory"),
                           (["export", run_dir, "--format", "extxyz", "--out", os.path.join(work, "no", "x.xyz")],
                            "does not exist")]:
        r = subprocess.run([suspend_bin] + args, capture_output=True, text=True)
        check(r.returncode == 2 and fragment in r.stderr and r.stderr.count("\n") == 1,
              f"{args}: exit {r.returncode}, {r.stderr!r}")
    # Damaged or foreign run folders: one line, exit 2, never a traceback.
    for damage in ("truncated", "checkpoint"):
        broken = os.path.join(work, damage)
        os.makedirs(broken)
        if damage == "truncated":
            with open(os.path.join(broken, "run.h5"), "wb") as f:
                f.write(own["run.h5"][:len(own["run.h5"]) // 3])
        else:
            shutil.copy(os.path.join(run_dir, "checkpoint.h5"), os.path.join(broken, "run.h5"))
        r = subprocess.run([suspend_bin, "export", broken, "--format", "extxyz"], capture_output=True, text=True)
        check(r.returncode == 2 and "is not a readable run" in r.stderr and r.stderr.count("\n") == 1,
              f"export of a {damage} run.h5: exit {r.returncode}, {r.stderr!r}")
    for name, content in own.items():
        check(open(os.path.join(run_dir, name), "rb").read() == content, f"{name} changed by a refused export")
    check(open(notes).read() == "my notes\n", "notes.txt changed by a refused export")
    for args in (["--out", xyz], ["--out", notes, "--force"]):
        r = subprocess.run([suspend_bin, "export", run_dir, "--format", "extxyz"] + args, capture_output=True, text=True)
        check(r.returncode == 0 and is_extxyz(args[1]), f"export again {args}: exit {r.returncode}, {r.stderr!r}")
    r = subprocess.run([suspend_bin, "export", run_dir, "--format", "gsd", "--out", gsd_file], capture_output=True,
                       text=True)
    check(r.returncode == 0, f"gsd export again: exit {r.returncode}, {r.stderr!r}")

if failures:
    sys.exit(1)
print(f"exports: extxyz and gsd of {len(snaps)} snapshots match run.h5")
