#!/usr/bin/env bash
# Regenerates the pictures of the README (docs/images/*.png) with the built
# `cgogn` tool only: meshes from tests/data, processed by the tool's
# subcommands, drawn by `cgogn render` at 480x360. Usage:
#   bash scripts/make_pictures.sh [path/to/cgogn]   (default build/release/tools/cgogn)
set -euo pipefail
cd "$(dirname "$0")/.."
cgogn=${1:-build/release/tools/cgogn}
[ -x "$cgogn" ] || { echo "make_pictures: $cgogn not found: build the tool first (cmake --build --preset release)" >&2; exit 1; }
out=docs/images
data=tests/data/surface
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
render() { "$cgogn" render "$@" --size 480x360; }

# Catmull-Clark subdivision: the control mesh of spot, then two steps
render "$data/spot_control_mesh.obj" "$out/subdivision-before.png" --edges
"$cgogn" subdivide "$data/spot_control_mesh.obj" "$tmp/spot-cc.obj" --scheme catmull-clark -n 2
render "$tmp/spot-cc.obj" "$out/subdivision-after.png" --edges

# decimation: suzanne after one Loop step (3872 triangles) down to 600
"$cgogn" triangulate "$data/suzanne.obj" "$tmp/suzanne-tri.obj"
"$cgogn" subdivide "$tmp/suzanne-tri.obj" "$tmp/suzanne-loop.obj" --scheme loop -n 1
render "$tmp/suzanne-loop.obj" "$out/decimation-before.png" --edges --view z
"$cgogn" decimate "$tmp/suzanne-loop.obj" "$tmp/suzanne-dec.obj" --faces 600
render "$tmp/suzanne-dec.obj" "$out/decimation-after.png" --edges --view z

# isotropic remeshing: spot's quads split into triangles, coloured by
# triangle quality over the same range [0, 1] on both sides
"$cgogn" subdivide "$data/spot_control_mesh.obj" "$tmp/spot-cc1.obj" --scheme catmull-clark -n 1
"$cgogn" triangulate "$tmp/spot-cc1.obj" "$tmp/spot-tri.obj"
render "$tmp/spot-tri.obj" "$out/remeshing-before.png" --edges --color quality --range 0 1
"$cgogn" remesh "$tmp/spot-tri.obj" "$tmp/spot-remeshed.obj"
render "$tmp/spot-remeshed.obj" "$out/remeshing-after.png" --edges --color quality --range 0 1

# hole filling: the boundary edges of elephant-with-holes in red, then none
render "$data/elephant-with-holes.off" "$out/holes-before.png" --show-defects --view x
"$cgogn" fill-holes "$data/elephant-with-holes.off" "$tmp/elephant-filled.off" > /dev/null
render "$tmp/elephant-filled.off" "$out/holes-after.png" --show-defects --view x

# mean curvature of a torus after three Catmull-Clark steps (robust range):
# positive outside, negative around the hole
"$cgogn" subdivide "$data/torus_quad.off" "$tmp/torus-cc3.obj" --scheme catmull-clark -n 3
render "$tmp/torus-cc3.obj" "$out/curvature.png" --color curvature

ls -l "$out"/*.png
