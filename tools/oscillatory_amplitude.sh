#!/usr/bin/env bash
# eta'(gamma_0) of the dense frictional suspension (cases/protocols/oscillatory_frictional.yaml): the amplitude
# campaign, the steady run of the same case, and results/protocols/oscillatory_amplitude.{json,png,svg} plus its table.
# Resumable (the sweep and the steady run continue where they stopped).
# usage: tools/oscillatory_amplitude.sh [RUNS_DIR=runs] [SUSPEND=build/bin/suspend]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-$root/runs}
suspend=${2:-$root/build/bin/suspend}
export OMP_WAIT_POLICY=passive
"$suspend" sweep "$root/cases/protocols/oscillatory_amplitude_campaign.yaml" --out "$runs/osc_amplitude" --jobs 1 --threads 1 --quiet
steady="$runs/osc_steady"
steady_case=("$root/cases/protocols/oscillatory_frictional.yaml" --set flow.type=simple_shear --set flow.shear_rate=1
             --set flow.strain_amplitude=null --set flow.angular_frequency=null --set run.output.series_per_cycle=null
             --set run.strain=20 --set run.average_from=5)
if [ ! -f "$steady/summary.json" ] || ! grep -q '"done"' "$steady/summary.json"; then
  if [ -f "$steady/checkpoint.h5" ]; then
    "$suspend" run "${steady_case[@]}" --restart "$steady/checkpoint.h5" --threads 1 --quiet
  else
    "$suspend" run "${steady_case[@]}" --out "$steady" --threads 1 --quiet
  fi
fi
/usr/bin/python3 "$root/tools/oscillatory_amplitude.py" "$runs/osc_amplitude" "$steady" "$root/results/protocols"
