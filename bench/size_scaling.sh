#!/usr/bin/env bash
# How the cost per unit strain grows with the number of spheres (issue 35; docs/performance.md section f):
# cases/validation/frictionless_jamming.yaml at N = 500 and N = 2000 (the same volume fraction, the box 4x the
# volume), each from its generated packing (made untimed), one thread, strain 0 to STRAIN. Prints per size the CPU
# seconds per unit strain, steps per unit strain and linear-solver iterations per step, then the ratio
# N = 2000 / N = 500 of each: an O(N) engine would show 4 for the CPU.
# usage: bench/size_scaling.sh SUSPEND [PHI (default 0.50)] [STRAIN (default 1)] [SMALL LARGE (default 500 2000)]
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help || $# -lt 1 ]]; then
  awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"
  [[ $# -ge 1 ]] && exit 0 || exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$1 phi=${2:-0.50} strain=${3:-1} small=${4:-500} large=${5:-2000}
[[ -x $bin ]] || { echo "error: $bin is not an executable suspend" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE
file=$root/cases/validation/frictionless_jamming.yaml
declare -A cps sps its
printf "%6s %12s %12s %10s\n" N "CPU s/strain" steps/strain "its/step"
for n in "$small" "$large"; do
  sets=(--set "particles.count=$n" --set "particles.phi=$phi" --set run.average_from=0 --threads 1 --quiet)
  "$bin" run "$file" "${sets[@]}" --out "$work/pack$n" --set run.strain=1e-6 > /dev/null
  /usr/bin/time -f "%U %S" -o "$work/time" "$bin" run "$file" "${sets[@]}" --out "$work/run$n" \
    --set "particles.initial={from: file, file: $work/pack$n/run.h5}" --set run.strain="$strain" > /dev/null
  read -r cps[$n] sps[$n] its[$n] < <(/usr/bin/python3 - "$work/run$n/run.h5" "$work/time" <<'PY'
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    s = f["series"]
    step, strain, its = (np.ravel(s[k][()]) for k in ("step", "accumulated_strain", "solver_iterations"))
cpu = sum(map(float, open(sys.argv[2]).read().split()[-2:]))
print(f"{cpu / strain[-1]:.3f} {step[-1] / strain[-1]:.0f} {its.mean():.1f}")
PY
)
  printf "%6s %12s %12s %10s\n" "$n" "${cps[$n]}" "${sps[$n]}" "${its[$n]}"
done
/usr/bin/python3 -c "
import sys
a = list(map(float, sys.argv[1:4])); b = list(map(float, sys.argv[4:7]))
print(f'ratio {sys.argv[8]} / {sys.argv[7]}: CPU per strain {b[0] / a[0]:.2f}, steps per strain {b[1] / a[1]:.2f}, iterations per step {b[2] / a[2]:.2f}')
" "${cps[$small]}" "${sps[$small]}" "${its[$small]}" "${cps[$large]}" "${sps[$large]}" "${its[$large]}" "$small" "$large"
