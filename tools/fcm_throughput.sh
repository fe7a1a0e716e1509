#!/usr/bin/env bash
# FCM against the pairwise engine: wall time per unit strain of the same case from the same packing, one thread
# each, timed one after the other in this one script (issue 14's target: FCM at most 3x the pairwise engine).
# The packing and the FCM pair tables are made by untimed runs first, so only the stepping is timed.
# Cases (name: file and settings):
#   d   cross-validation (d) at G_adh = 20: crossval_adhesive.yaml, g_adh 20, gamma_bar 0.045 (phi 0.40, imposed rate)
#   c   cross-validation (c) at phi 0.45: crossval_frictional.yaml, phi 0.45 (imposed rate)
#   bi  paper 004's bidisperse campaign case at phi 0.50, sigma* = 2, mu_s 0.5 (imposed stress)
#   p30, p40, p45  the FCM campaign's case (cases/phim/fcm_campaign.yaml) at phi 0.30, 0.40, 0.45 and sigma* = 1
# Prints per case and strain: steps, seconds, s/strain of each engine, the FCM/pairwise ratio, FCM's mean Stokes
# solves per step (summary.json fcm.stokes_solves_per_step) and the core-hours of a 20-strain run at that rate.
# The FCM runs use the default FCM settings (since 2026-12-05 the far field every 10 steps with the lagged
# predictor); every step as before: EXTRA "hydrodynamics.fcm.far_field_every=1 hydrodynamics.fcm.predictor=extrapolated".
# Usage: tools/fcm_throughput.sh [STRAINS (default "0.3")] [CASES (default "d c bi")] [BUILD_DIR (default build)]
#                               [EXTRA --set assignments for the FCM runs, e.g. "hydrodynamics.fcm.tolerance=1e-3"]
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help ]]; then awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"; exit 0; fi
root=$(cd "$(dirname "$0")/.." && pwd)
strains=${1:-0.3}
cases=${2:-d c bi}
build=${3:-$root/build}
extra=${4:-}
bin=$build/bin/suspend
if [[ ! -x $bin ]]; then echo "error: $bin not found; build first (see README)" >&2; exit 2; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_WAIT_POLICY=passive

case_args() {
  case $1 in
    d) echo "$root/cases/validation/crossval_adhesive.yaml --set contact.g_adh=20 --set contact.gamma_bar=0.045" ;;
    c) echo "$root/cases/validation/crossval_frictional.yaml --set particles.phi=0.45" ;;
    bi) echo "$root/cases/phim/adhesive_bidisperse.yaml --set particles.phi=0.5 --set flow.shear_stress=2" ;;
    p30|p40|p45) echo "$root/cases/phim/adhesive_bidisperse.yaml --set particles.phi=0.${1#p} --set flow.shear_stress=1" ;;
    *) echo "error: unknown case '$1' (d, c, bi, p30, p40, p45)" >&2; exit 2 ;;
  esac
}
for name in $cases; do case_args "$name" >/dev/null || exit 2; done
fcm_sets=()
for s in $extra; do fcm_sets+=(--set "$s"); done

printf "%-4s %7s %-9s %8s %9s %10s %11s %13s\n" case strain engine steps seconds "s/strain" "solves/step" "core-h/20str"
for name in $cases; do
  read -r -a args <<<"$(case_args "$name")"
  "$bin" run "${args[@]}" --out "$work/$name-pack" --threads 1 --quiet --set run.strain=1e-6 \
    --set run.average_from=0 >/dev/null
  from=(--set "particles.initial={from: file, file: $work/$name-pack/run.h5}" --set run.average_from=0
        --set run.output.snapshot_every=100 --set run.output.checkpoint_every=100)
  "$bin" run "${args[@]}" "${from[@]}" --out "$work/$name-warm" --threads 1 --quiet --set run.strain=1e-6 \
    --set hydrodynamics.model=fcm "${fcm_sets[@]}" >/dev/null  # FCM pair tables into the cache, untimed
  for strain in $strains; do
    declare -A seconds=()
    for engine in pairwise fcm; do
      set_engine=(--set hydrodynamics.model=$engine)
      [[ $engine == fcm ]] && set_engine+=("${fcm_sets[@]}")
      out=$work/$name-$engine-$strain
      start=$(date +%s.%N)
      "$bin" run "${args[@]}" "${from[@]}" "${set_engine[@]}" --out "$out" --threads 1 --quiet \
        --set run.strain="$strain" >/dev/null
      end=$(date +%s.%N)
      seconds[$engine]=$(/usr/bin/python3 -c "print($end - $start)")
      /usr/bin/python3 - "$out" "${seconds[$engine]}" "$name" "$strain" "$engine" <<'PY'
import sys, json, h5py
out, sec, name, strain, engine = sys.argv[1], float(sys.argv[2]), sys.argv[3], float(sys.argv[4]), sys.argv[5]
steps = int(h5py.File(out + "/run.h5", "r")["series"]["step"][-1])
summary = json.load(open(out + "/summary.json"))
solves = summary["fcm"]["stokes_solves_per_step"] if engine == "fcm" else float("nan")
print(f"{name:<4} {strain:7.3g} {engine:<9} {steps:8d} {sec:9.1f} {sec / strain:10.1f} {solves:11.2f} "
      f"{sec / strain * 20 / 3600:13.2f}")
PY
    done
    /usr/bin/python3 -c "print(f'{\"$name\":<4} {$strain:7.3g} ratio FCM/pairwise = {${seconds[fcm]} / ${seconds[pairwise]}:.2f}')"
  done
done
