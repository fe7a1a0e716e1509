#!/usr/bin/python3
"""tools/render_movie.py on a real run (cases/quickstart.yaml to strain 0.3, a snapshot every 0.1): the MP4 has a
frame per snapshot of run.h5 (counted by ffprobe), the still is a PNG of the frame size; without ffmpeg on PATH it
exits 2 with the line naming scripts/install-deps.sh --movie and writes nothing, as it does for a missing RUN_DIR.
Exits 77 (skipped) after those error checks when ffmpeg or ffprobe is not installed.
Usage: check_movie.py SUSPEND_BINARY SOURCE_DIR"""
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
from script_checks import check, failures, run_quickstart

suspend_bin, source = sys.argv[1], sys.argv[2]
tool = os.path.join(source, "tools/render_movie.py")
with tempfile.TemporaryDirectory() as work:
    run_dir = os.path.join(work, "run")
    run_quickstart(suspend_bin, source, run_dir, 0.3, 0.1)
    with h5py.File(os.path.join(run_dir, "run.h5"), "r") as f:
        snapshots = len(f["snapshots"])
    check(snapshots == 4, f"{snapshots} snapshots, expected 4 (strain 0 to 0.3)")

    # Without ffmpeg: a PATH holding only python3.
    bare, out = os.path.join(work, "bin"), os.path.join(work, "out")
    os.mkdir(bare)
    os.mkdir(out)
    os.symlink(sys.executable, os.path.join(bare, "python3"))
    cases = [([run_dir], {"PATH": bare}, "error: ffmpeg not found; install it with: bash scripts/install-deps.sh "
                                         "--movie\n"),
             ([os.path.join(work, "nowhere")], None, "no such directory"),
             ([out], None, "run.xdmf: no such file")]
    for args, env, expected in cases:
        r = subprocess.run([os.path.join(bare, "python3"), tool] + args + ["--out", os.path.join(out, "x.mp4")],
                           capture_output=True, text=True, env=env)
        check(r.returncode == 2 and expected in r.stderr and r.stderr.count("\n") == 1,
              f"{args} (env {env}): exit {r.returncode}, {r.stderr!r}")
        check(os.listdir(out) == [], f"{args}: wrote {os.listdir(out)}")

    if shutil.which("ffmpeg") is None or shutil.which("ffprobe") is None:
        # ffmpeg is optional (scripts/install-deps.sh --movie): ctest reports the movie part as skipped.
        print("movie: no ffmpeg/ffprobe on PATH, checked only the error exits")
        sys.exit(1 if failures else 77)

    movie = os.path.join(work, "run.mp4")
    r = subprocess.run([sys.executable, tool, run_dir, "--out", movie, "--fps", "8"], capture_output=True, text=True)
    check(r.returncode == 0, f"render_movie exit {r.returncode}: {r.stderr}")
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=nb_read_frames,width,height", "-of", "csv=p=0", movie],
                           capture_output=True, text=True)
    width, height, frames = (probe.stdout.strip().split(",") + ["?"] * 3)[:3]
    check(frames == str(snapshots), f"ffprobe: {probe.stdout.strip()!r} {probe.stderr.strip()}, "
                                    f"expected {snapshots} frames")
    still = os.path.join(work, "run.png")
    if os.path.isfile(still):
        with open(still, "rb") as f:
            png = f.read()
        # PNG signature, IHDR first (with the width and height, big-endian: the movie's frame size), IEND last.
        check(png[:8] == b"\x89PNG\r\n\x1a\n" and png[12:16] == b"IHDR" and png[-8:-4] == b"IEND",
              "the still is not a whole PNG")
        size = f"{int.from_bytes(png[16:20], 'big')},{int.from_bytes(png[20:24], 'big')}"
        check(size == f"{width},{height}", f"still {size}, movie frames {width},{height}")
    else:
        check(False, "no still PNG beside the movie")

if failures:
    sys.exit(1)
print(f"movie: {frames} frames for {snapshots} snapshots, a {width}x{height} still; without ffmpeg exit 2")
