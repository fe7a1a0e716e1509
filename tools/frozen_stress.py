#!/usr/bin/env python3
"""The particle stress of the pairwise and FCM models on identical configurations (issue 40).

A sheared trajectory of CASE (pairwise, as the case says) gives CONFIGS configurations, SPACING strains apart after
a first strain FROM. Each configuration is then started from its run.h5 (box and Lees-Edwards offset included) by
each model, and the stress of the first step is read: same positions, same contact forces (explicit contacts for
that step, so that they depend on the positions only, and fresh tangential springs for every model), each model's
own hydrodynamics. The models: pairwise with the force-dipole lubrication stress (-sym(d F), paper 000 eq. 9b),
pairwise with the stresslet form, and FCM (resolved stresslet plus sub-grid lubrication). What differs between
them on one configuration is the stress definition and the hydrodynamics, not the microstructure: set against the
trajectories' difference (docs/validation.md section 3), it splits the FCM/pairwise viscosity ratio into the part a
configuration carries and the part the two models' different microstructures carry.

usage: tools/frozen_stress.py CASE OUT [--from 2] [--spacing 0.5] [--configs 4] [--set KEY=VALUE ...]
       [--suspend build/bin/suspend]
Prints two tables: with the configuration's contact forces, and with the hydrodynamics alone (the same positions,
contact forces off: the configuration's hydrodynamic viscosity). Each gives, per model, the mean over configurations
(+- standard error) of eta_r, its hydrodynamic part (solvent, Stokes and lubrication, or resolved and sub-grid), N1,
N2 and Pi, all over eta_0 gammadot, and the ratio of each model's hydrodynamic eta_r to the pairwise force dipole's on
the same configuration. Runs are kept in OUT and reused, so an interrupted call resumes.
"""
import argparse
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from debian_python import require  # noqa: E402

USAGE = ("usage: tools/frozen_stress.py CASE OUT [--from 2] [--spacing 0.5] [--configs 4] [--set KEY=VALUE ...] "
         "[--suspend build/bin/suspend]")

MODELS = {
    "pairwise_force_dipole": ["hydrodynamics.model=pairwise", "hydrodynamics.lubrication.stress=force_dipole"],
    "pairwise_stresslet": ["hydrodynamics.model=pairwise", "hydrodynamics.lubrication.stress=stresslet"],
    "fcm": ["hydrodynamics.model=fcm"],
}
HYDRODYNAMIC = ("hydrodynamic", "lubrication")
NO_CONTACTS = "contact={law: soft_repulsion, k_hat: 1.0e-12}"  # the same positions without contact forces
XX, YY, ZZ, XY = 0, 1, 2, 3


def run(suspend, case, out, sets):
    if os.path.exists(os.path.join(out, "summary.json")):
        return  # done before: the script resumes
    cmd = [suspend, "run", case, "--out", out, "--threads", "1", "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("error: %s failed (%d): %s" % (" ".join(cmd), r.returncode, r.stderr.strip().splitlines()[-1:]))


def first_step_stress(run_dir):
    import h5py
    import numpy as np
    with h5py.File(os.path.join(run_dir, "run.h5"), "r") as f:
        s = f["series"]["stress"]
        rate = float(f["series"]["shear_rate"][0])
        total = np.array(s["total"][0]) / rate
        hydro = sum(np.array(s[k][0]) for k in HYDRODYNAMIC) / rate
    return total, hydro


def moments(t):
    return {"eta_r": t[XY], "N1": t[XX] - t[YY], "N2": t[YY] - t[ZZ], "Pi": -(t[XX] + t[YY] + t[ZZ]) / 3}


def mean_sem(values):
    import numpy as np
    v = np.array(values, dtype=float)
    return v.mean(), (v.std(ddof=1) / math.sqrt(len(v)) if len(v) > 1 else float("nan"))


def main():
    if len(sys.argv) < 3 or "-h" in sys.argv or "--help" in sys.argv:
        print(__doc__.split("usage:")[0].strip() + "\n\n" + USAGE, file=sys.stderr)
        sys.exit(2)
    p = argparse.ArgumentParser(usage=USAGE)
    p.add_argument("case")
    p.add_argument("out")
    p.add_argument("--from", dest="start", type=float, default=2.0)
    p.add_argument("--spacing", type=float, default=0.5)
    p.add_argument("--configs", type=int, default=4)
    p.add_argument("--set", action="append", default=[])
    p.add_argument("--suspend", default=os.path.join(os.path.dirname(__file__), "..", "build", "bin", "suspend"))
    a = p.parse_args()
    if not os.path.isfile(a.case):
        print("error: %s: no such case file" % a.case, file=sys.stderr)
        sys.exit(2)
    require("h5py", "numpy")
    case = os.path.abspath(a.case)
    os.makedirs(a.out, exist_ok=True)
    sets = a.set + ["run.average_from=0"]
    previous = None
    configs = []
    for k in range(a.configs):
        d = os.path.join(a.out, "trajectory_%d" % k)
        if previous is None:
            run(a.suspend, case, d, sets + ["run.strain=%g" % a.start])
        else:
            run(a.suspend, case, d, sets + ["particles.initial.from=file", "particles.initial.file=%s" % previous,
                                            "box=null", "particles.count=null", "run.strain=%g" % a.spacing])
        previous = os.path.abspath(os.path.join(d, "run.h5"))
        configs.append(previous)
    print("%d configurations of %s (%s), strain %g + k x %g" % (a.configs, a.case, " ".join(a.set) or "as shipped",
                                                              a.start, a.spacing))
    for contacts, contact_sets in (("with the configuration's contact forces", []),
                                   ("hydrodynamics alone (contact forces off)", [NO_CONTACTS])):
        rows = {m: [] for m in MODELS}
        for k, conf in enumerate(configs):
            for m, model_sets in MODELS.items():
                d = os.path.join(a.out, "frozen_%d_%s%s" % (k, m, "_alone" if contact_sets else ""))
                run(a.suspend, case, d, sets + model_sets + contact_sets + [
                    "particles.initial.from=file", "particles.initial.file=%s" % conf, "box=null",
                    "particles.count=null", "run.strain=1e-5", "run.time_step.contacts=explicit",
                    "run.time_step.mode=fixed", "run.time_step.fixed=1e-5"])
                total, hydro = first_step_stress(d)
                rows[m].append((moments(total), moments(hydro)))
        print("\n" + contacts)
        table(rows)


def table(rows):
    print("%-22s %18s %18s %18s %18s %18s %22s" % ("model", "eta_r", "eta_r hydrodynamic", "N1", "N2", "Pi",
                                                  "hydro / force dipole"))
    reference = [h["eta_r"] for _, h in rows["pairwise_force_dipole"]]
    for m, r in rows.items():
        cells = []
        for key, part in (("eta_r", 0), ("eta_r", 1), ("N1", 0), ("N2", 0), ("Pi", 0)):
            mu, se = mean_sem([x[part][key] for x in r])
            cells.append("%8.3f +- %-6.3f" % (mu, se))
        ratio = mean_sem([h["eta_r"] / ref for (_, h), ref in zip(r, reference)])
        print("%-22s %s %10.4f +- %-8.4f" % (m, " ".join(cells), *ratio))
    print("hydrodynamic N1, N2, Pi:")
    for m, r in rows.items():
        cells = ["%s %8.3f +- %-6.3f" % (key, *mean_sem([x[1][key] for x in r])) for key in ("N1", "N2", "Pi")]
        print("%-22s %s" % (m, "  ".join(cells)))


if __name__ == "__main__":
    main()
