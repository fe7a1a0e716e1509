#!/usr/bin/env bash
# Sets everything up on a fresh Debian machine and runs the demo: a small phi_m(sigma*) campaign of the mission's
# suspension (paper 004: adhesive, frictional, bidisperse, lubricated; cases/demo_campaign.yaml over
# cases/quickstart.yaml), two points at a time, then the Maron-Pierce fits of `suspend phim`.
# It builds only the program (the tests' build tree and configuration: `bash scripts/test.sh` afterwards compiles
# only the tests). About 5 minutes on 2 cores from a fresh machine: 2 for the packages, 2 for the build (seconds
# with a warm ccache), 1 for the sweep.
# usage: scripts/demo.sh [OUT (default runs/demo)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/runs/demo}
start=$SECONDS
stage() { printf '\n== [%s] %s (%d s so far)\n' "$1" "$2" $((SECONDS - start)); }

stage 1/3 "Debian packages (about 2 minutes when none are installed)"
bash "$root/scripts/install-deps.sh"

stage 2/3 "building the program only, build/bin/suspend (about 2 minutes on 2 cores; [done/total] counts the steps)"
bash "$root/scripts/build.sh" "$root/build" --target suspend
suspend="$root/build/bin/suspend"

points=$("$suspend" sweep "$root/cases/demo_campaign.yaml" --list | wc -l)
stage 3/3 "sweep of $points points, two at a time (under a minute; each line is a point started or finished)"
rm -rf "$out"
OMP_WAIT_POLICY=passive "$suspend" sweep "$root/cases/demo_campaign.yaml" --out "$out" --jobs 2 --threads 1
echo
"$suspend" phim "$out"
printf '\n(demo done in %d s)\n' $((SECONDS - start))
cat <<NEXT

Each point is a run directory ($out/points/NAME: run.h5, run.xdmf for ParaView, summary.json);
the table of all of them is $out/campaign.csv. To go further (from $root):
  build/bin/suspend run cases/quickstart.yaml --out runs/q --set flow.sigma_star=5     # one point, with progress
  build/bin/suspend analyze runs/q --snapshot all     # contact network, clusters, fabric of each snapshot
  tools/render_movie.py runs/q --out runs/q/run.mp4   # a movie of the run (bash scripts/install-deps.sh --movie)
  build/bin/suspend sweep cases/demo_campaign.yaml --out $out --status   # where a campaign stands
  build/bin/suspend sweep cases/phim/pairwise_campaign.yaml --out runs/phim_pairwise  # the full campaign (days)
  build/bin/suspend phim results/phim/pairwise                                        # its committed fits
  bash scripts/test.sh                                # the test suite (compiles only the tests now)
  docs/campaigns.md (sweeps and fits), results/README.md (phi_m(sigma*) against paper 004)
NEXT
