#!/usr/bin/env bash
# Wall time per unit strain of the pairwise engine on the frictionless jamming case (docs/performance.md, item e):
# N = 500 bidisperse (1 : 1.4, equal volumes) at phi = 0.50, overdamped with pairwise lubrication and frictionless
# linear springs (cases/validation/frictionless_jamming.yaml).
# The packing is made by a first, untimed run; the timed run starts from it, so only the stepping is measured.
# Prints s/strain, steps/strain, and the mean and largest overlap over the contacts of the run's snapshots (a_1).
# Usage: tools/bench_strain_rate.sh [STRAIN (default 0.5)] [THREADS (default 1)] [BUILD_DIR (default build)]
#                                  [CONTACTS: explicit (default) or implicit, run.time_step.contacts]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
strain=${1:-0.5}
threads=${2:-1}
build=${3:-$root/build}
contacts=${4:-explicit}
bin=$build/bin/suspend
case_file=$root/cases/validation/frictionless_jamming.yaml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_WAIT_POLICY=passive

"$bin" run "$case_file" --out "$work/pack" --threads "$threads" --quiet --set run.strain=1e-6 \
  --set run.average_from=0 >/dev/null
start=$(date +%s.%N)
"$bin" run "$case_file" --out "$work/run" --threads "$threads" --quiet \
  --set "particles.initial={from: file, file: $work/pack/run.h5}" --set run.strain="$strain" \
  --set run.average_from=0 --set run.output.snapshot_every=0.05 --set run.time_step.contacts="$contacts" >/dev/null
end=$(date +%s.%N)

/usr/bin/python3 - "$work/run/run.h5" "$start" "$end" "$threads" "$contacts" <<'PY'
import sys
import h5py
import numpy as np

path, start, end, threads = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
with h5py.File(path, "r") as f:
    step = np.ravel(f["series/step"][()])
    strain = np.ravel(f["series/strain"][()])
    overlaps = []
    for name in f["snapshots"]:
        g = f["snapshots"][name]
        r, a = g["position"][()], g["radius"][()]
        pairs = g["contact_pairs"][()].astype(int)
        box = g["box"][()]
        offset = g.attrs["shear_offset"]
        if len(pairs) == 0:
            continue
        d = r[pairs[:, 1]] - r[pairs[:, 0]]
        ky = np.round(d[:, 1] / box[1])  # Lees-Edwards minimum image, as core/box.hpp
        d[:, 1] -= ky * box[1]
        d[:, 0] -= ky * offset
        d[:, 0] -= box[0] * np.round(d[:, 0] / box[0])
        d[:, 2] -= box[2] * np.round(d[:, 2] / box[2])
        overlap = a[pairs[:, 0]] + a[pairs[:, 1]] - np.linalg.norm(d, axis=1)
        overlaps.append(overlap[overlap > 0])
span = strain[-1] - strain[0]
wall = end - start
o = np.concatenate(overlaps) if overlaps else np.zeros(1)
print(f"contacts {sys.argv[5]}, threads {threads}: strain {span:.3f} in {wall:.1f} s wall")
print(f"s/strain {wall / span:.2f}")
print(f"steps/strain {(step[-1] - step[0]) / span:.0f}")
print(f"mean overlap {o.mean():.5f} a_1 (max {o.max():.5f}) over {len(o)} contacts in {len(overlaps)} snapshots")
PY
