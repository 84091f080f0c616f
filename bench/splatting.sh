#!/usr/bin/env bash
# Raw against normalised splatting of the language latents (issue 38, docs/benchmarks.md "Raw or normalised
# splatting"). On one scene and one feature provider: `run` (CityLangSplat with raw latents, the default, and
# the paper's baseline, LangSplat as published: its 3-d autoencoder, normalised splatting), then CityLangSplat
# again with LangSplat's normalised splatting (`train-language --normalize-latents`), all at the same
# iterations per level on the same photometric model; with --ablation also LangSplat's objective on the
# 128-d autoencoder, raw and normalised. `evaluate` scores the fields together against the scene's GT point
# cloud, which no training reads (synth renders it from the true geometry).
# What it shows: which splatting scores higher at this schedule, per method, with this provider's features
# (synthetic: the mechanics benchmark; image-segments: the robustness benchmark's provider). What it does not:
# CLIP/SAM on real photos, or the paper's 30,000 iterations per level where the CPU cannot reach them.
#   bash bench/splatting.sh SCENE --work DIR [--models synthetic|image-segments] [--iterations N]
#                           [--rgb-model PLY] [--ablation]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
bin=${CLS_BIN:-$repo/build/citylangsplat}
usage="usage: $0 SCENE --work DIR [--models synthetic (or image-segments)] [--iterations 1000] [--rgb-model PLY (default: train it)] [--ablation]"
scene=""; work=""; models=synthetic; iterations=1000; rgb=(); geometry=""; ablation=0
while [ $# -gt 0 ]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --models) models=$2; shift 2 ;;
    --iterations) iterations=$2; shift 2 ;;
    --rgb-model) geometry=$(readlink -f "$2"); rgb=(--rgb-model "$geometry"); shift 2 ;;
    --ablation) ablation=1; shift ;;
    -h|--help) echo "$usage"; exit 0 ;;
    -*) echo "$usage" >&2; exit 2 ;;
    *) scene=$1; shift ;;
  esac
done
[ -n "$scene" ] && [ -n "$work" ] || { echo "$usage" >&2; exit 2; }
[ -x "$bin" ] || { echo "splatting.sh: $bin not found: build first (cmake --build build)" >&2; exit 1; }
mkdir -p "$work"
out=$work/run
[ -n "$geometry" ] || geometry=$out/rgb/point_cloud.ply  # what run trains when no model is given
methods=(citylangsplat); baselines=langsplat-original
[ $ablation = 1 ] && methods+=(langsplat) && baselines+=,langsplat
"$bin" run "$scene" --out "$out" --models "$models" --baseline "$baselines" --language-iterations "$iterations" "${rgb[@]}"
models_args=(--model "ours raw (default)=$out/language/citylangsplat")
for method in "${methods[@]}"; do
  baseline=(); [ $method = langsplat ] && baseline=(--baseline langsplat)
  "$bin" train-language --scene "$scene" --model "$geometry" --features "$out/features" \
    --autoencoder "$out/autoencoder.safetensors" --out "$work/$method-normalised" --iterations "$iterations" \
    --normalize-latents "${baseline[@]}" --resume
done
models_args+=(--model "ours normalised=$work/citylangsplat-normalised")
[ $ablation = 1 ] && models_args+=(--model "LangSplat-128 raw=$out/language/langsplat"
                                   --model "LangSplat-128 normalised=$work/langsplat-normalised")
models_args+=(--model "LangSplat original (3-d, normalised)=$out/language/langsplat-original")
"$bin" evaluate --scene "$scene" --labels "$out/labels" --out "$work/eval" --no-images "${models_args[@]}"
echo "splatting.sh: $work/eval/eval.md"
