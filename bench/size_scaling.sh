#!/usr/bin/env bash
# How the cost per unit strain grows with the number of spheres (issue 35; docs/performance.md section f):
# cases/validation/frictionless_jamming.yaml at N = 500 and N = 2000 (the same volume fraction, the box 4x the
# volume), each from its generated packing (made untimed), one thread, strain 0 to STRAIN. The two sizes run one
# after the other REPEAT times; per repetition it prints the CPU seconds per unit strain, steps per unit strain and
# linear-solver iterations per step of each size and their ratio N = 2000 / N = 500 (an O(N) engine shows 4 for
# the CPU), then the median CPU ratio. On a shared machine whose speed drifts by 10-20% within minutes, the
# interleaved repetitions and their median are what make the ratio reproducible. MODE `together` runs the two sizes
# at the same time instead, one on each core: the large run once, the small one over and over until the large one
# has ended, and the ratio is the large run's CPU against the mean of the small runs', so both see the same minutes
# of the machine (which drifts by tens of per cent: docs/performance.md section f).
# usage: bench/size_scaling.sh SUSPEND [PHI (default 0.50)] [STRAIN (default 1)] [SMALL LARGE (default 500 2000)]
#        [REPEAT (default 3)] [MODE: alternate (default) | together]
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help || $# -lt 1 ]]; then
  awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "$0"
  [[ $# -ge 1 ]] && exit 0 || exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$1 phi=${2:-0.50} strain=${3:-1} small=${4:-500} large=${5:-2000} repeat=${6:-3} mode=${7:-alternate}
[[ -x $bin ]] || { echo "error: $bin is not an executable suspend" >&2; exit 2; }
[[ $mode == alternate || $mode == together ]] || { echo "error: MODE is alternate or together, not $mode" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE
file=$root/cases/validation/frictionless_jamming.yaml
sets() { echo --set "particles.count=$1" --set "particles.phi=$phi" --set run.average_from=0 --threads 1 --quiet; }
for n in "$small" "$large"; do
  # shellcheck disable=SC2046
  "$bin" run "$file" $(sets "$n") --out "$work/pack$n" --set run.strain=1e-6 > /dev/null
done
measure() {  # prints CPU s / strain, steps / strain, iterations / step of one run of N = $1
  rm -rf "$work/run$1"
  # shellcheck disable=SC2046
  /usr/bin/time -f "%U %S" -o "$work/time$1" "$bin" run "$file" $(sets "$1") --out "$work/run$1" \
    --set "particles.initial={from: file, file: $work/pack$1/run.h5}" --set run.strain="$strain" > /dev/null
  /usr/bin/python3 - "$work/run$1/run.h5" "$work/time$1" <<'PY'
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    s = f["series"]
    step, strain, its = (np.ravel(s[k][()]) for k in ("step", "accumulated_strain", "solver_iterations"))
cpu = sum(map(float, open(sys.argv[2]).read().split()[-2:]))
print(f"{cpu / strain[-1]:.3f} {step[-1] / strain[-1]:.0f} {its.mean():.1f}")
PY
}
ratios=()
printf "%4s %6s %12s %12s %10s\n" rep N "CPU s/strain" steps/strain "its/step"
for ((r = 1; r <= repeat; ++r)); do
  if [[ $mode == together ]]; then
    measure "$large" > "$work/large" &
    large_pid=$!
    : > "$work/small"
    measure "$small" >> "$work/small"
    while kill -0 "$large_pid" 2> /dev/null; do measure "$small" >> "$work/small"; done
    wait "$large_pid"
    read -r c2 s2 i2 < "$work/large"
    # the mean over the small runs (their steps and iterations are the same every time: deterministic)
    read -r c1 s1 i1 < <(awk '{c += $1; s = $2; i = $3; n++} END {printf "%.3f %s %s\n", c / n, s, i}' "$work/small")
    echo "     ($(wc -l < "$work/small") runs of N = $small beside the one of N = $large)"
  else
    read -r c1 s1 i1 < <(measure "$small")
    read -r c2 s2 i2 < <(measure "$large")
  fi
  printf "%4s %6s %12s %12s %10s\n" "$r" "$small" "$c1" "$s1" "$i1"
  printf "%4s %6s %12s %12s %10s\n" "$r" "$large" "$c2" "$s2" "$i2"
  ratio=$(/usr/bin/python3 -c "print(f'{$c2 / $c1:.2f}')")
  ratios+=("$ratio")
  /usr/bin/python3 -c "print(f'ratio $large / $small: CPU per strain {$c2 / $c1:.2f}, steps per strain {$s2 / $s1:.2f}, iterations per step {$i2 / $i1:.2f}')"
done
/usr/bin/python3 -c "
import statistics, sys
r = [float(x) for x in sys.argv[1:]]
print(f'median CPU ratio $large / $small over {len(r)} repetitions: {statistics.median(r):.2f} (each: ' + ', '.join(sys.argv[1:]) + ')')
" "${ratios[@]}"
