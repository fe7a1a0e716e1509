#!/usr/bin/env python3
"""tools/phim_table.py --summary on drawn campaigns: a column per method (model, near-field functions, box, from the
points' case blocks; a table without them is the singular pairwise functions in its base case's box), and per
friction and sigma* the bracket with the most seeds at its ends before a narrower one of fewer seeds, as middle +-
half width with the flowing seeds, and a Maron-Pierce fit only where nothing brackets the group.
usage: check_phim_summary.py SOURCE_DIR"""
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(sys.argv[1], "tools"))
from phim_table import summary  # noqa: E402


def bracket(mu, sigma, lo, hi, seeds, flowed):
    return {"model": "pairwise", "mu_s": mu, "sigma_star": sigma, "points": 3, "phi_m": None, "bracket": [lo, hi],
            "bracket_seeds": [seeds, seeds], "bracket_flowing_fraction": [flowed / seeds, 0.0], "result": "bracket"}


def fit(mu, sigma, phi_m, err):
    return {"model": "pairwise", "mu_s": mu, "sigma_star": sigma, "points": 5, "phi_m": phi_m, "phi_m_err": err / 2,
            "phi_m_err_total": err, "result": "fit"}


def campaign(root, name, case, fits):
    d = os.path.join(root, "results", name)
    os.makedirs(d)
    with open(os.path.join(d, "phim.json"), "w") as f:
        json.dump({"min_phi": 0, "fits": fits}, f)
    with open(os.path.join(d, "campaign.json"), "w") as f:
        json.dump({"campaign": "c.yaml", "case": "cases/base.yaml", "points": [{"case": case}] * 4}, f)
    return d


with tempfile.TemporaryDirectory() as root:
    os.makedirs(os.path.join(root, "cases"))
    with open(os.path.join(root, "cases", "base.yaml"), "w") as f:
        f.write("box: {cube: 16}\n")
    old = campaign(root, "old", {"model": "pairwise"},  # written before case blocks named the near field and box
                   [bracket(0.5, 1.0, 0.49, 0.50, 1, 1), fit(0.5, None, 0.5905, 0.001), fit(0.5, 2.0, 0.55, 0.016)])
    searched = campaign(root, "searched", {"model": "pairwise", "functions": "singular", "box": 16.0},
                        [bracket(0.5, 1.0, 0.495, 0.505, 3, 2), bracket(0.5, None, 0.565, 0.575, 3, 3)])
    exact = campaign(root, "exact", {"model": "pairwise", "functions": "exact_relative", "box": 20.0},
                     [bracket(1.0, 0.7, 0.475, 0.48, 3, 3)])
    table = summary([old, searched, exact]).splitlines()

expected = [
    "| mu_s | sigma* | pairwise, exact, (20 a_1)^3 | pairwise, singular, (16 a_1)^3 |",
    "|---|---|---|---|",
    "| 0.5 | no adhesion | - | 0.5700 +- 0.0050 (3/3, 0/3) |",
    "| 0.5 | 2 | - | 0.5500 +- 0.0160 (fit) |",
    "| 0.5 | 1 | - | 0.5000 +- 0.0050 (2/3, 0/3) |",
    "| 1 | 0.7 | 0.4775 +- 0.0025 (3/3, 0/3) | - |",
]
if table != expected:
    print("summary table:\n" + "\n".join(table) + "\nexpected:\n" + "\n".join(expected))
    sys.exit(1)
print("summary: one column per method, 3-seed brackets before narrower 1-seed ones, fits only where nothing brackets")
