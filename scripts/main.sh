#!/usr/bin/env bash
# The main job: installs what is missing, builds (release), and runs the
# hello_mesh example, which builds meshes in code and reports what it made.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j 2
./build/release/examples/hello_mesh
