#!/usr/bin/env bash
# Accuracy of the overdamped step on a transient (issue 35; docs/overdamped.md section 4c): from one generated
# packing, eta_r averaged over consecutive strain windows for several step rules, against a reference run by OLD with
# half its contact displacement. Before the trajectories part (a tenth of a strain or so near phi_m) the window means
# differ by the step's error only, so a rule whose windows follow the reference is accurate at that step.
#   reference  OLD, run.time_step.max_displacement = 2.5e-4 (half of the h_r / 10 the Hertz case uses)
#   old        OLD as shipped
#   new        NEW as shipped
#   new-5e-3   NEW with max_displacement 5e-3 (the contact slip and particle bound 2.5x the default)
#   particles  NEW with run.time_step.bound = particles (the old rule with the new contact step)
# usage: bench/step_convergence.sh OLD_SUSPEND NEW_SUSPEND [CASE (a or b, default b)] [STRAIN (default 0.1)]
#   (a) mu_s 0.5, sigma* 1, phi 0.48; (b) mu_s 0.1, sigma* 10, phi 0.60 (cases/phim/adhesive_bidisperse.yaml)
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help || $# -lt 2 ]]; then
  awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"
  [[ $# -ge 2 ]] && exit 0 || exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
old=$1 new=$2 which=${3:-b} strain=${4:-0.1}
case $which in
  a) sets=(--set flow.shear_stress=1 --set particles.phi=0.48) ;;
  b) sets=(--set contact.mu_s=0.1 --set flow.shear_stress=10 --set particles.phi=0.60) ;;
  *) echo "error: case must be a or b, not '$which'" >&2; exit 2 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE
file=$root/cases/phim/adhesive_bidisperse.yaml
"$old" run "$file" "${sets[@]}" --out "$work/pack" --quiet --set run.strain=1e-6 --set run.average_from=0 > /dev/null
phi=$(/usr/bin/python3 -c "import json, sys; print(repr(json.load(open(sys.argv[1]))['phi']))" "$work/pack/summary.json")
start=(--set "particles.phi=$phi" --set "particles.initial={from: file, file: $work/pack/run.h5}"
       --set run.strain="$strain" --set run.average_from=0)
runs=("reference|$old|run.time_step.max_displacement=2.5e-4" "old|$old|" "new|$new|"
      "new-5e-3|$new|run.time_step.max_displacement=5e-3" "particles|$new|run.time_step.bound=particles")
for entry in "${runs[@]}"; do
  IFS='|' read -r name bin extra <<< "$entry"
  args=("${sets[@]}" "${start[@]}")
  [[ -n $extra ]] && args+=(--set "$extra")
  /usr/bin/time -f "%U %S" -o "$work/time" "$bin" run "$file" "${args[@]}" --out "$work/$name" --quiet > /dev/null
  /usr/bin/python3 - "$work/$name/run.h5" "$work/time" "$name" "$strain" <<'PY'
import sys
import h5py
import numpy as np
path, timing, name, strain = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
with h5py.File(path, "r") as f:
    s = f["series"]
    step, gamma, eta = (np.ravel(s[k][()]) for k in ("step", "accumulated_strain", "eta_r"))
cpu = sum(map(float, open(timing).read().split()[-2:]))
width = strain / 4
windows = [eta[(gamma > a) & (gamma <= a + width + 1e-12)].mean() for a in np.arange(4) * width]
print(f"{name:10s} steps/strain {step[-1] / gamma[-1]:8.0f}  CPU s {cpu:7.2f}  eta_r by {width:g} strain: "
      + " ".join(f"{w:7.1f}" for w in windows))
PY
done
