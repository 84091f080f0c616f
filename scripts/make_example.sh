#!/usr/bin/env bash
# Generates the bundled example: a synthetic scene of KIT's FZK-Haus (CityGML 2.0, LoD3) with the
# settings in examples/fzk-haus/synth.conf, into build/example/fzk-haus (or OUT_DIR).
# Does nothing if the scene there was generated with the same settings and inputs (synth
# --skip-if-same compares scene.json); replaces it otherwise.
#   bash scripts/make_example.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=../examples/fzk-haus/synth.conf
source examples/fzk-haus/synth.conf
BIN=${CITYLANGSPLAT:-build/citylangsplat}
OUT=${1:-build/example/fzk-haus}
if [ ! -x "$BIN" ]; then
  echo "make_example: $BIN not found: build first (bash scripts/setup.sh --no-example)" >&2
  exit 1
fi
"$BIN" synth --city "$CITY" --lod "$LOD" --out "$OUT" --views "$VIEWS" --width "$WIDTH" --height "$HEIGHT" \
  --seed "$SEED" --overwrite --skip-if-same
# The model's licence travels with its copy in the scene.
cp "$CITY_LICENSE" "$OUT/city/.licence.tmp"
mv "$OUT/city/.licence.tmp" "$OUT/city/$(basename "$CITY_LICENSE")"
echo "make_example: $OUT"
