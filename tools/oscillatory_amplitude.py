#!/usr/bin/env python3
"""eta'(gamma_0) of a dense frictional suspension under oscillatory shear, from the campaign of
cases/protocols/oscillatory_amplitude_campaign.yaml and the steady run of the same case, into
results/protocols/oscillatory_amplitude.{md,json,png}.

usage: tools/oscillatory_amplitude.py CAMPAIGN_DIR STEADY_RUN_DIR [OUT_DIR=results/protocols]
(run by tools/oscillatory_amplitude.sh)"""
import json
import os
import sys

from debian_python import require


def usage(message=None):
    if message:
        print("error: " + message, file=sys.stderr)
    print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
    sys.exit(2)


def main():
    if len(sys.argv) < 3 or sys.argv[1].startswith("-"):
        usage()
    campaign, steady_dir = sys.argv[1], sys.argv[2]
    for f in (os.path.join(campaign, "campaign.json"), os.path.join(steady_dir, "summary.json")):
        if not os.path.isfile(f):
            usage(f + " does not exist")
    require("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    out = sys.argv[3] if len(sys.argv) > 3 else os.path.join(os.path.dirname(__file__), "..", "results", "protocols")
    os.makedirs(out, exist_ok=True)
    points = json.load(open(os.path.join(campaign, "campaign.json")))["points"]
    steady = json.load(open(os.path.join(steady_dir, "summary.json")))
    rows = []
    for p in points:
        s = p.get("summary") or {}
        o = s.get("oscillatory")
        if p["status"] != "done" or not o:
            continue
        rows.append({"strain_amplitude": p["parameters"]["flow.strain_amplitude"],
                     "cycles": o["cycles"],
                     "eta_prime": o["eta_prime"], "eta_double_prime": o["eta_double_prime"],
                     "I3_I1": o["harmonics"]["I3_I1"],
                     "contact_eta_prime": (o["contributions"]["contact_normal"]["eta_prime"]["mean"] +
                                           o["contributions"]["contact_tangential"]["eta_prime"]["mean"]),
                     "Z": s["contacts_per_particle"]["mean"]})
    rows.sort(key=lambda r: r["strain_amplitude"])
    eta_s = steady["eta_r"]
    result = {"steady": {"eta_r": eta_s, "contacts_per_particle": steady["contacts_per_particle"]}, "points": rows}
    json.dump(result, open(os.path.join(out, "oscillatory_amplitude.json"), "w"), indent=1)

    def pm(e):
        sem = e["sem"]
        return f'{e["mean"]:.3g} +- {sem:.2g}' if sem is not None else f'{e["mean"]:.3g}'
    lines = ["| gamma_0 | cycles averaged | eta' | eta'' | eta' / steady eta_r | contact part of eta' | I3/I1 | Z |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f'| {r["strain_amplitude"]:g} | {r["cycles"]} | {pm(r["eta_prime"])} | {pm(r["eta_double_prime"])} | '
                     f'{r["eta_prime"]["mean"] / eta_s["mean"]:.3f} | {r["contact_eta_prime"]:.3g} | {r["I3_I1"]:.3f} | '
                     f'{r["Z"]:.2f} |')
    lines.append(f'| steady | - | {pm(eta_s)} | - | 1 | - | - | {steady["contacts_per_particle"]["mean"]:.2f} |')
    open(os.path.join(out, "oscillatory_amplitude_table.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    fig, ax = plt.subplots(figsize=(5, 3.6))
    g = [r["strain_amplitude"] for r in rows]
    ax.errorbar(g, [r["eta_prime"]["mean"] for r in rows],
                yerr=[r["eta_prime"]["sem"] or 0 for r in rows], marker="o", label="eta'")
    ax.plot(g, [r["contact_eta_prime"] for r in rows], "s--", label="contact part of eta'")
    ax.axhline(eta_s["mean"], color="k", lw=0.8, label="steady shear eta_r")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("strain amplitude gamma_0")
    ax.set_ylabel("eta' / eta_0")
    ax.legend(frameon=False, fontsize=8)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out, "oscillatory_amplitude." + ext), dpi=150)


if __name__ == "__main__":
    main()
