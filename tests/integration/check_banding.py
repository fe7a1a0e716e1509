#!/usr/bin/env python3
"""tools/banding_check.py's measure on drawn profiles: u_x(y) of a homogeneous shear (every local rate the cell's)
gives a smallest local rate ratio of 1; a band, the lower half of the cell sheared at a tenth of the upper half's
rate, gives 0.1 / (the cell's least-squares rate 0.55): 0.18, below the 0.25 the tool flags; snapshots before the
averaging window are left out; an earlier table's rows read back as they were written (--keep).
usage: check_banding.py SOURCE_DIR"""
import os
import sys

sys.path.insert(0, os.path.join(sys.argv[1], "tools"))
from banding_check import band_measures, kept_rows  # noqa: E402
import tempfile  # noqa: E402


def snapshot(strain, local, cell_rate, phi=None):
    return {"strain": strain, "gradient_profile": {"shear_rate": cell_rate, "local_rate": local,
                                                   "phi": phi or [0.5] * 8}}


homogeneous = snapshot(3.0, [1.0] * 7, 1.0)
banded = snapshot(4.0, [0.1] * 3 + [0.55] + [1.0] * 3, 0.55, [0.55] * 4 + [0.45] * 4)
early = snapshot(0.5, [0.0] * 7, 1.0)
ratios, contrasts = band_measures([early, homogeneous, banded], start=2.0)
failures = []
if len(ratios) != 2:
    failures.append("the snapshot before the window was counted: %s" % ratios)
if abs(ratios[0] - 1.0) > 1e-12:
    failures.append("homogeneous shear: ratio %g, expected 1" % ratios[0])
if abs(ratios[1] - 0.1 / 0.55) > 1e-12 or not ratios[1] < 0.25:
    failures.append("band: ratio %g, expected %g (below 0.25)" % (ratios[1], 0.1 / 0.55))
if abs(contrasts[1] - 0.2) > 1e-12:
    failures.append("band: phi contrast %g, expected (0.55 - 0.45) / 0.5 = 0.2" % contrasts[1])
table = ("point (flowing)  snapshots  min rate ratio phi contrast \n"
         "mu_s1_shear_stress0.7_phi0.4_seed1    5    0.609    0.245 \n"
         "mu_s1_shear_stress0.5_phi0.4_seed2    5    0.180    0.300 BANDED\n"
         "1 of 2 flowing point(s) banded (median smallest local rate below 0.25 of the cell's)\n")
with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
    f.write(table)
kept = kept_rows(f.name, 0.25)
os.unlink(f.name)
if sorted(kept) != ["mu_s1_shear_stress0.5_phi0.4_seed2", "mu_s1_shear_stress0.7_phi0.4_seed1"]:
    failures.append("--keep read the rows %s" % sorted(kept))
elif kept["mu_s1_shear_stress0.7_phi0.4_seed1"]["min_rate_ratio"] != 0.609 or \
        not kept["mu_s1_shear_stress0.5_phi0.4_seed2"]["banded"]:
    failures.append("--keep rows: %s" % kept)
if kept_rows("/nonexistent/banding.txt", 0.25):
    failures.append("a missing earlier table gave rows")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("banding measure: 1 for homogeneous shear, 0.18 for a band at a tenth of the rate, window respected, earlier rows kept")
