#!/usr/bin/env bash
# Copies the campaign tables of the raw runs (ignored folder runs/) into results/phim/METHOD/, fits them with
# `suspend phim` (all points, and phi >= 0.45 only as paper 004 does for mu_s <= 0.1: METHOD/from_phi0.45/) and
# redraws the figures, so the committed results follow the campaigns as they fill.
# usage: tools/collect_results.sh [RUNS_DIR=runs] [SUSPEND=build/bin/suspend]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-$root/runs}
suspend=${2:-$root/build/bin/suspend}
for method in pairwise fcm; do
  table="$runs/phim_$method/campaign.json"
  [ -f "$table" ] || continue
  out="$root/results/phim/$method"
  mkdir -p "$out"
  cp "$table" "$runs/phim_$method/campaign.csv" "$out/"
  "$suspend" phim "$out" > "$out/phim.txt"
  cat "$out/phim.txt"
  # paper 004 fits mu_s <= 0.1 on phi >= 0.45 only, nearer phi_m (section III C)
  mkdir -p "$out/from_phi0.45"
  "$suspend" phim "$out" --min-phi 0.45 -o "$out/from_phi0.45" > "$out/from_phi0.45/phim.txt"
done
/usr/bin/python3 "$root/tools/phim_figures.py" "$root/results/phim"
