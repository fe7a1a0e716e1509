#!/usr/bin/python3
"""Figures of a phi_m(sigma*) campaign, after paper 004 (Orsi et al.): Fig. 15 (phi_m against sigma*, every method on
one plot, with the paper's non-adhesive limits; where a jammed point lies below the Maron-Pierce fit, the bracket
between the densest flowing and the least dense jammed point instead), Fig. 11 (eta_r against phi per sigma*, with the Maron-Pierce fits),
Fig. 14 (eta_r against phi/phi_m), Figs. 16-19 (contact-stress ratios against phi/phi_m) and Fig. 22 (mu(J)).

usage: tools/phim_figures.py RESULTS_DIR [--out FIGURE_DIR]

RESULTS_DIR holds one folder per method (pairwise/, fcm/), each with the campaign.json of `suspend sweep` and the
phim.json of `suspend phim`. Figures are written as PNG and SVG to FIGURE_DIR (default RESULTS_DIR/figures).
"""
import json
import math
import os
import sys

from debian_python import require

PAPER_NON_ADHESIVE = {0.0: 0.651, 0.1: 0.632, 0.5: 0.592}  # paper 004 Fig. 15 (FDM)
METHOD_STYLE = {"pairwise": dict(marker="o", linestyle="-", fillstyle="full"),
                "fcm": dict(marker="s", linestyle="--", fillstyle="none")}


def usage(message=None):
    if message:
        print("error: " + message, file=sys.stderr)
    print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
    sys.exit(2)


def load(results):
    methods = {}
    for name in sorted(os.listdir(results)):
        folder = os.path.join(results, name)
        table, fits = os.path.join(folder, "campaign.json"), os.path.join(folder, "phim.json")
        if os.path.isfile(table) and os.path.isfile(fits):
            with open(table) as t, open(fits) as f:
                methods[name] = (json.load(t), json.load(f))
    return methods


def group_sigma(point):
    c = point["case"]
    if c["g_adh"] == 0:
        return math.inf
    if c["control"] == "stress":
        return float("%.6g" % (c["shear_stress"] / c["g_adh"]))
    return None


def mu_colour(mu_s, all_mu):
    import matplotlib.pyplot as plt
    order = sorted(all_mu)
    return plt.cm.viridis(order.index(mu_s) / max(1, len(order) - 1) * 0.85)


def sigma_colour(sigma, sigmas):
    import matplotlib.pyplot as plt
    order = sorted(sigmas)
    return plt.cm.plasma(order.index(sigma) / max(1, len(order) - 1) * 0.9)


def save(fig, out, name):
    for ext in ("png", "svg"):
        # No date and fixed element ids: a figure redrawn from the same table is the same file (small diffs).
        meta = {"Date": None} if ext == "svg" else {"Software": None}
        fig.savefig(os.path.join(out, name + "." + ext), dpi=130, bbox_inches="tight", metadata=meta)


def sigma_of(fit):
    return math.inf if fit["sigma_star"] is None else fit["sigma_star"]


def bracket(fit):
    """(densest flowing phi, least dense jammed phi) when a jammed point lies below the fitted phi_m (or there is no
    fit): the campaign's data then place phi_m in that interval, and the fit, which extrapolates past them, is not the
    result."""
    jammed = fit.get("jammed_phi") or []
    if not jammed or (fit.get("phi_m") is not None and not fit.get("jammed_below_phi_m")):
        return None
    hi = min(jammed)
    below = [p[0] for p in fit.get("data") or [] if p[0] < hi]
    return (max(below), hi) if below else None


def drawn_phi_m(fit):
    """What Fig. 15 draws for a group: (phi_m, its error bar, the bracket or None); the bracket's middle and half
    width where the data contradict the fit, the fit otherwise; None for a group with neither."""
    b = bracket(fit)
    if b:
        return 0.5 * (b[0] + b[1]), 0.5 * (b[1] - b[0]), b
    if fit.get("phi_m") is not None:
        return fit["phi_m"], fit["phi_m_err"], None
    return None


def figure_15(methods, out):
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    drawn = {method: [(f, d) for f in fits["fits"] if (d := drawn_phi_m(f))]
             for method, (_, fits) in methods.items()}
    shown = [pair for pairs in drawn.values() for pair in pairs]
    all_mu = sorted({f["mu_s"] for f, _ in shown} | set(PAPER_NON_ADHESIVE))
    finite_max = max([sigma_of(f) for f, _ in shown if sigma_of(f) < math.inf] + [10.0])
    x_inf = finite_max * 3.0  # where the non-adhesive limit is drawn
    bracket_label = "flowing below, jammed above (fit overshoots)"
    for method, pairs in drawn.items():
        style = METHOD_STYLE.get(method, dict(marker="^", linestyle=":", fillstyle="full"))
        for mu in sorted({f["mu_s"] for f, _ in pairs}):
            group = sorted(((f, d) for f, d in pairs if f["mu_s"] == mu), key=lambda pair: sigma_of(pair[0]))
            x = [x_inf if sigma_of(f) == math.inf else sigma_of(f) for f, _ in group]
            colour = mu_colour(mu, all_mu)
            ax.errorbar(x, [d[0] for _, d in group], yerr=[d[1] for _, d in group], color=colour, capsize=3,
                        label="%s, $\\mu_s$ = %g" % (method, mu), **style)
            for xi, (_, (_, _, b)) in zip(x, group):
                if b:
                    ax.vlines(xi, b[0], b[1], color=colour, linewidth=5, alpha=0.45, label=bracket_label)
                    bracket_label = None
    for mu, phi in PAPER_NON_ADHESIVE.items():
        ax.axhline(phi, color=mu_colour(mu, all_mu), linestyle=":", linewidth=1)
        ax.annotate("paper 004, $\\mu_s$ = %g, no adhesion" % mu, (0.55, phi), fontsize=7, va="bottom",
                    color=mu_colour(mu, all_mu))
    ax.axvspan(0.7, 0.8, color="0.85", zorder=0)
    ax.annotate("paper 004: $\\mu_s \\geq 0.3$ curves\nmeet near 0.5", (0.82, 0.49), fontsize=7)
    lowest = min([d[2][0] if d[2] else d[0] - d[1] for _, d in shown] + [0.47])
    highest = max([d[0] + d[1] for _, d in shown if not d[2]] + [0.67])
    ax.set_ylim(lowest - 0.01, highest + 0.01)
    ax.set_xscale("log")
    ax.set_xlim(0.5, x_inf * 1.5)
    ax.set_xticks([1, 10, x_inf])
    ax.set_xticklabels(["1", "10", "$\\infty$"])
    ax.set_xlabel("$\\sigma^* = 6\\pi\\Sigma_{12} a_1^2 / F^{adh}$")
    ax.set_ylabel("$\\phi_m^\\mu(\\sigma^*)$")
    ax.legend(fontsize=7, loc="lower right")
    ax.set_title("Maximum volume fraction against reduced stress (paper 004 Fig. 15)", fontsize=9)
    save(fig, out, "fig15_phim_sigma_star")
    plt.close(fig)


def figure_11(methods, out):
    import matplotlib.pyplot as plt
    import numpy as np
    for method, (_, fits) in methods.items():
        mus = sorted({f["mu_s"] for f in fits["fits"]})
        fig, axes = plt.subplots(1, len(mus), figsize=(4.2 * len(mus), 3.8), squeeze=False)
        for ax, mu in zip(axes[0], mus):
            groups = [f for f in fits["fits"] if f["mu_s"] == mu]
            sigmas = [sigma_of(f) for f in groups]
            for f in groups:
                c = sigma_colour(sigma_of(f), sigmas)
                data = np.array(f["data"]).reshape(-1, 3)
                label = "$\\sigma^*$ = " + ("$\\infty$" if sigma_of(f) == math.inf else "%g" % sigma_of(f))
                if len(data):
                    ax.errorbar(data[:, 0], data[:, 1], yerr=data[:, 2], fmt="o", color=c, capsize=2, label=label)
                if f.get("phi_m") is not None:
                    phi = np.linspace(min(data[:, 0].min(), 0.3), f["phi_m"] * 0.985, 100)
                    ax.plot(phi, f["alpha"] / (1 - phi / f["phi_m"]) ** 2, color=c)
                for phi_j in f.get("jammed_phi", []):
                    ax.axvline(phi_j, color=c, linestyle=":", linewidth=0.8)
            ax.set_yscale("log")
            ax.set_xlabel("$\\phi$")
            ax.set_ylabel("$\\eta_r$")
            ax.set_title("%s, $\\mu_s$ = %g (dotted: jammed points)" % (method, mu), fontsize=9)
            ax.legend(fontsize=7)
        save(fig, out, "fig11_eta_phi_%s" % method)
        plt.close(fig)


def reduced_points(methods):
    """(method, mu_s, sigma*, phi/phi_m, derived) of every done point whose group has a phi_m; phi_m is the one
    Fig. 15 draws (the bracket's middle where a jammed point contradicts the fit), so both figures agree."""
    rows = []
    for method, (table, fits) in methods.items():
        phim = {(f["mu_s"], sigma_of(f)): d[0] for f in fits["fits"] if (d := drawn_phi_m(f))}
        for p in table["points"]:
            s = group_sigma(p)
            key = (p["case"]["mu_s"], s)
            if p["status"] == "done" and key in phim and p.get("derived"):
                rows.append((method, key[0], s, p["summary"]["phi"] / phim[key], p["derived"]))
    return rows


def figure_reduced(methods, out):
    import matplotlib.pyplot as plt
    rows = reduced_points(methods)
    if not rows:
        return
    all_mu = sorted({r[1] for r in rows})
    panels = [("eta_r", "$\\eta_r$", "fig14_eta_reduced_phi", True),
              ("Sigma_c22/Sigma_12", "$-\\Sigma^c_{22}/\\Sigma_{12}$", "fig16_contact_22_reduced_phi", False),
              ("Sigma_c12/Sigma_12", "$\\Sigma^c_{12}/\\Sigma_{12}$", "fig19_contact_12_reduced_phi", False)]
    for key, label, name, log in panels:
        fig, ax = plt.subplots(figsize=(5.4, 4.0))
        for method, mu, s, x, d in rows:
            sign = -1.0 if key == "Sigma_c22/Sigma_12" else 1.0
            style = METHOD_STYLE.get(method, {})
            ax.errorbar(x, sign * d[key]["mean"], yerr=d[key]["sem"], marker=style.get("marker", "^"),
                        fillstyle=style.get("fillstyle", "full"), color=mu_colour(mu, all_mu), linestyle="none",
                        capsize=2, markersize=4)
        for method in methods:
            for mu in all_mu:
                ax.plot([], [], marker=METHOD_STYLE.get(method, {}).get("marker", "^"), linestyle="none",
                        fillstyle=METHOD_STYLE.get(method, {}).get("fillstyle", "full"), color=mu_colour(mu, all_mu),
                        label="%s, $\\mu_s$ = %g" % (method, mu))
        if log:
            ax.set_yscale("log")
        ax.set_xlabel("$\\phi / \\phi_m^\\mu(\\sigma^*)$")
        ax.set_ylabel(label)
        ax.legend(fontsize=7)
        save(fig, out, name)
        plt.close(fig)


def figure_22(methods, out):
    import matplotlib.pyplot as plt
    rows = reduced_points(methods)
    if not rows:
        return
    sigmas = sorted({r[2] for r in rows})
    fig, ax = plt.subplots(figsize=(5.4, 4.0))
    for method, mu, s, x, d in rows:
        if d["J"]["mean"] > 0 and d["mu"]["mean"] > 0:
            style = METHOD_STYLE.get(method, {})
            ax.errorbar(d["J"]["mean"], d["mu"]["mean"], xerr=d["J"]["sem"], yerr=d["mu"]["sem"],
                        marker=style.get("marker", "^"), fillstyle=style.get("fillstyle", "full"),
                        color=sigma_colour(s, sigmas), linestyle="none", capsize=2, markersize=4)
    for s in sigmas:
        ax.plot([], [], "o", color=sigma_colour(s, sigmas),
                label="$\\sigma^*$ = " + ("$\\infty$" if s == math.inf else "%g" % s))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("$J = -\\eta_0\\dot\\gamma / \\Sigma^c_{22}$")
    ax.set_ylabel("$\\mu = -\\Sigma_{12} / \\Sigma^c_{22}$")
    ax.legend(fontsize=7)
    ax.set_title("Macroscopic friction against viscous number (paper 004 Fig. 22)", fontsize=9)
    save(fig, out, "fig22_mu_J")
    plt.close(fig)


def main(argv):
    args = [a for a in argv[1:]]
    if not args or args[0] in ("-h", "--help"):
        usage()
    out = None
    if "--out" in args:
        k = args.index("--out")
        if k + 1 >= len(args):
            usage("--out needs a folder")
        out = args[k + 1]
        del args[k:k + 2]
    if len(args) != 1:
        usage("give exactly one RESULTS_DIR")
    results = args[0]
    if not os.path.isdir(results):
        usage("'%s' is not a folder" % results)
    require("matplotlib", "numpy")
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "suspend"
    methods = load(results)
    if not methods:
        usage("no METHOD/campaign.json with METHOD/phim.json under '%s' (run suspend sweep, then suspend phim)" % results)
    out = out or os.path.join(results, "figures")
    os.makedirs(out, exist_ok=True)
    figure_15(methods, out)
    figure_11(methods, out)
    figure_reduced(methods, out)
    figure_22(methods, out)
    print("figures written to %s" % out)


if __name__ == "__main__":
    main(sys.argv)
