#!/usr/bin/env bash
# Sets everything up on a fresh Debian machine and runs the demo case (cases/quickstart.yaml).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh" "$root/build"
out=${1:-$root/runs/quickstart}
rm -rf "$out"
"$root/build/bin/suspend" run "$root/cases/quickstart.yaml" --out "$out"
