#!/usr/bin/env bash
# Builds the libFuzzer targets of the io readers with clang (ASan + UBSan) and
# runs each for a bounded time: FUZZ_SECONDS in total (default 60), split
# evenly. Seeds: the malformed corpus of tests/io/bad, the shipped example
# mesh, and small valid files written by the cgogn tool. Fails on any crash,
# leak or sanitizer report.
set -euo pipefail
cd "$(dirname "$0")/.."
total=${FUZZ_SECONDS:-60}
formats=(off obj ply stl medit vtk vtu gmsh tetgen)
per=$(( total / ${#formats[@]} ))
[ "$per" -ge 1 ] || per=1

build=build/fuzz
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCGOGN_BUILD_FUZZERS=ON -DCGOGN_BUILD_TESTS=OFF -DCGOGN_BUILD_EXAMPLES=OFF -DCGOGN_BUILD_BENCHMARKS=OFF \
  -DCGOGN_BUILD_TOOLS=OFF -DCGOGN_WERROR=ON >/dev/null
targets=()
for f in "${formats[@]}"; do targets+=("fuzz_$f"); done
cmake --build "$build" -j 2 --target "${targets[@]}"

# seed corpora: valid files written by a release build of the tool when there
# is one, plus every malformed file of the test corpus with a matching extension
seeds=$build/seeds
rm -rf "$seeds"
tool=build/release/tools/cgogn
for f in "${formats[@]}"; do mkdir -p "$seeds/$f"; done
cp examples/data/*.obj "$seeds/obj/"
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
  "$tool" convert "$tets" "$build/two_tets.ele"
  { cat "$build/two_tets.node"; printf '\0'; cat "$build/two_tets.ele"; } > "$seeds/tetgen/two_tets"
fi

status=0
for f in "${formats[@]}"; do
  echo "== fuzz_$f (${per}s)"
  work=$build/corpus/$f
  mkdir -p "$work"
  if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz/fuzz_$f" "$work" "$seeds/$f" -max_total_time="$per" -max_len=65536 -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/crash-$f-" 2>"$build/fuzz_$f.log"; then
    echo "fuzz_$f FAILED: see $build/fuzz_$f.log and $build/crash-$f-*" >&2
    tail -40 "$build/fuzz_$f.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|cov:" "$build/fuzz_$f.log" | tail -2
  fi
done
exit $status
