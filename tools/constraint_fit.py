#!/usr/bin/env python3
"""The constraint-rheology form of the adhesive boundary phi_m(sigma*) fitted to the boundary searches (issue 36).

Richards et al. (J. Rheol. 64, 405 (2020)), after the constraint-based model of Guy et al. (Phys. Rev. Lett. 121,
128001 (2018)): adhesive contacts are constraints that stress releases. With a(sigma*) the fraction of them intact,

    phi_m(sigma*) = phi_alp a + phi_mu (1 - a),     a(sigma*) = 1 - exp(-(sigma_a / sigma*)^kappa),

phi_m runs from the adhesive loose packing phi_alp (all adhesive constraints intact, sigma* -> 0) to the frictional
non-adhesive phi_mu (sigma* -> infinity); sigma_a is the stress scale on which adhesive bonds give, kappa how sharply
(a is the released-constraint mirror of Wyart & Cates' fraction of frictional contacts; docs/references.md).

Data: each (model, mu_s, sigma*) group of the given `suspend phim` tables (phim.json) that the search bracketed, as
the bracket's midpoint with the standard deviation of a uniform distribution over it (width / sqrt(12)); the
non-adhesive group (sigma* = inf) is the point a = 0. Per friction, weighted least-squares fits of phi_mu, phi_alp
and sigma_a with kappa = 1, and with kappa free as well (from five points); a parameter that ends at its bound is
named (phi_alp is pinned only by stresses low enough to approach it). Then the frictions
>= --shared-from (0.3) fitted together with one phi_alp, and the chi^2 difference to the separate fits (paper 004's
claim that these curves meet near 0.5 at low stress, section IV).

usage: tools/constraint_fit.py PHIM_JSON_OR_DIR [...] [--model pairwise|fcm] [--shared-from MU] [--json OUT]
"""
import json
import math
import os
import sys

from debian_python import require

USAGE = __doc__.strip().splitlines()[-1]


def fail(message):
    print("error: " + message, file=sys.stderr)
    print(USAGE, file=sys.stderr)
    sys.exit(2)


def load_groups(paths, model):
    """{mu_s: [(sigma_star or inf, phi, sd)]} from the bracketed groups of the phim tables."""
    out = {}
    for path in paths:
        if os.path.isdir(path):
            path = os.path.join(path, "phim.json")
        try:
            with open(path) as f:
                fits = json.load(f)["fits"]
        except (OSError, ValueError, KeyError) as e:
            fail("%s: not a `suspend phim` table (%s)" % (path, e))
        for g in fits:
            if model and g.get("model") != model:
                continue
            bracket = g.get("bracket")
            if g.get("result") != "bracket" or not bracket or bracket[1] - bracket[0] > 0.05:
                continue  # unbracketed, or a search still wide open
            sigma = g.get("sigma_star")
            sigma = math.inf if sigma is None else float(sigma)
            phi = 0.5 * (bracket[0] + bracket[1])
            sd = (bracket[1] - bracket[0]) / math.sqrt(12.0)
            points = out.setdefault(float(g["mu_s"]), [])
            same = [k for k, p in enumerate(points) if p[0] == sigma]
            if same and points[same[0]][2] <= sd:
                continue  # a group searched by two campaigns: the narrower bracket
            if same:
                points.pop(same[0])
            points.append((sigma, phi, sd))
    return out


def intact(sigma, sigma_a, kappa):
    """a(sigma*): the fraction of adhesive constraints intact; 0 at sigma* = inf."""
    import numpy as np
    s = np.asarray(sigma, dtype=float)
    with np.errstate(divide="ignore", over="ignore"):
        return np.where(np.isinf(s), 0.0, -np.expm1(-np.power(sigma_a / s, kappa)))


def boundary(sigma, phi_mu, phi_alp, sigma_a, kappa):
    a = intact(sigma, sigma_a, kappa)
    return phi_alp * a + phi_mu * (1.0 - a)


def fit_one(points, free_kappa):
    """Weighted fit of one friction's boundary (kappa free or 1); None when it has too few points."""
    import numpy as np
    from scipy.optimize import curve_fit
    sigma = np.array([p[0] for p in points])
    phi = np.array([p[1] for p in points])
    sd = np.array([p[2] for p in points])
    adhesive = np.isfinite(sigma)
    if adhesive.sum() < 2 or (~adhesive).sum() < 1 or (free_kappa and len(points) < 5):
        return None  # three or four parameters and at least one degree of freedom
    start = [phi[~adhesive][0], min(phi[adhesive]) - 0.02, float(np.median(sigma[adhesive])), 1.0]
    lower, upper = [0.3, 0.05, 1e-3, 0.2], [0.74, 0.74, 1e3, 10.0]
    if free_kappa:
        f = boundary
    else:
        def f(s, phi_mu, phi_alp, sigma_a):
            return boundary(s, phi_mu, phi_alp, sigma_a, 1.0)
        start, lower, upper = start[:3], lower[:3], upper[:3]
    try:
        p, cov = curve_fit(f, sigma, phi, p0=start, sigma=sd, absolute_sigma=True, bounds=(lower, upper),
                           maxfev=20000, check_finite=False)
    except (RuntimeError, ValueError) as e:
        return {"error": str(e)}
    chi2 = float(np.sum(((f(sigma, *p) - phi) / sd) ** 2))
    err = np.sqrt(np.diag(cov))
    names = ["phi_mu", "phi_alp", "sigma_a", "kappa"]
    out = {n: float(v) for n, v in zip(names, p)}
    out.update({n + "_err": float(e) for n, e in zip(names, err)})
    if not free_kappa:
        out["kappa"], out["kappa_err"] = 1.0, None
    out.update({"points": len(points), "chi2": chi2, "dof": len(points) - len(p)})
    # A parameter at its bound is not determined by the data (phi_alp: no stress low enough to pin it).
    out["at_bound"] = [n for n, v, lo, hi in zip(names, p, lower, upper) if min(v - lo, hi - v) < 1e-6 * (hi - lo)]
    return out


def fit_shared(groups):
    """The frictions together: one phi_alp, their own phi_mu and sigma_a, one kappa."""
    import numpy as np
    from scipy.optimize import least_squares
    frictions = sorted(groups)
    if len(frictions) < 2:
        return None
    data = [(i, s, phi, sd) for i, mu in enumerate(frictions) for (s, phi, sd) in groups[mu]]
    index = np.array([d[0] for d in data])
    sigma = np.array([d[1] for d in data])
    phi = np.array([d[2] for d in data])
    sd = np.array([d[3] for d in data])
    n = len(frictions)

    def residual(q):
        phi_alp, kappa = q[0], q[1]
        phi_mu, sigma_a = q[2:2 + n], q[2 + n:]
        return (boundary(sigma, phi_mu[index], phi_alp, sigma_a[index], kappa) - phi) / sd

    start = [min(phi) - 0.02, 1.0] + [max(phi[index == i]) for i in range(n)] + [1.0] * n
    lower = [0.05, 0.2] + [0.3] * n + [1e-3] * n
    upper = [0.74, 10.0] + [0.74] * n + [1e3] * n
    r = least_squares(residual, start, bounds=(lower, upper))
    jac = r.jac
    try:
        cov = np.linalg.inv(jac.T @ jac)
    except np.linalg.LinAlgError:
        cov = np.full((len(start), len(start)), np.nan)
    err = np.sqrt(np.abs(np.diag(cov)))
    return {"frictions": frictions, "phi_alp": float(r.x[0]), "phi_alp_err": float(err[0]),
            "kappa": float(r.x[1]), "kappa_err": float(err[1]),
            "phi_mu": [float(v) for v in r.x[2:2 + n]], "sigma_a": [float(v) for v in r.x[2 + n:]],
            "chi2": float(np.sum(r.fun ** 2)), "dof": len(data) - len(start), "points": len(data)}


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    paths, model, shared_from, json_out = [], None, 0.3, None
    it = iter(argv)
    for a in it:
        if a == "--model":
            model = next(it, None)
        elif a == "--shared-from":
            try:
                shared_from = float(next(it, "x"))
            except ValueError:
                fail("--shared-from takes a friction coefficient")
        elif a == "--json":
            json_out = next(it, None)
        elif a.startswith("--"):
            fail("unknown option " + a)
        else:
            paths.append(a)
    for p in paths:
        if not os.path.exists(p):
            fail(p + " does not exist")
    require("numpy", "scipy")
    groups = load_groups(paths, model)
    if not groups:
        fail("no bracketed group in " + ", ".join(paths))
    result = {"form": "phi_m = phi_alp a + phi_mu (1 - a), a = 1 - exp(-(sigma_a / sigma*)^kappa)",
              "frictions": [], "shared": None}
    print("%-6s %6s %18s %18s %16s %14s %10s" % ("mu_s", "points", "phi_mu", "phi_alp", "sigma_a", "kappa",
                                                "chi2/dof"))
    for mu in sorted(groups):
        row = {"mu_s": mu, "data": groups[mu]}
        for kind, free in (("fit", False), ("fit_free_kappa", True)):
            f = fit_one(groups[mu], free)
            row[kind] = f
            if not f or "error" in f:
                if not free:
                    print("%-6g %6d  %s" % (mu, len(groups[mu]), (f or {}).get("error", "too few bracketed stresses")))
                continue
            kappa = "%.2f +- %.2f" % (f["kappa"], f["kappa_err"]) if f["kappa_err"] is not None else "1 (fixed)"
            dof = "%.2f" % (f["chi2"] / f["dof"]) if f["dof"] > 0 else "-"
            note = "  at bound: " + ", ".join(f["at_bound"]) if f["at_bound"] else ""
            print("%-6g %6d %8.4f +- %.4f %8.4f +- %.4f %7.3f +- %.3f %14s %10s%s" % (
                mu, f["points"], f["phi_mu"], f["phi_mu_err"], f["phi_alp"], f["phi_alp_err"], f["sigma_a"],
                f["sigma_a_err"], kappa, dof, note))
        result["frictions"].append(row)
    strong = {mu: g for mu, g in groups.items() if mu >= shared_from}
    shared = fit_shared(strong)
    result["shared"] = shared
    if shared:
        separate = sum(r["fit"]["chi2"] for r in result["frictions"]
                       if r["mu_s"] >= shared_from and r["fit"] and "error" not in r["fit"])
        shared["chi2_separate"] = separate
        print("mu_s >= %g together, one phi_alp: phi_alp %.4f +- %.4f, kappa %.2f +- %.2f, chi2 %.2f for %d dof "
              "(separate fits: %.2f)" % (shared_from, shared["phi_alp"], shared["phi_alp_err"], shared["kappa"],
                                        shared["kappa_err"], shared["chi2"], shared["dof"], separate))
    if json_out:
        with open(json_out + ".part", "w") as f:
            json.dump(result, f, indent=1, default=lambda x: None if x == math.inf else x)
        os.replace(json_out + ".part", json_out)
        print("written to " + json_out)


if __name__ == "__main__":
    main(sys.argv[1:])
