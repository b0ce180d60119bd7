#!/usr/bin/env bash
# Installs what cgogn needs to build, test and benchmark on Debian 12 (as root),
# and the viewer's npm packages (three.js and esbuild, pinned in
# viewer/package-lock.json) into viewer/node_modules.
# Does nothing when everything is there already.
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(cmake ninja-build g++ clang libclang-rt-14-dev clang-format doxygen pkgconf python3
          libgtest-dev libgmock-dev libbenchmark-dev
          libeigen3-dev libtbb-dev libcli11-dev nlohmann-json3-dev zlib1g-dev libpng-dev
          libopenmesh-dev libcgal-dev
          pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest python3-meshio
          python3-venv python3-pip python3-setuptools python3-wheel python3-build
          chromium)
# node and npm bundle the viewer's script; Debian's when there is none
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
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
# npm ci installs exactly the lock file's versions (integrity-checked)
if [ ! -f viewer/node_modules/.package-lock.json ] ||
   [ viewer/package-lock.json -nt viewer/node_modules/.package-lock.json ]; then
  (cd viewer && npm ci --no-audit --no-fund)
fi
