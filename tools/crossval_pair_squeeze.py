#!/usr/bin/python3
"""Squeeze resistance of the two-sphere cross-validation case (cases/validation/crossval_pair_squeeze.yaml).

usage: crossval_pair_squeeze.py DIR [--table FILE] [--tolerance 0.03]

DIR is the output of `suspend crossval cases/validation/crossval_pair_squeeze.yaml --out DIR` (DIR/pairwise and
DIR/fcm hold run.h5). In every snapshot the two equal spheres sit on one line (the vorticity axis) and separate
under the electrostatic repulsion F = F_ER a-bar exp(-h / lambda_D) (paper 000 eq. 6, parameters read from the
case stored in run.h5). Their relative velocity along the line of centres u gives each model's squeeze function,
    X11A - X12A = 2 F / (6 pi eta a u)        (eta = 1, a = 1),
interpolated to xi = h / a = 0.01, 0.02, 0.05, 0.1 and compared with the exact value of the Jeffrey & Onishi table
(lambda = 1 rows). Two verdicts per gap: FCM + correction against the exact value, and against the pairwise model.
The case runs the pairwise model with `lubrication.functions: exact_relative` (the exact relative-motion
functions of equal spheres); with the default singular functions (Stokes drag + the singular terms of paper 000
Appendix A) it lacks the O(1) remainder of X12A and falls 2.9% / 5.1% below the exact function at xi = 0.05 / 0.1
(docs/lubrication.md section 3). Exits 1 when FCM differs from the exact value or from the pairwise model by more
than the tolerance. Needs Debian's python3-h5py (the rest is the standard library).
"""
import math
import os
import sys

from debian_python import require

XI = (0.01, 0.02, 0.05, 0.1)


def exact_squeeze(table):
    """(xi, X11A - X12A) of the equal-sphere rows of the resistance table, sorted by xi."""
    self_terms, pair_terms = {}, {}
    with open(table) as f:
        for line in f:
            parts = line.split()
            if len(parts) < 4:
                continue
            try:
                s, lam, gamma, xa = (float(v) for v in parts[:4])
            except ValueError:
                continue
            if lam != 1.0:
                continue
            (self_terms if gamma == 0.0 else pair_terms)[s] = xa
    return sorted((s - 2.0, self_terms[s] - pair_terms[s]) for s in self_terms if s in pair_terms)


def interpolate(points, xi):
    """Linear interpolation in log(xi) of sorted (xi, value) points."""
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x0 <= xi <= x1:
            t = (math.log(xi) - math.log(x0)) / (math.log(x1) - math.log(x0))
            return y0 + t * (y1 - y0)
    raise ValueError(f"xi = {xi} outside the range {points[0][0]:.3g} ... {points[-1][0]:.3g} of the data")


def repulsion_of(case_text):
    """F_ER and lambda_D from the resolved case (contact.repulsion.force, .debye_length)."""
    force = debye = None
    in_repulsion = False
    for line in case_text.splitlines():
        stripped = line.strip()
        if stripped.startswith("repulsion:"):
            in_repulsion = True
            continue
        if in_repulsion:
            if not line.startswith("    "):
                in_repulsion = False
            elif stripped.startswith("force:"):
                force = float(stripped.split(":", 1)[1])
            elif stripped.startswith("debye_length:"):
                debye = float(stripped.split(":", 1)[1])
    if force is None or debye is None:
        raise ValueError("the case in run.h5 has no contact.repulsion force and debye_length")
    return force, debye


def measured_squeeze(run_h5):
    """(xi, 2 F / (6 pi u)) from the snapshots of one run, sorted by xi."""
    os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
    import suspend  # python/suspend: the reader of run.h5
    run = suspend.load_run(run_h5)
    force, debye = repulsion_of(run.attributes["case"])
    points = []
    for snap in run.snapshots():
        x, v, a = snap["position"], snap["velocity"], snap["radius"]
        if len(a) != 2 or abs(a[0] - 1.0) > 1e-12 or abs(a[1] - 1.0) > 1e-12:
            raise ValueError(f"{run_h5}: expected two spheres of radius 1")
        d = [x[1][k] - x[0][k] for k in range(3)]
        r = math.sqrt(sum(c * c for c in d))
        n = [c / r for c in d]
        u = sum((v[1][k] - v[0][k]) * n[k] for k in range(3))
        h = r - 2.0
        if h <= 0.0 or u <= 0.0:
            continue
        f_rep = force * 1.0 * math.exp(-h / debye)  # a-bar = 1 for equal spheres of radius 1
        points.append((h, 2.0 * f_rep / (6.0 * math.pi * u)))
    points.sort()
    return points


def main(argv):
    args = argv[1:]
    here = os.path.dirname(os.path.abspath(__file__))
    table = os.path.join(here, "..", "tests", "data", "two_sphere_resistance_table.txt")
    tolerance = 0.03
    dirs = []
    i = 0
    try:
        while i < len(args):
            if args[i] in ("-h", "--help"):
                raise ValueError
            if args[i] == "--table":
                table, i = args[i + 1], i + 2
            elif args[i] == "--tolerance":
                tolerance, i = float(args[i + 1]), i + 2
            else:
                dirs.append(args[i])
                i += 1
    except (IndexError, ValueError):
        dirs = []
    if len(dirs) != 1:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    for m in ("pairwise", "fcm"):
        if not os.path.isfile(os.path.join(dirs[0], m, "run.h5")):
            print(f"error: {os.path.join(dirs[0], m, 'run.h5')} not found (run suspend crossval first)", file=sys.stderr)
            return 2
    require("h5py", "numpy")
    exact = exact_squeeze(table)
    runs = {m: measured_squeeze(os.path.join(dirs[0], m, "run.h5")) for m in ("pairwise", "fcm")}
    ok = True
    print(f"{'xi':>6s} {'exact':>10s} {'pairwise':>10s} {'(vs exact)':>10s} {'fcm':>10s} {'(vs exact)':>10s} "
          f"{'(vs pairwise)':>13s}")
    for xi in XI:
        e = interpolate(exact, xi)
        p = interpolate(runs["pairwise"], xi)
        c = interpolate(runs["fcm"], xi)
        exact_ok = abs(c / e - 1) <= tolerance
        pairwise_ok = abs(c / p - 1) <= tolerance
        ok &= exact_ok and pairwise_ok
        print(f"{xi:6.3f} {e:10.5g} {p:10.5g} {100 * (p / e - 1):+9.2f}% {c:10.5g} {100 * (c / e - 1):+9.2f}% "
              f"{100 * (c / p - 1):+12.2f}%  fcm vs exact {'ok' if exact_ok else 'FAIL'}, "
              f"fcm vs pairwise {'ok' if pairwise_ok else 'FAIL'}")
    print(f"X11A - X12A = 2 F / (6 pi a u) from {len(runs['pairwise'])} pairwise and {len(runs['fcm'])} FCM snapshots; "
          f"tolerance {100 * tolerance:.2g}%")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
