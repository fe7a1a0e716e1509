#!/usr/bin/env python3
"""Shear banding in the flowing points of a campaign (issue 36, item 5: is the homogeneous assumption still true at
low sigma*?), from the gradient profiles `suspend analyze` gives for each snapshot of a point's averaging window.

For each snapshot, the local shear rates between neighbouring slabs across y (GradientProfile::local_rate) are
divided by the cell's least-squares rate; a band is a part of the cell that barely shears while the rest carries
the flow, so the smallest of these ratios drops towards 0 (homogeneous shear keeps it near 1, within the noise of
slab means over ~40 spheres). Per point: the median over the window's snapshots of that smallest ratio, the median
phi contrast across the slabs (max - min over the mean), and a flag when the median ratio is below --threshold
(default 0.25: a quarter of the cell's rate). A drifting band still shows in each snapshot, where a time average of
the profile would blur it.

--keep FILE takes the rows of an earlier table (this tool's text output, e.g. the committed banding.txt) for the points
whose snapshots this folder no longer holds: a campaign folder rebuilt from its table on a new machine
(tools/restore_campaign.py) has the points' records but not their runs, and its banding must not be lost with them.

usage: tools/banding_check.py CAMPAIGN_RUN_DIR [--suspend BIN] [--bins N] [--threshold R] [--keep FILE] [--json]
"""
import json
import math
import os
import statistics
import subprocess
import sys

USAGE = __doc__.strip().splitlines()[-1]


def fail(message):
    print("error: " + message, file=sys.stderr)
    print(USAGE, file=sys.stderr)
    sys.exit(2)


def analyze(suspend, point, bins):
    run = subprocess.run([suspend, "analyze", point, "--snapshot", "all", "--json", "--no-distributions", "--bins",
                          str(bins)], capture_output=True, text=True)
    if run.returncode != 0:
        return None
    return json.loads(run.stdout)


def band_measures(snapshots, start):
    """Per snapshot at strain >= start (`suspend analyze --json` objects): the smallest local shear rate across y over
    the cell's least-squares rate, and the phi contrast across the slabs."""
    ratios, contrasts = [], []
    for s in snapshots:
        if s.get("strain", 0.0) < start - 1e-9:
            continue
        g = s["gradient_profile"]
        rate = g.get("shear_rate")
        local = [r for r in g.get("local_rate") or [] if r is not None and math.isfinite(r)]
        if not rate or not math.isfinite(rate) or rate <= 0 or not local:
            continue
        ratios.append(min(local) / rate)
        phi = g["phi"]
        contrasts.append((max(phi) - min(phi)) / statistics.mean(phi))
    return ratios, contrasts


def point_row(suspend, point, bins, threshold):
    with open(os.path.join(point, "summary.json")) as f:
        summary = json.load(f)
    if summary.get("status") != "done":
        return None
    window = summary.get("window") or {}
    start = window.get("from_strain", 0.0)
    snapshots = analyze(suspend, point, bins)
    if not snapshots:
        return None
    ratios, contrasts = band_measures(snapshots, start)
    if not ratios:
        return None
    r = statistics.median(ratios)
    return {"point": os.path.basename(point), "snapshots": len(ratios), "min_rate_ratio": r,
            "phi_contrast": statistics.median(contrasts), "banded": r < threshold}


def kept_rows(path, threshold):
    """The point rows of an earlier text table (missing file: none)."""
    rows = {}
    try:
        lines = open(path).read().splitlines()
    except OSError:
        return rows
    for line in lines[1:]:
        f = line.split()
        if len(f) < 4 or not f[1].isdigit():
            continue
        try:
            r = float(f[2])
            rows[f[0]] = {"point": f[0], "snapshots": int(f[1]), "min_rate_ratio": r, "phi_contrast": float(f[3]),
                          "banded": r < threshold}
        except ValueError:
            continue
    return rows


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    folder, suspend, bins, threshold, as_json, keep = None, None, 8, 0.25, False, None
    it = iter(argv)
    for a in it:
        try:
            if a == "--suspend":
                suspend = next(it)
            elif a == "--bins":
                bins = int(next(it))
            elif a == "--threshold":
                threshold = float(next(it))
            elif a == "--keep":
                keep = next(it)
            elif a == "--json":
                as_json = True
            elif a.startswith("--"):
                fail("unknown option " + a)
            else:
                folder = a
        except (StopIteration, ValueError):
            fail(a + " takes a value")
    if folder is None or not os.path.isdir(os.path.join(folder, "points")):
        fail("%s is not a campaign run folder (no points/)" % folder)
    if suspend is None:
        suspend = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "bin", "suspend")
    if not os.access(suspend, os.X_OK):
        fail(suspend + " is not an executable; give --suspend BIN")
    points = sorted(os.path.join(folder, "points", p) for p in os.listdir(os.path.join(folder, "points")))
    rows = [r for r in (point_row(suspend, p, bins, threshold) for p in points
                        if os.path.isfile(os.path.join(p, "summary.json"))) if r]
    if keep:
        have = {r["point"] for r in rows}
        rows += [r for name, r in kept_rows(keep, threshold).items() if name not in have]
        rows.sort(key=lambda r: r["point"])
    if as_json:
        print(json.dumps(rows, indent=1))
        return
    print("%-55s %9s %15s %12s %s" % ("point (flowing)", "snapshots", "min rate ratio", "phi contrast", ""))
    for r in rows:
        print("%-55s %9d %15.3f %12.3f %s" % (r["point"], r["snapshots"], r["min_rate_ratio"], r["phi_contrast"],
                                             "BANDED" if r["banded"] else ""))
    banded = sum(r["banded"] for r in rows)
    print("%d of %d flowing point(s) banded (median smallest local rate below %g of the cell's)"
          % (banded, len(rows), threshold))


if __name__ == "__main__":
    main(sys.argv[1:])
