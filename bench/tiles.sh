#!/usr/bin/env bash
# Tiled vs untiled on one district (docs/scale.md, docs/benchmarks.md "Tiles"): 8 LoD2 houses (the
# shared 100-building CityJSON cut to a 4 x 2 block), `synth --per-building`, cut by `tile`, run with
# run-tiles (Slurm through a private single-node cluster, or local processes), merged, and compared
# with one untiled `run` of the same district given the same training budget (the tiles' iterations
# summed), both evaluated by one `evaluate` call on the district's ground truth.
# What it shows: what tiling costs in 2D/3D mIoU and wall time, and the seam count of the merge.
# What it does not: synthetic features (a mechanics benchmark, not CLIP/SAM), one small district on
# 2 cores, no GPU.
#   bash bench/tiles.sh [--executor local|slurm] [--work DIR] [--rgb N] [--language N]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
bin=$repo/build/citylangsplat
executor=local; work=/tmp/cls-bench-tiles; rgb=1500; language=200
while [ $# -gt 0 ]; do
  case $1 in
    --executor) executor=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --rgb) rgb=$2; shift 2 ;;
    --language) language=$2; shift 2 ;;
    *) echo "usage: $0 [--executor local|slurm] [--work DIR] [--rgb N] [--language N]" >&2; exit 2 ;;
  esac
done
rm -rf "$work" && mkdir -p "$work"
work=$(readlink -f "$work")
if [ "$executor" = slurm ] && [ -z "${SLURM_CONF:-}" ]; then
  cluster=$(mktemp -d /tmp/cls-slurm.XXXXXX)
  trap 'bash "$repo/tests/tiles/slurm_cluster.sh" stop "$cluster"; rm -rf "$cluster"' EXIT
  bash tests/tiles/slurm_cluster.sh start "$cluster" --accounting || bash tests/tiles/slurm_cluster.sh start "$cluster"
  eval "$(bash tests/tiles/slurm_cluster.sh env "$cluster")"
fi

python3 tests/tiles/cityjson_subset.py data/citygml/citygml4j/lod2_buildings_v2.json --box 0,0,36,18 \
  --out "$work/district.city.json"
"$bin" -q synth --city "$work/district.city.json" --out "$work/district" --per-building --views 48 \
  --width 200 --height 150 --gt-density 50
"$bin" tile --scene "$work/district" --out "$work/tiles" --max-images 28 --min-share 0.2
tiles=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['tiles']))" "$work/tiles/tiles.json")
# Steps per image equal: a tile of m images runs N iterations; the district of 48 runs N * 48 / mean(m).
scale=$(python3 -c "import json,sys; t=json.load(open(sys.argv[1]))['tiles']; print(48 * len(t) / sum(len(x['images']) for x in t))" \
  "$work/tiles/tiles.json")
untiled_rgb=$(python3 -c "print(round($rgb * $scale))")
untiled_language=$(python3 -c "print(round($language * $scale))")
common=(--models synthetic --autoencoder-epochs 20 --baseline none)

start=$SECONDS
if [ "$executor" = slurm ]; then
  "$bin" run-tiles "$work/tiles" --executor slurm --wait --rgb-iterations "$rgb" --language-iterations "$language" "${common[@]}"
else
  "$bin" run-tiles "$work/tiles" --executor local --jobs 2 --rgb-iterations "$rgb" --language-iterations "$language" "${common[@]}"
fi
"$bin" merge "$work/tiles" --out "$work/merged" | tee "$work/merge.txt"
tiled_s=$((SECONDS - start))
if [ "$executor" = slurm ] && sacct -n -X -j 1 >/dev/null 2>&1; then
  echo "--- sacct (the arrays of run-tiles):"
  sacct --format=JobID%12,JobName%16,State,ExitCode,Elapsed -X
fi

start=$SECONDS
"$bin" -q run "$work/district" --out "$work/untiled" --rgb-iterations "$untiled_rgb" \
  --language-iterations "$untiled_language" "${common[@]}" > "$work/untiled.log" 2>&1
untiled_s=$((SECONDS - start))
start=$SECONDS
"$bin" -q run "$work/district" --out "$work/untiled_same" --rgb-iterations "$rgb" --language-iterations "$language" \
  "${common[@]}" > "$work/untiled_same.log" 2>&1
untiled_same_s=$((SECONDS - start))
"$bin" -q render "$work/merged/language/citylangsplat" --scene "$work/district" --out "$work/merged_render" --views test

"$bin" -q evaluate --scene "$work/district" --model tiled="$work/merged/language/citylangsplat" \
  --model untiled="$work/untiled/language/citylangsplat" --model untiled_same="$work/untiled_same/language/citylangsplat" \
  --out "$work/eval" > /dev/null
python3 - "$work" "$tiles" "$tiled_s" "$untiled_s" "$rgb" "$language" "$executor" "$untiled_rgb" "$untiled_language" \
  "$untiled_same_s" <<'PY'
import json, sys
work, tiles, tiled_s, untiled_s, rgb, language, executor, untiled_rgb, untiled_language, untiled_same_s = sys.argv[1:]
plan = json.load(open(f"{work}/tiles/tiles.json"))
merge = json.load(open(f"{work}/merged/merge.json"))["methods"]["citylangsplat"]
e = json.load(open(f"{work}/eval/eval.json"))["results"]
images = [len(t["images"]) for t in plan["tiles"]]
print(f"district: 8 buildings, 48 images 200x150; {tiles} tiles, images per tile {images}; executor {executor}")
print(f"tiles: {rgb} photometric + {language} language iterations each; untiled: {untiled_rgb} + {untiled_language} "
      f"(the same steps per image); untiled_same: {rgb} + {language} (the tiles' settings)")
print(f"merged: {merge['gaussians']} Gaussians; in another tile's cell: {merge['in_another_tiles_cell']} "
      f"(a plain union of the tiles: {merge['naive_union_in_another_tiles_cell']})")
psnr = {"tiled": json.load(open(f"{work}/merged_render/render.json"))["mean_psnr"],
        "untiled": json.load(open(f"{work}/untiled/render/render.json"))["mean_psnr"],
        "untiled_same": json.load(open(f"{work}/untiled_same/render/render.json"))["mean_psnr"]}
print("| | wall (s) | Gaussians | held-out PSNR (dB) | 2D mIoU | 3D mIoU | 3D mIoU, best labelling |")
print("|---|---:|---:|---:|---:|---:|---:|")
for name, secs in (("tiled", tiled_s), ("untiled", untiled_s), ("untiled_same", untiled_same_s)):
    r = e[name]
    print(f"| {name} | {float(secs):.0f} | {r['3d']['gaussians']} | {psnr[name]:.2f} | {100 * r['2d']['miou']:.2f} | "
          f"{100 * r['3d']['miou']:.2f} | {100 * r['3d']['best_labelling']['miou']:.2f} |")
for other in ("untiled", "untiled_same"):
    d2 = 100 * (e["tiled"]["2d"]["miou"] - e[other]["2d"]["miou"])
    d3 = 100 * (e["tiled"]["3d"]["miou"] - e[other]["3d"]["miou"])
    print(f"tiled - {other}: 2D {d2:+.2f}, 3D {d3:+.2f} mIoU points")
PY
