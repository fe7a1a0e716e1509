#!/usr/bin/env bash
# Copies a running or finished campaign's table into the repository's results and fits it, so that tables are
# committed as they fill: RESULTS/campaign.json and campaign.csv (paths made relative to the repository), and
# RESULTS/phim.json, phim.csv and phim.txt from `suspend phim`.
# usage: tools/publish_campaign.sh CAMPAIGN_DIR RESULTS_DIR [SUSPEND (default build/bin/suspend)]
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help ]]; then awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"; exit 0; fi
if [[ $# -lt 2 ]]; then echo "usage: tools/publish_campaign.sh CAMPAIGN_DIR RESULTS_DIR [SUSPEND]" >&2; exit 2; fi
root=$(cd "$(dirname "$0")/.." && pwd)
from=$1 to=$2 suspend=${3:-$root/build/bin/suspend}
if [[ ! -f $from/campaign.json ]]; then echo "error: $from/campaign.json not found (a campaign folder of suspend sweep)" >&2; exit 2; fi
mkdir -p "$to"
for f in campaign.json campaign.csv; do
  sed "s|$root/||g" "$from/$f" > "$to/$f.part" && mv "$to/$f.part" "$to/$f"
done
(cd "$root" && "$suspend" phim "${to#"$root"/}" > "${to#"$root"/}/phim.txt")
echo "$to: $(grep -c '"name"' "$to/campaign.json") points; fits in $to/phim.txt"
