#!/usr/bin/env bash
# Sets everything up on a fresh Debian machine and runs the test suite: unit + integration tests and the
# reduced validation set, on a warnings-as-errors Release build. `scripts/test.sh --sanitize` runs the same
# suite on a Debug build with the address and undefined-behaviour sanitizers.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "--sanitize" ]; then
  build="$root/build-sanitize"
  bash "$root/scripts/build.sh" "$build" -DCMAKE_BUILD_TYPE=Debug -DSUSPEND_SANITIZE=ON -DSUSPEND_WERROR=ON -DSUSPEND_BENCH=OFF
else
  build="$root/build"
  bash "$root/scripts/build.sh" "$build" -DSUSPEND_WERROR=ON
fi
cd "$build"
ctest --output-on-failure --timeout 900 -j "$(nproc)" -LE "validation-full"
