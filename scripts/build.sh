#!/usr/bin/env bash
# Configures and builds suspend. Usage: scripts/build.sh [BUILD_DIR] [--target NAME]... [extra cmake args...]
# Default: ./build, Release, warnings as errors: one configuration for the demo, the tests and CI, so that building
# the tests after the demo compiles only the tests. Executables land in BUILD_DIR/bin.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
if [[ $# -gt 0 && $1 != -* ]]; then build=$1; shift; fi
targets=()
cmake_args=()
while [[ $# -gt 0 ]]; do
  if [[ $1 == --target ]]; then targets+=(--target "$2"); shift 2; else cmake_args+=("$1"); shift; fi
done
bash "$root/scripts/install-deps.sh"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DSUSPEND_WERROR=ON "${cmake_args[@]}" >/dev/null
elif [ ${#cmake_args[@]} -gt 0 ]; then
  cmake "$build" "${cmake_args[@]}" >/dev/null
fi
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"
