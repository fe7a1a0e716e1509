#!/usr/bin/env python3
"""The phi_m(sigma*) table of a campaign's phim.json as Markdown, for results/README.md: one row per group with the
result `suspend phim` chose (the Maron-Pierce fit with its total error, or the bracket with its seeds), so the page,
the figures (tools/phim_figures.py) and phim.json state every phi_m and bracket once, from one source.

With --summary, Fig. 15 as one table over several campaigns: a row per friction and sigma*, a column per method (the
model, the near-field functions and the box of the campaign's points, from the case blocks of its campaign.json). A
cell is the bracket with the most seeds at its ends, then the narrowest, any of the campaigns gives, written as its middle +- half its width with the seeds that
flowed at its two ends, or, where no campaign brackets the group, the Maron-Pierce fit with its total error. Tables
written before the case blocks named them are the singular pairwise functions (the only ones then) and the box of
the campaign's base case.

With --check README, verifies that each table between `<!-- phim table: DIR -->` and `<!-- end phim table -->`, and
each between `<!-- phim summary: DIR DIR ... -->` and `<!-- end phim summary -->`, in README is the one the phim.json
files give now (exit 1 naming the first difference), so a page that drifts from its data fails the tests; --update
README rewrites those tables from the data in place (tools/collect_results.sh runs it as the campaigns fill). Both do
the same for `<!-- campaign cost: DIR ... -->` blocks, the core-hours of campaigns (tools/campaign_cost.py).

usage: tools/phim_table.py PHIM_DIR | --summary PHIM_DIR... | --check README.md | --update README.md"""
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


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
    fits = read_fits(phim_dir)
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


def read_fits(phim_dir):
    path = os.path.join(phim_dir, "phim.json")
    try:
        with open(path) as f:
            return json.load(f)["fits"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        usage(f"{path}: not a phim.json of suspend phim ({e})")


def method_of(phim_dir):
    """(model, functions, box) of a campaign's points, the most common over its case blocks."""
    path = os.path.join(phim_dir, "campaign.json")
    try:
        with open(path) as f:
            table = json.load(f)
    except (OSError, ValueError) as e:
        usage(f"{path}: not a campaign table ({e})")
    base_box = None
    counts = {}
    for p in table.get("points", []):
        case = p.get("case") or {}
        model = case.get("model")
        functions = case.get("functions") or ("fcm" if model == "fcm" else "singular")
        box = case.get("box")
        if box is None and case.get("count") is None:
            if base_box is None:
                base_box = case_file_box(phim_dir, table.get("case"))
            box = base_box
        key = (model, functions, box if box is not None else "?")
        counts[key] = counts.get(key, 0) + 1
    if not counts:
        usage(f"{path}: no points")
    return max(counts, key=counts.get)


def case_file_box(phim_dir, case_path):
    """The cube edge of a campaign's base case file (a path from the repository root), or "?"."""
    import yaml  # Debian python3-yaml, scripts/install-deps.sh
    root = os.path.abspath(phim_dir)
    while not os.path.isdir(os.path.join(root, "cases")) and os.path.dirname(root) != root:
        root = os.path.dirname(root)  # the repository: the folder holding cases/
    try:
        with open(os.path.join(root, case_path or "")) as f:
            return float(yaml.safe_load(f)["box"]["cube"])
    except (OSError, TypeError, KeyError, ValueError, yaml.YAMLError):
        return "?"


def method_label(method):
    model, functions, box = method
    size = f"{box:g} a_1" if isinstance(box, float) else f"{box}"
    if model == "fcm":
        return f"FCM, ({size})^3"
    return f"{model}, {functions.replace('_relative', '')}, ({size})^3"


def cell_of(f):
    """(sort key: a bracket before a fit, then more seeds at the bracket's ends, then narrower; text) of one group."""
    b = f.get("bracket")
    if b:
        n, q = f["bracket_seeds"], f["bracket_flowing_fraction"]
        return (0, -min(n), b[1] - b[0]), (f"{0.5 * (b[0] + b[1]):.4f} +- {0.5 * (b[1] - b[0]):.4f} "
                                  f"({round(q[0] * n[0])}/{n[0]}, {round(q[1] * n[1])}/{n[1]})")
    if f.get("phi_m") is not None:
        err = f.get("phi_m_err_total", f["phi_m_err"])
        return (1, 0, err), f"{number(f['phi_m'])} +- {number(err)} (fit)"
    return None


def summary(phim_dirs):
    cells, methods = {}, []
    for d in phim_dirs:
        method = method_of(d)
        if method not in methods:
            methods.append(method)
        for f in read_fits(d):
            c = cell_of(f)
            if c is None:
                continue
            key = (f["mu_s"], f["sigma_star"], method)
            if key not in cells or c[0] < cells[key][0]:
                cells[key] = c
    order = {"pairwise": 0, "fcm": 1}
    methods.sort(key=lambda m: (order.get(m[0], 2), m[1], str(m[2])))
    rows = ["| mu_s | sigma* | " + " | ".join(method_label(m) for m in methods) + " |",
            "|---|---|" + "---|" * len(methods)]
    groups = sorted({(k[0], k[1]) for k in cells}, key=lambda g: (g[0], -(g[1] or math.inf)))
    for mu, sigma in groups:
        row = [cells.get((mu, sigma, m), (None, "-"))[1] for m in methods]
        rows.append(f"| {mu:g} | {sigma_text(sigma)} | " + " | ".join(row) + " |")
    return "\n".join(rows) + "\n"


def first_difference(readme, what, written, now):
    for k, (a, b) in enumerate(zip(written.splitlines() + [""] * 99, now.splitlines())):
        if a != b:
            print(f"{readme}: the table of {what} differs from its phim.json at row {k + 1}:\n  page: {a}\n"
                  f"  data: {b}\n(regenerate it with tools/phim_table.py --update {readme})")
            return 1
    return 0


def costs(base, folders):
    from campaign_cost import cost_table  # tools/campaign_cost.py, beside this file
    return cost_table([(d, os.path.join(base, d, "campaign.json")) for d in folders.split()])


COST_BLOCK = r"<!-- campaign cost: ([^>]+?) -->\n(.*?)<!-- end campaign cost -->"


def read_page(readme):
    """The page's text and the folder its table paths are relative to."""
    try:
        text = open(readme).read()
    except OSError as e:
        usage(f"{readme}: {e}")
    return text, os.path.dirname(os.path.abspath(readme))


def update(readme):
    text, base = read_page(readme)
    text = re.sub(r"(<!-- phim table: (\S+) -->\n)(.*?)(<!-- end phim table -->)",
                  lambda m: m.group(1) + table(os.path.join(base, m.group(2))) + m.group(4), text, flags=re.S)
    text = re.sub(r"(<!-- phim summary: ([^>]+?) -->\n)(.*?)(<!-- end phim summary -->)",
                  lambda m: m.group(1) + summary([os.path.join(base, d) for d in m.group(2).split()]) + m.group(4),
                  text, flags=re.S)
    text = re.sub(COST_BLOCK, lambda m: m.group(0).split("-->\n", 1)[0] + "-->\n" + costs(base, m.group(1)) +
                  "<!-- end campaign cost -->", text, flags=re.S)
    with open(readme + ".part", "w") as f:
        f.write(text)
    os.replace(readme + ".part", readme)
    return 0


def check(readme):
    text, base = read_page(readme)
    blocks = re.findall(r"<!-- phim table: (\S+) -->\n(.*?)<!-- end phim table -->", text, re.S)
    summaries = re.findall(r"<!-- phim summary: ([^>]+?) -->\n(.*?)<!-- end phim summary -->", text, re.S)
    if not blocks and not summaries:
        usage(f"{readme}: no '<!-- phim table: DIR -->' block")
    for folder, written in blocks:
        if written != table(os.path.join(base, folder)):
            return first_difference(readme, folder, written, table(os.path.join(base, folder)))
    for folders, written in summaries:
        now = summary([os.path.join(base, d) for d in folders.split()])
        if written != now:
            return first_difference(readme, "--summary " + folders, written, now)
    cost_blocks = re.findall(COST_BLOCK, text, re.S)
    for folders, written in cost_blocks:
        if written != costs(base, folders):
            return first_difference(readme, "campaign cost " + folders, written, costs(base, folders))
    print(f"{readme}: {len(blocks)} phi_m table(s), {len(summaries)} summary table(s) and {len(cost_blocks)} cost "
          "table(s) agree with their campaigns")
    return 0


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        usage()
    if argv[1] == "--check":
        if len(argv) != 3:
            usage("--check needs the README")
        return check(argv[2])
    if argv[1] == "--update":
        if len(argv) != 3:
            usage("--update needs the README")
        return update(argv[2])
    if argv[1] == "--summary":
        if len(argv) < 3 or not all(os.path.isdir(d) for d in argv[2:]):
            usage("--summary needs folders with phim.json")
        sys.stdout.write(summary(argv[2:]))
        return 0
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        usage(f"'{argv[1]}' is not a folder with phim.json")
    sys.stdout.write(table(argv[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
