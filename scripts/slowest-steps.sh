#!/usr/bin/env bash
# Prints the N slowest steps (compilations, links) of the last build of each
# Ninja build folder given, from its .ninja_log, and the sum of all its steps
# (the build's CPU time when one step is one process).
#   bash scripts/slowest-steps.sh [-n N] build/release [build/asan ...]
set -euo pipefail
n=15
if [ "${1:-}" = "-n" ]; then
  n=$2
  shift 2
fi
for dir in "$@"; do
  log=$dir/.ninja_log
  if [ ! -f "$log" ]; then
    echo "== $dir: no .ninja_log (not built with Ninja)"
    continue
  fi
  # a step rebuilt later appears again: keep its last line (ninja's own rule)
  awk -v dir="$dir" -v n="$n" '
    NR > 1 && !/^#/ { t[$4] = ($2 - $1) / 1000 }
    END {
      total = 0; count = 0
      for (k in t) { total += t[k]; count++ }
      printf "== %s: %d steps, %.0f s in all; the %d slowest:\n", dir, count, total, n
      fflush()
      cmd = "sort -rn | head -n " n
      for (k in t) printf "%8.1f s  %s\n", t[k], k | cmd
      close(cmd)
    }' "$log"
done
