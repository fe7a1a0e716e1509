#!/usr/bin/python3
"""Compare pairwise-engine runs with the published fits (stdlib only).

usage: validate_pairwise.py frictionless DIR_phi1 DIR_phi2 ... [--tolerance 0.2]
       validate_pairwise.py frictional   DIR_phi1 ...          [--tolerance 0.25]
       validate_pairwise.py thickening   DIR_low_rate DIR_high_rate [--factor 3]
       validate_pairwise.py normal_stress frictionless|frictional DIR ...
The normal_stress check holds the signs docs/validation.md section 4 found, each at least one standard error from
zero (the reduced CI runs are short): N1 < 0, N2 < 0 and Pi > 0; frictionless, the contacts' N1 > 0 > their N2
and a lubrication N1 below zero that outweighs the contacts' (the negative N1 is hydrodynamic) and lies below the
lubrication N2; frictional, the contacts' N2 < 0 and below their N1 (the order the contacts set).
Each DIR holds a summary.json. Prints one line per run and exits 1 if a criterion fails.
"""
import json
import sys

FITS = {  # Mari et al. 2014, via paper 000 Fig. 7
    "frictionless": lambda phi: 1.4 * (1 - phi / 0.66) ** -1.6,
    "frictional": lambda phi: 0.71 * (1 - phi / 0.575) ** -2.3,
}


def load(d):
    try:
        with open(d + "/summary.json") as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"error: {d}/summary.json: {e}")


def check_normal_stress(kind, d):
    """Signs of N1, N2, Pi and of their contact and lubrication parts, each at least one standard error from zero."""
    s = load(d)
    parts = s["contributions"]
    checks = [("N1 < 0", s["N1"], -1), ("N2 < 0", s["N2"], -1), ("Pi > 0", s["Pi"], +1)]
    def combined(*terms):  # sum of (sign, value) terms, errors added in quadrature
        return {"mean": sum(sg * v["mean"] for sg, v in terms), "sem": sum(v["sem"] ** 2 for _, v in terms) ** 0.5}

    if kind == "frictionless":
        contact, lub = parts["contact_normal"], parts["lubrication"]
        checks += [("contact N1 > 0", contact["N1"], +1), ("contact N2 < 0", contact["N2"], -1),
                   ("lubrication N1 < 0", lub["N1"], -1),
                   ("lubrication N1 + contact N1 < 0", combined((1, lub["N1"]), (1, contact["N1"])), -1),
                   # the order: the lubrication stress puts N1 below N2 (|N1| > |N2| of its part)
                   ("lubrication N1 - N2 < 0", combined((1, lub["N1"]), (-1, lub["N2"])), -1)]
    else:
        normal, tangential = parts["contact_normal"], parts["contact_tangential"]
        checks += [("contact N2 < 0", normal["N2"], -1),
                   # the order: the contacts, normal and frictional, put N2 below N1 (|N2| > |N1|)
                   ("contact N2 - N1 < 0",
                    combined((1, normal["N2"]), (1, tangential["N2"]), (-1, normal["N1"]), (-1, tangential["N1"])),
                    -1)]
    ok = True
    for name, v, sign in checks:
        good = sign * v["mean"] >= v["sem"] >= 0
        ok &= good
        print(f"normal stress {kind:12s} phi {s['phi']:.4f}  {name:32s} {v['mean']:+9.4g} +- {v['sem']:.2g}"
              f"  {'ok' if good else 'FAIL'}")
    return ok


def main(argv):
    if len(argv) >= 4 and argv[1] == "normal_stress" and argv[2] in ("frictionless", "frictional"):
        return 0 if all([check_normal_stress(argv[2], d) for d in argv[3:]]) else 1
    if len(argv) < 3 or argv[1] not in ("frictionless", "frictional", "thickening"):
        print(__doc__.split("\n\n")[1].split("\nEach")[0], file=sys.stderr)
        return 2
    kind, rest = argv[1], argv[2:]
    opts = {"--tolerance": None, "--factor": "3"}
    dirs = []
    i = 0
    while i < len(rest):
        if rest[i] in opts:
            if i + 1 >= len(rest):
                sys.exit(f"error: {rest[i]} needs a value")
            opts[rest[i]] = rest[i + 1]
            i += 2
        else:
            dirs.append(rest[i])
            i += 1
    ok = True
    if kind in FITS:
        tol = float(opts["--tolerance"] or (0.2 if kind == "frictionless" else 0.25))
        rows = []
        for d in dirs:
            s = load(d)
            phi, eta, sem = s["phi"], s["eta_r"]["mean"], s["eta_r"]["sem"]
            fit = FITS[kind](phi)
            dev = eta / fit - 1
            good = abs(dev) <= tol
            ok &= good
            rows.append((phi, eta, s["Pi"]["mean"]))
            print(f"{kind:12s} phi {phi:.4f}  eta_r {eta:9.4g} +- {sem:.2g}  fit {fit:9.4g}  "
                  f"deviation {100 * dev:+6.1f}% (allowed {100 * tol:.0f}%)  Pi {s['Pi']['mean']:.4g} +- {s['Pi']['sem']:.2g}"
                  f"  {'ok' if good else 'FAIL'}")
        if kind == "frictionless" and len(rows) >= 2:
            rows.sort()
            (p0, e0, pi0), (p1, e1, pi1) = rows[0], rows[-1]
            good = pi0 > 0 and pi1 / pi0 > e1 / e0
            ok &= good
            print(f"Pi rises faster than eta_r from phi {p0:.3f} to {p1:.3f}: Pi x{pi1 / pi0:.3g}, eta_r x{e1 / e0:.3g}"
                  f"  {'ok' if good else 'FAIL'}")
    elif kind == "thickening":
        low, high = load(dirs[0]), load(dirs[1])
        ratio = high["eta_r"]["mean"] / low["eta_r"]["mean"]
        good = ratio >= float(opts["--factor"])
        ok &= good
        print(f"thickening: eta_r {low['eta_r']['mean']:.4g} (low rate) -> {high['eta_r']['mean']:.4g} (high rate), "
              f"x{ratio:.3g} (required x{opts['--factor']})  {'ok' if good else 'FAIL'}")
    else:
        sys.exit(__doc__)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
