#!/usr/bin/env python3
"""The machine time of campaigns, from their tables: per campaign the points by status and the core-hours they took
(issue 36 asks for the CPU hours of every campaign): a point's CPU time (user + system, summed over its runs) where
its table records one, else its wall time, which is the CPU time of a one-thread point on a quiet machine but also
counts while the machine is shared or the sweep paused (SIGSTOP). The points costed by wall time are counted apart,
and points that ran before wall times were recorded count as 0, also apart.

usage: tools/campaign_cost.py CAMPAIGN_DIR_OR_campaign.json [...]
"""
import json
import os
import sys

USAGE = __doc__.strip().splitlines()[-1]


def fail(message):
    print("error: " + message, file=sys.stderr)
    print(USAGE, file=sys.stderr)
    sys.exit(2)


def cost_table(entries):
    """The Markdown table of (name, campaign.json path) entries; a missing or unreadable table fails."""
    rows, total = [], 0.0
    for name, table in entries:
        try:
            with open(table) as f:
                points = json.load(f)["points"]
        except (OSError, ValueError, KeyError) as e:
            fail("%s: not a campaign table (%s)" % (table, e))
        status = {}
        hours, untimed, by_wall = 0.0, 0, 0
        for p in points:
            status[p.get("status", "?")] = status.get(p.get("status", "?"), 0) + 1
            seconds = p.get("cpu_seconds")
            if not seconds:
                seconds = p.get("wall_seconds")
                by_wall += 1 if seconds else 0
            if seconds:
                hours += seconds / 3600.0
            elif p.get("status") in ("done", "jammed", "failed"):
                untimed += 1
        total += hours
        rows.append((name, len(points), ", ".join("%d %s" % (n, s) for s, n in sorted(status.items())), hours,
                     by_wall, untimed))
    lines = ["| campaign | points | by status | core-hours | points costed by wall time | finished without a time |",
             "|---|---|---|---|---|---|"]
    for name, n, by_status, hours, by_wall, untimed in rows:
        lines.append("| %s | %d | %s | %.1f | %d | %d |" % (name, n, by_status, hours, by_wall, untimed))
    lines.append("| all | | | %.1f | | |" % total)
    return "\n".join(lines) + "\n"


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    entries = []
    for path in argv:
        table = os.path.join(path, "campaign.json") if os.path.isdir(path) else path
        name = os.path.relpath(os.path.dirname(os.path.abspath(table)))
        entries.append((name[len("results/"):] if name.startswith("results/") else name, table))
    sys.stdout.write(cost_table(entries))


if __name__ == "__main__":
    main(sys.argv[1:])
