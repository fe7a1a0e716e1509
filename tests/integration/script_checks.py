"""What the Python integration checks share: a list of failed checks and a short quickstart run."""
import os
import subprocess

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def run_quickstart(suspend_bin, source, run_dir, strain, snapshot_every):
    """cases/quickstart.yaml to `strain`, a snapshot every `snapshot_every`, on one thread (a fraction of a second,
    where spin-waiting OpenMP threads on a busy node can take ten)."""
    subprocess.run([suspend_bin, "run", os.path.join(source, "cases/quickstart.yaml"), "--set", f"run.strain={strain}",
                    "--set", f"run.average_from={strain / 3:g}", "--set", f"run.output.snapshot_every={snapshot_every}",
                    "--out", run_dir, "--quiet", "--threads", "1"], check=True)
