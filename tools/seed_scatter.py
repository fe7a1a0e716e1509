#!/usr/bin/env python3
"""Seed-to-seed scatter of eta_r against the block error, per point of a campaign run with several packings.

Points whose parameters agree except run.seed form one point; for each with at least three flowing (`done`) seeds it
prints the mean eta_r, the seeds' sample standard deviation sd, the mean of their block-averaged standard errors
(sem, the error a single run states) and the ratio sd / sem. A ratio near 1 says one run's error bar is honest for the
packing-to-packing spread; above 1, one packing understates the error by that factor (issue 34, docs/campaigns.md).

usage: tools/seed_scatter.py CAMPAIGN_DIR_OR_campaign.json [...] [--json]
"""
import json
import math
import os
import statistics
import sys


def load_points(path):
    if os.path.isdir(path):
        path = os.path.join(path, "campaign.json")
    with open(path) as f:
        return json.load(f)["points"]


def seed_groups(points):
    groups = {}
    for p in points:
        parameters = dict(p.get("parameters") or {})
        parameters.pop("run.seed", None)
        groups.setdefault(tuple(sorted(parameters.items())), []).append(p)
    return groups


def scatter_rows(points):
    rows = []
    for key, members in sorted(seed_groups(points).items()):
        flowing = [p for p in members if p.get("status") == "done"
                   and (p.get("summary") or {}).get("eta_r", {}).get("mean") is not None]
        if len(flowing) < 3:
            continue
        eta = [p["summary"]["eta_r"]["mean"] for p in flowing]
        sem = [p["summary"]["eta_r"]["sem"] for p in flowing]
        sd = statistics.stdev(eta)
        mean_sem = sum(sem) / len(sem)
        rows.append({"point": ", ".join(f"{k}={v:g}" for k, v in key), "seeds": len(flowing),
                     "eta_r": statistics.fmean(eta), "sd": sd, "block_sem": mean_sem,
                     "ratio": sd / mean_sem if mean_sem > 0 else math.inf})
    return rows


def main(argv):
    as_json = "--json" in argv
    paths = [a for a in argv if a != "--json"]
    if not paths or any(a.startswith("-") for a in paths):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    points = []
    for path in paths:
        try:
            points += load_points(path)
        except (OSError, ValueError, KeyError) as error:
            print(f"seed_scatter: cannot read the campaign table {path}: {error}", file=sys.stderr)
            return 2
    rows = scatter_rows(points)
    if as_json:
        print(json.dumps(rows, indent=1))
        return 0
    if not rows:
        print("seed_scatter: no point has three or more flowing seeds")
        return 0
    print(f"{'point':58s} {'seeds':>5s} {'eta_r':>9s} {'sd':>8s} {'block sem':>9s} {'sd/sem':>7s}")
    for r in rows:
        print(f"{r['point']:58s} {r['seeds']:5d} {r['eta_r']:9.2f} {r['sd']:8.2f} {r['block_sem']:9.2f} "
              f"{r['ratio']:7.2f}")
    ratios = sorted(r["ratio"] for r in rows)
    print(f"sd / block sem over {len(rows)} points: {ratios[0]:.2f} - {ratios[-1]:.2f}, "
          f"median {statistics.median(ratios):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
