#!/usr/bin/env bash
# Resumes the project's long campaigns on this machine, in the background, one after the other on both cores:
# the issue-14 seed ensemble (results/multirate, rate control), the FCM phi_m campaign (results/phim/fcm), the
# ensembles of issue 14's fast setting (far_field_every 10 + lagged predictor) on (d) and (c) (results/predictor,
# results/fast_frictional), the pairwise sigma* = 1 points with the exact two-sphere functions
# (results/exact_relative_check), the stress-controlled check of the FCM campaign's k = 20
# (results/multirate_stress), then the pairwise campaign (results/phim/pairwise). Points under an hour go before
# the check's every-step points (2-3 h each), which a session on a new machine, losing its runs/ folder, rarely
# sees finish. A campaign folder that a new machine lacks is first rebuilt from the committed table where there is
# one (tools/restore_campaign.py), so only unfinished points run (a finished campaign costs nothing). The binary is
# copied to RUNS/bin/suspend-campaign, so that rebuilding build/ meanwhile does not change what runs. One background
# job runs the sweeps in turn (two sweeps started side by side share the cores, and `nice` does not order jobs
# started in different sessions).
# Logs: RUNS/NAME.log; stop with `pkill -f suspend-campaign`.
# usage: tools/resume_campaigns.sh [SUSPEND (default build/bin/suspend)] [RUNS (default runs)]
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help ]]; then awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"; exit 0; fi
root=$(cd "$(dirname "$0")/.." && pwd)
suspend=${1:-$root/build/bin/suspend}
runs=${2:-$root/runs}
if [[ ! -x $suspend ]]; then echo "error: $suspend not found; build first (see README)" >&2; exit 2; fi
mkdir -p "$runs/bin"
# copy then rename: a running sweep keeps its (busy) binary, new sweeps get the new one
cp "$suspend" "$runs/bin/suspend-campaign.new"
mv -f "$runs/bin/suspend-campaign.new" "$runs/bin/suspend-campaign"
# name | campaign file | committed table
campaigns=(
  "multirate|$root/cases/validation/fcm_multirate_ensemble.yaml|$root/results/multirate/campaign.json"
  "phim_fcm|$root/cases/phim/fcm_campaign.yaml|$root/results/phim/fcm/campaign.json"
  "predictor|$root/cases/validation/fcm_predictor_ensemble.yaml|$root/results/predictor/campaign.json"
  "fast_frictional|$root/cases/validation/fcm_fast_frictional_ensemble.yaml|$root/results/fast_frictional/campaign.json"
  "exact_relative_check|$root/cases/phim/pairwise_exact_relative_check.yaml|$root/results/exact_relative_check/campaign.json"
  "multirate_stress|$root/cases/validation/fcm_multirate_stress.yaml|$root/results/multirate_stress/campaign.json"
  "phim_pairwise|$root/cases/phim/pairwise_campaign.yaml|$root/results/phim/pairwise/campaign.json"
)
queue=()
for entry in "${campaigns[@]}"; do
  IFS='|' read -r name file table <<< "$entry"
  if [[ -f $table && ! -d $runs/$name/points ]]; then
    /usr/bin/python3 "$root/tools/restore_campaign.py" "$table" "$runs/$name"
  fi
  queue+=("$name|$file")
done
export OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE
(
  for entry in "${queue[@]}"; do
    IFS='|' read -r name file <<< "$entry"
    "$runs/bin/suspend-campaign" sweep "$file" --out "$runs/$name" --jobs 2 --threads 1 --quiet >> "$runs/$name.log" 2>&1 || true
  done
) < /dev/null > /dev/null 2>&1 &
disown
echo "resuming in the background: ${queue[*]%%|*} (logs in $runs/NAME.log)"
