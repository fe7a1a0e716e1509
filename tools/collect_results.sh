#!/usr/bin/env bash
# Copies the campaign tables of the raw runs (ignored folder runs/) into results/phim/METHOD/ (the phi_m campaigns,
# issue 34's boundary searches and FCM seed scatter, issue 36's boundary searches (pairwise with the exact near
# field, FCM at mu_s 0.3 and 1 and at the low frictions, the 20 a_1 box, sigma* 0.5 and 0.3); issue
# 40's normal-stress ensembles to results/normal_stress_functions/ and results/normal_stress_frictional/), fits them with `suspend phim` (all points, and phi >= 0.45 only as paper 004 does
# for mu_s <= 0.1: METHOD/from_phi0.45/) and redraws the figures, so the committed results follow the campaigns as
# they fill; a table already committed is fitted again with the current `suspend phim`; issue 35's step ensembles of
# case (a) to results/step_control/.
# usage: tools/collect_results.sh [RUNS_DIR=runs] [SUSPEND=build/bin/suspend]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-$root/runs}
suspend=${2:-$root/build/bin/suspend}
# copy_table RUN_FOLDER RESULTS_FOLDER: the campaign table, with paths relative to the repository, not this machine's
# checkout
copy_table() {
  mkdir -p "$2"
  for f in campaign.json campaign.csv; do
    sed "s|$root/||g" "$1/$f" > "$2/$f.part" && mv "$2/$f.part" "$2/$f"
  done
}
# name in runs/ | folder under results/phim/
for entry in "phim_pairwise|pairwise" "phim_fcm|fcm" "pairwise_boundary|pairwise_boundary" \
    "pairwise_boundary_low_friction|pairwise_boundary_low_friction" \
    "pairwise_boundary_low_friction_low_stress|pairwise_boundary_low_friction_low_stress" \
    "pairwise_boundary_exact|pairwise_boundary_exact" "fcm_seed_scatter|fcm_seed_scatter" \
    "fcm_boundary|fcm_boundary" "pairwise_boundary_exact_others|pairwise_boundary_exact_others" \
    "pairwise_box20|pairwise_box20" "pairwise_low_stress|pairwise_low_stress" \
    "fcm_boundary_low_friction|fcm_boundary_low_friction" "fcm_low_stress|fcm_low_stress" \
    "pairwise_yield_stress|pairwise_yield_stress"; do
  IFS='|' read -r name method <<< "$entry"
  out="$root/results/phim/$method"
  [ -f "$runs/$name/campaign.json" ] && copy_table "$runs/$name" "$out"
  [ -f "$out/campaign.json" ] || continue
  if [ "$method" = pairwise_yield_stress ]; then  # a search in sigma* at fixed phi: against the exact-field boundaries
    boundaries=()
    for b in pairwise_boundary_exact pairwise_boundary_exact_others; do
      [ -f "$root/results/phim/$b/phim.json" ] && boundaries+=("results/phim/$b")
    done
    (cd "$root" && /usr/bin/python3 tools/yield_vs_boundary.py results/phim/pairwise_yield_stress "${boundaries[@]}" \
      > results/phim/pairwise_yield_stress/against_boundary.txt) || true
    continue
  fi
  if [ "$method" = fcm_seed_scatter ]; then  # a seed study, not a phi_m campaign
    /usr/bin/python3 "$root/tools/seed_scatter.py" "$out" > "$out/seed_scatter.txt"
    cat "$out/seed_scatter.txt"
    continue
  fi
  (cd "$root" && "$suspend" phim "results/phim/$method" > "results/phim/$method/phim.txt")
  cat "$out/phim.txt"
  [[ $method != pairwise && $method != fcm ]] && continue  # the boundary searches: no fits from phi 0.45
  # paper 004 fits mu_s <= 0.1 on phi >= 0.45 only, nearer phi_m (section III C)
  mkdir -p "$out/from_phi0.45"
  (cd "$root" && "$suspend" phim "results/phim/$method" --min-phi 0.45 -o "results/phim/$method/from_phi0.45" \
    > "results/phim/$method/from_phi0.45/phim.txt")
done
# Issue 36: the constraint-rheology boundary (phi_alp) per near-field model and method, from the boundary tables.
fit_boundaries() {  # NAME TABLE_FOLDER...
  local name=$1 tables=()
  shift
  for t in "$@"; do [ -f "$root/results/phim/$t/phim.json" ] && tables+=("results/phim/$t"); done
  [ ${#tables[@]} -eq 0 ] && return
  (cd "$root" && /usr/bin/python3 tools/constraint_fit.py "${tables[@]}" --json "results/phim/constraint_fit/$name.json" \
    > "results/phim/constraint_fit/$name.txt" 2> /dev/null) || rm -f "$root/results/phim/constraint_fit/$name.txt"
  # (a table with no bracketed group yet: nothing to fit, nothing written)
}
# Issue 36, item 5: shear banding in the flowing points of the boundary searches (from the raw runs' snapshots; the
# committed rows are kept for points whose runs this machine does not have, a folder restored from its table).
for name in pairwise_boundary_exact pairwise_boundary_exact_others pairwise_low_stress fcm_boundary fcm_low_stress \
    pairwise_box20; do
  [ -d "$runs/$name/points" ] && [ -d "$root/results/phim/$name" ] || continue
  banding=$root/results/phim/$name/banding.txt
  /usr/bin/python3 "$root/tools/banding_check.py" "$runs/$name" --suspend "$suspend" --keep "$banding" \
    > "$banding.part" 2>&1 && mv "$banding.part" "$banding" || rm -f "$banding.part"
done
mkdir -p "$root/results/phim/constraint_fit"
fit_boundaries pairwise_singular pairwise_boundary pairwise_boundary_low_friction pairwise_boundary_low_friction_low_stress
fit_boundaries pairwise_exact pairwise_boundary_exact pairwise_boundary_exact_others pairwise_low_stress
fit_boundaries fcm fcm_boundary fcm_boundary_low_friction fcm_low_stress
# How far phi_m moves (issue 36): with the exact near field, with the box, between the methods, against the seeds'
# spread (tools/boundary_shift.py), each once both sides have a table.
boundary_shift() {  # boundary_shift NAME "A dirs" "B dirs"
  local a=() b=() d
  for d in $2; do [ -f "$root/results/phim/$d/campaign.json" ] && a+=("results/phim/$d"); done
  for d in $3; do [ -f "$root/results/phim/$d/campaign.json" ] && b+=("results/phim/$d"); done
  [ ${#a[@]} -gt 0 ] && [ ${#b[@]} -gt 0 ] || return 0
  mkdir -p "$root/results/phim/shifts"
  (cd "$root" && /usr/bin/python3 tools/boundary_shift.py "${a[@]}" --against "${b[@]}" > "results/phim/shifts/$1.txt")
}
boundary_shift exact_against_singular "pairwise_boundary pairwise_boundary_low_friction pairwise_boundary_low_friction_low_stress" \
  "pairwise_boundary_exact_others"
boundary_shift box20_against_box16 "pairwise_boundary_exact pairwise_boundary_exact_others" "pairwise_box20"
boundary_shift fcm_against_pairwise_exact "pairwise_boundary_exact pairwise_boundary_exact_others pairwise_low_stress" \
  "fcm_boundary fcm_boundary_low_friction fcm_low_stress"
/usr/bin/python3 "$root/tools/phim_figures.py" "$root/results/phim"
# results/README.md's phi_m tables (one campaign each, and Fig. 15 over all of them) from the tables just fitted
/usr/bin/python3 "$root/tools/phim_table.py" --update "$root/results/README.md"
# Issue 40's normal-stress ensemble: its table, and the means of singular against exact_relative per phi.
if [ -f "$runs/normal_stress_functions/campaign.json" ]; then
  out="$root/results/normal_stress_functions"
  copy_table "$runs/normal_stress_functions" "$out"
  for phi in 0.45 0.5 0.55; do
    /usr/bin/python3 "$root/tools/ensemble_means.py" "$out/campaign.json" hydrodynamics.lubrication.functions \
      --where particles.phi=$phi
  done > "$out/ensemble_means.txt" 2>&1 || true
fi
# Issue 40's frictional (mu = 1) normal-stress ensemble: its table and the means per phi.
if [ -f "$runs/normal_stress_frictional/campaign.json" ]; then
  out="$root/results/normal_stress_frictional"
  copy_table "$runs/normal_stress_frictional" "$out"
  /usr/bin/python3 "$root/tools/ensemble_means.py" "$out/campaign.json" particles.phi > "$out/ensemble_means.txt" 2>&1 \
    || true
fi
# Issue 35's step ensembles of case (a): the halved-step reference and each bound halved alone, against the default.
for entry in "step_reference|adhesive_reference" "step_bounds|adhesive_bounds"; do
  IFS='|' read -r name folder <<< "$entry"
  [ -f "$runs/$name/campaign.json" ] && copy_table "$runs/$name" "$root/results/step_control/$folder"
done
if [ -f "$root/results/step_control/adhesive_bounds/campaign.json" ]; then
  for key in run.time_step.max_displacement run.time_step.gap_change; do  # each halved bound against default, reference
    (cd "$root/results/step_control" && /usr/bin/python3 ../../tools/ensemble_means.py adhesive_bounds/campaign.json \
      adhesive_after/campaign.json adhesive_reference/campaign.json "$key" --where contact.mu_s=0.5 2>&1) || true
  done > "$root/results/step_control/adhesive_bounds/ensemble_means.txt"
fi
