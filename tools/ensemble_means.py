#!/usr/bin/env python3
"""Ensemble means of a campaign's points grouped by one varied key (e.g. seeds of the same case run two ways):
per group, the mean over its points of eta_r, Sigma^c_12/Sigma_12, N1, N2 and Pi, the ensemble standard error
(sample standard deviation / sqrt(n)), the mean of the points' own block-averaged errors, the difference
of each group from the first with its combined error, and the mean difference over twins (points whose other
parameters, e.g. the seed, are equal) with two errors: from the scatter of the differences, and from the runs' own
block-averaged errors (sqrt of the sum of both twins' squared errors, over n). Twins share their start but
decorrelate within a few strains (docs/validation.md section 3), so the scatter error is meaningful only when it
agrees with the second; with few twins it can be small by chance. Made for issue 14's question whether the
multi-rate FCM step shifts eta_r beyond run-to-run scatter (cases/validation/fcm_multirate_ensemble.yaml).

usage: tools/ensemble_means.py CAMPAIGN.json [MORE.json ...] KEY [--where PARAMETER=VALUE ...]
  KEY      the dotted parameter that names the groups (hydrodynamics.fcm.far_field_every)
  --where  only the points whose parameter has this value (e.g. contact.mu_s=0.5 for one case of a campaign
           that runs several)
Points of a campaign that does not vary KEY (it set one value for all points) form a group named after the
campaign's folder, so a second campaign can be set against the first one's groups: e.g.
  tools/ensemble_means.py results/multirate/campaign.json runs/predictor/campaign.json \
      hydrodynamics.fcm.far_field_every
compares the predictor ensemble (group "predictor") with the every-step runs (group "1") seed by seed.
"""
import json
import math
import os
import sys

QUANTITIES = (("eta_r", "eta_r"), ("Sigma_c12/Sigma_12", "Sigma^c_12/Sigma_12"), ("N1", "N1"), ("N2", "N2"),
              ("Pi", "Pi"), ("contacts_per_particle", "contacts per particle"))


def mean_and_error(values):
    """Mean and its standard error (sample standard deviation / sqrt(n); nan for one value)."""
    n = len(values)
    m = sum(values) / n
    return m, (math.sqrt(sum((x - m) ** 2 for x in values) / (n - 1) / n) if n > 1 else math.nan)


def _same_number(value, text):
    try:
        return float(value) == float(text)
    except (TypeError, ValueError):
        return False


def usage(message):
    sys.stderr.write(f"error: {message}\n" if message else "")
    sys.stderr.write("usage: tools/ensemble_means.py CAMPAIGN.json [MORE.json ...] KEY [--where PARAMETER=VALUE ...]\n")
    sys.exit(2)


def main(argv):
    if len(argv) < 2 or argv[0] in ("-h", "--help"):
        usage("")
    where = {}
    while "--where" in argv:
        at = argv.index("--where")
        if at + 1 >= len(argv) or "=" not in argv[at + 1]:
            usage("--where needs PARAMETER=VALUE")
        name, value = argv[at + 1].split("=", 1)
        where[name] = value
        del argv[at:at + 2]
    if len(argv) < 2:
        usage("")
    paths, key = argv[:-1], argv[-1]
    groups = {}
    for path in paths:
        if not os.path.isfile(path):
            usage(f"{path}: no such campaign table (give DIR/campaign.json)")
        with open(path) as f:
            table = json.load(f)
        varies = any(key in p["parameters"] for p in table["points"])
        folder = os.path.basename(os.path.dirname(os.path.abspath(path)))
        for p in table["points"]:
            if p.get("status") != "done" or (varies and key not in p["parameters"]):
                continue
            if any(str(p["parameters"].get(k)) != v and not _same_number(p["parameters"].get(k), v)
                   for k, v in where.items()):
                continue
            d = dict(p["derived"])
            d.setdefault("contacts_per_particle", p["summary"].get("contacts_per_particle", {"mean": math.nan, "sem": math.nan}))
            twin = tuple(sorted((k, str(v)) for k, v in p["parameters"].items() if k != key))  # e.g. the seed
            group = str(p["parameters"][key]) if varies else folder
            groups.setdefault(group, []).append(
                (p["name"], {q: d[q]["mean"] for q, _ in QUANTITIES}, d["eta_r"]["sem"], twin,
                 {q: d[q]["sem"] for q, _ in QUANTITIES}))
    if not groups:
        usage(f"{', '.join(paths)}: no finished point varies {key}")
    first = None
    first_rows = None
    print(f"{key:>10} {'n':>3} " + " ".join(f"{label:>26}" for _, label in QUANTITIES) + "  mean block SE of eta_r")
    numeric = lambda g: g.replace('.', '', 1).isdigit()
    for name in sorted(groups, key=lambda g: (0, float(g), "") if numeric(g) else (1, 0.0, g)):
        rows = groups[name]
        n = len(rows)
        stats = {q: mean_and_error([r[1][q] for r in rows]) for q, _ in QUANTITIES}
        print(f"{name:>10} {n:>3} " + " ".join(f"{stats[q][0]:>15.4g} +- {stats[q][1]:<7.2g}" for q, _ in QUANTITIES)
              + f"  {sum(r[2] for r in rows) / n:.3g}")
        for r in rows:
            print(f"{'':>14} {r[0]}: eta_r {r[1]['eta_r']:.4g}, ratio {r[1]['Sigma_c12/Sigma_12']:.3f}, N2 {r[1]['N2']:.3g}, "
                  f"contacts per particle {r[1]['contacts_per_particle']:.3f}")
        if first is None:
            first, first_rows = stats, {r[3]: (r[1], r[4]) for r in rows}
        else:
            diffs = []
            for q, label in QUANTITIES:
                d = stats[q][0] - first[q][0]
                err = math.hypot(stats[q][1], first[q][1])
                diffs.append(f"{label} {d:+.4g} +- {err:.2g} ({d / err if err > 0 else math.nan:+.1f} errors)")
            print(f"{'':>14} against the first group: " + "; ".join(diffs))
            # Paired: the same other parameters (packing) run both ways; what the pair shares cancels from the
            # difference as long as the twins stay correlated.
            pairs = [(r[1], r[4], *first_rows[r[3]]) for r in rows if r[3] in first_rows]
            if len(pairs) > 1:
                diffs = []
                for q, label in QUANTITIES:
                    m, se = mean_and_error([a[q] - b[q] for a, _, b, _ in pairs])
                    own = math.sqrt(sum(ea[q] ** 2 + eb[q] ** 2 for _, ea, _, eb in pairs)) / len(pairs)
                    diffs.append(f"{label} {m:+.4g} +- {se:.2g} ({m / se if se > 0 else math.nan:+.1f} errors; "
                                 f"runs' own errors +- {own:.2g}, {m / own if own > 0 else math.nan:+.1f})")
                print(f"{'':>14} paired with the first group ({len(pairs)} twins): " + "; ".join(diffs))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
