#!/usr/bin/env python3
"""The machine time of campaigns, from their tables: per campaign the points by status and the core-hours they took
(each point runs on one thread, so its wall time is its core time; issue 36 asks for the CPU hours of every
campaign). Points that ran before wall times were recorded count as 0 and are counted apart.

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
        hours, untimed = 0.0, 0
        for p in points:
            status[p.get("status", "?")] = status.get(p.get("status", "?"), 0) + 1
            seconds = p.get("wall_seconds")
            if seconds:
                hours += seconds / 3600.0
            elif p.get("status") in ("done", "jammed", "failed"):
                untimed += 1
        total += hours
        rows.append((name, len(points), ", ".join("%d %s" % (n, s) for s, n in sorted(status.items())), hours,
                     untimed))
    lines = ["| campaign | points | by status | core-hours | finished without a wall time |", "|---|---|---|---|---|"]
    for name, n, by_status, hours, untimed in rows:
        lines.append("| %s | %d | %s | %.1f | %d |" % (name, n, by_status, hours, untimed))
    lines.append("| all | | | %.1f | |" % total)
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
