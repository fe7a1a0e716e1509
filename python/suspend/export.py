"""Exports a run's snapshots for OVITO, ASE and freud (docs/output.md, "Exports"), one frame per snapshot.

extxyz: extended XYZ. `Lattice=` holds the sheared periodic cell (a_1 = (L_x, 0, 0), a_2 = (offset, L_y, 0),
  a_3 = (0, 0, L_z)), `Properties=species:S:1:pos:R:3:radius:R:1:velo:R:3:omega:R:3`, and each frame's strain, time
  and step in the comment line. Species k is written as the (k+1)-th element symbol (H, He, Li, ...), which OVITO
  shows as particle types and ASE can read; the radius column carries the size.
gsd: HOOMD's GSD through python3-gsd (read by freud and OVITO). The box is HOOMD's [L_x, L_y, L_z, xy, xz, yz] with
  the Lees-Edwards tilt xy = offset / L_y; positions are centred and wrapped into that triclinic cell;
  particles/typeid is the species, particles/diameter 2 a, velocity and angular velocity as in run.h5 (HOOMD has no
  angular-velocity field, so it goes to log/particles/angular_velocity), and the contact pairs as bonds.
Lengths in a_1, times in 1/gammadot_ref."""
import os

SYMBOLS = ["H", "He", "Li", "Be", "B", "C", "N", "O", "F", "Ne"]


def _cell(s):
    lx, ly, lz = (float(v) for v in s["box"])
    return lx, ly, lz, float(s["shear_offset"])


def write_extxyz(run, out):
    with open(out, "w") as f:
        for s in run.snapshots():
            lx, ly, lz, offset = _cell(s)
            species = s["species"]
            if species.max(initial=0) >= len(SYMBOLS):
                raise ValueError(f"{len(SYMBOLS)} species at most can be written as element symbols")
            n = len(s["radius"])
            f.write(f"{n}\n")
            f.write(f'Lattice="{lx!r} 0 0 {offset!r} {ly!r} 0 0 0 {lz!r}" '
                    'Properties=species:S:1:pos:R:3:radius:R:1:velo:R:3:omega:R:3 '
                    f'strain={float(s["strain"])!r} time={float(s["time"])!r} step={int(s["step"])} pbc="T T T"\n')
            p, v, w, r = s["position"], s["velocity"], s["angular_velocity"], s["radius"]
            for i in range(n):
                f.write(f"{SYMBOLS[species[i]]} {p[i, 0]!r} {p[i, 1]!r} {p[i, 2]!r} {r[i]!r} "
                        f"{v[i, 0]!r} {v[i, 1]!r} {v[i, 2]!r} {w[i, 0]!r} {w[i, 1]!r} {w[i, 2]!r}\n")


def hoomd_positions(position, lx, ly, lz, offset):
    """Positions of the rectangular primary cell [0, L)^3 moved into HOOMD's triclinic cell centred at the origin
    (tilt xy = offset / L_y): the same periodic arrangement, shifted by lattice vectors only."""
    import numpy as np
    r = position - np.array([lx, ly, lz]) / 2
    xy = offset / ly
    r[:, 0] -= lx * np.round((r[:, 0] - xy * r[:, 1]) / lx)
    return r


def write_gsd(run, out):
    import gsd
    import gsd.hoomd
    import numpy as np
    import warnings
    mode = "wb" if int(gsd.__version__.split(".")[0]) < 3 else "w"
    # gsd compares a frame's type names with its numeric defaults, which numpy answers with a FutureWarning on
    # every export; the comparison's result is right, so the warning is only noise on stderr.
    with warnings.catch_warnings(), gsd.hoomd.open(name=out, mode=mode) as trajectory:
        warnings.filterwarnings("ignore", category=FutureWarning, module="numpy")
        for s in run.snapshots():
            lx, ly, lz, offset = _cell(s)
            frame = gsd.hoomd.Frame() if hasattr(gsd.hoomd, "Frame") else gsd.hoomd.Snapshot()
            frame.configuration.step = int(s["step"])
            frame.configuration.box = [lx, ly, lz, offset / ly, 0.0, 0.0]
            n = len(s["radius"])
            frame.particles.N = n
            kinds = int(s["species"].max(initial=0)) + 1
            frame.particles.types = [f"species{k}" for k in range(kinds)]
            frame.particles.typeid = s["species"].astype(np.uint32)
            frame.particles.position = hoomd_positions(s["position"], lx, ly, lz, offset).astype(np.float32)
            frame.particles.diameter = (2 * s["radius"]).astype(np.float32)
            frame.particles.velocity = s["velocity"].astype(np.float32)
            pairs = s.get("contact_pairs", np.zeros((0, 2), dtype=np.int64))
            frame.bonds.N = len(pairs)
            frame.bonds.types = ["contact"]
            frame.bonds.typeid = np.zeros(len(pairs), dtype=np.uint32)
            frame.bonds.group = pairs.astype(np.uint32).reshape(-1, 2)
            frame.log["particles/angular_velocity"] = s["angular_velocity"]
            frame.log["value/strain"] = np.array([float(s["strain"])])
            frame.log["value/time"] = np.array([float(s["time"])])
            frame.log["value/shear_offset"] = np.array([offset])
            trajectory.append(frame)


def check_snapshot(s):
    """Raises ValueError naming what is wrong with a snapshot (dict of Run.snapshot) that an export would write."""
    import numpy as np
    where = f"snapshots/{s['index']:06d}"

    def numbers(name, shape, positive=False, integer=False):
        if name not in s:
            raise ValueError(f"{where}/{name} is missing")
        a = np.asarray(s[name])
        if a.dtype.kind not in ("iu" if integer else "fiu") or a.shape != shape:
            raise ValueError(f"{where}/{name}: expected {'integers' if integer else 'numbers'} of shape {shape}, "
                             f"found {a.dtype} of shape {a.shape}")
        if not np.isfinite(a).all() or (positive and not (a > 0).all()) or (integer and (a < 0).any()):
            raise ValueError(f"{where}/{name}: holds a non-finite, negative or zero value")
        return a

    n = len(np.atleast_1d(s.get("radius", [])))
    numbers("radius", (n,), positive=True)
    numbers("box", (3,), positive=True)
    numbers("shear_offset", ())
    for name in ("strain", "time"):
        numbers(name, ())
    numbers("step", (), integer=True)
    for name in ("position", "velocity", "angular_velocity"):
        numbers(name, (n, 3))
    species = numbers("species", (n,), integer=True)
    if "contact_pairs" in s:
        pairs = np.asarray(s["contact_pairs"])
        if pairs.size and (pairs.dtype.kind not in "iu" or pairs.ndim != 2 or pairs.shape[1] != 2
                           or pairs.min() < 0 or pairs.max() >= n):
            raise ValueError(f"{where}/contact_pairs: not pairs of particle indices below {n}")
    return species


def is_export(path, fmt):
    """Whether an existing file is an export of this format (so that exporting again may replace it)."""
    try:
        with open(path, "rb") as f:
            head = f.read(4096)
    except OSError:
        return False
    if fmt == "gsd":
        return head[:8] == bytes.fromhex("df65df65df65df65")  # GSD's magic number, little-endian
    lines = head.split(b"\n")
    return len(lines) > 2 and lines[0].strip().isdigit() and b"Lattice=" in lines[1]


def refuse_out(out, fmt, force):
    """Why `out` may not be written (None when it may): suspend.output_rules, an earlier export of `fmt` replaced."""
    from suspend.output_rules import refuse_file
    return refuse_file(out, lambda path: is_export(path, fmt), force, f"a {fmt} export")


def main(argv=None):
    import argparse
    import sys
    argv = sys.argv[1:] if argv is None else argv
    usage = "usage: suspend export RUN_DIR --format extxyz|gsd [--out FILE] [--force]"
    if not argv or argv[0] in ("-h", "--help"):
        print(usage, file=sys.stderr)
        return 2
    parser = argparse.ArgumentParser(prog="suspend export", usage=usage)
    parser.add_argument("run")
    parser.add_argument("--format", required=True, choices=["extxyz", "gsd"])
    parser.add_argument("--out")
    parser.add_argument("--force", action="store_true")
    args = parser.parse_args(argv)
    from suspend import load_run
    try:
        run = load_run(args.run)
        snapshots = run.snapshot_count
    except FileNotFoundError as e:
        print(f"error: export: {e}", file=sys.stderr)
        return 2
    except (OSError, KeyError, ValueError) as e:  # truncated HDF5, a checkpoint or foreign file as run.h5
        print(f"error: export: {args.run} is not a readable run ({str(e).splitlines()[0]})", file=sys.stderr)
        return 2
    if snapshots == 0:
        print(f"error: export: {run.path} has no snapshots", file=sys.stderr)
        return 2
    # Every snapshot checked before anything is written: a damaged one is named, not half-exported.
    try:
        for s in run.snapshots():
            species = check_snapshot(s)
            if args.format == "extxyz" and species.max(initial=0) >= len(SYMBOLS):
                raise ValueError(f"snapshots/{s['index']:06d} has {int(species.max()) + 1} species; extended XYZ "
                                 f"writes at most {len(SYMBOLS)} (as element symbols); use --format gsd")
    except (OSError, KeyError, ValueError, TypeError) as e:
        print(f"error: export: {run.path}: {str(e).splitlines()[0]}", file=sys.stderr)
        return 2
    out = args.out or os.path.join(os.path.dirname(run.path), "run." + ("xyz" if args.format == "extxyz" else "gsd"))
    refusal = refuse_out(out, args.format, args.force)
    if refusal:
        print(f"error: export: --out {out}: {refusal}", file=sys.stderr)
        return 2
    tmp = out + ".part"
    try:
        if args.format == "extxyz":
            write_extxyz(run, tmp)
        else:
            try:
                import gsd.hoomd  # noqa: F401
            except ImportError:
                print("error: export --format gsd needs python3-gsd (apt-get install python3-gsd)", file=sys.stderr)
                return 2
            write_gsd(run, tmp)
        os.replace(tmp, out)  # no half-written file under the final name
    except (OSError, KeyError, ValueError) as e:  # a snapshot damaged or missing part-way
        print(f"error: export: cannot write {out} from {run.path} ({str(e).splitlines()[0]})", file=sys.stderr)
        return 2
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    print(f"{out}: {run.snapshot_count} frames ({args.format})")
    return 0


if __name__ == "__main__":
    sys_path = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    import sys
    sys.path.insert(0, sys_path)
    sys.exit(main())
