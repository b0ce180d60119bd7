#!/usr/bin/env bash
# Installs the Debian 12 packages that cgogn needs to build, test and
# benchmark (as root). Does nothing when everything is there already.
# Node and npm are not among them: the viewer's script is bundled in the
# repository (viewer/dist); scripts/bundle-viewer.sh rebuilds it.
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(cmake ninja-build g++ clang libclang-rt-14-dev clang-format doxygen pkgconf python3
          libgtest-dev libgmock-dev libbenchmark-dev
          libeigen3-dev libtbb-dev libcli11-dev nlohmann-json3-dev zlib1g-dev libpng-dev
          libopenmesh-dev libcgal-dev
          libopenmpi-dev openmpi-bin libmetis-dev libpetsc-real3.18-dev
          pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest python3-meshio python3-vtk9
          python3-venv python3-pip python3-setuptools python3-wheel python3-build
          chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: missing ${missing[*]}; run as root (or install them)" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
