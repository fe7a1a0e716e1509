#!/usr/bin/env bash
# Resumes the project's long campaigns on this machine, in the background, one after the other on both cores:
# issue 34's boundary searches (runs/pairwise_boundary, runs/pairwise_boundary_low_friction and
# runs/pairwise_boundary_low_friction_low_stress, from cases/phim/pairwise_boundary*.yaml) and FCM seed scatter (runs/fcm_seed_scatter); tools/collect_results.sh copies
# their tables and fits to results/phim/NAME as they fill; issue 40's normal-stress ensemble
# (runs/normal_stress_functions, cases/validation/normal_stress_functions.yaml: singular against exact two-sphere
# functions on the frictionless case, and runs/normal_stress_frictional: paper 000's case FR at phi 0.45-0.56); issue 36's boundary searches at mu_s 0.3 and 1 with the exact two-sphere
# functions (runs/pairwise_boundary_exact, cases/phim/pairwise_boundary_exact.yaml), then in the issue's order of
# value FCM at mu_s 0.3 and 1 (fcm_boundary), the yield stress by creep bisected in sigma*
# (pairwise_yield_stress), the exact near field at mu_s 0, 0.1 and 0.5 (pairwise_boundary_exact_others), the
# (20 a_1)^3 box (pairwise_box20), sigma* 0.5 and 0.3 (pairwise_low_stress), FCM at the low frictions
# (fcm_boundary_low_friction) and FCM at sigma* 0.5 and 0.3 (fcm_low_stress), each from cases/phim/NAME.yaml into
# runs/NAME;
# issue 35's accuracy ensembles of the default step (runs/step_frictionless, runs/step_ensemble: the packings of
# each case run by the current engine, set against the same campaigns run by the engine before issue 35,
# runs/step_*_before with a binary built at 2fbb67f, and runs/step_particles: the former step rule with the current
# contact step; runs/step_reference: the adhesive case with every step bound halved, implicit and explicit springs,
# the converged reference the first ensembles showed is needed: packings 6-10 pair it with
# all ten of the default, then runs/step_bounds: each of its two bounds halved alone; runs/step_frictionless_diagnostic: what moves the
# frictionless case's contacts per particle; docs/performance.md section f). Issue 36's campaigns run first, in the
# issue's order of value (pairwise_boundary_exact again after FCM for the sigma* 10 groups added to it); the finished
# issues' few unfinished points (issues 35 and 40) follow. A campaign folder that a new machine lacks is first rebuilt
# from the committed table where there is one (tools/restore_campaign.py), so only unfinished points run (a finished
# campaign costs nothing). The binary is copied to RUNS/bin/suspend-campaign, so that rebuilding build/ meanwhile
# does not change what runs. One background job runs the sweeps in turn (two sweeps started side by side share the
# cores, and `nice` does not order jobs started in different sessions).
# The campaigns of issues 13 and 14 (results/phim/*, results/multirate, results/predictor, results/fast_frictional,
# results/exact_relative_check, results/multirate_stress) ran before issue 35's step and contact changes and are
# finished or superseded by the boundary campaigns; their committed tables are the record. Their few unfinished
# points are not resumed: run now they would mix the current step with the former one in one table.
# Logs: RUNS/NAME.log; stop with `pkill -f suspend-campaign`. A campaign whose folder would refuse its file (changed
# other than by added points) is named in a warning before the queue starts.
# The same campaigns run by the engine before issue 35 (runs/step_*_before) need a binary built at 2fbb67f: set
# SUSPEND_BEFORE to it (e.g. `git worktree add /tmp/base 2fbb67f && bash /tmp/base/scripts/build.sh /tmp/base/build`)
# and they are resumed first (their committed tables: results/step_control/*_before).
# The campaigns keep the binary they run with: without SUSPEND, an existing RUNS/bin/suspend-campaign is kept, so
# that a point resumed from its checkpoint continues bit for bit whatever was built since; give SUSPEND (e.g.
# build/bin/suspend) to replace it, which a change of results needs (the new binary then runs every point not yet
# finished). The first resume on a machine copies build/bin/suspend.
# usage: [SUSPEND_BEFORE=BIN] tools/resume_campaigns.sh [SUSPEND (default: keep RUNS/bin/suspend-campaign, else
#        build/bin/suspend)] [RUNS (default runs)]
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help ]]; then awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"; exit 0; fi
root=$(cd "$(dirname "$0")/.." && pwd)
suspend=${1:-}
runs=${2:-$root/runs}
if [[ -z $suspend && ! -x $runs/bin/suspend-campaign ]]; then suspend=$root/build/bin/suspend; fi
if [[ -n $suspend && ! -x $suspend ]]; then echo "error: $suspend not found; build first (see README)" >&2; exit 2; fi
mkdir -p "$runs/bin"
# One chain at a time: a second would run its points beside the first's (four runs on two cores).
if pgrep -f "$runs/bin/suspend-campaign sweep" > /dev/null; then
  echo "error: campaigns are already running from $runs (pgrep -af suspend-campaign); stop them first with" \
       "pkill -f suspend-campaign (each point checkpoints), then resume" >&2
  exit 2
fi
# copy then rename: never a half-written binary at the path; a running sweep starts its later points with the new
# one (it runs the path, campaign/sweep.hpp own_executable)
if [[ -z $suspend ]]; then
  echo "keeping the campaign binary $runs/bin/suspend-campaign (give a SUSPEND to replace it)"
else
  cp "$suspend" "$runs/bin/suspend-campaign.new"
  mv -f "$runs/bin/suspend-campaign.new" "$runs/bin/suspend-campaign"
fi
# name | campaign file | committed table
campaigns=(
  "fcm_boundary|$root/cases/phim/fcm_boundary.yaml|$root/results/phim/fcm_boundary/campaign.json"
  "pairwise_boundary_exact|$root/cases/phim/pairwise_boundary_exact.yaml|$root/results/phim/pairwise_boundary_exact/campaign.json"
  "pairwise_yield_stress|$root/cases/phim/pairwise_yield_stress.yaml|$root/results/phim/pairwise_yield_stress/campaign.json"
  "pairwise_boundary_exact_others|$root/cases/phim/pairwise_boundary_exact_others.yaml|$root/results/phim/pairwise_boundary_exact_others/campaign.json"
  "pairwise_box20|$root/cases/phim/pairwise_box20.yaml|$root/results/phim/pairwise_box20/campaign.json"
  "pairwise_low_stress|$root/cases/phim/pairwise_low_stress.yaml|$root/results/phim/pairwise_low_stress/campaign.json"
  "fcm_boundary_low_friction|$root/cases/phim/fcm_boundary_low_friction.yaml|$root/results/phim/fcm_boundary_low_friction/campaign.json"
  "fcm_low_stress|$root/cases/phim/fcm_low_stress.yaml|$root/results/phim/fcm_low_stress/campaign.json"
  "step_reference|$root/cases/validation/step_control_ensemble_reference.yaml|$root/results/step_control/adhesive_reference/campaign.json"
  "step_bounds|$root/cases/validation/step_control_ensemble_bounds.yaml|$root/results/step_control/adhesive_bounds/campaign.json"
  "pairwise_boundary|$root/cases/phim/pairwise_boundary.yaml|$root/results/phim/pairwise_boundary/campaign.json"
  "fcm_seed_scatter|$root/cases/phim/fcm_seed_scatter.yaml|$root/results/phim/fcm_seed_scatter/campaign.json"
  "pairwise_boundary_low_friction|$root/cases/phim/pairwise_boundary_low_friction.yaml|$root/results/phim/pairwise_boundary_low_friction/campaign.json"
  "pairwise_boundary_low_friction_low_stress|$root/cases/phim/pairwise_boundary_low_friction_low_stress.yaml|$root/results/phim/pairwise_boundary_low_friction_low_stress/campaign.json"
  "normal_stress_functions|$root/cases/validation/normal_stress_functions.yaml|$root/results/normal_stress_functions/campaign.json"
  "normal_stress_frictional|$root/cases/validation/normal_stress_frictional.yaml|$root/results/normal_stress_frictional/campaign.json"
  "step_frictionless|$root/cases/validation/step_control_ensemble_frictionless.yaml|$root/results/step_control/frictionless_after/campaign.json"
  "step_ensemble|$root/cases/validation/step_control_ensemble.yaml|$root/results/step_control/adhesive_after/campaign.json"
  "step_particles|$root/cases/validation/step_control_ensemble_particles.yaml|$root/results/step_control/adhesive_particles/campaign.json"
  "step_frictionless_diagnostic|$root/cases/validation/step_control_ensemble_frictionless_diagnostic.yaml|$root/results/step_control/frictionless_diagnostic/campaign.json"
)
before=()
if [[ -n ${SUSPEND_BEFORE:-} ]]; then
  if [[ ! -x $SUSPEND_BEFORE ]]; then echo "error: SUSPEND_BEFORE=$SUSPEND_BEFORE is not an executable" >&2; exit 2; fi
  before=(
    "step_frictionless_before|$root/cases/validation/step_control_ensemble_frictionless.yaml|$root/results/step_control/frictionless_before/campaign.json"
    "step_ensemble_before|$root/cases/validation/step_control_ensemble.yaml|$root/results/step_control/adhesive_before/campaign.json"
  )
fi
queue=()
for entry in "${before[@]}" "${campaigns[@]}"; do
  IFS='|' read -r name file table <<< "$entry"
  if [[ -f $table && ! -d $runs/$name/points ]]; then
    /usr/bin/python3 "$root/tools/restore_campaign.py" "$table" "$runs/$name"
  fi
  binary=$runs/bin/suspend-campaign
  [[ $name == *_before ]] && binary=$SUSPEND_BEFORE
  queue+=("$name|$file|$binary")
done
export OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE
# A campaign its folder would refuse (a changed campaign file: `sweep` allows only added points) is said now, not
# found later in its log after the queue has passed it.
for entry in "${queue[@]}"; do
  IFS='|' read -r name file binary <<< "$entry"
  [[ -d $runs/$name ]] || continue
  if ! problem=$("$binary" sweep "$file" --out "$runs/$name" --status 2>&1 > /dev/null); then
    echo "warning: $name will be skipped: ${problem#error: }" >&2
  fi
done
(
  for entry in "${queue[@]}"; do
    IFS='|' read -r name file binary <<< "$entry"
    "$binary" sweep "$file" --out "$runs/$name" --jobs 2 --threads 1 --quiet >> "$runs/$name.log" 2>&1 || true
  done
) < /dev/null > /dev/null 2>&1 &
disown
echo "resuming in the background: ${queue[*]%%|*} (logs in $runs/NAME.log)"
