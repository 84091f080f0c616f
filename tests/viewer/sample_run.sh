#!/usr/bin/env bash
# The viewer's browser test needs a model whose queries mean something: a small synthetic FZK-Haus
# scene (24 views of 200x150) through `run --models synthetic` with a short schedule and no baseline
# (about 4 minutes on 2 cores; a second call reuses every stage).
#   bash tests/viewer/sample_run.sh CITYLANGSPLAT OUT
set -euo pipefail
BIN=$1
OUT=$2
DATA="$(cd "$(dirname "$0")/../.." && pwd)/data/citygml/fzk-haus/fzk_haus_lod3_v2.gml"
"$BIN" synth --city "$DATA" --lod 3 --out "$OUT/scene" --views 24 --width 200 --height 150 --seed 2 \
  --overwrite --skip-if-same
"$BIN" run "$OUT/scene" --out "$OUT/run" --models synthetic --rgb-iterations 1500 --language-iterations 150 \
  --autoencoder-epochs 15 --baseline none
