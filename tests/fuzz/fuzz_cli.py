#!/usr/bin/env python3
"""Fuzzes `suspend` as a hostile tester would (issue 15) and checks the contract on every run.

Usage: fuzz_cli.py SUSPEND SOURCE_DIR [--seed N] [--cases N] [--runs N] [--budget SECONDS]

Mutations, all drawn from one seeded generator:
  * key overrides: every key of the shipped cases' resolved form (`suspend check`), set to hostile values (empty,
    nan, inf, huge, tiny, negative, text, lists, maps, tags, very long text) or misspelt;
  * text mutations of the case files: a line deleted, duplicated or cut, a number replaced, a tag, a second
    document, an unclosed quote, tabs, a truncated file;
  * command lines: bad options and values for run, check, pair, mobility and sweep.
Each mutation runs `suspend check` (or the command itself); a sample is also run (`suspend run`, small and short).

The contract, checked on every run:
  * exit code 0, 2, 3, 4 or 5 only (never a crash, never 1);
  * exit 2: one line on stderr, starting with "error: ", and nothing left in --out;
  * exit 0: no NaN or infinity in summary.json, and the checkpoint's positions finite;
  * no run past the time budget (a hang).
Prints the counts (tried / exit 0 / exit 2 named / exit 3-5 / crashes / hangs / contract violations) and exits 1
when anything broke the contract.
"""
import argparse
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import debian_python  # noqa: E402

HOSTILE = ["", "nan", "NaN", "inf", "-inf", ".inf", "-1", "0", "-0", "1e308", "-1e308", "1e-308", "1e-300", "1e999",
           "abc", "[1, 2]", "{a: 1}", "true", "null", "~", "0x10", "1,5", "2.5.1", "'0.4'", "!!binary aGVsbG8=",
           "x" * 3000, "1e12", "0.999999", "100000000", "3", "-3", "0.5"]


def base_keys(suspend, case):
    """Dotted keys of the resolved case (indentation of `suspend check`'s YAML)."""
    out = subprocess.run([suspend, "check", case], capture_output=True, text=True, timeout=60).stdout
    keys, stack = [], []
    for line in out.splitlines():
        if line.startswith("# derived"):
            break
        if line.startswith("#") or not line.strip() or line.lstrip().startswith("-"):
            continue
        indent = len(line) - len(line.lstrip())
        m = re.match(r"\s*([A-Za-z_][A-Za-z0-9_]*):\s*(.*)$", line)
        if not m:
            continue
        stack = stack[: indent // 2]
        stack.append(m.group(1))
        if m.group(2):
            keys.append(".".join(stack))
    return keys


def mutate_text(rng, text):
    lines = text.splitlines(keepends=True)
    kind = rng.randrange(9)
    k = rng.randrange(len(lines)) if lines else 0
    if kind == 0 and lines:
        del lines[k]
    elif kind == 1 and lines:
        lines.insert(k, lines[k])
    elif kind == 2 and lines:
        lines[k] = lines[k][: rng.randrange(len(lines[k]) + 1)] + "\n"
    elif kind == 3:
        numbers = [m for m in re.finditer(r"-?\d+(\.\d+)?(e[-+]?\d+)?", text)]
        if numbers:
            m = rng.choice(numbers)
            return text[: m.start()] + rng.choice(HOSTILE) + text[m.end():]
    elif kind == 4 and lines:
        lines[k] = re.sub(r":\s", ": !!str ", lines[k], count=1)
    elif kind == 5:
        lines.append("---\nrun: {strain: 1}\n")
    elif kind == 6 and lines:
        lines[k] = lines[k].replace(": ", ': "', 1)
    elif kind == 7 and lines:
        lines[k] = "\t" + lines[k]
    else:
        return text[: rng.randrange(len(text) + 1)]
    return "".join(lines)


def progressed(path, h5py):
    """Whether the run stopped at `path` (its checkpoint) had taken steps."""
    try:
        with h5py.File(path, "r") as f:
            return int(f.attrs["step"]) > 0
    except (OSError, KeyError):
        return False


def finite_json(x):
    if isinstance(x, float):
        return math.isfinite(x)
    if isinstance(x, dict):
        return all(finite_json(v) for v in x.values())
    if isinstance(x, list):
        return all(finite_json(v) for v in x)
    return True


class Tally:
    def __init__(self):
        self.counts = {"tried": 0, "exit 0": 0, "exit 2 named": 0, "exit 3-5": 0, "crashes": 0, "hangs": 0,
                       "slow": 0, "violations": 0}
        self.problems = []

    def bad(self, kind, what, r_err=""):
        self.counts[kind] += 1
        if kind != "violations":
            self.counts["violations"] += 1
        self.problems.append("%s: %s%s" % (kind, what, (": " + r_err.strip().replace("\n", " | ")[:300]) if r_err else ""))


def check_run(tally, cmd, out_dir, budget, h5py):
    tally.counts["tried"] += 1
    what = " ".join(a if len(a) < 80 else a[:77] + "..." for a in cmd[1:])
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace")
    try:
        _, err = proc.communicate(timeout=budget)
    except subprocess.TimeoutExpired:
        # Past the budget: Ctrl-C must stop it cleanly (exit 130, a checkpoint). A slow run that is getting
        # somewhere (explicit stiff contacts in a mutated case) is not a hang: its checkpoint then has steps.
        proc.send_signal(signal.SIGINT)
        try:
            proc.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
        if proc.returncode == 130 and out_dir and progressed(os.path.join(out_dir, "checkpoint.h5"), h5py):
            tally.counts["slow"] += 1
        else:
            tally.bad("hangs", "%s (exit %s after Ctrl-C)" % (what, proc.returncode))
        return
    code = proc.returncode

    class R:
        stderr = err
    r = R()
    if code < 0 or code == 1 or code > 5:
        tally.bad("crashes", "exit %d: %s" % (code, what), r.stderr)
        return
    if code == 2:
        lines = [l for l in r.stderr.splitlines() if l.strip()]
        if len(lines) != 1 or not lines[0].startswith("error: "):
            tally.bad("violations", "exit 2 without one 'error:' line: " + what, r.stderr)
        elif out_dir and os.path.exists(out_dir) and os.listdir(out_dir):
            tally.bad("violations", "exit 2 left files in --out: " + what)
        else:
            tally.counts["exit 2 named"] += 1
        return
    if code in (3, 4, 5):
        tally.counts["exit 3-5"] += 1
        return
    tally.counts["exit 0"] += 1
    if out_dir and os.path.exists(os.path.join(out_dir, "summary.json")):
        text = open(os.path.join(out_dir, "summary.json")).read()
        try:
            summary = json.loads(text)
        except ValueError:
            tally.bad("violations", "summary.json is not JSON: " + what)
            return
        if not finite_json(summary):
            tally.bad("violations", "non-finite number in summary.json: " + what)
        with h5py.File(os.path.join(out_dir, "checkpoint.h5"), "r") as f:
            x = f["particles/position"][()]
            if not (abs(x) < float("inf")).all():
                tally.bad("violations", "non-finite position in the checkpoint: " + what)


def main():
    debian_python.require("h5py")
    import h5py
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("suspend")
    p.add_argument("source_dir")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--cases", type=int, default=300, help="mutated cases checked (default 300)")
    p.add_argument("--runs", type=int, default=30, help="of which also run, small and short (default 30)")
    p.add_argument("--budget", type=float, default=60.0, help="seconds before a run counts as a hang")
    p.add_argument("--keep", help="copy the case files that broke the contract here")
    a = p.parse_args()
    if not os.access(a.suspend, os.X_OK):
        p.error("SUSPEND must be the suspend executable")
    rng = random.Random(a.seed)
    bases = [os.path.join(a.source_dir, f) for f in
             ("cases/quickstart.yaml", "tests/data/restart_case.yaml", "cases/validation/frictional_mu1.yaml",
              "cases/validation/adhesive_hertz.yaml", "cases/validation/crossval_dilute.yaml")]
    keys = {b: base_keys(a.suspend, b) for b in bases}
    # Small and short, set first so that a mutation can still override them.
    def small(base):
        size = ["box={cube: 8}"] if any(k.startswith("box.") for k in keys[base]) else ["particles.count=24"]
        sets = []
        for s in ["run.strain=0.02", "run.average_from=0", "run.threads=1"] + size:
            sets += ["--set", s]
        return sets
    tally = Tally()
    work = tempfile.mkdtemp(prefix="suspend_fuzz_")
    try:
        for n in range(a.cases):
            base = rng.choice(bases)
            out = os.path.join(work, "out%d" % n)
            case = base
            sets = []
            if rng.random() < 0.5:
                key = rng.choice(keys[base])
                if rng.random() < 0.1:
                    key = key + rng.choice(["x", ".", "..y", "_"])
                sets = ["--set", "%s=%s" % (key, rng.choice(HOSTILE))]
            else:
                case = os.path.join(work, "case%d.yaml" % n)
                with open(case, "w") as f:
                    f.write(mutate_text(rng, open(base).read()))
            running = n < a.runs
            cmd = [a.suspend, "run" if running else "check", case] + (small(base) if running else []) + sets
            if running:
                cmd += ["--out", out, "--quiet"]
            before = len(tally.problems)
            check_run(tally, cmd, out if running else None, a.budget, h5py)
            if a.keep and len(tally.problems) > before and case != base:
                os.makedirs(a.keep, exist_ok=True)
                shutil.copy(case, a.keep)
            shutil.rmtree(out, ignore_errors=True)
        lines = [
            ["pair", "--a1", "1e-300"], ["pair", "--a1", "1", "--a2", "nan"], ["pair", "--gap", "-1"],
            ["pair", "--outer-cutoff", "0"], ["pair", "--outer-cutoff", "nan"], ["mobility", "--force", "nan,0,0"],
            ["mobility", "--radius", "1e-6"], ["run"], ["check"], ["--bogus"], ["run", bases[1], "--threads", "0"],
            ["run", bases[1], "--threads", "abc"], ["run", bases[1], "--out", "/proc/nope"],
            ["run", bases[1], "--restart", "/nonexistent.h5"], ["run", "/dev/null", "--out", work + "/o"],
            ["run", work, "--out", work + "/o"], ["sweep", bases[1], "--out", work + "/s"], ["check", bases[1], "--set"],
            ["check", bases[1], "--set", "=1"], ["check", bases[1], "--set", "particles"], ["crossval", "/nonexistent"],
        ]
        for args in lines:
            out = work + "/o" if "--out" in args else None
            check_run(tally, [a.suspend] + args, out, a.budget, h5py)
            if out:
                shutil.rmtree(out, ignore_errors=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    c = tally.counts
    print("fuzz (seed %d): tried %d / exit 0 %d / exit 2 named %d / exit 3-5 %d / crashes %d / hangs %d / "
          "contract violations %d (slow but progressing, stopped at the budget: %d)"
          % (a.seed, c["tried"], c["exit 0"], c["exit 2 named"], c["exit 3-5"], c["crashes"], c["hangs"],
             c["violations"], c["slow"]))
    for problem in tally.problems:
        print("  " + problem)
    return 1 if c["violations"] else 0


if __name__ == "__main__":
    sys.exit(main())
