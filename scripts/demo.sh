#!/usr/bin/env bash
# Sets everything up on a fresh Debian machine and runs the demo: a small phi_m(sigma*) campaign of the mission's
# suspension (paper 004: adhesive, frictional, bidisperse, lubricated; cases/demo_campaign.yaml over
# cases/quickstart.yaml), two points at a time, then the Maron-Pierce fits of `suspend phim`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh" "$root/build"
out=${1:-$root/runs/demo}
rm -rf "$out"
suspend="$root/build/bin/suspend"
OMP_WAIT_POLICY=passive "$suspend" sweep "$root/cases/demo_campaign.yaml" --out "$out" --jobs 2 --threads 1
echo
"$suspend" phim "$out"
cat <<NEXT

Each point is a run directory ($out/points/NAME: run.h5, run.xdmf for ParaView, summary.json);
the table of all of them is $out/campaign.csv. To go further (from $root):
  build/bin/suspend run cases/quickstart.yaml --out runs/q --set flow.sigma_star=5     # one point, with progress
  build/bin/suspend analyze runs/q --snapshot all     # contact network, clusters, fabric of each snapshot
  tools/render_snapshot.py runs/q                     # a picture of the last snapshot (or open runs/q/run.xdmf)
  build/bin/suspend sweep cases/phim/pairwise_campaign.yaml --out runs/phim_pairwise  # the full campaign (days)
  build/bin/suspend phim results/phim/pairwise                                        # its committed fits
  docs/campaigns.md (sweeps and fits), results/README.md (phi_m(sigma*) against paper 004)
NEXT
