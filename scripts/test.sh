#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds (release), runs ctest,
# then prints how many tests were skipped, and ends by drawing one picture of
# a test mesh with the built tool (its path is printed). A test skips only when
# it needs a large mesh that is not in the repository (see tests/data/README.md;
# set CGOGN_LARGE_DATA_DIR to the folder holding them to run those too), or
# chromium for the viewer's browser tests (install-deps.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j 2
log=$(mktemp)
trap 'rm -f "$log"' EXIT
ctest --preset release -j 2 | tee "$log"
skipped=$(grep -c '\*\*\*Skipped' "$log" || true)
echo "skipped tests: $skipped (each needs a large mesh: set CGOGN_LARGE_DATA_DIR to run it; or chromium)"
picture=build/release/cgogn-picture.png
build/release/tools/cgogn render tests/data/surface/spot_control_mesh.obj "$picture" --edges --color quality --size 640x480
echo "picture: $(pwd)/$picture"
