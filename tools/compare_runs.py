#!/usr/bin/env python3
"""Compares two runs of the same case bit for bit: every numeric dataset of run.h5 (series and snapshots) and the
numbers of summary.json. Made to check that a refactor leaves results unchanged (old binary against new, same case,
same seed). Prints, per differing dataset, the largest relative difference; exit code 0 when every compared number
is identical, 1 otherwise.

usage: tools/compare_runs.py RUN_A RUN_B [--tolerance REL]   (REL: differences up to it count as equal)
"""
import json
import math
import os
import signal
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from debian_python import require  # noqa: E402

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")

SKIPPED_KEYS = {"wall_seconds", "timings", "case", "started", "finished", "version", "command", "threads"}


# Read through `| head`: a closed pipe ends the output quietly.
signal.signal(signal.SIGPIPE, signal.SIG_DFL)

h5py = np = None  # imported in main(), after the arguments are checked


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind in "fiub":
                out[name] = np.asarray(obj[()], dtype=float)
        f.visititems(visit)
    return out


def flatten(value, prefix, out):
    if isinstance(value, dict):
        for k, v in value.items():
            if k not in SKIPPED_KEYS:
                flatten(v, f"{prefix}.{k}" if prefix else k, out)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            flatten(v, f"{prefix}[{i}]", out)
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        out[prefix] = float(value)


def relative(a, b):
    scale = np.maximum(np.abs(a), np.abs(b))
    diff = np.abs(a - b)
    both_nan = np.isnan(a) & np.isnan(b)
    with np.errstate(invalid="ignore", divide="ignore"):
        r = np.where(scale > 0, diff / np.where(scale > 0, scale, 1), 0.0)
    r = np.where(both_nan, 0.0, r)
    return float(np.nanmax(r)) if r.size else 0.0


def usage_error(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def main():
    args = sys.argv[1:]
    if len(args) < 2 or "-h" in args or "--help" in args:
        usage_error(__doc__.strip().splitlines()[-1].strip())
    tol = 0.0
    if "--tolerance" in args:
        i = args.index("--tolerance")
        tol = float(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        usage_error(__doc__.strip().splitlines()[-1].strip())
    a, b = args
    for d in (a, b):
        if not os.path.isfile(os.path.join(d, "run.h5")):
            usage_error(f"error: {d}: no run.h5 (give two run folders)")
    require("h5py", "numpy")
    global h5py, np
    import h5py
    import numpy as np
    worst, differing = 0.0, []
    da, db = datasets(os.path.join(a, "run.h5")), datasets(os.path.join(b, "run.h5"))
    for name in sorted(set(da) | set(db)):
        if name not in da or name not in db:
            differing.append(f"{name}: only in {'A' if name in da else 'B'}")
            continue
        if da[name].shape != db[name].shape:
            differing.append(f"{name}: shapes {da[name].shape} and {db[name].shape}")
            worst = math.inf
            continue
        r = relative(da[name], db[name])
        worst = max(worst, r)
        if r > tol:
            differing.append(f"{name}: max relative difference {r:.3g}")
    sa, sb = {}, {}
    for d, s in ((a, sa), (b, sb)):
        p = os.path.join(d, "summary.json")
        if os.path.exists(p):
            with open(p) as f:
                flatten(json.load(f), "", s)
    for k in sorted(set(sa) & set(sb)):
        r = relative(np.array([sa[k]]), np.array([sb[k]]))
        worst = max(worst, r)
        if r > tol:
            differing.append(f"summary {k}: {sa[k]!r} and {sb[k]!r}")
    print(f"{len(da)} datasets, {len(sa)} summary numbers; largest relative difference {worst:.3g}")
    for line in differing:
        print("  " + line)
    sys.exit(0 if not differing else 1)


if __name__ == "__main__":
    main()
