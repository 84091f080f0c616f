#!/usr/bin/env bash
# Installs the browser viewer's npm dependencies (three, Spark) from web/package-lock.json into
# build/web/node_modules, which `citylangsplat view` serves under /vendor/ so the page works offline.
# Idempotent: skips `npm ci` while the installed tree was made from the same package.json + lock.
#   bash scripts/install_web.sh
set -euo pipefail
cd "$(dirname "$0")/.."

DEST=build/web
STAMP="$DEST/node_modules/.citylangsplat-lock.sha256"

if ! command -v npm >/dev/null 2>&1; then
  echo "install_web: npm is not installed (Debian: apt-get install npm; scripts/setup.sh does it)" >&2
  exit 1
fi

want=$(cat web/package.json web/package-lock.json | sha256sum | cut -d' ' -f1)
if [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$want" ]; then
  echo "install_web: $DEST/node_modules is up to date"
  exit 0
fi

mkdir -p "$DEST"
cp web/package.json web/package-lock.json "$DEST/"
# --ignore-scripts: the page only needs the packages' files; no install hook has to run.
npm ci --prefix "$DEST" --ignore-scripts --no-audit --no-fund
echo "$want" > "$STAMP"
echo "install_web: installed $(node -p "Object.entries(require('./web/package.json').dependencies).map((d) => d.join('@')).join(' ')") into $DEST/node_modules"
