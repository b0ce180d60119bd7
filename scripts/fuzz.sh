#!/usr/bin/env bash
# Builds the libFuzzer targets of the io readers in the asan preset's build
# (build/asan: clang, ASan + UBSan, the library at -O1 with assertions on and
# libFuzzer's coverage instrumentation) and runs each for a
# bounded time: FUZZ_SECONDS of wall-clock time in total (default 300), with
# FUZZ_JOBS targets at once (default 2, one per core), so that each target
# gets FUZZ_SECONDS x FUZZ_JOBS / (number of targets) seconds. The targets are
# one per reader, and fuzz_append, which loads any
# format into a map that already holds a mesh and attributes, and
# fuzz_graph, the graph readers, fuzz_incidence_graph, the .ig reader, and
# fuzz_map_file, the .cgmap reader of whole maps).
# Fails on any
# crash, leak, timeout or sanitizer report.
#
# Each target starts from its corpus in fuzz/corpus/<target> (kept in the
# repository, minimized: each run starts from the coverage reached before),
# plus seeds made here: the malformed corpus of tests/io/bad, the shipped
# example mesh and small valid files written by the cgogn tool. Each target
# uses the dictionary fuzz/dict/<format>.dict (fuzz_append: all of them).
# New inputs go to <build folder>/corpus/<target>. With FUZZ_MERGE=1, each
# committed corpus is then replaced by the minimized merge (libFuzzer
# -merge=1) of itself and the new inputs, those under 4 KB.
set -euo pipefail
cd "$(dirname "$0")/.."
total=${FUZZ_SECONDS:-300}
formats=(off obj ply stl medit vtk vtu gmsh tetgen ovm)
targets=()
for f in "${formats[@]}"; do targets+=("$f"); done
targets+=(append graph incidence_graph map_file)
jobs=${FUZZ_JOBS:-2}
per=$(( total * jobs / ${#targets[@]} ))
[ "$per" -ge 1 ] || per=1

build=build/asan
[ -f "$build/CMakeCache.txt" ] || cmake --preset asan >/dev/null
build_targets=()
for t in "${targets[@]}"; do build_targets+=("fuzz_$t"); done
cmake --build --preset asan -j 2 --target "${build_targets[@]}"

# seed corpora: valid files written by a release build of the tool when there
# is one, plus every malformed file of the test corpus with a matching extension
seeds=$build/seeds
rm -rf "$seeds"
tool=build/release/tools/cgogn
for t in "${targets[@]}"; do mkdir -p "$seeds/$t"; done
cp examples/data/*.obj "$seeds/obj/"
cp tests/data/surface/mobius_strip.off tests/data/surface/hemi_icosahedron.off "$seeds/off/"
if [ -x "$tool" ]; then
  "$tool" convert examples/data/spot_control_mesh.obj "$seeds/off/spot.off"
  "$tool" convert examples/data/spot_control_mesh.obj "$seeds/ply/spot_ascii.ply"
  "$tool" convert --binary examples/data/spot_control_mesh.obj "$seeds/ply/spot_binary.ply"
  "$tool" convert examples/data/spot_control_mesh.obj "$seeds/stl/spot_ascii.stl"
  "$tool" convert --binary examples/data/spot_control_mesh.obj "$seeds/stl/spot_binary.stl"
fi
for f in tests/io/bad/*; do
  case "$f" in
    *.off) cp "$f" "$seeds/off/" ;; *.obj) cp "$f" "$seeds/obj/" ;; *.ply) cp "$f" "$seeds/ply/" ;;
    *.stl) cp "$f" "$seeds/stl/" ;; *.mesh) cp "$f" "$seeds/medit/" ;; *.vtk) cp "$f" "$seeds/vtk/" ;;
    *.vtu) cp "$f" "$seeds/vtu/" ;; *.msh) cp "$f" "$seeds/gmsh/" ;;
  esac
done
for stem in tests/io/bad/tetgen_*.node; do
  { cat "$stem"; printf '\0'; cat "${stem%.node}.ele"; } > "$seeds/tetgen/$(basename "${stem%.node}")"
done
printf 'MeshVersionFormatted 1\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 -1 0\nTetrahedra\n2\n1 2 3 4 0\n1 3 2 5 0\nEnd\n' > "$seeds/medit/two_tets.mesh"
if [ -x "$tool" ]; then
  tets=$seeds/medit/two_tets.mesh
  "$tool" convert "$tets" "$seeds/vtk/ascii.vtk"
  "$tool" convert --binary "$tets" "$seeds/vtk/binary.vtk"
  "$tool" convert "$tets" "$seeds/vtu/ascii.vtu"
  "$tool" convert --binary "$tets" "$seeds/vtu/appended.vtu"
  "$tool" convert "$tets" "$seeds/gmsh/ascii.msh"
  "$tool" convert --binary "$tets" "$seeds/gmsh/binary.msh"
  "$tool" convert "$tets" "$seeds/ovm/two_tets.ovm"
  "$tool" convert "$tets" "$build/two_tets.ele"
  { cat "$build/two_tets.node"; printf '\0'; cat "$build/two_tets.ele"; } > "$seeds/tetgen/two_tets"
fi
# an .ovm cube: OpenVolumeMesh's inward half-faces, properties of every kind
printf 'OVM ASCII\nVertices\n8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\nEdges\n12\n0 1\n1 2\n2 3\n3 0\n4 5\n5 6\n6 7\n7 4\n0 4\n1 5\n2 6\n3 7\nFaces\n6\n4 0 2 4 6\n4 8 10 12 14\n4 0 18 9 17\n4 2 20 11 19\n4 4 22 13 21\n4 6 16 15 23\nPolyhedra\n1\n6 0 3 5 7 9 11\nvprop double "t"\n0 1 2 3 4 5 6 7\neprop int "e"\n0 0 0 0 0 0 0 0 0 0 0 0\ncprop vec3d "c"\n1 2 3\n' > "$seeds/ovm/cube.ovm"
# fuzz_append: every seed and corpus file of reader k, behind the byte k
k=0
for f in "${formats[@]}"; do
  for s in "$seeds/$f"/* fuzz/corpus/"$f"/*; do
    [ -f "$s" ] || continue
    { printf "\\x$(printf %02x "$k")"; cat "$s"; } > "$seeds/append/$f-$(basename "$s")"
  done
  k=$((k + 1))
done
# fuzz_graph: the first byte chooses the format (0 .cg, 1 .cgr, 2 .skel,
# 3 .obj, 4 .vtk, 5 .vtu; +6: indices from 1)
printf '\x00# D:3 NV:4 NE:4\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n# tree\ne 0 1\ne 1 2\ne 1 3\ne 3 3\n' > "$seeds/graph/tree.cg"
printf '\x01# D:3 NV:3 NE:2\nv 0 0 0 0.5\nv 1 0 0 0.25\nv 2 0 0 1e-3\ne 0 1\ne 1 2\n' > "$seeds/graph/path.cgr"
printf '\x02ID Cx Cy Cz RADIUS #NEIGHBORS NEIGHBORS_LIST\n3\n0 0 0 0 1 1 1\n1 1 0 0 1 2 0 2\n2 2 0 0 1 0\n' > "$seeds/graph/path.skel"
printf '\x03v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3 1\nl -1 -2\nf 1 2 3\n' > "$seeds/graph/lines.obj"
printf '\x06# D:2 NV:2 NE:1\nv 0 0\nv 1 1\ne 1 2\n' > "$seeds/graph/one_based.cg"
printf '\x04# vtk DataFile Version 3.0\nlines\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n0 0 0 1 0 0 2 0 0\nCELLS 2 7\n2 0 1\n3 0 1 2\nCELL_TYPES 2\n3\n4\nPOINT_DATA 3\nSCALARS radius double 1\nLOOKUP_TABLE default\n1 2 3\n' > "$seeds/graph/lines.vtk"
# fuzz_incidence_graph: an .ig file (a book of three triangles, a wire, a lone vertex)
printf 'IG 7 8 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 2 0 0\nv 3 3 3\n# spine, then the sides\ne 0 1\ne 1 2\ne 2 0\ne 1 3\ne 3 0\ne 1 4\ne 4 0\ne 1 5\nf 3 0 1 2\nf 3 0 3 4\nf 3 5 6 0\n' > "$seeds/incidence_graph/book.ig"
# fuzz_map_file: the first byte chooses the map type (0 CMap2, 1 CMap3,
# 2 GMap2, 3 GMap3, 4 Graph, 5 CMapN<3>, 6 GMapN<2>, 7 CMap1)
{ printf '\x00'; cat tests/data/maps/compatibility_v1.cgmap; } > "$seeds/map_file/compatibility_v1"
if [ -x "$tool" ]; then
  "$tool" convert "$seeds/medit/two_tets.mesh" "$build/two_tets.cgmap"
  { printf '\x01'; cat "$build/two_tets.cgmap"; } > "$seeds/map_file/two_tets"
  "$tool" convert tests/data/surface/mobius_strip.off "$build/mobius.cgmap"
  { printf '\x02'; cat "$build/mobius.cgmap"; } > "$seeds/map_file/mobius"
  printf '# D:3 NV:3 NE:2\nv 0 0 0\nv 1 0 0\nv 2 0 0\ne 0 1\ne 1 2\n' > "$build/path.cg"
  "$tool" convert "$build/path.cg" "$build/path.cgmap"
  { printf '\x04'; cat "$build/path.cgmap"; } > "$seeds/map_file/path"
fi
cat fuzz/dict/*.dict > "$build/append.dict"

dict_of() {
  if [ "$1" = append ]; then echo "$build/append.dict"; else echo "fuzz/dict/$1.dict"; fi
}

# runs target $1; its exit status tells whether it found nothing
fuzz_one() {
  local t=$1 work=$build/corpus/$1
  mkdir -p "$work" "fuzz/corpus/$t"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz/fuzz_$t" "$work" "fuzz/corpus/$t" "$seeds/$t" -dict="$(dict_of "$t")" \
    -max_total_time="$per" -max_len=65536 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$build/crash-$t-" 2>"$build/fuzz_$t.log"
}

status=0
# FUZZ_JOBS targets at a time; their reports are printed in the targets' order
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  rm -f "$build/fuzz_$t.status"
  (if fuzz_one "$t"; then echo 0; else echo 1; fi >"$build/fuzz_$t.status") &
done
wait
for t in "${targets[@]}"; do
  echo "== fuzz_$t (${per}s)"
  if [ "$(cat "$build/fuzz_$t.status" 2>/dev/null)" != 0 ]; then
    echo "fuzz_$t FAILED: see $build/fuzz_$t.log and $build/crash-$t-*" >&2
    tail -40 "$build/fuzz_$t.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|cov:" "$build/fuzz_$t.log" | tail -2
  fi
done

# The committed corpora keep inputs under 4 KB: the larger ones come from
# the seeds made above, which every run has anyway.
if [ "$status" = 0 ] && [ "${FUZZ_MERGE:-0}" = 1 ]; then
  for t in "${targets[@]}"; do
    candidates=$build/merge_input/$t merged=$build/merged/$t
    rm -rf "$candidates" "$merged"
    mkdir -p "$candidates" "$merged"
    find "fuzz/corpus/$t" "$build/corpus/$t" -type f -size -4096c -exec cp {} "$candidates/" \;
    "$build/fuzz/fuzz_$t" -merge=1 -max_len=65536 -timeout=10 "$merged" "$candidates" 2>"$build/merge_$t.log"
    rm -rf "fuzz/corpus/$t"
    mv "$merged" "fuzz/corpus/$t"
    echo "fuzz/corpus/$t: $(ls "fuzz/corpus/$t" | wc -l) files, $(du -sh "fuzz/corpus/$t" | cut -f1)"
  done
fi
exit $status
