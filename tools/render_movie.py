#!/usr/bin/python3
"""Renders every snapshot of a run into an MP4 (matplotlib's FFMpegWriter, so it needs ffmpeg), drawn as
tools/render_snapshot.py draws one: the spheres coloured by species, the contact network coloured by the contact
force magnitude on one colour scale for the whole movie, and the Lees-Edwards sheared cell, with the strain and the
relative viscosity eta_r (run.h5's series, the row nearest the snapshot) above each frame. Also writes the last
frame as a still PNG. Everything is read through run.xdmf's references, like render_snapshot.py.
Usage: tools/render_movie.py RUN_DIR --out FILE.mp4 [--still FRAME.png (default: FILE.png)] [--fps N (default 4)] [--force]
[--dpi N (default 110)]"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

from debian_python import require

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from suspend.output_rules import refuse_file, starts_with  # noqa: E402
from render_snapshot import collection, draw, read_snapshot


def eta_r_at(root, base):
    """eta_r(time) from the series of the HDF5 file the XDMF references, or None if there is none."""
    import h5py
    import numpy as np
    step = collection(root, "particles")[0]
    path = os.path.join(base, step.find("Geometry/DataItem").text.strip().split(":", 1)[0])
    with h5py.File(path, "r") as f:
        if "series/eta_r" not in f or "series/time" not in f:
            return None
        time, eta_r = np.asarray(f["series/time"]), np.asarray(f["series/eta_r"])
    # Matched on time, not strain: time grows monotonically under every flow, while an oscillatory strain returns to
    # the same values; under steady shear the two pick the same row.
    return lambda t: float(eta_r[np.argmin(np.abs(time - t))]) if len(time) else None


def temporary(path, suffix):
    """An empty file beside `path`, so os.replace onto it is atomic; the suffix tells ffmpeg and savefig the format."""
    fd, name = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(path)), prefix=".render_movie.", suffix=suffix)
    os.close(fd)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(name, 0o666 & ~umask)  # mkstemp makes it 0600; the result is an ordinary file
    return name


def mp4(path):
    """An earlier movie: an ISO media file ('ftyp' box first)."""
    try:
        with open(path, "rb") as f:
            return f.read(8)[4:8] == b"ftyp"
    except OSError:
        return False


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        # --help: the whole docstring; no arguments: its usage line
        print(__doc__ if len(sys.argv) > 1 else "Usage: " + " ".join(__doc__.split("Usage:")[1].split()),
              file=sys.stderr)
        sys.exit(2)
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", help="run directory (with run.xdmf and run.h5)")
    parser.add_argument("--out", required=True, help="MP4 to write")
    parser.add_argument("--still", help="PNG of the last frame (default: --out with .png)")
    parser.add_argument("--force", action="store_true", help="replace existing files that are not earlier renders")
    parser.add_argument("--fps", type=int, default=4, help="frames (snapshots) per second (default 4)")
    parser.add_argument("--dpi", type=int, default=110, help="pixels per inch of the 7 x 6 inch frame (default 110)")
    args = parser.parse_args()
    if args.fps < 1 or args.dpi < 10:
        parser.exit(2, "error: --fps must be at least 1 and --dpi at least 10\n")
    xdmf = os.path.join(args.run, "run.xdmf")
    if not os.path.isdir(args.run):
        parser.exit(2, f"error: {args.run}: no such directory\n")
    if not os.path.isfile(xdmf):
        parser.exit(2, f"error: {xdmf}: no such file (suspend run writes it at the end or at a stop)\n")
    still = args.still or os.path.splitext(args.out)[0] + ".png"
    for path, test, kind in ((args.out, mp4, "an MP4"), (still, starts_with(b"\x89PNG"), "a PNG")):
        refusal = refuse_file(path, test, args.force, kind)
        if refusal:
            parser.exit(2, f"error: {path}: {refusal}\n")
    if shutil.which("ffmpeg") is None:
        parser.exit(2, "error: ffmpeg not found; install it with: bash scripts/install-deps.sh --movie\n")
    require("h5py", "numpy", "matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.animation import FFMpegWriter

    base = os.path.dirname(os.path.abspath(xdmf))
    root = ET.parse(xdmf).getroot()
    count = len(collection(root, "particles"))
    if count == 0:
        parser.exit(2, f"error: {xdmf}: the run has no snapshots (see run.output.snapshot_every)\n")
    eta_r = eta_r_at(root, base)
    # One colour scale for the movie (a pass over the forces first), topped at the median over snapshots of the
    # largest force rather than the largest: the strain-0 snapshot can hold the unrelaxed start's forces (ten times
    # the sheared ones in the quickstart), which would wash out every other frame. Larger forces saturate; the colour
    # bar's arrow says so.
    tops = [float(np.max(s["force"])) for s in (read_snapshot(root, base, k) for k in range(count))
            if s["force"] is not None and len(s["force"])]
    top = float(np.median(tops)) if tops else 1.0
    norm = matplotlib.colors.Normalize(0.0, top)
    movie_tmp, still_tmp = temporary(args.out, ".mp4"), temporary(still, ".png")
    try:
        fig = plt.figure(figsize=(7, 6), dpi=args.dpi)
        writer = FFMpegWriter(fps=args.fps, metadata={"title": os.path.basename(os.path.abspath(args.run))})
        with writer.saving(fig, movie_tmp, args.dpi):
            for k in range(count):
                snap = read_snapshot(root, base, k)
                value = eta_r(snap["time"]) if eta_r and snap["time"] is not None else None
                contacts = 0 if snap["ends"] is None else len(snap["ends"])
                fig.clf()  # redraw from scratch: a 3-D scene has no cheap per-frame update
                draw(fig, snap, f"{os.path.basename(os.path.abspath(args.run))}: strain {snap['strain']:.3f}, "
                                f"eta_r {'n/a' if value is None else f'{value:.3g}'}, {contacts} contacts", norm)
                writer.grab_frame()
        fig.savefig(still_tmp, dpi=args.dpi)
        os.replace(movie_tmp, args.out)
        os.replace(still_tmp, still)
    except (subprocess.CalledProcessError, BrokenPipeError) as e:  # ffmpeg's own message is above, on stderr
        sys.exit(f"error: ffmpeg failed ({e.__class__.__name__}); nothing written")
    finally:
        for name in (movie_tmp, still_tmp):
            if os.path.exists(name):
                os.remove(name)
    print(f"{args.out}: {count} frames at {args.fps} fps, force scale 0 to {top:.4g} (eta_0 gammadot_ref a_1^2); "
          f"still {still}")


if __name__ == "__main__":
    main()
