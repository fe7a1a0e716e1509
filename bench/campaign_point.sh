#!/usr/bin/env bash
# The cost of a campaign point near phi_m, two binaries side by side (issue 35; docs/performance.md section f):
#   (a) cases/phim/adhesive_bidisperse.yaml, mu_s 0.5, sigma* 1, phi 0.48, strain 0 to 1
#   (b) the same case, mu_s 0.1, sigma* 10, phi 0.60, strain 0 to 0.5
#   (c) cases/validation/frictionless_jamming.yaml as shipped (N = 500, phi 0.50), strain 0 to 2
# Each case starts from one generated packing (made untimed by OLD, read by both from its run.h5), runs on one thread
# with OLD then NEW, and the script prints per binary the CPU seconds per unit strain (user + system time of the run
# process), steps per unit strain, linear-solver iterations per step and the mean eta_r over the window, then the
# ratio OLD / NEW of the CPU per strain. Each binary runs with its own defaults: the comparison is of what a user gets.
# usage: bench/campaign_point.sh OLD_SUSPEND NEW_SUSPEND [CASES (default "a b c")] [STRAIN_SCALE (default 1)]
#        [MODE: alternate (default) | together]
#   STRAIN_SCALE multiplies the strain windows (0.1 for a quick look). MODE together runs OLD and NEW at the same
#   time, one on each core (leave the machine otherwise idle), so both see the same minutes of a machine whose speed
#   drifts by tens of per cent (bench/size_scaling.sh has the same mode).
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help || $# -lt 2 ]]; then
  awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"
  [[ $# -ge 2 ]] && exit 0 || exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
old=$1 new=$2 cases=${3:-a b c} scale=${4:-1} mode=${5:-alternate}
[[ $mode == alternate || $mode == together ]] || { echo "error: MODE is alternate or together, not $mode" >&2; exit 2; }
for bin in "$old" "$new"; do
  [[ -x $bin ]] || { echo "error: $bin is not an executable suspend" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE

# name | case file | --set assignments | strain
declare -A file sets strain
file[a]=$root/cases/phim/adhesive_bidisperse.yaml
sets[a]="flow.shear_stress=1 particles.phi=0.48"
strain[a]=1
file[b]=$root/cases/phim/adhesive_bidisperse.yaml
sets[b]="contact.mu_s=0.1 flow.shear_stress=10 particles.phi=0.60"
strain[b]=0.5
file[c]=$root/cases/validation/frictionless_jamming.yaml
sets[c]=""
strain[c]=2

printf "%-4s %-4s %12s %12s %10s %10s\n" case bin "CPU s/strain" steps/strain "its/step" eta_r
for c in $cases; do
  [[ -n ${file[$c]:-} ]] || { echo "error: unknown case '$c' (a, b or c)" >&2; exit 2; }
  args=()
  for s in ${sets[$c]}; do args+=(--set "$s"); done
  target=$(/usr/bin/python3 -c "print(${strain[$c]} * $scale)")
  "$old" run "${file[$c]}" "${args[@]}" --out "$work/$c.pack" --threads 1 --quiet --set run.strain=1e-6 \
    --set run.average_from=0 > /dev/null
  # A case with a box reads the packing at the volume fraction it reached.
  phi=$(/usr/bin/python3 -c "import json, sys; print(repr(json.load(open(sys.argv[1]))['phi']))" "$work/$c.pack/summary.json")
  [[ ${sets[$c]} == *particles.phi* ]] && args+=(--set "particles.phi=$phi")
  declare -A cpu=()
  run_one() {  # $1 = old or new: runs the case, writes "CPU steps its eta" to $work/$c.$1.line
    local bin=$old out=$work/$c.$1
    [[ $1 == new ]] && bin=$new
    /usr/bin/time -f "%U %S" -o "$out.time" "$bin" run "${file[$c]}" "${args[@]}" --out "$out" --threads 1 --quiet \
      --set "particles.initial={from: file, file: $work/$c.pack/run.h5}" --set run.strain="$target" \
      --set run.average_from=0 > "$out.log" 2>&1 || { echo "error: $1 run of ($c) failed: $(tail -1 "$out.log")" >&2; return 1; }
    /usr/bin/python3 - "$out/run.h5" "$out.time" > "$out.line" <<'PY'
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    s = f["series"]
    step, strain = np.ravel(s["step"][()]), np.ravel(s["accumulated_strain"][()])
    its, eta = np.ravel(s["solver_iterations"][()]), np.ravel(s["eta_r"][()])
user, system = map(float, open(sys.argv[2]).read().split()[-2:])
print(f"{(user + system) / strain[-1]:.3f} {step[-1] / strain[-1]:.0f} {its.mean():.1f} {eta.mean():.2f}")
PY
  }
  if [[ $mode == together ]]; then
    run_one old & old_pid=$!
    run_one new & new_pid=$!
    wait "$old_pid" || exit 1
    wait "$new_pid" || exit 1
  else
    run_one old || exit 1
    run_one new || exit 1
  fi
  for which in old new; do
    read -r cps sps its eta < "$work/$c.$which.line"
    cpu[$which]=$cps
    printf "%-4s %-4s %12s %12s %10s %10s\n" "($c)" "$which" "$cps" "$sps" "$its" "$eta"
  done
  printf "%-4s ratio old / new CPU per strain: %.2f\n" "($c)" "$(/usr/bin/python3 -c "print(${cpu[old]} / ${cpu[new]})")"
done
