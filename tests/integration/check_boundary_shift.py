#!/usr/bin/env python3
"""tools/boundary_shift.py on drawn searches: the majority bracket, each seed's own bracket and the spread of their
midpoints, the shift of one search against another with the error of two uniform brackets, the spread bounded by
the grid's resolution where the seeds agree, and a seed that flows above a phi where it jammed named.
usage: check_boundary_shift.py SOURCE_DIR"""
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.join(sys.argv[1], "tools"))
from boundary_shift import boundaries, compare, spread  # noqa: E402


def point(phi, seed, flowed, shift=0.0, mu=0.5, stress=1.0):
    return {"status": "done" if flowed else "jammed", "parameters": {"run.seed": float(seed)},
            "case": {"phi": round(phi + shift, 6), "mu_s": mu, "g_adh": 1.0, "shear_stress": stress}}


def search(shift):
    # every seed flows at 0.40 and 0.46 and jams at 0.52 and 0.505; at 0.49 seeds 1 and 3 flow, seed 2 jams
    out = []
    for phi, flows in ((0.40, (1, 1, 1)), (0.46, (1, 1, 1)), (0.49, (1, 0, 1)), (0.505, (0, 0, 0)), (0.52, (0, 0, 0))):
        out += [point(phi, seed + 1, f, shift) for seed, f in enumerate(flows)]
    return out


failures = []
a = boundaries(search(0.0))[(0.5, 1.0)]
if a["bracket"] != (0.49, 0.505):
    failures.append("majority bracket %s, expected (0.49, 0.505)" % (a["bracket"],))
if sorted(a["seeds"]) != sorted([0.4975, 0.475, 0.4975]):
    failures.append("seed midpoints %s, expected 0.4975, 0.475, 0.4975" % a["seeds"])
s, bound = spread(a)
if bound or abs(s - statistics.stdev([0.4975, 0.475, 0.4975])) > 1e-12:
    failures.append("seed spread %s (bound %s), expected the stdev 0.0130" % (s, bound))
rows = compare(boundaries(search(0.0)), boundaries(search(0.01)))
r = rows[0]
if abs(r["shift"] - 0.01) > 1e-9 or abs(r["error"] - math.sqrt(2 * 0.015 ** 2 / 12)) > 1e-12:
    failures.append("shift %s +- %s, expected 0.01 +- %g" % (r["shift"], r["error"], math.sqrt(2 * 0.015 ** 2 / 12)))
if abs(r["in_spreads"] - 0.01 / s) > 1e-9:
    failures.append("shift in seed spreads %s, expected %g" % (r["in_spreads"], 0.01 / s))
# seeds that agree: the spread is only bounded, by the bracket width over sqrt(12)
agree = [point(phi, seed, phi < 0.5, mu=1.0) for phi in (0.45, 0.49, 0.51) for seed in (1, 2, 3)]
s, bound = spread(boundaries(agree)[(1.0, 1.0)])
if not bound or abs(s - 0.02 / math.sqrt(12)) > 1e-12:
    failures.append("agreeing seeds: spread %s (bound %s), expected <= %g" % (s, bound, 0.02 / math.sqrt(12)))
# seed 2 flows at 0.53 after jamming at 0.51: named, its bracket still the one below its first jam
reentrant = agree + [point(0.53, 2, True, mu=1.0), point(0.53, 1, False, mu=1.0), point(0.53, 3, False, mu=1.0)]
b = boundaries(reentrant)[(1.0, 1.0)]
if b["reentrant"] != [2] or b["bracket"] != (0.49, 0.51):
    failures.append("re-entrant seed: %s, bracket %s" % (b["reentrant"], b["bracket"]))
# a group one search lacks has no shift; no adhesion is its own group
only = compare(boundaries(search(0.0)), boundaries([point(0.5, 1, True, stress=10.0) | {"case": {
    "phi": 0.5, "mu_s": 0.5, "g_adh": 0.0, "shear_stress": 10.0}}]))
if len(only) != 2 or any(x["shift"] is not None for x in only) or only[0]["sigma_star"] is not None:
    failures.append("groups held by one search: %s" % only)
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("boundary shift: brackets, seed spread 0.013, shift 0.01 +- 0.0087, resolution bound, re-entrant seed named")
