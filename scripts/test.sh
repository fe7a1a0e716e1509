#!/usr/bin/env bash
# Sets everything up on a fresh Debian machine and runs the test suite: unit + integration tests and the
# reduced validation set, on the warnings-as-errors Release build of scripts/build.sh (the demo's build: after
# the demo only the tests compile). `scripts/test.sh --sanitize` runs the same suite on a Debug build with the
# address and undefined-behaviour sanitizers.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-deps.sh" --movie
if [ "${1:-}" = "--sanitize" ]; then
  build="$root/build-sanitize"
  bash "$root/scripts/build.sh" "$build" -DCMAKE_BUILD_TYPE=Debug -DSUSPEND_SANITIZE=ON -DSUSPEND_BENCH=OFF
else
  build="$root/build"
  bash "$root/scripts/build.sh" "$build"
fi
cd "$build"
ctest --output-on-failure --timeout 900 -j "$(nproc)" -LE "validation-full"
