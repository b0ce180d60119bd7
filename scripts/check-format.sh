#!/usr/bin/env bash
# Fails when a C++ file the project owns does not match .clang-format
# (clang-format --dry-run -Werror); prints the files that differ.
# To fix: git ls-files '*.h' '*.cpp' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
status=0
while IFS= read -r f; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f" >&2
    status=1
  fi
done < <(git ls-files '*.h' '*.cpp')
exit $status
