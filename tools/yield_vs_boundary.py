#!/usr/bin/env python3
"""The yield stress measured by creep against the phi_m(sigma*) boundary (issue 36, item 7: the boundary read the
other way is sigma_Y(phi); do the two measurements agree?).

From the creep campaign (a search in flow.shear_stress at fixed phi, `flows: above`): per (mu_s, phi) the largest
sigma* at which a majority of seeds arrested, s_a, and the smallest at which a majority flowed, s_f. From the
boundary searches (`suspend phim` tables of the same model and near field): per (mu_s, sigma*) the bracket
[phi_f, phi_j] between the densest phi that flowed and the least dense that jammed; phi_f and phi_j are interpolated
linearly in log sigma* between the searched stresses (not extrapolated). The two agree at phi when
phi_f(s_a) <= phi (arrested where the boundary says a denser sample could flow, so phi is at or above its flowing
side) and phi <= phi_j(s_f) (flowing at s_f where the boundary jams only denser samples).

usage: tools/yield_vs_boundary.py CREEP_TABLE_OR_DIR BOUNDARY_PHIM_OR_DIR [...] [--json]
"""
import json
import math
import os
import sys

USAGE = __doc__.strip().splitlines()[-1]


def fail(message):
    print("error: " + message, file=sys.stderr)
    print(USAGE, file=sys.stderr)
    sys.exit(2)


def load_json(path, name):
    if os.path.isdir(path):
        path = os.path.join(path, name)
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail("%s: %s" % (path, e))


def yield_brackets(points):
    """{(mu_s, phi): (s_a, s_f)} from the creep campaign's finished points."""
    tallies = {}
    for p in points:
        if p.get("status") not in ("done", "jammed"):
            continue
        c = p.get("case") or {}
        if not c.get("g_adh") or c.get("shear_stress") is None:
            continue
        sigma = c["shear_stress"] / c["g_adh"]
        t = tallies.setdefault((c["mu_s"], c["phi"]), {}).setdefault(sigma, [0, 0])
        t[0 if p["status"] == "jammed" else 1] += 1
    out = {}
    for key, levels in tallies.items():
        arrested = [s for s, (j, f) in levels.items() if j > f]
        flowed = [s for s, (j, f) in levels.items() if f > j]
        out[key] = (max(arrested) if arrested else None, min(flowed) if flowed else None)
    return out


def boundary_brackets(fits):
    """{mu_s: sorted [(sigma*, phi_f, phi_j)]} of the bracketed adhesive groups."""
    out = {}
    for g in fits:
        b = g.get("bracket")
        if g.get("sigma_star") is None or not b or b[1] - b[0] > 0.05:
            continue
        out.setdefault(g["mu_s"], []).append((float(g["sigma_star"]), b[0], b[1]))
    return {mu: sorted(v) for mu, v in out.items()}


def interpolate(rows, sigma, column):
    """Linear in log sigma* between the searched stresses; None outside them."""
    if sigma is None or not rows or not rows[0][0] <= sigma <= rows[-1][0]:
        return None
    for (s0, *v0), (s1, *v1) in zip(rows, rows[1:]):
        if s0 <= sigma <= s1:
            w = 0.0 if s1 == s0 else (math.log(sigma) - math.log(s0)) / (math.log(s1) - math.log(s0))
            return (1 - w) * v0[column] + w * v1[column]
    return rows[0][1 + column] if sigma == rows[0][0] else None


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    as_json = "--json" in argv
    args = [a for a in argv if a != "--json"]
    for a in args:
        if a.startswith("--"):
            fail("unknown option " + a)
        if not os.path.exists(a):
            fail(a + " does not exist")
    if len(args) < 2:
        fail("give the creep campaign and at least one boundary table")
    creep = yield_brackets(load_json(args[0], "campaign.json").get("points", []))
    boundary = {}
    for path in args[1:]:
        for mu, rows in boundary_brackets(load_json(path, "phim.json").get("fits", [])).items():
            boundary.setdefault(mu, []).extend(rows)
    boundary = {mu: sorted(rows) for mu, rows in boundary.items()}
    rows = []
    for (mu, phi), (s_a, s_f) in sorted(creep.items()):
        b = boundary.get(mu, [])
        lo = interpolate(b, s_a, 0)
        hi = interpolate(b, s_f, 1)
        agree = None if lo is None or hi is None else lo <= phi + 1e-12 and phi <= hi + 1e-12
        rows.append({"mu_s": mu, "phi": phi, "arrested_at": s_a, "flowed_at": s_f, "boundary_phi_flowing_at_s_a": lo,
                     "boundary_phi_jammed_at_s_f": hi, "agree": agree})
    if as_json:
        print(json.dumps(rows, indent=1))
        return
    print("%-5s %6s %22s %24s %s" % ("mu_s", "phi", "sigma_Y in (s_a, s_f)", "boundary phi_f(s_a), phi_j(s_f)",
                                     "agree"))
    for r in rows:
        sy = "(%s, %s)" % tuple("-" if v is None else "%g" % v for v in (r["arrested_at"], r["flowed_at"]))
        bd = "%s, %s" % tuple("-" if v is None else "%.4f" % v for v in (r["boundary_phi_flowing_at_s_a"],
                                                                         r["boundary_phi_jammed_at_s_f"]))
        print("%-5g %6g %22s %24s %s" % (r["mu_s"], r["phi"], sy, bd,
                                         "-" if r["agree"] is None else ("yes" if r["agree"] else "NO")))


if __name__ == "__main__":
    main(sys.argv[1:])
