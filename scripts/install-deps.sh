#!/usr/bin/env bash
# Installs the Debian packages suspend needs, if any are missing (apt-get as root, sudo otherwise).
# usage: scripts/install-deps.sh [--movie]   (--movie adds ffmpeg, which tools/render_movie.py needs: ~90 packages,
# so the demo does without it)
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config git ccache
          libeigen3-dev libfftw3-dev libhdf5-dev libyaml-cpp-dev libcli11-dev
          libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libopenmpi-dev openmpi-bin
          python3 python3-numpy python3-scipy python3-h5py python3-matplotlib python3-gsd python3-yaml)
if [[ ${1:-} == --movie ]]; then packages+=(ffmpeg); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "suspend: installing ${#missing[@]} missing Debian packages (about 2 minutes on a fresh machine): ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
