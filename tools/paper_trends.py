#!/usr/bin/env python3
"""The contact-stress trends of paper 004 (section III D-E), from the phi_m campaign tables of both methods: for one
friction coefficient, each volume fraction's points at every reduced stress sigma* side by side, with the contact
share of the shear stress Sigma^c_12/Sigma_12 (Fig. 19: it rises as sigma* falls), the reduced second contact normal
stress -Sigma^c_22/Sigma_12 (Fig. 17: adhesion hardly changes it at fixed phi), and the macroscopic friction
mu = -Sigma_12/Sigma^c_22 with the viscous number J (Fig. 22: at fixed J, mu rises as sigma* falls; at high phi mu is
mostly a function of phi). Then, per phi with at least two stresses, the spread of each quantity over sigma*
(largest minus smallest, and that difference in combined standard errors). Last, Fig. 19 [bottom]: each adhesive
point's Sigma^c_12/Sigma_12 against the non-adhesive points' (the master curve, linear between them) at the same
phi/phi_m, with phi_m the one Fig. 15 draws for the group (tools/phim_figures.py: the fit, or the bracket's middle
where a jammed point lies below it). Flowing (`done`) points only; phi is rounded to 0.01 to line up points of one
phi.

usage: tools/paper_trends.py RESULTS_DIR [--mu-s MU] [--markdown]
  RESULTS_DIR  holds pairwise/ and/or fcm/, each with campaign.csv (results/phim)
  --mu-s MU    friction coefficient of the groups shown (default 0.5, the paper's Figs. 17, 19, 22)
"""
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_methods import interpolate  # noqa: E402  (linear between neighbouring points, errors carried)
from phim_figures import drawn_phi_m, sigma_of  # noqa: E402  (the phi_m that Fig. 15 draws)

METHODS = ("pairwise", "fcm")
QUANTITIES = (("Sigma_c12/Sigma_12", "S_c12/S_12", 1.0), ("Sigma_c22/Sigma_12", "-S_c22/S_12", -1.0), ("mu", "mu", 1.0))


def usage(message):
    sys.stderr.write(f"error: {message}\n" if message else "")
    sys.stderr.write("usage: tools/paper_trends.py RESULTS_DIR [--mu-s MU] [--markdown]\n")
    sys.exit(2)


def parse(argv):
    if not argv or argv[0] in ("-h", "--help"):
        sys.stderr.write(__doc__.strip() + "\n")
        sys.exit(2)
    args = {"dir": None, "mu_s": 0.5, "markdown": False}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--markdown":
            args["markdown"] = True
        elif a == "--mu-s":
            if i + 1 == len(argv):
                usage("--mu-s needs a value")
            try:
                args["mu_s"] = float(argv[i + 1])
            except ValueError:
                usage(f"--mu-s: '{argv[i + 1]}' is not a number")
            i += 1
        elif a.startswith("-"):
            usage(f"unknown option '{a}' (allowed: --mu-s MU, --markdown)")
        elif args["dir"] is None:
            args["dir"] = a
        else:
            usage(f"one RESULTS_DIR expected, got also '{a}'")
        i += 1
    if args["dir"] is None:
        usage("RESULTS_DIR missing")
    if not os.path.isdir(args["dir"]):
        usage(f"RESULTS_DIR '{args['dir']}' is not a directory")
    return args


def sigma_label(row):
    """sigma* of a point: the imposed stress, or inf for the non-adhesive limit (g_adh = 0), as `suspend phim`."""
    g_adh = row.get("g_adh") or row.get("contact.g_adh") or ""
    if g_adh != "" and float(g_adh) == 0.0:
        return math.inf
    return float(row["sigma_star"])


def load(path, mu_s):
    """{phi (0.01): {sigma*: {quantity: (mean, sem)}, "J": (mean, sem)}} of the flowing points at mu_s."""
    table = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] != "done" or abs(float(row["mu_s"]) - mu_s) > 1e-9:
                continue
            values = {q: (float(row[q]), float(row[q + "_sem"] or "nan")) for q, _, _ in QUANTITIES}
            values["J"] = (float(row["J"]), float(row["J_sem"] or "nan"))
            table.setdefault(round(float(row["phi"]), 2), {})[sigma_label(row)] = values
    return table


def master_curve(path, table, mu_s):
    """Fig. 19 [bottom]: (phi, sigma*, phi/phi_m, adhesive ratio, master-curve ratio, difference in errors) of every
    adhesive point whose phi/phi_m lies within the non-adhesive points' range; phim.json next to the table."""
    fits_file = os.path.join(os.path.dirname(path), "phim.json")
    if not os.path.isfile(fits_file):
        return []
    with open(fits_file) as f:
        fits = json.load(f)["fits"]
    phi_m = {}
    for fit in fits:
        drawn = drawn_phi_m(fit)
        if abs(fit["mu_s"] - mu_s) < 1e-9 and drawn:
            phi_m[sigma_of(fit)] = drawn[0]
    if math.inf not in phi_m:
        return []
    q = "Sigma_c12/Sigma_12"
    curve = sorted((phi / phi_m[math.inf], {q: v[math.inf][q]}) for phi, v in table.items() if math.inf in v)
    rows = []
    for phi in sorted(table):
        for s, v in sorted(table[phi].items()):
            if math.isinf(s) or s not in phi_m:
                continue
            x = phi / phi_m[s]
            on_curve = interpolate(curve, x, q)
            if on_curve:
                m, e = on_curve
                rows.append((phi, s, x, v[q], (m, e), (v[q][0] - m) / math.hypot(v[q][1], e)))
    return rows


def fmt(v, sign=1.0):
    m, e = v
    return f"{sign * m:.3g} +- {e:.2g}" if math.isfinite(e) else f"{sign * m:.3g}"


def label(s):
    return "no adhesion" if math.isinf(s) else f"{s:g}"


def main(argv):
    args = parse(argv)
    found = False
    for method in METHODS:
        path = os.path.join(args["dir"], method, "campaign.csv")
        if not os.path.isfile(path):
            continue
        found = True
        table = load(path, args["mu_s"])
        print(f"\n{method}, mu_s = {args['mu_s']:g}: per phi and sigma*, " +
              ", ".join(name for _, name, _ in QUANTITIES) + ", J")
        if args["markdown"]:
            print("\n| phi | sigma* | " + " | ".join(name for _, name, _ in QUANTITIES) + " | J |")
            print("|---" * (len(QUANTITIES) + 3) + "|")
        for phi in sorted(table):
            for s in sorted(table[phi]):
                v = table[phi][s]
                cells = [fmt(v[q], sign) for q, _, sign in QUANTITIES] + [f"{v['J'][0]:.3g}"]
                if args["markdown"]:
                    print(f"| {phi:.2f} | {label(s)} | " + " | ".join(cells) + " |")
                else:
                    print(f"  phi {phi:.2f}  sigma* {label(s):>11}  " + "  ".join(f"{c:>16}" for c in cells))
        print(f"\n{method}, mu_s = {args['mu_s']:g}: spread over sigma* at fixed phi (max - min, in combined errors)")
        for phi in sorted(table):
            if len(table[phi]) < 2:
                continue
            parts = []
            for q, name, sign in QUANTITIES:
                vals = [(sign * v[q][0], v[q][1]) for v in table[phi].values()]
                hi, lo = max(vals), min(vals)
                err = math.hypot(hi[1], lo[1])
                parts.append(f"{name} {lo[0]:.3g}-{hi[0]:.3g} ({(hi[0] - lo[0]) / err:.1f})")
            stresses = ", ".join(label(s) for s in sorted(table[phi]))
            print(f"  phi {phi:.2f} (sigma* {stresses}): " + "; ".join(parts))
        rows = master_curve(path, table, args["mu_s"])
        if rows:
            print(f"\n{method}, mu_s = {args['mu_s']:g}: Sigma^c_12/Sigma_12 of the adhesive points against the "
                  "non-adhesive master curve at the same phi/phi_m (Fig. 19 [bottom])")
            for phi, s, x, own, curve, z in rows:
                print(f"  phi {phi:.2f}  sigma* {label(s):>4}  phi/phi_m {x:.3f}  {fmt(own):>16}  master "
                      f"{fmt(curve):>16}  difference {own[0] - curve[0]:+.3f} ({z:+.1f} errors)")
    if not found:
        usage(f"no pairwise/campaign.csv or fcm/campaign.csv under '{args['dir']}'")


if __name__ == "__main__":
    main(sys.argv[1:])
