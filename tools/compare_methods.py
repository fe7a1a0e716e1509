#!/usr/bin/env python3
"""Point-by-point comparison of the FCM and pairwise phi_m campaigns (issue 13): for every finished FCM point, the
pairwise value at the same mu_s, sigma* and phi, and their ratio. The pairwise campaign samples phi on its own grid,
so its value at the FCM point's phi is interpolated between the two flowing pairwise points around it (log eta_r
linear in phi; Sigma^c_12/Sigma_12 and contacts per particle linear), or, outside their range, taken from the
group's fit eta_r = alpha (1 - phi/phi_m)^-2 (phim.json; marked 'fit'). Errors are the points' block-averaged
standard errors, carried through the interpolation; the ratio's error combines both.

usage: tools/compare_methods.py RESULTS_DIR [--markdown]
  RESULTS_DIR  holds pairwise/ and fcm/, each with campaign.json (and phim.json) (results/phim)
"""
import json
import math
import os
import sys

METHODS = ("pairwise", "fcm")


def usage(message):
    sys.stderr.write(f"error: {message}\n" if message else "")
    sys.stderr.write("usage: tools/compare_methods.py RESULTS_DIR [--markdown]\n")
    sys.exit(2)


def group_of(point):
    """(mu_s, sigma*) of a point; the non-adhesive limit (g_adh = 0) is sigma* = inf, as `suspend phim` has it."""
    p = point["parameters"]
    case = point.get("case", {})
    mu = p.get("contact.mu_s", case.get("mu_s"))
    g_adh = p.get("contact.g_adh", case.get("g_adh"))
    sigma = math.inf if g_adh == 0 else p.get("flow.shear_stress", case.get("shear_stress"))
    return float(mu), float(sigma)


def flowing(table):
    """Per group, the done points as (phi, {quantity: (mean, sem)}), sorted by phi."""
    groups = {}
    for point in table["points"]:
        if point.get("status") != "done":
            continue
        s, d = point["summary"], point["derived"]
        values = {"eta_r": (d["eta_r"]["mean"], d["eta_r"]["sem"]),
                  "Sigma_c12/Sigma_12": (d["Sigma_c12/Sigma_12"]["mean"], d["Sigma_c12/Sigma_12"]["sem"]),
                  "contacts": (s["contacts"]["mean"] / s["particles"], s["contacts"]["sem"] / s["particles"])}
        groups.setdefault(group_of(point), []).append((s["phi"], values))
    for rows in groups.values():
        rows.sort(key=lambda r: r[0])
    return groups


def interpolate(rows, phi, quantity):
    """Value and error at phi between the flowing points around it (None outside their range)."""
    for (p0, v0), (p1, v1) in zip(rows, rows[1:]):
        if p0 <= phi <= p1:
            w = (phi - p0) / (p1 - p0) if p1 > p0 else 0.0
            (m0, e0), (m1, e1) = v0[quantity], v1[quantity]
            if quantity == "eta_r":  # log-linear: eta_r grows faster than linearly in phi
                m = math.exp((1 - w) * math.log(m0) + w * math.log(m1))
                e = m * math.hypot((1 - w) * e0 / m0, w * e1 / m1)
            else:
                m, e = (1 - w) * m0 + w * m1, math.hypot((1 - w) * e0, w * e1)
            return m, e
    return None


def from_fit(fit, phi):
    """eta_r = alpha (1 - phi/phi_m)^-2 of a `suspend phim` fit, with the error of alpha and phi_m."""
    if fit is None or phi >= fit["phi_m"]:
        return None
    base = 1.0 - phi / fit["phi_m"]
    m = fit["alpha"] * base ** -2
    de_dphim = m * 2.0 / base * phi / fit["phi_m"] ** 2
    return m, math.hypot(m * fit["alpha_err"] / fit["alpha"], de_dphim * fit["phi_m_err"])


def ratio(a, b):
    (ma, ea), (mb, eb) = a, b
    r = ma / mb
    return r, r * math.hypot(ea / ma, eb / mb)


def load(results):
    tables, fits = {}, {}
    for method in METHODS:
        path = os.path.join(results, method, "campaign.json")
        if not os.path.isfile(path):
            usage(f"{path}: no campaign table (RESULTS_DIR needs pairwise/ and fcm/)")
        with open(path) as f:
            tables[method] = json.load(f)
        fit_path = os.path.join(results, method, "phim.json")
        fits[method] = {}
        if os.path.isfile(fit_path):
            with open(fit_path) as f:
                for fit in json.load(f)["fits"]:
                    sigma = fit["sigma_star"]  # JSON null for the non-adhesive limit
                    fits[method][(float(fit["mu_s"]), math.inf if sigma is None else float(sigma))] = fit
    return tables, fits


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        usage("")
    results = argv[0]
    markdown = False
    for arg in argv[1:]:
        if arg == "--markdown":
            markdown = True
        else:
            usage(f"unexpected argument '{arg}'")
    if not os.path.isdir(results):
        usage(f"{results}: no such directory")
    tables, fits = load(results)
    pairwise, fcm = flowing(tables["pairwise"]), flowing(tables["fcm"])
    header = ["mu_s", "sigma*", "phi", "eta_r FCM", "eta_r pairwise", "ratio", "S_c12/S_12 FCM", "pairwise",
              "contacts/particle FCM", "pairwise"]
    rows = []
    ratios = []
    for key in sorted(fcm):
        for phi, values in fcm[key]:
            rows_p = pairwise.get(key, [])
            eta_p = interpolate(rows_p, phi, "eta_r")
            source = ""
            if eta_p is None:
                eta_p, source = from_fit(fits["pairwise"].get(key), phi), " (fit)"
            cells = ["%g" % key[0], "%g" % key[1], "%.3f" % phi, "%.3g +- %.2g" % values["eta_r"]]
            if eta_p is None:
                cells += ["-", "-"]
            else:
                r = ratio(values["eta_r"], eta_p)
                ratios.append(r)
                cells += ["%.3g +- %.2g%s" % (eta_p + (source,)), "%.3f +- %.3f" % r]
            for q in ("Sigma_c12/Sigma_12", "contacts"):
                other = interpolate(rows_p, phi, q)
                cells += ["%.3f +- %.3f" % values[q], "%.3f +- %.3f" % other if other else "-"]
            rows.append(cells)
    if not rows:
        usage(f"{results}/fcm/campaign.json: no finished FCM point yet")
    if markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for cells in rows:
            print("| " + " | ".join(cells) + " |")
    else:
        widths = [max(len(h), *(len(c[i]) for c in rows)) for i, h in enumerate(header)]
        print("  ".join(h.rjust(w) for h, w in zip(header, widths)))
        for cells in rows:
            print("  ".join(c.rjust(w) for c, w in zip(cells, widths)))
    if ratios:
        weights = [1.0 / e ** 2 for _, e in ratios if e > 0]
        mean = sum(r / e ** 2 for r, e in ratios if e > 0) / sum(weights)
        print(f"\n{len(ratios)} points: eta_r FCM / pairwise, error-weighted mean {mean:.3f} +- "
              f"{1.0 / math.sqrt(sum(weights)):.3f} (range {min(r for r, _ in ratios):.3f}-"
              f"{max(r for r, _ in ratios):.3f})")


if __name__ == "__main__":
    main(sys.argv[1:])
