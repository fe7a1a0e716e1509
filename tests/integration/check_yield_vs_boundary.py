#!/usr/bin/env python3
"""tools/yield_vs_boundary.py on a drawn boundary: phi_f(sigma*) = 0.45 + 0.05 log10(sigma*), phi_j = phi_f + 0.01,
searched at sigma* 0.5, 1, 2, 5. A creep bracket that straddles the boundary agrees; one whose sample flowed at a
stress where the boundary jams it (phi above phi_j(s_f)) does not; one outside the searched stresses says so.
usage: check_yield_vs_boundary.py SOURCE_DIR"""
import json
import math
import os
import subprocess
import sys
import tempfile

src = sys.argv[1]
fits = [{"model": "pairwise", "mu_s": 0.5, "sigma_star": s, "result": "bracket",
         "bracket": [0.45 + 0.05 * math.log10(s), 0.46 + 0.05 * math.log10(s)]} for s in (0.5, 1, 2, 5)]


def creep(phi, arrested, flowed):
    return [{"status": status, "case": {"mu_s": 0.5, "phi": phi, "shear_stress": s, "g_adh": 1.0}}
            for s, status in ((arrested, "jammed"), (flowed, "done")) for _ in range(3)]


points = creep(0.455, 0.8, 1.2) + creep(0.50, 0.8, 1.2) + creep(0.45, 0.1, 0.2)
with tempfile.TemporaryDirectory() as d:
    with open(os.path.join(d, "phim.json"), "w") as f:
        json.dump({"fits": fits}, f)
    with open(os.path.join(d, "campaign.json"), "w") as f:
        json.dump({"points": points}, f)
    out = subprocess.run([sys.executable, os.path.join(src, "tools", "yield_vs_boundary.py"), d, d, "--json"],
                         check=True, capture_output=True, text=True).stdout
rows = {r["phi"]: r for r in json.loads(out)}
failures = []
if rows[0.455]["agree"] is not True:
    failures.append("phi 0.455 between phi_f(0.8) = %.4f and phi_j(1.2) = %.4f should agree: %s"
                    % (0.45 + 0.05 * math.log10(0.8), 0.46 + 0.05 * math.log10(1.2), rows[0.455]))
if rows[0.50]["agree"] is not False:
    failures.append("phi 0.50 flowed at 1.2 where the boundary jams above %.4f: %s"
                    % (0.46 + 0.05 * math.log10(1.2), rows[0.50]))
if rows[0.45]["agree"] is not None:
    failures.append("stresses 0.1-0.2 lie outside the searched 0.5-5: %s" % rows[0.45])
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("the yield stresses by creep agree with the boundary where they straddle it, and not where they do not")
