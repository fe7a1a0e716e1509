#!/usr/bin/env bash
# SIGKILL at any moment, checkpoint writes included (issue 15): with a checkpoint written every few steps, a run is
# killed again and again at seeded random moments and continued each time from whatever checkpoint.h5 holds. The
# checkpoint is replaced atomically, so it is never half-written: every continuation must start (or, before the first
# checkpoint, the run starts again), the temporaries of killed writers are removed by the next run, and the end state must
# be the unbroken run's, bit for bit.
# Usage: kill_during_checkpoint.sh SUSPEND CASE [SEED]
set -euo pipefail
suspend=$1
case_file=$(realpath "$2")
RANDOM=${3:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(--set particles.count=50 --set run.strain=1.5 --set run.average_from=0.05 --set run.threads=1
  --set run.output.checkpoint_every=0.002 --set run.output.series_every=0.002 --quiet)
"$suspend" run "$case_file" --out "$work/ref" "${args[@]}"

dir=$work/killed
kills=0 continued=0
for attempt in $(seq 1 200); do
  if [ -f "$dir/checkpoint.h5" ]; then
    "$suspend" run "$case_file" "${args[@]}" --restart "$dir/checkpoint.h5" 2>"$work/err" &
    continued=$((continued + 1))
  else
    rm -rf "$dir"
    "$suspend" run "$case_file" "${args[@]}" --out "$dir" 2>"$work/err" &
  fi
  pid=$!
  sleep "0.$((RANDOM % 40 + 5))"
  if kill -KILL "$pid" 2>/dev/null; then
    kills=$((kills + 1))
    wait "$pid" 2>/dev/null || true
    continue
  fi
  code=0
  wait "$pid" || code=$?
  # Killed after its last checkpoint: the run is complete (summary.json is written before that checkpoint).
  if [ "$code" = 2 ] && grep -q "is already reached by the checkpoint" "$work/err" && [ -f "$dir/summary.json" ]; then
    code=0
  fi
  if [ "$code" != 0 ]; then
    echo "FAIL: continuation after $kills kills ended with exit $code: $(cat "$work/err")"
    exit 1
  fi
  break
done
[ -f "$dir/summary.json" ] || { echo "FAIL: the run never finished"; exit 1; }
left=$(find "$dir" -name '*.tmp.*' | wc -l)
strip() { grep -v wall_seconds "$1"; }
if ! cmp -s <(strip "$dir/summary.json") <(strip "$work/ref/summary.json"); then
  echo "FAIL: after $kills kills the run ends with another summary than the unbroken run"
  diff <(strip "$dir/summary.json") <(strip "$work/ref/summary.json") | head -20
  exit 1
fi
/usr/bin/python3 - "$dir/checkpoint.h5" "$work/ref/checkpoint.h5" <<'PY'
import sys
import h5py
a, b = (h5py.File(p, "r") for p in sys.argv[1:3])
for name in ("particles/position", "particles/velocity", "particles/angular_velocity"):
    if a[name][()].tobytes() != b[name][()].tobytes():
        sys.exit("FAIL: %s differs from the unbroken run's" % name)
PY
[ "$left" = 0 ] || { echo "FAIL: $left temporary files of killed writers left: $(ls "$dir")"; exit 1; }
echo "killed $kills times ($continued continuations from the checkpoint; the temporaries of killed writers removed):"
echo "the run ends bit for bit where the unbroken run ends"
[ "$kills" -ge 5 ] || { echo "FAIL: only $kills kills: the case is too short to test anything"; exit 1; }
