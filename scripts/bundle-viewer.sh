#!/usr/bin/env bash
# Rebuilds the viewer's script, viewer/dist/cgogn-viewer.js: viewer/src/main.js
# and three.js bundled and minified by esbuild, both at the versions pinned in
# viewer/package-lock.json. The bundle is part of the repository, so that
# building cgogn (which embeds it in cgogn::render) needs neither Node nor the
# network; run this after changing viewer/src or the lock file, and commit
# the result.
#   bash scripts/bundle-viewer.sh           rewrite the bundle
#   bash scripts/bundle-viewer.sh --check   fail when the committed bundle is
#                                           not what the sources make (CI)
# Needs node and npm: installs Debian's when they are missing (as root).
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
[ "${1:-}" = "--check" ] && check=1
if ! command -v npm >/dev/null 2>&1; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "bundle-viewer: node and npm are missing; install them (Debian: nodejs npm)" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends nodejs npm
fi
# npm ci installs exactly the lock file's versions (integrity-checked)
if [ ! -f viewer/node_modules/.package-lock.json ] ||
   [ viewer/package-lock.json -nt viewer/node_modules/.package-lock.json ]; then
  (cd viewer && npm ci --no-audit --no-fund --loglevel=error)
fi
committed=viewer/dist/cgogn-viewer.js
out=$(pwd)/$committed
if [ "$check" = 1 ]; then
  out=$(mktemp --suffix=.js)
  trap 'rm -f "$out"' EXIT
fi
(cd viewer && node_modules/.bin/esbuild src/main.js --bundle --minify --format=iife --target=es2020 \
  --log-level=warning --outfile="$out")
if [ "$check" = 1 ]; then
  if ! cmp -s "$out" "$committed"; then
    echo "bundle-viewer: $committed is not what viewer/src and viewer/package-lock.json make:" \
         "run bash scripts/bundle-viewer.sh and commit it" >&2
    exit 1
  fi
  echo "bundle-viewer: $committed is up to date ($(wc -c < "$committed") bytes)"
else
  echo "bundle-viewer: wrote $committed ($(wc -c < "$committed") bytes)"
fi
