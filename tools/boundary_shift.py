#!/usr/bin/env python3
"""How far phi_m moves between two boundary searches of the same groups, against the packing-to-packing spread
(issue 36: the exact near field against the singular one, the (20 a_1)^3 box against the (16 a_1)^3 one, FCM against
the pairwise engine).

Each search (a campaign table of `suspend sweep` with a `search:` in phi, three seeds per value) gives per group
(mu_s, sigma*; sigma* = Sigma_12 / g_adh in the case's units, "no adhesion" without it):
- the majority bracket [phi_f, phi_j]: the densest value where most seeds flowed below the least dense where most
  jammed, as the search reads it;
- each seed's own bracket, from that seed's points alone: the densest phi it flowed at below the least dense it
  jammed at. The spread of the seeds' midpoints (their standard deviation) is the packing-to-packing spread of phi_m
  at this system size. Seeds that share one bracket resolve no spread below the search's grid: the spread is then
  given as at most the resolution, the seeds' median bracket width / sqrt(12), and that bound divides the shift. A
  seed that flows above a phi where it jammed is counted and named.
The shift is B's majority-bracket middle minus A's, with the error of two brackets read as uniform over their widths,
sqrt((w_A^2 + w_B^2) / 12), and in units of the larger seed spread. Groups only one table holds are listed as such.

Either side may be several tables (one search split over files, e.g. the singular pairwise boundaries of
pairwise_boundary and pairwise_boundary_low_friction*): their points are pooled.

usage: tools/boundary_shift.py A_TABLE_OR_DIR... --against B_TABLE_OR_DIR... [--json]
"""
import json
import math
import os
import statistics
import sys

USAGE = __doc__.strip().splitlines()[-1]


def fail(message):
    print("error: " + message, file=sys.stderr)
    print(USAGE, file=sys.stderr)
    sys.exit(2)


def load_points(path):
    table = os.path.join(path, "campaign.json") if os.path.isdir(path) else path
    try:
        with open(table) as f:
            return json.load(f)["points"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        fail("%s: not a campaign table (%s)" % (table, e))


def group_of(p):
    c = p["case"]
    sigma = c["shear_stress"] / c["g_adh"] if c.get("g_adh") and c.get("shear_stress") is not None else None
    return (c["mu_s"], sigma)


def bracket(flowed, jammed):
    """[densest flowing phi below the least dense jammed phi, that jammed phi], or None when a side is missing; and
    whether some flowing phi lies above a jammed one."""
    if not flowed or not jammed:
        return None, False
    hi = min(jammed)
    below = [x for x in flowed if x < hi]
    if not below:
        return None, True
    return (max(below), hi), max(flowed) > hi


def boundaries(points):
    """{group: {"bracket": (lo, hi), "seeds": [midpoints], "reentrant": [seed, ...]}} of a table's finished points."""
    by_group = {}
    for p in points:
        if p.get("status") not in ("done", "jammed"):
            continue
        seed = int((p.get("parameters") or {}).get("run.seed", 1))
        phi = p["case"]["phi"]
        g = by_group.setdefault(group_of(p), {})
        g.setdefault(phi, {}).setdefault(seed, p["status"] == "done")
    out = {}
    for group, values in by_group.items():
        majority_flowed = [phi for phi, s in values.items() if 2 * sum(s.values()) > len(s)]
        majority_jammed = [phi for phi, s in values.items() if 2 * sum(s.values()) <= len(s)]
        b, _ = bracket(majority_flowed, majority_jammed)
        seeds = sorted({seed for s in values.values() for seed in s})
        mids, widths, reentrant = [], [], []
        for seed in seeds:
            f = [phi for phi, s in values.items() if s.get(seed) is True]
            j = [phi for phi, s in values.items() if s.get(seed) is False]
            sb, back = bracket(f, j)
            if back:
                reentrant.append(seed)
            if sb:
                mids.append(0.5 * (sb[0] + sb[1]))
                widths.append(sb[1] - sb[0])
        resolution = statistics.median(widths) / math.sqrt(12.0) if widths else None
        out[group] = {"bracket": b, "seeds": mids, "resolution": resolution, "reentrant": reentrant}
    return out


def spread(r):
    """(the seeds' spread of phi_m, whether it is only the resolution bound) of one group, or (None, False)."""
    if len(r["seeds"]) < 2:
        return None, False
    s = statistics.stdev(r["seeds"])
    if r["resolution"] is not None and s < r["resolution"]:
        return r["resolution"], True
    return s, False


def compare(a, b):
    rows = []
    for group in sorted(set(a) | set(b), key=lambda g: (g[0], -(g[1] if g[1] is not None else math.inf))):
        ra, rb = a.get(group), b.get(group)
        row = {"mu_s": group[0], "sigma_star": group[1], "a": ra, "b": rb, "shift": None, "error": None,
               "in_spreads": None}
        if ra and rb and ra["bracket"] and rb["bracket"]:
            (a0, a1), (b0, b1) = ra["bracket"], rb["bracket"]
            row["shift"] = 0.5 * (b0 + b1) - 0.5 * (a0 + a1)
            row["error"] = math.sqrt(((a1 - a0) ** 2 + (b1 - b0) ** 2) / 12.0)
            spreads = [s for s, _ in (spread(ra), spread(rb)) if s]
            if spreads and max(spreads) > 0:
                row["in_spreads"] = row["shift"] / max(spreads)
        rows.append(row)
    return rows


def text(rows, name_a, name_b):
    def side(r):
        if not r or not r["bracket"]:
            return "-"
        s, bound = spread(r)
        out = "[%g, %g]" % r["bracket"]
        if s is None:
            out += " (%d seed)" % len(r["seeds"])
        else:
            out += " spread %s%.4f (%d seeds)" % ("<=" if bound else "", s, len(r["seeds"]))
        if r["reentrant"]:
            out += " re-entrant seed(s) %s" % ",".join(map(str, r["reentrant"]))
        return out

    lines = ["A: %s" % name_a, "B: %s" % name_b,
             "%-5s %-12s %-45s %-45s %s" % ("mu_s", "sigma*", "A bracket, seed spread", "B bracket, seed spread",
                                            "shift B - A (in seed spreads)")]
    for r in rows:
        sigma = "no adhesion" if r["sigma_star"] is None else "%g" % r["sigma_star"]
        shift = "-" if r["shift"] is None else "%+.4f +- %.4f" % (r["shift"], r["error"])
        if r["in_spreads"] is not None:
            shift += " (%+.1f)" % r["in_spreads"]
        lines.append("%-5g %-12s %-45s %-45s %s" % (r["mu_s"], sigma, side(r["a"]), side(r["b"]), shift))
    return "\n".join(lines) + "\n"


def main(argv):
    args = [a for a in argv if a != "--json"]
    if args.count("--against") != 1:
        fail("give the tables of A, --against, then those of B")
    k = args.index("--against")
    a, b = args[:k], args[k + 1:]
    if not a or not b or any(x.startswith("-") for x in a + b):
        fail("give the tables of A, --against, then those of B")
    rows = compare(boundaries([p for x in a for p in load_points(x)]), boundaries([p for x in b for p in load_points(x)]))
    if "--json" in argv:
        print(json.dumps(rows, indent=1))
    else:
        sys.stdout.write(text(rows, " ".join(a), " ".join(b)))


if __name__ == "__main__":
    main(sys.argv[1:])
