#!/usr/bin/env bash
# The main command: installs what is missing, builds (release), and runs the
# `cgogn` tool on the mesh the project ships: `info` (counts, topology,
# geometry), then a conversion OBJ -> binary PLY, `check` of the result, and
# a picture (PNG) and a viewer page (HTML) of the mesh, whose paths it prints.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j 2
cgogn=./build/release/tools/cgogn
mesh=examples/data/spot_control_mesh.obj
"$cgogn" info "$mesh"
"$cgogn" convert --binary "$mesh" build/release/spot_control_mesh.ply
"$cgogn" check build/release/spot_control_mesh.ply
# a picture of it, and the page to turn it around in a browser
"$cgogn" render "$mesh" build/release/spot_control_mesh.png --edges --size 800x600
"$cgogn" view "$mesh" build/release/spot_control_mesh.html --edges
echo "picture: $(pwd)/build/release/spot_control_mesh.png"
echo "viewer page: $(pwd)/build/release/spot_control_mesh.html"
