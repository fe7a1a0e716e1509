#!/usr/bin/env bash
# Full disk (issue 15): a run that cannot write its output stops with exit code 5 and says what failed, never
# crashes, leaves no temporary file, keeps its last complete checkpoint, and once there is room continues from it to
# the same summary as an unbroken run (the run.h5 damaged by the failed write is rebuilt from what the checkpoint
# knew). The disk fills through a file size limit (ulimit -f with SIGXFSZ ignored: writes fail with EFBIG) on every
# machine, and through a small tmpfs (ENOSPC) where the machine lets us mount one.
# Usage: full_disk.sh SUSPEND CASE
set -euo pipefail
suspend=$1
case_file=$(realpath "$2")
work=$(mktemp -d)
mounted=""
cleanup() {
  if [ -n "$mounted" ]; then umount "$mounted" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
args=(--set run.strain=0.3 --set run.average_from=0.1 --set run.output.series_every=0.002
  --set run.output.snapshot_every=0.01 --set run.output.checkpoint_every=0.05 --quiet)
"$suspend" run "$case_file" --out "$work/ref" "${args[@]}"
strip() { grep -v wall_seconds "$1"; }
# Limits as fractions of the unbroken run's files, so that they stay right when the outputs change size.
run_kb=$(($(stat -c %s "$work/ref/run.h5") / 1024))
checkpoint_kb=$(($(stat -c %s "$work/ref/checkpoint.h5") / 1024))

failures=0 with_checkpoint=0 without_checkpoint=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# Checks one stopped run in $1 (exit code $2, stderr in $3); $4 makes room again (a command).
check_stopped() {
  local dir=$1 code=$2 err=$3 make_room=$4
  if [ "$code" = 0 ]; then
    strip "$dir/summary.json" | cmp -s - <(strip "$work/ref/summary.json") || fail "$dir: finished with another summary"
    return
  fi
  [ "$code" = 5 ] || { fail "$dir: exit code $code (stderr: $(cat "$err"))"; return; }
  if ls "$dir" | grep -q '\.tmp'; then fail "$dir: temporary files left: $(ls "$dir")"; fi
  if [ ! -f "$dir/checkpoint.h5" ]; then
    grep -q "^error: cannot write .*run.h5" "$err" || fail "$dir: no line saying what could not be written: $(cat "$err")"
    grep -q "no checkpoint was written yet" "$err" || fail "$dir: does not say that no checkpoint exists"
    without_checkpoint=$((without_checkpoint + 1))
    return
  fi
  # With a checkpoint the run stops before the disk is full, at a checkpoint, every file complete.
  grep -q "^error: the disk is nearly full: room for .* kB more next to .*run.h5, the next checkpoint interval needs about .* kB; stopped at the checkpoint of strain" "$err" ||
    fail "$dir: no line saying that the disk is nearly full and where it stopped: $(cat "$err")"
  with_checkpoint=$((with_checkpoint + 1))
  $make_room
  local rc=0
  "$suspend" run "$case_file" "${args[@]}" --restart "$dir/checkpoint.h5" 2>"$err.restart" || rc=$?
  [ "$rc" = 0 ] || { fail "$dir: restart exit code $rc: $(cat "$err.restart")"; return; }
  strip "$dir/summary.json" | cmp -s - <(strip "$work/ref/summary.json") ||
    fail "$dir: the continued run's summary differs from the unbroken run's"
}

no_op() { :; }
for kb in $((run_kb / 50)) $((run_kb * 4 / 10)) $((run_kb * 6 / 10)) $((run_kb * 9 / 10)); do
  dir=$work/limit$kb
  code=0
  (trap '' XFSZ; ulimit -f "$kb"; exec "$suspend" run "$case_file" --out "$dir" "${args[@]}") 2>"$work/err$kb" || code=$?
  check_stopped "$dir" "$code" "$work/err$kb" no_op
  echo "file size limit ${kb} kB: exit $code"
done

# A sweep whose points run out of room: they stay pending, no further point starts, exit 5; the same command
# continues the sweep once there is room.
cat >"$work/sweep.yaml" <<EOF
case: $case_file
set: {run.strain: 0.3, run.average_from: 0.1, run.output.series_every: 0.002, run.output.snapshot_every: 0.01,
      run.output.checkpoint_every: 0.05}
vary: {run.seed: [3, 4, 5]}
EOF
code=0
(trap '' XFSZ; ulimit -f $((run_kb * 6 / 10)); exec "$suspend" sweep "$work/sweep.yaml" --out "$work/sweep" --jobs 1 --quiet) \
  2>"$work/sweep_err" || code=$?
[ "$code" = 5 ] || fail "sweep on a full disk: exit $code: $(cat "$work/sweep_err")"
statuses() { /usr/bin/python3 -c "import json,sys; print(' '.join(p['status'] for p in json.load(open(sys.argv[1]))['points']))" "$1"; }
pending=$(statuses "$work/sweep/campaign.json" | tr ' ' '\n' | grep -c pending || true)
[ "$pending" = 3 ] || fail "sweep on a full disk: $pending of 3 points pending: $(cat "$work/sweep/campaign.json")"
code=0
"$suspend" sweep "$work/sweep.yaml" --out "$work/sweep" --jobs 1 --quiet 2>"$work/sweep_err2" || code=$?
[ "$code" = 0 ] || fail "sweep continued with room: exit $code: $(cat "$work/sweep_err2")"
done_points=$(statuses "$work/sweep/campaign.json" | tr ' ' '\n' | grep -c done || true)
[ "$done_points" = 3 ] || fail "sweep continued: $done_points of 3 points done"
echo "sweep on a full disk: exit 5, $pending points pending; continued with room: $done_points done"

if [ "$(id -u)" = 0 ] && mkdir -p "$work/mnt" && mount -t tmpfs -o size=64k tmpfs "$work/mnt" 2>/dev/null; then
  mounted=$work/mnt
  # The checkpoint and its temporary copy share the disk with run.h5.
  for kb in $((run_kb / 2 + 2 * checkpoint_kb)) $((run_kb * 8 / 10 + 2 * checkpoint_kb)); do
    rm -rf "${mounted:?}"/*
    mount -o "remount,size=${kb}k" "$mounted"
    dir=$mounted/run
    code=0
    "$suspend" run "$case_file" --out "$dir" "${args[@]}" 2>"$work/tmpfs_err$kb" || code=$?
    grow() { mount -o remount,size=64m "$mounted"; }
    check_stopped "$dir" "$code" "$work/tmpfs_err$kb" grow
    echo "tmpfs of ${kb} kB: exit $code"
  done
  # Someone else fills the disk between two checkpoints: the write fails (exit 5), the last checkpoint is kept
  # whole, and the restart either rebuilds run.h5 from what the checkpoint knew and continues exactly, or says
  # that run.h5 is damaged beyond that.
  rm -rf "${mounted:?}"/*
  mount -o remount,size=64m "$mounted"
  dir=$mounted/filled
  "$suspend" run "$case_file" --out "$dir" "${args[@]}" 2>"$work/filled_err" &
  pid=$!
  while kill -0 "$pid" 2>/dev/null && [ ! -f "$dir/checkpoint.h5" ]; do sleep 0.05; done
  dd if=/dev/zero of="$mounted/filler" bs=64k 2>/dev/null || true
  code=0
  wait "$pid" || code=$?
  echo "disk filled by another file after the first checkpoint: exit $code"
  if [ "$code" = 5 ]; then
    grep -q "^error: cannot write " "$work/filled_err" || fail "filled: no line saying what failed"
    grep -q "the last complete checkpoint (strain .*) is kept in" "$work/filled_err" ||
      fail "filled: does not name the kept checkpoint: $(cat "$work/filled_err")"
    if ls "$dir" | grep -q '\.tmp'; then fail "filled: temporary files left: $(ls "$dir")"; fi
    rm -f "$mounted/filler"
    rc=0
    "$suspend" run "$case_file" "${args[@]}" --restart "$dir/checkpoint.h5" 2>"$work/filled_restart" || rc=$?
    if [ "$rc" = 0 ]; then
      strip "$dir/summary.json" | cmp -s - <(strip "$work/ref/summary.json") ||
        fail "filled: the continued run's summary differs from the unbroken run's"
      echo "  restart: run.h5 rebuilt, continued to the unbroken run's summary"
    else
      [ "$rc" = 2 ] && grep -q "could not be rebuilt.*continue it into a new folder with --out" "$work/filled_restart" ||
        fail "filled: restart failed unclearly (exit $rc): $(cat "$work/filled_restart")"
      echo "  restart: run.h5 damaged beyond the checkpoint's part, refused with: $(cat "$work/filled_restart")"
      # The checkpoint itself is whole: continued into a new folder, the run ends where the unbroken run ends.
      rc=0
      "$suspend" run "$case_file" "${args[@]}" --restart "$dir/checkpoint.h5" --out "$work/branch" 2>"$work/branch_err" || rc=$?
      [ "$rc" = 0 ] || fail "filled: continuing into a new folder: exit $rc: $(cat "$work/branch_err")"
      cmp -s <(/usr/bin/python3 -c "import h5py,sys; f=h5py.File(sys.argv[1]); print(f['snapshots'][sorted(f['snapshots'])[-1]]['position'][()].tobytes().hex())" "$work/branch/run.h5") \
        <(/usr/bin/python3 -c "import h5py,sys; f=h5py.File(sys.argv[1]); print(f['snapshots'][sorted(f['snapshots'])[-1]]['position'][()].tobytes().hex())" "$work/ref/run.h5") ||
        fail "filled: the run continued into a new folder does not end in the unbroken run's final state"
      echo "  continued into a new folder: ends in the unbroken run's final state"
    fi
  elif [ "$code" != 0 ]; then
    fail "filled: exit code $code: $(cat "$work/filled_err")"
  fi
else
  echo "tmpfs: cannot mount here (not root or no permission); the file size limit covers the same paths"
fi

echo "stopped with a checkpoint kept: $with_checkpoint, before the first checkpoint: $without_checkpoint"
[ "$with_checkpoint" -ge 1 ] || fail "no case stopped after a checkpoint: raise the limits"
[ "$without_checkpoint" -ge 1 ] || fail "no case stopped before the first checkpoint: lower the smallest limit"
[ "$failures" = 0 ]
