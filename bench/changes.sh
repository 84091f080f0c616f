#!/usr/bin/env bash
# Change detection (issue 35 §3, docs/benchmarks.md "Change detection"): per LoD3 building a synthetic
# scene whose photos show the building as it is, given a city model that lacks openings: `drop=F` (a
# fraction F of the windows and doors merged into their walls, `synth --drop-openings F`) or `lod2` (the
# building's LoD2 model, where the data has one). `run` with the image-segments provider (segments of the
# images, features from the exact ground truth under them: nothing comes from the label maps, which lack
# those openings), then `changes`; its proposals against the openings the photos show and the given model
# lacks (the LoD3 file's openings whose gml:id the given model does not have), matched one to one by IoU on
# the wall's plane (>= 0.5): precision and recall per building (bench/changes_score.py; "of them in a
# photo": the missing openings whose centre some view's ground-truth labels show).
# What it shows: whether the language field and the photos find the openings the model lacks, with stand-in
# features. What it does not: CLIP/SAM on real photos, real SfM points.
#   bash bench/changes.sh [--work DIR] [--buildings "fzk citygml4j texture4"] [--variants "drop=0.3 lod2"]
#                         [--rgb-iterations N] [--language-iterations N] [--size 240x180]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
bin=${CLS_BIN:-$repo/build/citylangsplat}
work=/tmp/cls-bench-changes; buildings="fzk citygml4j texture4"; variants="drop=0.3 lod2"
rgb_iterations=1500; language_iterations=300; size=240x180
while [ $# -gt 0 ]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --buildings) buildings=$2; shift 2 ;;
    --variants) variants=$2; shift 2 ;;
    --rgb-iterations) rgb_iterations=$2; shift 2 ;;
    --language-iterations) language_iterations=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    *) echo "usage: $0 [--work DIR (/tmp/cls-bench-changes)] [--buildings \"fzk citygml4j texture4\"]" \
            "[--variants \"drop=0.3 lod2\"] [--rgb-iterations 1500] [--language-iterations 300] [--size 240x180]" >&2
       exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "changes.sh: $bin not found: build first (cmake --build build)" >&2; exit 1; }
data=$repo/data/citygml
declare -A city=([fzk]=$data/fzk-haus/fzk_haus_lod3_v2.gml [citygml4j]=$data/citygml4j/lod3_building_v2.gml
                 [texture4]=$data/cityjson/texture4.city.json)
declare -A lod2=([fzk]=$data/fzk-haus/fzk_haus_lod2_v2.gml)
mkdir -p "$work"
work=$(readlink -f "$work")
for b in $buildings; do
  [ -n "${city[$b]:-}" ] || { echo "changes.sh: unknown building $b (fzk, citygml4j, texture4)" >&2; exit 2; }
  mkdir -p "$work/$b"
  rgb=$work/$b/rgb
  for v in $variants; do
    args=(-q synth --city "${city[$b]}" --lod 3 --views 32 --width "${size%x*}" --height "${size#*x}" --seed 1 --skip-if-same)
    case $v in
      lod2) [ -n "${lod2[$b]:-}" ] || { echo "$b: no LoD2 model in the data: $v skipped" >&2; continue; }
            args+=(--given-city "${lod2[$b]}" --given-lod 2) ;;
      drop=*) args+=(--drop-openings "${v#drop=}") ;;
      *) echo "changes.sh: unknown variant $v (drop=FRACTION, lod2)" >&2; exit 2 ;;
    esac
    scene=$work/$b/scene-$v
    "$bin" "${args[@]}" --out "$scene"
    if [ ! -f "$rgb/point_cloud.ply" ]; then  # the photos are the same for every variant
      echo "$b: train-rgb ($rgb_iterations iterations, $(date +%H:%M:%S))" >&2
      "$bin" -q train-rgb --scene "$scene" --out "$rgb" --iterations "$rgb_iterations" \
        --densify-until $((rgb_iterations / 2)) > "$rgb.log" 2>&1 \
        || { echo "changes.sh: train-rgb failed, see $rgb.log" >&2; tail -5 "$rgb.log" >&2; exit 1; }
    fi
    out=$work/$b/run-$v
    echo "$b $v: run ($(date +%H:%M:%S))" >&2
    "$bin" -q run "$scene" --models image-segments --rgb-model "$rgb/point_cloud.ply" --align off --baseline none \
      --language-iterations "$language_iterations" --out "$out" > "$out.log" 2>&1 \
      || { echo "changes.sh: run failed, see $out.log" >&2; tail -5 "$out.log" >&2; exit 1; }
    "$bin" -q changes "$out" > "$out.changes.log" 2>&1 \
      || { echo "changes.sh: changes failed, see $out.changes.log" >&2; tail -5 "$out.changes.log" >&2; exit 1; }
    given=$(python3 -c "import json,sys,os; d=sys.argv[1]; print(os.path.join(d, json.load(open(os.path.join(d, 'scene.json')))['city_model']))" "$scene")
    /usr/bin/python3 bench/changes_score.py --true-city "${city[$b]}" --given-city "$given" --changes "$out/changes/changes.json" \
      --scene "$scene" > "$out/changes/score.json"
    echo "$b $v: $(cat "$out/changes/score.json")" >&2
  done
done
# The table: per building and given model, and the mean of each variant over the buildings that have it.
python3 - "$work" "$buildings" "$variants" <<'PY'
import json, os, sys
work, buildings, variants = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
rows = []
for v in variants:
    mine = []
    for b in buildings:
        path = os.path.join(work, b, "run-" + v, "changes", "score.json")
        if not os.path.exists(path): continue
        s = json.load(open(path))
        c = json.load(open(os.path.join(work, b, "run-" + v, "changes", "changes.json")))
        mine.append(s)
        fmt = lambda x: "-" if x is None else f"{x:.2f}"
        rows.append(f"| {b} | {v} | {s['true_openings']} | {s['missing']} | {s['visible']} | {s['proposals']} | {s['matched']} | "
                    f"{fmt(s['precision'])} | {fmt(s['recall'])} | {len(c['contradicted'])} |")
    if len(mine) > 1:
        tp, pr, mi = sum(s["matched"] for s in mine), sum(s["proposals"] for s in mine), sum(s["missing"] for s in mine)
        rows.append(f"| all | {v} | {sum(s['true_openings'] for s in mine)} | {mi} | {sum(s['visible'] for s in mine)} | {pr} | {tp} | "
                    f"{tp / pr if pr else 0:.2f} | {tp / mi if mi else 0:.2f} | |")
md = ["| building | given model | openings | missing | of them in a photo | proposals | matched (IoU >= 0.5) | precision | recall | contradicted surfaces |",
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"] + rows
open(os.path.join(work, "changes.md"), "w").write("\n".join(md) + "\n")
print("\n".join(md))
PY
