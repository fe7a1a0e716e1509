#!/usr/bin/env bash
# Cost of the two storages of the resistance matrix's coupling blocks (hydrodynamics.solver.storage: dense, the
# default, and pair_form; docs/performance.md section d): one case from its generated packing (made untimed), one
# thread, strain 0 to STRAIN, the two storages one after the other REPEAT times. Per run it prints CPU seconds per unit
# strain, steps per unit strain, linear-solver iterations per step and the mean relative viscosity; per repetition the
# ratio pair_form / dense of the CPU per strain; then their median (the machine's speed drifts within minutes).
# usage: bench/coupling_storage.sh SUSPEND [CASE (default cases/validation/frictionless_jamming.yaml)]
#        [N (default: the case's)] [STRAIN (default 0.5)] [REPEAT (default 3)]
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help || $# -lt 1 ]]; then
  awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"
  [[ $# -ge 1 ]] && exit 0 || exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$1 file=${2:-$root/cases/validation/frictionless_jamming.yaml} n=${3:-} strain=${4:-0.5} repeat=${5:-3}
[[ -x $bin ]] || { echo "error: $bin is not an executable suspend" >&2; exit 2; }
[[ -f $file ]] || { echo "error: case $file not found" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE
sets=(--set run.average_from=0 --threads 1 --quiet)
[[ -n $n ]] && sets+=(--set "particles.count=$n")
"$bin" run "$file" "${sets[@]}" --out "$work/pack" --set run.strain=1e-6 > /dev/null
measure() {  # prints CPU s / strain, steps / strain, iterations / step, eta_r of one run with storage $1
  rm -rf "$work/run"
  /usr/bin/time -f "%U %S" -o "$work/time" "$bin" run "$file" "${sets[@]}" --out "$work/run" \
    --set "particles.initial={from: file, file: $work/pack/run.h5}" --set run.strain="$strain" \
    --set hydrodynamics.solver.storage="$1" > /dev/null
  /usr/bin/python3 - "$work/run/run.h5" "$work/time" "$work/run/summary.json" <<'PY'
import json, sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    s = f["series"]
    step, strain, its = (np.ravel(s[k][()]) for k in ("step", "accumulated_strain", "solver_iterations"))
cpu = sum(map(float, open(sys.argv[2]).read().split()[-2:]))
eta = json.load(open(sys.argv[3]))["eta_r"]["mean"]
print(f"{cpu / strain[-1]:.3f} {step[-1] / strain[-1]:.0f} {its.mean():.1f} {eta:.5g}")
PY
}
ratios=()
printf "%4s %10s %12s %12s %10s %10s\n" rep storage "CPU s/strain" steps/strain "its/step" eta_r
for ((r = 1; r <= repeat; ++r)); do
  read -r c1 s1 i1 e1 < <(measure dense)
  read -r c2 s2 i2 e2 < <(measure pair_form)
  printf "%4s %10s %12s %12s %10s %10s\n" "$r" dense "$c1" "$s1" "$i1" "$e1"
  printf "%4s %10s %12s %12s %10s %10s\n" "$r" pair_form "$c2" "$s2" "$i2" "$e2"
  ratios+=("$(/usr/bin/python3 -c "print(f'{$c2 / $c1:.3f}')")")
done
/usr/bin/python3 -c "
import statistics, sys
r = [float(x) for x in sys.argv[1:]]
print(f'median CPU ratio pair_form / dense over {len(r)} repetitions: {statistics.median(r):.3f} (each: ' + ', '.join(sys.argv[1:]) + ')')
" "${ratios[@]}"
