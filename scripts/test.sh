#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds (release), runs ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j 2
ctest --preset release -j 2
