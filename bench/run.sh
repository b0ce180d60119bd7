#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs the side-by-side suites and writes the Google Benchmark JSON
# and the markdown tables:
#   bench/run.sh [--input=data|generated|small] [extra Google Benchmark flags]
# Environment: BUILD (default build/release), OUT (default bench/results),
# CGOGN_BENCH_REPS (read-only repetitions, default 5), CGOGN_BENCH_TOPO_REPS
# (topology repetitions, default 3), CGOGN_LARGE_DATA_DIR (the large meshes).
# The suites run in one process; each memory measurement runs in its own
# process so that its peak RSS is that library's.
set -eu
cd "$(dirname "$0")/.."
# the large meshes (nefertiti, armadillo_tet_461k, ...) are not in the
# repository: --input=data needs CGOGN_LARGE_DATA_DIR (it names a missing
# mesh), --input=generated and --input=small need nothing
BUILD=${BUILD:-build/release}
OUT=${OUT:-bench/results}
BIN="$BUILD/bench/bench_suite"
[ -x "$BIN" ] || { echo "build first: cmake --preset release && cmake --build --preset release -j2" >&2; exit 1; }
mkdir -p "$OUT"

"$BIN" "$@" --benchmark_filter='^(surface|volume)/' \
	--benchmark_out="$OUT/suite.json" --benchmark_out_format=json

files="$OUT/suite.json"
for name in $("$BIN" --benchmark_list_tests --benchmark_filter='^memory/'); do
	base=${name%%/iterations*}
	f="$OUT/$(echo "$base" | tr '/' '_').json"
	"$BIN" "$@" --benchmark_filter="^$base/" --benchmark_out="$f" --benchmark_out_format=json >/dev/null
	files="$files $f"
done

# shellcheck disable=SC2086
python3 bench/suite/report.py $files > "$OUT/tables.md"
# shellcheck disable=SC2086
python3 bench/suite/report.py --check $files
echo "tables: $OUT/tables.md"
