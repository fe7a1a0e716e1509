#!/usr/bin/env python3
"""Restores the finished points of a campaign folder from a campaign table (campaign.json), so that a sweep whose
raw runs were lost (a new machine, a cleaned scratch disk) continues with the points it had not finished instead of
running all of them again. Each done or jammed point gets its point.json (status, message, wall time, and the
particles.initial it started from, if any) and its summary.json back, which is all `suspend sweep` reads of a
finished point; the table the sweep then writes holds the same rows. A failed point gets its point.json with its
message, so that it waits for `suspend sweep --retry-failed` as it did where it ran (a numerical failure is
deterministic: running it again costs its whole time to fail the same way). Snapshots and series of the restored points are not recovered (the table never held them).

usage: tools/restore_campaign.py TABLE.json OUT_DIR     (then: suspend sweep CAMPAIGN.yaml --out OUT_DIR)
"""
import json
import os
import sys


def write_atomically(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def usage_error(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def main():
    if len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help"):
        usage_error(__doc__.strip().splitlines()[-1].strip())
    table, out = sys.argv[1], sys.argv[2]
    try:
        with open(table) as f:
            points = json.load(f)["points"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        usage_error(f"error: {table}: not a readable campaign table ({e})")
    restored = kept = 0
    for p in points:
        failed = p["status"] == "failed"
        if not failed and (p["status"] not in ("done", "jammed") or p.get("summary") is None):
            continue
        folder = os.path.join(out, "points", p["name"])
        if any(os.path.exists(os.path.join(folder, f)) for f in ("point.json", "summary.json", "run.h5")):
            kept += 1  # the folder's own record or run wins over the table's, and is never written over
            continue
        os.makedirs(folder, exist_ok=True)
        if not failed:
            write_atomically(os.path.join(folder, "summary.json"), json.dumps(p["summary"], indent=2) + "\n")
        # core/error.hpp: exit_jammed 4; a failure's own code is not in the table, exit_numerical_error 3 stands for it
        record = {"status": p["status"], "exit_code": {"done": 0, "jammed": 4}.get(p["status"], 3),
                  "message": p.get("message", ""), "wall_seconds": p["wall_seconds"],
                  "cpu_seconds": p.get("cpu_seconds", 0.0), "runs": 1}
        initial = (p.get("parameters") or {}).get("particles.initial")
        if initial:  # a searched point started from a flowing state (campaign/point_record.hpp)
            record["initial"] = initial
        write_atomically(os.path.join(folder, "point.json"), json.dumps(record, indent=2) + "\n")
        restored += 1
    print(f"{restored} finished or failed point(s) restored into {out}, {kept} already there; "
          f"{len(points) - restored - kept} left for the sweep")


if __name__ == "__main__":
    main()
