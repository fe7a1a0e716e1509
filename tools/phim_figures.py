#!/usr/bin/python3
"""Figures of a phi_m(sigma*) campaign, after paper 004 (Orsi et al.): Fig. 15 (phi_m against sigma*, every method on
one plot, with the paper's non-adhesive limits; where a jammed point lies below the Maron-Pierce fit, the bracket
between the densest flowing and the least dense jammed point instead, and no fit; fits with chi^2/dof above
POOR_FIT_CHI2 open; the boundary searches' brackets hatched, with flowed/seeds at each end, in place of the one-seed
group they replace), Fig. 11 (eta_r against phi per sigma*, with the Maron-Pierce fits, dashed where a jammed point
contradicts them), Fig. 14 (eta_r against phi/phi_m, with the paper's Maron-Pierce master curve), Figs. 16-19
(contact-stress ratios against phi/phi_m), Fig. 22 (mu(J)) and Fig. 32 (alpha(sigma*) where the fits hold); Fig. 15
also carries the constraint-model curves and the yield stresses measured by creep. Figure text cites paper 004 as "Orsi et al.".

usage: tools/phim_figures.py RESULTS_DIR [--out FIGURE_DIR]

RESULTS_DIR holds one folder per method (pairwise/, fcm/), each with the campaign.json of `suspend sweep` and the
phim.json of `suspend phim`, and the boundary searches' folders (pairwise_boundary*/). Figures are written as PNG and SVG to FIGURE_DIR (default RESULTS_DIR/figures).
"""
import json
import math
import os
import sys

from debian_python import require

PAPER_NON_ADHESIVE = {0.0: 0.651, 0.1: 0.632, 0.5: 0.592}  # paper 004 Fig. 15 (FDM)
PAPER = "Orsi et al."  # paper 004 as the figures cite it (docs/references.md)
PAPER_ALPHA = (0.65, 1.0)  # paper 004's Maron-Pierce prefactors (Fig. 32, results/README.md): Fig. 14's master curve
# A Maron-Pierce fit with chi^2/dof above this is drawn open in Fig. 15: the errors are already inflated by
# sqrt(chi^2/dof), but above ~10 the misfit is systematic (the data curve away from the form), not noise.
POOR_FIT_CHI2 = 10.0
# The methods drawn. The boundary searches (three seeds per phi, issues 34 and 36) are drawn in Fig. 15 as searched
# brackets that replace the one-seed result of the same method and group; each kind of search has its hatch and a
# small shift in sigma*. Folder prefix (the first that matches) -> (method, label, hatch, shift).
METHOD_NAME = {"pairwise": "pairwise", "fcm": "FCM"}
SEARCHES = [
    ("pairwise_boundary_exact", ("pairwise", "pairwise, exact near field", "\\\\\\", 0.95)),
    ("pairwise_low_stress", ("pairwise", "pairwise, exact near field", "\\\\\\", 0.95)),
    ("pairwise_box20", ("pairwise", "pairwise, exact, $(20 a_1)^3$ box", "xxxx", 0.90)),
    ("pairwise_boundary", ("pairwise", "pairwise, singular near field", "/////", 1.0)),
    ("fcm_boundary", ("fcm", "FCM", "....", 1.06)),
    ("fcm_low_stress", ("fcm", "FCM", "....", 1.06)),
]
SEARCH_DRAWN_WIDTH = 0.01  # drawn (replacing the one-seed group) once converged: the searches' tolerance
YIELD_DRAWN_RATIO = 1.5  # a creep yield-stress bracket is drawn once its flowed end is within 1.5x its arrested end
METHOD_STYLE = {"pairwise": dict(marker="o", linestyle="-", fillstyle="full"),
                "fcm": dict(marker="s", linestyle="--", fillstyle="none")}
METHOD_SHIFT = {"pairwise": 1.0, "fcm": 1.06}  # Fig. 15: FCM drawn 6% to the right of its sigma* for clarity
SIGMA_LABEL = "$\\sigma^* = 6\\pi\\Sigma_{12} a_1^2 / F_{\\mathrm{adh}}$ (dimensionless)"
ETA_LABEL = "$\\eta_r = \\eta / \\eta_0$ (relative viscosity)"
REDUCED_PHI_LABEL = "$\\phi / \\phi_m(\\mu_s, \\sigma^*)$ (dimensionless)"


def method_name(method):
    return METHOD_NAME.get(method, method)


def method_order(method):
    return (list(METHOD_NAME).index(method) if method in METHOD_NAME else len(METHOD_NAME), method)


def sigma_text(sigma):
    return "$\\infty$" if sigma == math.inf else "%g" % sigma


def usage(message=None):
    if message:
        print("error: " + message, file=sys.stderr)
    print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
    sys.exit(2)


def search_kind(name):
    for prefix, kind in SEARCHES:
        if name.startswith(prefix):
            return kind
    return None


def load(results):
    """The methods' (campaign table, phim.json) by folder name, and the boundary searches' groups (phim.json fits of
    every search folder of SEARCHES, each with its kind under "search"), and the constraint-model fits
    (constraint_fit/*.json, tools/constraint_fit.py) by name."""
    methods, searched = {}, []
    for name in sorted(os.listdir(results)):
        folder = os.path.join(results, name)
        table, fits = os.path.join(folder, "campaign.json"), os.path.join(folder, "phim.json")
        if not (os.path.isfile(table) and os.path.isfile(fits)):
            continue
        if name in METHOD_NAME:
            with open(table) as t, open(fits) as f:
                methods[name] = (json.load(t), json.load(f))
        elif search_kind(name):
            with open(fits) as f:
                searched += [dict(g, search=search_kind(name)) for g in json.load(f)["fits"]]
    return methods, searched


def load_constraint_fits(results):
    folder = os.path.join(results, "constraint_fit")
    fits = {}
    if os.path.isdir(folder):
        for name in sorted(os.listdir(folder)):
            if name.endswith(".json"):
                with open(os.path.join(folder, name)) as f:
                    fits[name[:-5]] = json.load(f)
    return fits


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
    """The group's bracket (highest requested phi that flowed, lowest that jammed) when `suspend phim` made it the
    result (no fit, or a fit the data contradict), else None: one source for the figures, phim.json and the page's
    tables (tools/phim_table.py)."""
    if fit.get("result") == "bracket" and fit.get("bracket"):
        return tuple(fit["bracket"])
    return None


def drawn_phi_m(fit):
    """What Fig. 15 draws for a group: (phi_m, its error bar, the bracket or None); the bracket's middle and half
    width where the data contradict the fit, the fit with its total error (bootstrap and leave-one-point-out)
    otherwise; None for a group with neither."""
    b = bracket(fit)
    if b:
        return 0.5 * (b[0] + b[1]), 0.5 * (b[1] - b[0]), b
    if fit.get("phi_m") is not None:
        return fit["phi_m"], fit.get("phi_m_err_total", fit["phi_m_err"]), None
    return None


def poor_fit(fit):
    return (fit.get("chi2_reduced") or 0.0) > POOR_FIT_CHI2


def axis_break(ax, x):
    """Two short slanted strokes across the bottom and top spines at data abscissa x: the axis jumps from the finite
    sigma* to the non-adhesive limit drawn at 'infinity'."""
    import matplotlib.transforms as transforms
    trans = transforms.blended_transform_factory(ax.transData, ax.transAxes)
    for y in (0.0, 1.0):
        for dx in (0.965, 1.035):
            ax.plot([x * dx / 1.04, x * dx * 1.04], [y - 0.015, y + 0.015], transform=trans, color="k",
                    linewidth=0.9, clip_on=False, zorder=5)
        ax.plot([x * 0.965, x * 1.035], [y, y], transform=trans, color="white", linewidth=2.5, clip_on=False,
                zorder=4)


def searched_bracket(ax, x, b, fractions, seeds, colour, hatch="/////"):
    """A searched bracket: a hatched bar from the densest phi that a majority of seeds flowed at to the least dense
    that a majority jammed at, each end labelled with flowed/seeds."""
    from matplotlib.patches import Rectangle
    ax.add_patch(Rectangle((x / 1.07, b[0]), x * (1.07 - 1 / 1.07), b[1] - b[0], facecolor="white", edgecolor=colour,
                           hatch=hatch, linewidth=1.2, zorder=3))
    for phi, fraction, n, va in ((b[0], fractions[0], seeds[0], "top"), (b[1], fractions[1], seeds[1], "bottom")):
        ax.annotate("%d/%d" % (round(fraction * n), n), (x * 1.08, phi), fontsize=5.5, color=colour, va=va,
                    ha="left", zorder=5)


def figure_15(methods, out, searched=(), constraint=None, yield_stress=None):
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    fig, ax = plt.subplots(figsize=(8.6, 4.6))
    # a search still running has a wide bracket: not yet a result
    searched = [f for f in searched
                if f.get("bracket") and f["bracket"][1] - f["bracket"][0] <= SEARCH_DRAWN_WIDTH + 1e-9]
    replaced = {(f["search"][0], f["mu_s"], sigma_of(f)) for f in searched}
    drawn = {method: [(f, d) for f in fits["fits"] if (d := drawn_phi_m(f))
                      and (method, f["mu_s"], sigma_of(f)) not in replaced]
             for method, (_, fits) in methods.items()}
    shown = [pair for pairs in drawn.values() for pair in pairs]
    shown += [(f, (0.5 * sum(f["bracket"]), 0.5 * (f["bracket"][1] - f["bracket"][0]), tuple(f["bracket"])))
              for f in searched]
    all_mu = sorted({f["mu_s"] for f, _ in shown} | set(PAPER_NON_ADHESIVE))
    finite_max = max([sigma_of(f) for f, _ in shown if sigma_of(f) < math.inf] + [10.0])
    x_inf = finite_max * 3.0  # where the non-adhesive limit is drawn
    handles = []
    any_poor = any_bracket = False
    for method, pairs in sorted(drawn.items(), key=lambda item: method_order(item[0])):
        style = METHOD_STYLE.get(method, dict(marker="^", linestyle=":"))
        shift = METHOD_SHIFT.get(method, 1.0)
        for mu in sorted({f["mu_s"] for f, _ in pairs}):
            group = sorted(((f, d) for f, d in pairs if f["mu_s"] == mu), key=lambda pair: sigma_of(pair[0]))
            colour = mu_colour(mu, all_mu)
            # Guide lines join neighbouring fits only: never a fit to a bracket, nor a finite sigma* to infinity.
            run = []
            for f, d in group + [(None, None)]:
                if f is not None and not d[2] and sigma_of(f) < math.inf:
                    run.append((sigma_of(f) * shift, d[0]))
                    continue
                if len(run) > 1:
                    ax.plot([r[0] for r in run], [r[1] for r in run], color=colour, linestyle=style["linestyle"],
                            linewidth=1.2, zorder=2)
                run = []
            for f, (phi_m, err, b) in group:
                x = (x_inf if sigma_of(f) == math.inf else sigma_of(f)) * shift
                if b:  # the data contradict the fit: the bracket is the result, no marker and no fit
                    ax.errorbar([x, x], [b[0], b[1]], color=colour, linewidth=5, alpha=0.6, capsize=0,
                                solid_capstyle="butt", zorder=3)
                    ax.plot([x, x], [b[0], b[1]], color=colour, linestyle="none", marker="_", markersize=9,
                            markeredgewidth=1.5, zorder=3)
                    any_bracket = True
                    continue
                poor = poor_fit(f)
                any_poor |= poor
                ax.errorbar([x], [phi_m], yerr=[err], color=colour, capsize=3, marker=style["marker"],
                            markersize=6, linestyle="none", markerfacecolor="white" if poor else colour,
                            markeredgewidth=1.3, zorder=4)
            handles.append(Line2D([], [], color=colour, marker=style["marker"], linestyle=style["linestyle"],
                                  label="%s, $\\mu_s$ = %g" % (method_name(method), mu)))
    for kind in sorted({f["search"] for f in searched}, key=lambda k: (method_order(k[0]), k[1])):
        _, label, hatch, shift = kind
        for mu in sorted({f["mu_s"] for f in searched if f["search"] == kind}):
            colour = mu_colour(mu, all_mu)
            for f in (f for f in searched if f["mu_s"] == mu and f["search"] == kind):
                x = (x_inf if sigma_of(f) == math.inf else sigma_of(f)) * shift
                searched_bracket(ax, x, f["bracket"], f["bracket_flowing_fraction"], f["bracket_seeds"], colour,
                                 hatch)
            handles.append(Patch(facecolor="white", edgecolor=colour, hatch=hatch,
                                 label="%s, $\\mu_s$ = %g, searched:\nflowed/seeds at each end" % (label, mu)))
    # The constraint-rheology boundary of each near-field model and method (tools/constraint_fit.py), where it fits.
    for name, result in sorted((constraint or {}).items()):
        for row in result.get("frictions", []):
            # kappa = 1 or free, whichever fits better with every parameter inside its bounds
            usable = [f for f in (row.get("fit"), row.get("fit_free_kappa"))
                      if f and "error" not in f and not f.get("at_bound") and f.get("dof", 0) > 0]
            if not usable or row["mu_s"] not in all_mu:
                continue
            f = min(usable, key=lambda q: q["chi2"] / q["dof"])
            import numpy as np
            s = np.logspace(math.log10(0.25), math.log10(finite_max), 80)
            a = -np.expm1(-np.power(f["sigma_a"] / s, f["kappa"]))
            ax.plot(s, f["phi_alp"] * a + f["phi_mu"] * (1 - a), color=mu_colour(row["mu_s"], all_mu), linewidth=0.8,
                    linestyle=(0, (1, 1)) if name.startswith("fcm") else "-", alpha=0.7, zorder=1)
    for mu, phi, lo, hi in yield_stress or []:
        if mu in all_mu:
            ax.plot([lo, hi], [phi, phi], color=mu_colour(mu, all_mu), linewidth=2.5, solid_capstyle="butt", zorder=4)
            ax.plot([lo, hi], [phi, phi], color=mu_colour(mu, all_mu), marker="|", markersize=8, linestyle="none",
                    zorder=4)
    if yield_stress:
        handles.append(Line2D([], [], color="0.3", linewidth=2.5, marker="|", markersize=8,
                              label="yield stress by creep at fixed $\\phi$:\narrested to flowed $\\sigma^*$"))
    if constraint:
        handles.append(Line2D([], [], color="0.3", linewidth=0.8, alpha=0.7,
                              label="constraint model fit:\n$\\phi_{alp} a + \\phi_\\mu (1 - a)$"))
    if any_poor:
        handles.append(Line2D([], [], color="0.3", marker="o", markerfacecolor="white", linestyle="none",
                              label="open: Maron-Pierce fit with\n$\\chi^2/\\mathrm{dof} > %g$" % POOR_FIT_CHI2))
    if any_bracket:
        handles.append(Patch(color="0.3", alpha=0.6,
                             label="bar: densest flowing to least dense\njammed $\\phi$ (a jammed point lies\n"
                                   "below the fitted $\\phi_m$: no fit)"))
    for mu, phi in PAPER_NON_ADHESIVE.items():
        ax.axhline(phi, color=mu_colour(mu, all_mu), linestyle=":", linewidth=1.1, zorder=1)
    handles.append(Line2D([], [], color="0.3", linestyle=":",
                          label="%s, no adhesion (FDM),\ncolour by $\\mu_s$" % PAPER))
    ax.axvspan(0.7, 0.8, color="0.88", zorder=0)
    handles.append(Patch(color="0.88", label="%s: $\\mu_s \\geq 0.3$ curves\nmeet near $\\phi_m \\approx 0.5$"
                                           % PAPER))
    lowest = min([d[2][0] if d[2] else d[0] - d[1] for _, d in shown] + [0.47])
    highest = max([d[2][1] if d[2] else d[0] + d[1] for _, d in shown] + [0.67])
    ax.set_ylim(lowest - 0.01, highest + 0.01)
    ax.set_xscale("log")
    lowest_sigma = min([sigma_of(f) for f, _ in shown] + [0.5])
    ax.set_xlim(0.8 * lowest_sigma, x_inf * 1.5)
    ax.set_xticks([1, 10, x_inf])
    ax.set_xticks([t for t in (0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 2, 3, 4, 5, 6, 7, 8, 9) if t > 0.8 * lowest_sigma],
                  minor=True)
    ax.set_xticklabels(["1", "10", "$\\infty$"])
    axis_break(ax, math.sqrt(finite_max * x_inf))
    ax.set_xlabel(SIGMA_LABEL)
    ax.set_ylabel("$\\phi_m(\\mu_s, \\sigma^*)$ (maximum volume fraction)")
    ax.legend(handles=handles, fontsize=7.5, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0,
              frameon=False, labelspacing=0.9)
    save(fig, out, "fig15_phim_sigma_star")
    plt.close(fig)


def figure_11(methods, out):
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.lines import Line2D
    for method, (_, fits) in methods.items():
        mus = sorted({f["mu_s"] for f in fits["fits"]})
        fig, axes = plt.subplots(1, len(mus), figsize=(4.4 * len(mus), 4.0), squeeze=False)
        for ax, mu in zip(axes[0], mus):
            groups = [f for f in fits["fits"] if f["mu_s"] == mu]
            sigmas = [sigma_of(f) for f in groups]
            extra = []
            for f in groups:
                c = sigma_colour(sigma_of(f), sigmas)
                data = np.array(f["data"]).reshape(-1, 3)
                label = "$\\sigma^*$ = " + sigma_text(sigma_of(f))
                if f.get("chi2_reduced") is not None:
                    label += ", $\\chi^2/\\mathrm{dof}$ = %.3g" % f["chi2_reduced"]
                if len(data):
                    ax.errorbar(data[:, 0], data[:, 1], yerr=data[:, 2], fmt="o", color=c, capsize=2, label=label,
                                markersize=5)
                if f.get("phi_m") is not None:
                    # a fit whose phi_m lies above a jammed point is contradicted by the data: dashed
                    contradicted = bool(bracket(f))
                    phi = np.linspace(min(data[:, 0].min(), 0.3), f["phi_m"] * 0.985, 100)
                    ax.plot(phi, f["alpha"] / (1 - phi / f["phi_m"]) ** 2, color=c,
                            linestyle="--" if contradicted else "-", linewidth=1.2)
                    if contradicted and "--" not in extra:
                        extra.append("--")
                for phi_j in f.get("jammed_phi", []):
                    ax.axvline(phi_j, color=c, linestyle=":", linewidth=1.0)
                    if ":" not in extra:
                        extra.append(":")
            handles, _ = ax.get_legend_handles_labels()
            handles += [Line2D([], [], color="0.3", linestyle="-", label="Maron-Pierce fit")]
            if "--" in extra:
                handles.append(Line2D([], [], color="0.3", linestyle="--",
                                      label="fit past a jammed point\n(not the result)"))
            if ":" in extra:
                handles.append(Line2D([], [], color="0.3", linestyle=":", label="$\\phi$ of a jammed point"))
            ax.set_yscale("log")
            ax.set_xlabel("$\\phi$ (volume fraction)")
            ax.set_ylabel(ETA_LABEL)
            ax.set_title("%s, $\\mu_s$ = %g" % (method_name(method), mu), fontsize=9)
            ax.legend(handles=handles, fontsize=6.5, loc="upper left")
        fig.tight_layout()
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


def method_marker(method):
    style = METHOD_STYLE.get(method, {})
    return dict(marker=style.get("marker", "^"), fillstyle=style.get("fillstyle", "full"))


def figure_reduced(methods, out):
    import matplotlib.pyplot as plt
    import numpy as np
    rows = reduced_points(methods)
    if not rows:
        return
    all_mu = sorted({r[1] for r in rows})
    panels = [("eta_r", ETA_LABEL, "fig14_eta_reduced_phi", True, "upper left"),
              ("Sigma_c22/Sigma_12", "$-\\Sigma^c_{22}/\\Sigma_{12}$ (dimensionless)", "fig16_contact_22_reduced_phi",
               False, "upper left"),
              ("Sigma_c12/Sigma_12", "$\\Sigma^c_{12}/\\Sigma_{12}$ (dimensionless)", "fig19_contact_12_reduced_phi",
               False, "lower right")]
    for key, label, name, log, where in panels:
        fig, ax = plt.subplots(figsize=(5.6, 4.2))
        if log:
            ax.set_yscale("log")
        sign = -1.0 if key == "Sigma_c22/Sigma_12" else 1.0
        for method, mu, s, x, d in rows:
            ax.errorbar(x, sign * d[key]["mean"], yerr=d[key]["sem"], color=mu_colour(mu, all_mu), linestyle="none",
                        capsize=2, markersize=4, **method_marker(method))
        # only the series that have points here
        for method in sorted(methods, key=method_order):
            for mu in all_mu:
                if any(r[0] == method and r[1] == mu for r in rows):
                    ax.plot([], [], linestyle="none", color=mu_colour(mu, all_mu),
                            label="%s, $\\mu_s$ = %g" % (method_name(method), mu), **method_marker(method))
        if key == "eta_r":
            # the axes follow the data; the master curve is cut at their edges
            ax.relim()
            ax.autoscale_view()
            xlim, ylim = ax.get_xlim(), ax.get_ylim()
            x = np.linspace(xlim[0], 0.999, 400)
            lo, hi = PAPER_ALPHA
            ax.fill_between(x, lo / (1 - x) ** 2, hi / (1 - x) ** 2, color="0.82", zorder=0, linewidth=0,
                            label="Maron-Pierce $\\eta_r = \\alpha\\,(1 - \\phi/\\phi_m)^{-2}$\n"
                                  "$\\alpha$ = %g$-$%g (%s)" % (lo, hi, PAPER))
            ax.set_xlim(xlim)
            ax.set_ylim(ylim)
        ax.set_xlabel(REDUCED_PHI_LABEL)
        ax.set_ylabel(label)
        ax.legend(fontsize=7, loc=where)
        save(fig, out, name)
        plt.close(fig)


def figure_32(methods, searched, out):
    """Paper 004 Fig. 32: the Maron-Pierce prefactor alpha(sigma*) of every fit that holds (no jammed point below its
    phi_m, chi^2/dof at most POOR_FIT_CHI2), per method and friction, against the paper's 0.65-1."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    rows = []
    for method, (_, fits) in methods.items():
        rows += [(method, f) for f in fits["fits"]]
    rows += [(f["search"][0], f) for f in searched]
    rows = [(m, f) for m, f in rows if f.get("alpha") is not None and f.get("result") != "bracket"
            and not poor_fit(f) and sigma_of(f) < math.inf]
    if not rows:
        return
    all_mu = sorted({f["mu_s"] for _, f in rows})
    fig, ax = plt.subplots(figsize=(5.6, 4.0))
    for method, f in rows:
        style = METHOD_STYLE.get(method, dict(marker="^"))
        ax.errorbar([sigma_of(f) * METHOD_SHIFT.get(method, 1.0)], [f["alpha"]], yerr=[f["alpha_err"]],
                    color=mu_colour(f["mu_s"], all_mu), marker=style["marker"], linestyle="none", capsize=3)
    ax.axhspan(*PAPER_ALPHA, color="0.9", zorder=0)
    handles = [Line2D([], [], color=mu_colour(mu, all_mu), marker="o", linestyle="none", label="$\\mu_s$ = %g" % mu)
               for mu in all_mu]
    handles += [Line2D([], [], color="0.3", marker=METHOD_STYLE[m]["marker"], linestyle="none",
                       label=method_name(m)) for m in METHOD_STYLE if any(r[0] == m for r in rows)]
    handles.append(Line2D([], [], color="0.85", linewidth=8, label="%s: %g$-$%g" % ((PAPER,) + PAPER_ALPHA)))
    ax.set_xscale("log")
    ax.set_xlabel(SIGMA_LABEL)
    ax.set_ylabel("$\\alpha(\\sigma^*)$ (Maron-Pierce prefactor)")
    ax.legend(handles=handles, fontsize=7.5, frameon=False)
    save(fig, out, "fig32_alpha_sigma_star")
    plt.close(fig)


def yield_stress_brackets(results):
    """The yield stress by creep bisected in sigma* at fixed phi (results/phim/pairwise_yield_stress): per (mu_s, phi)
    the largest stress at which most seeds arrested and the smallest at which most flowed, once that bracket is
    narrower than YIELD_DRAWN_RATIO (a search still at its first halvings says little and would cover the figure)."""
    path = os.path.join(results, "pairwise_yield_stress", "campaign.json")
    if not os.path.isfile(path):
        return []
    with open(path) as f:
        points = json.load(f)["points"]
    levels = {}
    for p in points:
        if p.get("status") not in ("done", "jammed"):
            continue
        c = p["case"]
        key = (c["mu_s"], c["phi"])
        sigma = c["shear_stress"] / c["g_adh"] if c.get("g_adh") else None
        if sigma is None:
            continue
        tally = levels.setdefault(key, {}).setdefault(sigma, [0, 0])
        tally[0 if p["status"] == "jammed" else 1] += 1
    out = []
    for (mu, phi), tallies in sorted(levels.items()):
        arrested = [s for s, (j, f) in tallies.items() if j > f]
        flowed = [s for s, (j, f) in tallies.items() if f > j]
        if arrested and flowed and min(flowed) <= YIELD_DRAWN_RATIO * max(arrested):
            out.append((mu, phi, max(arrested), min(flowed)))
    return out


def figure_22(methods, out):
    import matplotlib.pyplot as plt
    rows = reduced_points(methods)
    if not rows:
        return
    sigmas = sorted({r[2] for r in rows})
    fig, ax = plt.subplots(figsize=(5.6, 4.2))
    for method, mu, s, x, d in rows:
        if d["J"]["mean"] > 0 and d["mu"]["mean"] > 0:
            ax.errorbar(d["J"]["mean"], d["mu"]["mean"], xerr=d["J"]["sem"], yerr=d["mu"]["sem"],
                        color=sigma_colour(s, sigmas), linestyle="none", capsize=2, markersize=4,
                        **method_marker(method))
    for s in sigmas:
        ax.plot([], [], "o", color=sigma_colour(s, sigmas), label="$\\sigma^*$ = " + sigma_text(s))
    for method in sorted(methods, key=method_order):
        if any(r[0] == method for r in rows):
            ax.plot([], [], linestyle="none", color="0.3", label=method_name(method), **method_marker(method))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("$J = -\\eta_0\\dot\\gamma / \\Sigma^c_{22}$ (viscous number, dimensionless)")
    ax.set_ylabel("$\\mu = -\\Sigma_{12} / \\Sigma^c_{22}$ (dimensionless)")
    ax.legend(fontsize=7, loc="upper left")
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
    methods, searched = load(results)
    if not methods:
        usage("no METHOD/campaign.json with METHOD/phim.json under '%s' (run suspend sweep, then suspend phim)" % results)
    out = out or os.path.join(results, "figures")
    os.makedirs(out, exist_ok=True)
    figure_15(methods, out, searched, load_constraint_fits(results), yield_stress_brackets(results))
    figure_32(methods, searched, out)
    figure_11(methods, out)
    figure_reduced(methods, out)
    figure_22(methods, out)
    print("figures written to %s" % out)


if __name__ == "__main__":
    main(sys.argv)
