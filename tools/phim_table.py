#!/usr/bin/env python3
"""The phi_m(sigma*) table of a campaign's phim.json as Markdown, for results/README.md: one row per group with the
result `suspend phim` chose (the Maron-Pierce fit with its total error, or the bracket with its seeds), so the page,
the figures (tools/phim_figures.py) and phim.json state every phi_m and bracket once, from one source.
With --check README, verifies that each table between `<!-- phim table: DIR -->` and `<!-- end phim table -->` in
README is the one DIR/phim.json gives now (exit 1 naming the first difference), so a page that drifts from its data
fails the tests.

usage: tools/phim_table.py PHIM_DIR | tools/phim_table.py --check README.md"""
import json
import math
import os
import re
import sys


def usage(message=None):
    if message:
        print("error: " + message, file=sys.stderr)
    print(__doc__.strip().splitlines()[-1].strip(), file=sys.stderr)
    sys.exit(2)


def number(x, digits=4):
    return "-" if x is None else f"{x:.{digits}f}"


def sigma_text(s):
    return "no adhesion" if s is None else f"{s:g}"


def table(phim_dir):
    path = os.path.join(phim_dir, "phim.json")
    try:
        with open(path) as f:
            fits = json.load(f)["fits"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        usage(f"{path}: not a phim.json of suspend phim ({e})")
    rows = ["| model | mu_s | sigma* | phi_m (result) | bracket (flowed/seeds) | Maron-Pierce fit, total error | "
            "chi^2/dof | points |", "|---|---|---|---|---|---|---|---|"]
    order = sorted(fits, key=lambda f: (f["model"], -f["mu_s"], -(f["sigma_star"] or math.inf)))
    for f in order:
        b = f.get("bracket")
        bracket = "-"
        if b:
            n, q = f["bracket_seeds"], f["bracket_flowing_fraction"]
            bracket = f"({b[0]:g}, {b[1]:g}) ({round(q[0] * n[0])}/{n[0]}, {round(q[1] * n[1])}/{n[1]})"
        fit = "-"
        if f.get("phi_m") is not None:
            fit = f"{number(f['phi_m'])} +- {number(f.get('phi_m_err_total', f['phi_m_err']))}"
        result = f.get("result")
        phi_m = {"fit": fit, "bracket": f"in {bracket.split(' (')[0]}" if b else "-"}.get(result, "-")
        chi = "-" if f.get("chi2_reduced") is None else f"{f['chi2_reduced']:.3g}"
        rows.append(f"| {f['model']} | {f['mu_s']:g} | {sigma_text(f['sigma_star'])} | {phi_m} | {bracket} | {fit} | "
                    f"{chi} | {f['points']} |")
    return "\n".join(rows) + "\n"


def check(readme):
    try:
        text = open(readme).read()
    except OSError as e:
        usage(f"{readme}: {e}")
    base = os.path.dirname(os.path.abspath(readme))
    blocks = re.findall(r"<!-- phim table: (\S+) -->\n(.*?)<!-- end phim table -->", text, re.S)
    if not blocks:
        usage(f"{readme}: no '<!-- phim table: DIR -->' block")
    for folder, written in blocks:
        now = table(os.path.join(base, folder))
        if written != now:
            for k, (a, b) in enumerate(zip(written.splitlines() + [""] * 99, now.splitlines())):
                if a != b:
                    print(f"{readme}: the table of {folder} differs from its phim.json at row {k + 1}:\n  page: {a}\n"
                          f"  data: {b}\n(regenerate it with tools/phim_table.py {folder})")
                    return 1
    print(f"{readme}: {len(blocks)} phi_m table(s) agree with their phim.json")
    return 0


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        usage()
    if argv[1] == "--check":
        if len(argv) != 3:
            usage("--check needs the README")
        return check(argv[2])
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        usage(f"'{argv[1]}' is not a folder with phim.json")
    sys.stdout.write(table(argv[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
