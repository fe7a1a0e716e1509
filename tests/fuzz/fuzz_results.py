#!/usr/bin/env python3
"""Never lose a result (issue 37): a hostile user's attempts on finished results, in one class per rule.

Usage: fuzz_results.py SUSPEND SOURCE_DIR [--seed N] [--rounds N] [--only CLASS,...]

Classes (each attempt drawn from one seeded generator):
  overwrite     every writing command (run, restart, sweep, export, phim, crossval, the render and restore tools)
                aimed at the files and folders of a finished run, a campaign and a user's file: refused with
                exit 2 and every byte left as it was (an export over a user's file only with --force);
  concurrency   two `suspend run` into one folder at random delays, HDF5 file locking on or off, and a restart
                aimed at a running folder: one runs, the other exits 2, the result is the lone run's; two sweeps on
                one folder give the clean sweep's table with every point run once;
  damaged       a finished run.h5 truncated, with a dataset, attribute or snapshot removed, a string or NaN put in,
                a checkpoint or an empty file in its place: analyze and export exit 0 with sound output or 2 with
                one line, never 1, never a traceback;
  phim          the campaign table with a field removed, retyped, made non-finite, negative or out of range: exit 2
                or a fit that leaves out every group holding a degenerate point, never NaN in phim.json;
  particles     a particle table with one bad row (nan, inf, 1e999, text, 3 or 5 columns, a radius <= 0), a
                count that disagrees, a species that gets no sphere, campaign files that say two things: exit 2,
                naming the line or key;
  checkpoint    a checkpoint's radii, positions, species or count edited, its checksums kept or removed: refused;
  continuation  a finished run continued to a longer strain against one run straight there (bit-identical
                checkpoints), and a run started from the last snapshot of a sheared run (same box, offset, positions
                and contacts);
  output        standard output on a full device, --threads far above the cores, and bad values of the keys a
                user writes (the message names that key).
The contract on every command: exit 0, 2, 3, 4, 5, 130 or 143; exit 2 with one line starting "error: "; never a
traceback. Prints, per class, the attempts and those that broke a rule, then the problems; exits 1 if any broke.
"""
import argparse
import hashlib
import json
import math
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import debian_python  # noqa: E402

CLASSES = ["overwrite", "concurrency", "damaged", "phim", "particles", "checkpoint", "continuation", "output"]


class Tally:
    def __init__(self):
        self.tried = {c: 0 for c in CLASSES}
        self.broke = {c: 0 for c in CLASSES}
        self.problems = []

    def attempt(self, cls, ok, what):
        self.tried[cls] += 1
        if not ok:
            self.broke[cls] += 1
            self.problems.append(f"{cls}: {what}")
        return ok


def run(args, env=None, timeout=120, stdout=subprocess.PIPE):
    extra = dict(os.environ, OMP_WAIT_POLICY="passive", **(env or {}))
    try:
        r = subprocess.run(args, stdout=stdout, stderr=subprocess.PIPE, text=True, errors="replace",
                           timeout=timeout, env=extra)
    except subprocess.TimeoutExpired:
        return 999, "", "timeout"
    return r.returncode, r.stdout or "", r.stderr


def contract(code, err):
    """Why an exit broke the contract (None when it did not)."""
    if "Traceback" in err:
        return "a traceback"
    if code not in (0, 2, 3, 4, 5, 130, 143):
        return f"exit {code}"
    if code == 2:
        lines = [line for line in err.splitlines() if line.strip()]
        if len(lines) != 1 or not lines[0].startswith("error: "):
            return "exit 2 without exactly one 'error:' line"
    return None


def digest(*paths):
    """Hash of every file under the paths (names and bytes)."""
    h = hashlib.sha256()
    for top in paths:
        if os.path.isfile(top):
            h.update(top.encode() + open(top, "rb").read())
            continue
        for root, dirs, files in os.walk(top):
            dirs.sort()
            for f in sorted(files):
                p = os.path.join(root, f)
                h.update(p.encode() + open(p, "rb").read())
    return h.hexdigest()


def strict_json(text):
    """JSON without NaN or infinity (None when it is not such JSON)."""
    def refuse(_):
        raise ValueError("non-finite")
    try:
        return json.loads(text, parse_constant=refuse)
    except ValueError:
        return None


class Context:
    def __init__(self, suspend, source, work, rng):
        self.suspend, self.source, self.work, self.rng = suspend, source, work, rng
        self.case = os.path.join(source, "tests/data/restart_case.yaml")
        self.tools = os.path.join(source, "tools")
        self.small = ["--threads", "1", "--quiet", "--set", "particles.count=50", "--set", "run.average_from=0"]
        self.n = 0

    def fresh(self, name):
        self.n += 1
        return os.path.join(self.work, f"{name}{self.n}")

    def finished_run(self, strain=0.1, extra=()):
        d = self.fresh("run")
        code, _, err = run([self.suspend, "run", self.case, "--out", d, "--set", f"run.strain={strain}"] + self.small
                           + list(extra))
        if code != 0:
            raise RuntimeError(f"the base run failed ({code}): {err}")
        return d

    def campaign_file(self, points=3):
        path = os.path.join(self.work, f"campaign{points}.yaml")
        phis = ", ".join(f"{0.30 + 0.05 * k / max(1, points - 1) * 2:.3f}" for k in range(points))
        with open(path, "w") as f:
            f.write(f"case: {self.case}\nset: {{run.strain: 0.05, run.average_from: 0, particles.count: 30}}\n"
                    f"vary: {{particles.phi: [{phis}]}}\n")
        return path

    def campaign(self):
        d = self.fresh("campaign")
        code, _, err = run([self.suspend, "sweep", self.campaign_file(), "--out", d, "--quiet", "--jobs", "2"])
        if code != 0:
            raise RuntimeError(f"the base sweep failed ({code}): {err}")
        return d

    def copy(self, folder):
        d = self.fresh(os.path.basename(folder).rstrip("0123456789") + "_copy")
        shutil.copytree(folder, d)
        return d


# ---- item 1 -------------------------------------------------------------------------------------------------------
def overwrite(ctx, tally, rounds):
    rng, s = ctx.rng, ctx.suspend
    base, other, camp = ctx.finished_run(), ctx.finished_run(0.05), ctx.campaign()
    py = "/usr/bin/python3"
    for _ in range(rounds):
        r, r2, c = ctx.copy(base), ctx.copy(other), ctx.copy(camp)
        user = os.path.join(ctx.work, f"notes{ctx.n}.txt")
        with open(user, "w") as f:
            f.write("a user's notes\n")
        fmt = rng.choice(["extxyz", "gsd"])
        own = rng.choice(["run.h5", "checkpoint.h5", "summary.json", "run.xdmf"])
        force = ["--force"] if rng.random() < 0.5 else []
        attempts = [
            ([s, "run", ctx.case, "--out", r] + ctx.small, False),
            ([s, "run", ctx.case, "--restart", r2 + "/checkpoint.h5", "--out", r, "--set", "run.strain=0.2"]
             + ctx.small, False),
            ([s, "run", ctx.case, "--out", c] + ctx.small, False),
            ([s, "export", r, "--format", fmt, "--out", os.path.join(r, own)] + force, False),
            ([s, "export", r, "--format", fmt, "--out", os.path.join(c, "campaign.json")] + force, False),
            ([s, "export", r, "--format", "extxyz", "--out", user] + force, bool(force)),
            ([s, "sweep", ctx.campaign_file(), "--out", r, "--quiet"], False),
            ([s, "phim", c, "--out", r], False),
            ([s, "crossval", ctx.case, "--out", r, "--quiet"], False),
            ([py, os.path.join(ctx.tools, "render_snapshot.py"), r, "--out", os.path.join(r, own)] + force, False),
            ([py, os.path.join(ctx.tools, "render_snapshot.py"), r, "--out", user], False),
            ([py, os.path.join(ctx.tools, "render_movie.py"), r, "--out", os.path.join(r2, own)] + force, False),
            ([py, os.path.join(ctx.tools, "restore_campaign.py"), os.path.join(camp, "campaign.json"), c], True),
        ]
        cmd, may_change_user = rng.choice(attempts)
        before = digest(r, r2, c) + digest(user)
        code, _, err = run(cmd)
        what = " ".join(os.path.basename(a) if a.startswith(ctx.work) else a for a in cmd[1:])
        broken = contract(code, err)
        if broken:
            tally.attempt("overwrite", False, f"{what}: {broken}: {err.strip()[:200]}")
            continue
        after = digest(r, r2, c) + (digest(user) if not may_change_user else before[64:])
        if after != before:
            tally.attempt("overwrite", False, f"{what}: exit {code}, and a result or the user's file changed")
        elif code != 0 and not may_change_user:
            tally.attempt("overwrite", code == 2, f"{what}: exit {code}")
        else:
            tally.attempt("overwrite", code == 0 or not may_change_user, f"{what}: exit {code}: {err.strip()[:200]}")


# ---- item 2 -------------------------------------------------------------------------------------------------------
def summary_without_clock(folder):
    try:
        s = json.load(open(os.path.join(folder, "summary.json")))
    except (OSError, ValueError):
        return None
    for k in ("wall_seconds",):
        s.pop(k, None)
    return s


def concurrency(ctx, tally, rounds):
    rng, s = ctx.rng, ctx.suspend
    args = ["run", ctx.case, "--set", "run.strain=0.2"] + ctx.small
    alone = ctx.fresh("alone")
    run([s] + args + ["--out", alone])
    reference = summary_without_clock(alone)
    # The same run continued to strain 0.4 from its final checkpoint: what a restart that starts after the first
    # run ended must give.
    run([s] + args + ["--restart", os.path.join(alone, "checkpoint.h5"), "--set", "run.strain=0.4"])
    continued = summary_without_clock(alone)
    env_base = dict(os.environ, OMP_WAIT_POLICY="passive")
    for k in range(rounds):
        d = ctx.fresh("shared")
        env = dict(env_base, HDF5_USE_FILE_LOCKING=rng.choice(["FALSE", "TRUE"]))
        first = subprocess.Popen([s] + args + ["--out", d], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                 text=True, env=env)
        restart = k % 3 == 2
        if restart:  # a restart aimed at the running folder, once it has a checkpoint
            while not os.path.exists(os.path.join(d, "checkpoint.h5")) and first.poll() is None:
                time.sleep(0.001)
            second = [s] + args + ["--restart", os.path.join(d, "checkpoint.h5"), "--set", "run.strain=0.4"]
        else:  # at once, or a little later
            time.sleep(rng.choice([0.0, rng.uniform(0.0, 0.1)]))
            second = [s] + args + ["--out", d]
        running = first.poll() is None
        code2, _, err2 = run(second, env={"HDF5_USE_FILE_LOCKING": env["HDF5_USE_FILE_LOCKING"]})
        _, err1 = first.communicate()
        code1 = first.returncode
        what = f"round {k} (HDF5 locking {env['HDF5_USE_FILE_LOCKING']}): exits {code1} and {code2}"
        if restart and (not running or (code1, code2) == (0, 0)):
            # The first had ended (before the poll, or between the poll and the restart's lock): the restart
            # continues its final checkpoint, as after any finished run, and must give the continued reference.
            ok = code1 == 0 and code2 == 0 and summary_without_clock(d) == continued
        elif restart:  # the restart was refused while the first held the folder
            ok = (code1, code2) == (0, 2) and summary_without_clock(d) == reference
        else:  # either may win the folder (the second can start first); the folder holds the winner's run alone
            ok = sorted((code1, code2)) == [0, 2] and summary_without_clock(d) == reference
        ok = ok and contract(code1, err1) is None and contract(code2, err2) is None
        tally.attempt("concurrency", ok, f"{what}: {err2.strip()[:160]} {err1.strip()[:160]}")
    # Two sweeps on one folder.
    clean, shared = ctx.fresh("clean"), ctx.fresh("sweeps")
    campaign = ctx.campaign_file(6)
    run([s, "sweep", campaign, "--out", clean, "--quiet"])
    procs = []
    for _ in range(2):  # the second a little later, so that it reaches points the first has finished
        procs.append(subprocess.Popen([s, "sweep", campaign, "--out", shared, "--quiet", "--jobs", "1"],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env_base))
        time.sleep(rng.uniform(0.05, 0.3))
    codes = [p.wait() for p in procs]

    def table(folder):
        try:
            t = json.load(open(os.path.join(folder, "campaign.json")))
        except (OSError, ValueError):
            return None
        for p in t["points"]:
            p.pop("wall_seconds", None)
            p.pop("cpu_seconds", None)
        return t["points"]
    runs = []
    for name in os.listdir(os.path.join(shared, "points")) if os.path.isdir(os.path.join(shared, "points")) else []:
        try:
            runs.append(json.load(open(os.path.join(shared, "points", name, "point.json")))["runs"])
        except (OSError, ValueError, KeyError):
            runs.append(None)
    tally.attempt("concurrency", codes == [0, 0] and table(shared) == table(clean) and set(runs) == {1},
                  f"two sweeps on one folder: exits {codes}, runs per point {runs}, same table "
                  f"{table(shared) == table(clean)}")


# ---- item 3 -------------------------------------------------------------------------------------------------------
def damage(rng, folder, h5py, np):
    """One random damage to folder/run.h5; returns what was done."""
    path = os.path.join(folder, "run.h5")
    kind = rng.choice(["truncate", "dataset", "attribute", "string", "nan", "snapshot", "checkpoint", "empty"])
    if kind == "truncate":
        size = os.path.getsize(path)
        with open(path, "r+b") as f:
            f.truncate(rng.randrange(size))
        return kind
    if kind == "checkpoint":
        shutil.copy(os.path.join(folder, "checkpoint.h5"), path)
        return kind
    if kind == "empty":
        open(path, "w").close()
        return kind
    with h5py.File(path, "a") as f:
        datasets, groups = [], []
        f.visititems(lambda name, obj: (datasets if isinstance(obj, h5py.Dataset) else groups).append(name))
        if kind == "dataset":
            victim = rng.choice(datasets)
            del f[victim]
            return f"{kind} {victim}"
        if kind == "attribute":
            holders = [n for n in groups + datasets if len(f[n].attrs)]
            if not holders:
                return "nothing"
            victim = rng.choice(holders)
            attr = rng.choice(list(f[victim].attrs))
            del f[victim].attrs[attr]
            return f"{kind} {victim}@{attr}"
        if kind == "string":
            victim = rng.choice(datasets)
            del f[victim]
            f[victim] = "not a number"
            return f"{kind} {victim}"
        if kind == "nan":
            floats = [n for n in datasets if f[n].dtype.kind == "f" and f[n].size and f[n].maxshape == f[n].shape]
            if not floats:
                return "nothing"
            victim = rng.choice(floats)
            data = f[victim][()]
            flat = data.reshape(-1)
            flat[rng.randrange(flat.size)] = rng.choice([np.nan, np.inf, -np.inf])
            f[victim][...] = data
            return f"{kind} {victim}"
        snaps = sorted(f["snapshots"]) if "snapshots" in f else []
        if len(snaps) < 2:
            return "nothing"
        victim = snaps[rng.randrange(len(snaps) - 1)]
        del f["snapshots/" + victim]
        return f"{kind} {victim}"


def damaged(ctx, tally, rounds):
    import h5py
    import numpy as np
    rng, s = ctx.rng, ctx.suspend
    base = ctx.finished_run(0.3, ["--set", "run.output.snapshot_every=0.1"])
    try:
        import gsd  # noqa: F401
        formats = ["extxyz", "gsd"]
    except ImportError:
        formats = ["extxyz"]
    for _ in range(rounds):
        d = ctx.copy(base)
        what = damage(rng, d, h5py, np)
        if rng.random() < 0.5:
            cmd = [s, "analyze", d] + rng.choice([[], ["--snapshot", "all", "--json"], ["--snapshot", "0"]])
        else:
            cmd = [s, "export", d, "--format", rng.choice(formats), "--out", os.path.join(d, f"out{ctx.n}")]
        code, out, err = run(cmd)
        broken = contract(code, err)
        if not broken and code == 0 and "--json" in cmd and strict_json(out) is None:
            broken = "exit 0 with NaN, infinity or no JSON"
        if not broken and code == 0 and cmd[1] == "export" and not os.path.exists(cmd[-1]):
            broken = "exit 0 without the export"
        if not broken and code == 0 and cmd[1] == "export" and cmd[-3] == "extxyz" and (
                "nan" in open(cmd[-1]).read().lower() or "inf " in open(cmd[-1]).read()):
            broken = "exit 0 exporting NaN or infinity"
        tally.attempt("damaged", broken is None, f"{what}; {' '.join(cmd[1:3])}: {broken}: {err.strip()[:200]}")


# ---- item 3, phim -------------------------------------------------------------------------------------------------
def mutate_table(rng, table):
    """One random change to a campaign table (a dict); returns what was done."""
    points = table["points"]
    p = rng.choice(points)
    kind = rng.choice(["delete", "retype", "nonfinite", "negative_eta", "zero_sem", "inf_sem", "phi_over_1",
                       "top", "status"])
    if kind == "top":
        table.pop(rng.choice(list(table)))
        return kind
    if kind == "status":
        p["status"] = rng.choice(["done", "jammed", "running", 3, None])
        return kind
    s = p.get("summary") or {}
    if kind == "negative_eta" and "eta_r" in s:
        s["eta_r"]["mean"] = -abs(s["eta_r"]["mean"])
    elif kind == "zero_sem" and "eta_r" in s:
        s["eta_r"]["sem"] = 0.0
    elif kind == "inf_sem" and "eta_r" in s:
        s["eta_r"]["sem"] = "INF"
    elif kind == "phi_over_1":
        s["phi"] = rng.choice([1.2, 7.0])
    else:
        # A random leaf of the point.
        path, node = [], p
        while isinstance(node, dict) and node:
            key = rng.choice(list(node))
            path.append(key)
            if not isinstance(node[key], dict) or rng.random() < 0.3:
                break
            node = node[key]
        if kind == "delete":
            node.pop(path[-1], None)
        elif kind == "retype":
            node[path[-1]] = rng.choice(["text", [1, 2], None, {"a": 1}, True])
        else:
            node[path[-1]] = rng.choice(["NAN", "INF", "-INF"])
        return f"{kind} {'.'.join(map(str, path))}"
    return kind


def phim(ctx, tally, rounds):
    rng, s = ctx.rng, ctx.suspend
    camp = ctx.campaign()
    original = json.load(open(os.path.join(camp, "campaign.json")))
    for _ in range(rounds):
        table = json.loads(json.dumps(original))
        what = mutate_table(rng, table)
        d = ctx.fresh("phim")
        os.makedirs(d)
        text = json.dumps(table).replace('"NAN"', "NaN").replace('"-INF"', "-Infinity").replace('"INF"', "Infinity")
        if rng.random() < 0.1:
            text = text[: rng.randrange(len(text))]
            what = "truncated"
        with open(os.path.join(d, "campaign.json"), "w") as f:
            f.write(text)
        code, out, err = run([s, "phim", d, "--json"])
        broken = contract(code, err)
        if not broken and code == 0:
            result = strict_json(out)
            if result is None:
                broken = "exit 0 with NaN or infinity in the fit"
            else:
                for fit in result["fits"]:
                    if fit.get("phi_m") is None:
                        continue
                    for phi, eta, sem in fit["data"]:
                        if not (0 < phi < 1 and eta > 0 and 0 < sem < math.inf):
                            broken = f"fitted a degenerate point (phi {phi}, eta_r {eta} +- {sem})"
        tally.attempt("phim", broken is None, f"{what}: {broken}: {err.strip()[:200]}")


# ---- item 4 -------------------------------------------------------------------------------------------------------
def particles(ctx, tally, rounds):
    rng, s = ctx.rng, ctx.suspend
    bad_values = ["nan", "inf", "-inf", "1e999", "abc", "1.5x", "--1", "0x1p"]
    for k in range(rounds):
        n = rng.randrange(8, 30)
        side = 12.0
        rows = [f"{(i % 4) * 3 + 1.5} {((i // 4) % 4) * 3 + 1.5} {(i // 16) * 3 + 1.5} 1" for i in range(n)]
        line = rng.randrange(n)
        kind = rng.choice(["value", "columns", "radius", "count"])
        if kind == "value":
            words = rows[line].split()
            words[rng.randrange(4)] = rng.choice(bad_values)
            rows[line] = " ".join(words)
        elif kind == "columns":
            rows[line] = " ".join(rows[line].split()[: rng.choice([2, 3])]) if rng.random() < 0.5 else rows[line] + " 7"
        elif kind == "radius":
            words = rows[line].split()
            words[3] = rng.choice(["0", "-1", "-0"])
            rows[line] = " ".join(words)
        path = os.path.join(ctx.work, f"particles{k}.txt")
        with open(path, "w") as f:
            f.write("# x y z radius\n" + "\n".join(rows) + "\n")
        phi = n * 4.0 / 3.0 * math.pi / side ** 3
        cmd = [s, "check", ctx.case, "--set", "particles.count=" + (str(n + 1) if kind == "count" else "null"),
               "--set", f"box={{cube: {side}}}", "--set", f"particles.phi={phi}", "--set", "particles.bidisperse=null",
               "--set", f"particles.initial={{from: file, file: {path}}}"]
        if kind == "count":
            cmd[cmd.index("--set", 4) + 1] = "box=null"
        code, _, err = run(cmd)
        expected = f"{path}:{line + 2}:" if kind != "count" else "particles.count"
        ok = contract(code, err) is None and code == 2 and expected in err
        tally.attempt("particles", ok, f"{kind} on line {line + 2}: exit {code}: {err.strip()[:200]}")
    head = f"case: {ctx.case}\n"
    campaigns = [
        ("set: {particles.phi: 0.4}\nvary: {particles.phi: [0.40, 0.45]}\n", "also varied"),
        ("vary: []\n", "vary"),
        ("vary: {particles.phi: []}\n", "vary.particles.phi"),
        ("points:\n  - {run.seed: 1}\n  - {run.seed: 1}\n", "twice"),
        ("vary: {run.seed: [" + ", ".join(map(str, range(1, 101))) + "], particles.phi: [" +
         ", ".join(f"0.{30 + i}" for i in range(30)) + "], contact.mu: [" + ", ".join(f"{i / 10}" for i in range(10)) +
         "]}\n", "at most 20000"),
    ]
    for body, fragment in campaigns:
        path = os.path.join(ctx.work, f"campaign{ctx.n}.yaml")
        ctx.n += 1
        with open(path, "w") as f:
            f.write(head + body)
        start = time.time()
        code, _, err = run([s, "sweep", path, "--list"])
        ok = contract(code, err) is None and code == 2 and fragment in err and time.time() - start < 20
        tally.attempt("particles", ok, f"campaign '{body.strip()[:40]}': exit {code}: {err.strip()[:200]}")
    code, _, err = run([s, "check", ctx.case, "--set", "particles.count=null", "--set", "box={cube: 6}",
                        "--set", "particles.bidisperse.size_ratio=4"])
    tally.attempt("particles", code == 2 and "no sphere of species 1" in err and contract(code, err) is None,
                  f"a species without spheres: exit {code}: {err.strip()[:200]}")


# ---- item 5 -------------------------------------------------------------------------------------------------------
def checkpoint(ctx, tally, rounds):
    import h5py
    import numpy as np
    rng, s = ctx.rng, ctx.suspend
    base = ctx.finished_run(0.1)
    for _ in range(rounds):
        d = ctx.copy(base)
        path = os.path.join(d, "checkpoint.h5")
        kind = rng.choice(["radius", "position", "species", "count"])
        integrity = rng.choice(["kept", "removed"])
        with h5py.File(path, "a") as f:
            p = f["particles"]
            n = p["radius"].shape[0]
            i = rng.randrange(n)
            if kind == "radius":
                r = p["radius"][()]
                r[i] *= rng.choice([1.01, 1.4, 0.5])
                p["radius"][...] = r
            elif kind == "position":
                x = p["position"][()]
                x[i, rng.randrange(3)] += rng.uniform(0.01, 0.5)
                p["position"][...] = x
            elif kind == "species":
                sp = p["species"][()]
                sp[i] = 1 - sp[i]
                p["species"][...] = sp
            else:
                for name in list(p):
                    data = p[name][()]
                    del p[name]
                    p.create_dataset(name, data=np.delete(data, i, axis=0), fletcher32=True)
            if integrity == "removed" and "checksums" in f:
                del f["checksums"]
        code, _, err = run([s, "run", ctx.case, "--restart", path, "--set", "run.strain=0.15"] + ctx.small)
        ok = code == 2 and contract(code, err) is None
        tally.attempt("checkpoint", ok, f"{kind} edited, checksums {integrity}: exit {code}: {err.strip()[:200]}")


# ---- items 6 and 7 ------------------------------------------------------------------------------------------------
def continuation(ctx, tally, rounds):
    import h5py
    rng, s = ctx.rng, ctx.suspend
    for k in range(rounds):
        s1 = round(rng.uniform(0.03, 0.12), 3)
        s2 = round(s1 + rng.uniform(0.02, 0.1), 3)
        a, b = ctx.fresh("continued"), ctx.fresh("straight")
        c1 = run([s, "run", ctx.case, "--out", a, "--set", f"run.strain={s1}"] + ctx.small)[0]
        c2 = run([s, "run", ctx.case, "--restart", a + "/checkpoint.h5", "--set", f"run.strain={s2}"] + ctx.small)[0]
        c3 = run([s, "run", ctx.case, "--out", b, "--set", f"run.strain={s2}"] + ctx.small)[0]
        same = False
        if (c1, c2, c3) == (0, 0, 0):
            with h5py.File(a + "/checkpoint.h5") as fa, h5py.File(b + "/checkpoint.h5") as fb:
                same = fa.attrs["step"] == fb.attrs["step"] and all(
                    (fa[n][()] == fb[n][()]).all() for n in ("particles/position", "particles/velocity"))
        tally.attempt("continuation", same, f"strain {s1} continued to {s2}: exits {(c1, c2, c3)}, bit-identical {same}")
    for k in range(max(1, rounds // 2)):
        strain = round(rng.uniform(0.1, 0.3), 3)
        a, b = ctx.fresh("sheared"), ctx.fresh("from_sheared")
        box = ["--set", "particles.count=null", "--set", "box={cube: 7}"]
        c1, _, e1 = run([s, "run", ctx.case, "--out", a, "--set", f"run.strain={strain}"] + ctx.small + box)
        c2, _, e2 = run([s, "run", ctx.case, "--out", b, "--set", "run.strain=0.02", "--set",
                         f"particles.initial={{from: file, file: {a}/run.h5}}"] + ctx.small +
                        ["--set", "particles.count=null"])
        same = False
        if (c1, c2) == (0, 0):
            with h5py.File(a + "/run.h5") as fa, h5py.File(b + "/run.h5") as fb:
                end, start = fa["snapshots"][sorted(fa["snapshots"])[-1]], fb["snapshots/000000"]
                same = (end.attrs["shear_offset"] == start.attrs["shear_offset"]
                        and (end["position"][()] == start["position"][()]).all()
                        and end["contact_pairs"].shape == start["contact_pairs"].shape)
        tally.attempt("continuation", same, f"start from the snapshot at strain {strain}: exits {(c1, c2)}, same state "
                                            f"{same}: {e2.strip()[:160]}")


# ---- item 8 -------------------------------------------------------------------------------------------------------
def output(ctx, tally, rounds):
    rng, s = ctx.rng, ctx.suspend
    base = ctx.finished_run(0.1)
    commands = [["check", ctx.case], ["pair", "--gap", "0.1"], ["analyze", base], ["sweep", ctx.campaign_file(), "--list"],
                ["--version"], ["mobility"]]
    for cmd in commands:
        with open("/dev/full", "w") as full:
            code, _, err = run([s] + cmd, stdout=full)
        tally.attempt("output", code != 0 and err.strip() != "" and contract(code, err) is None,
                      f"{' '.join(cmd[:1])} > /dev/full: exit {code}: {err.strip()[:120]}")
    code, _, err = run([s, "run", ctx.case, "--out", ctx.fresh("threads"), "--set", "run.strain=0.02", "--quiet",
                        "--set", "run.average_from=0",
                        "--set", "particles.count=50", "--threads", "4096"])
    tally.attempt("output", code == 0 and "warning" in err, f"--threads 4096: exit {code}: {err.strip()[:120]}")
    hertz = os.path.join(ctx.source, "cases/phim/adhesive_bidisperse.yaml")
    keys = [(hertz, "contact.mu_s"), (hertz, "contact.g_adh"), (hertz, "contact.eps_bar"), (ctx.case, "contact.k_hat"),
            (ctx.case, "contact.mu"), (ctx.case, "contact.rolling.mu_r"), (ctx.case, "particles.phi")]
    for _ in range(rounds):
        case, key = rng.choice(keys)
        value = rng.choice(["-1", "nan", "abc", "1e999", "[1]"])
        code, _, err = run([s, "check", case, "--set", f"{key}={value}"])
        tally.attempt("output", code == 2 and key in err and contract(code, err) is None,
                      f"{key}={value}: exit {code}: {err.strip()[:160]}")


def main():
    debian_python.require("h5py", "numpy")
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("suspend")
    p.add_argument("source_dir")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--rounds", type=int, default=6, help="attempts per class (default 6)")
    p.add_argument("--only", help="comma-separated classes")
    a = p.parse_args()
    rng = random.Random(a.seed)
    tally = Tally()
    chosen = a.only.split(",") if a.only else CLASSES
    work = tempfile.mkdtemp(prefix="suspend_results_")
    try:
        ctx = Context(os.path.abspath(a.suspend), os.path.abspath(a.source_dir), work, rng)
        for name in chosen:
            globals()[name](ctx, tally, a.rounds)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    total = sum(tally.broke.values())
    print(f"never lose a result (seed {a.seed}, {a.rounds} rounds): " + ", ".join(
        f"{c} {tally.tried[c] - tally.broke[c]}/{tally.tried[c]}" for c in chosen) + f"; {total} broke the contract")
    for problem in tally.problems:
        print("  " + problem)
    return 1 if total else 0


if __name__ == "__main__":
    sys.exit(main())
