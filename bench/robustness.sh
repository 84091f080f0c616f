#!/usr/bin/env bash
# Robustness to a misplaced city model (docs/benchmarks.md "Robustness", issue 13): per LoD3 building a
# synthetic scene, then the same scene given city transforms off by growing errors (`synth --city-error`,
# the exact one kept aside). Every run uses the image-segments provider (segments of the images, features
# from the exact ground truth under them: nothing comes from the label maps, so a wrong transform shows),
# one shared photometric model per building, and scores 2D on the held-out views and 3D on the ground-truth
# cloud, which `synth` renders from the true geometry and the method never sees.
# Rows: the LangSplat baseline (no CityGML: the same at every error), CityLangSplat with the given transform
# (--align off), CityLangSplat with the refinement (--align auto), and the label maps of the transform used.
# What it shows: how much a wrong transform costs the CityGML terms, and whether `align` wins it back.
# What it does not: CLIP/SAM (ground-truth features plus noise), models lacking openings or LoD2-only models
# (not in this matrix yet), real SfM points.
#   bash bench/robustness.sh [--work DIR] [--buildings "fzk citygml4j texture4"] [--errors "0 t=0.25 ..."]
#                            [--rgb-iterations N] [--language-iterations N]
# A building's photometric model is trained once into WORK/<building>/rgb and reused when present.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
bin=${CLS_BIN:-$repo/build/citylangsplat}
work=/tmp/cls-bench-robustness; buildings="fzk citygml4j texture4"
errors="0 t=0.25 t=0.5,r=0.5 t=1,r=2"; rgb_iterations=1500; language_iterations=300
while [ $# -gt 0 ]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --buildings) buildings=$2; shift 2 ;;
    --errors) errors=$2; shift 2 ;;
    --rgb-iterations) rgb_iterations=$2; shift 2 ;;
    --language-iterations) language_iterations=$2; shift 2 ;;
    *) echo "usage: $0 [--work DIR (/tmp/cls-bench-robustness)] [--buildings \"fzk citygml4j texture4\"]" \
            "[--errors \"0 t=0.25 t=0.5,r=0.5 t=1,r=2\"] [--rgb-iterations 1500] [--language-iterations 300]" >&2
       exit 2 ;;
  esac
done
case " $errors " in *" 0 "*) ;; *) echo "robustness.sh: --errors must include 0 (the baseline and the reference row run there)" >&2; exit 2 ;; esac
[ -x "$bin" ] || { echo "robustness.sh: $bin not found: build first (cmake --build build)" >&2; exit 1; }
data=$(cd "$repo/../shared/data/citygml" 2>/dev/null && pwd || echo "$repo/data/citygml")
declare -A city=([fzk]=$data/fzk-haus/fzk_haus_lod3_v2.gml [citygml4j]=$data/citygml4j/lod3_building_v2.gml
                 [texture4]=$data/cityjson/texture4.city.json)
mkdir -p "$work"
work=$(readlink -f "$work")
synth() {  # synth OUT [ERROR]
  local args=(-q synth --city "${city[$b]}" --lod 3 --views 32 --width 240 --height 180 --seed 1 --out "$1" --skip-if-same)
  [ "${2:-0}" = 0 ] || args+=(--city-error "$2")
  "$bin" "${args[@]}"
}
run() {  # run SCENE OUT [run options]
  local scene=$1 out=$2; shift 2
  echo "  run $(basename "$out") ($(date +%H:%M:%S))" >&2
  "$bin" -q run "$scene" --models image-segments --rgb-model "$work/$b/rgb/point_cloud.ply" \
    --language-iterations "$language_iterations" --out "$out" "$@" > "$out.log" 2>&1 \
    || { echo "robustness.sh: run failed, see $out.log" >&2; tail -5 "$out.log" >&2; exit 1; }
}
for b in $buildings; do
  [ -n "${city[$b]:-}" ] || { echo "robustness.sh: unknown building $b (fzk, citygml4j, texture4)" >&2; exit 2; }
  mkdir -p "$work/$b"
  synth "$work/$b/scene-0"
  if [ ! -f "$work/$b/rgb/point_cloud.ply" ]; then
    echo "$b: train-rgb ($rgb_iterations iterations)" >&2
    "$bin" -q train-rgb --scene "$work/$b/scene-0" --out "$work/$b/rgb" --iterations "$rgb_iterations" \
      --densify-until $((rgb_iterations / 2)) > "$work/$b/rgb.log" 2>&1 \
      || { echo "robustness.sh: train-rgb failed, see $work/$b/rgb.log" >&2; tail -5 "$work/$b/rgb.log" >&2; exit 1; }
  fi
  for e in $errors; do
    scene=$work/$b/scene-$e
    synth "$scene" "$e"
    if [ "$e" = 0 ]; then
      run "$scene" "$work/$b/run-$e-off" --align off  # with the baseline: it does not depend on the city model
    else
      run "$scene" "$work/$b/run-$e-off" --align off --no-baseline
      run "$scene" "$work/$b/run-$e-align" --align auto --no-baseline
    fi
  done
done
python3 - "$work" "$buildings" "$errors" <<'PY'
import json, os, sys
work, buildings, errors = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
def scores(run, method):
    path = os.path.join(work, run, "eval", "eval.json")
    if not os.path.exists(path): return None
    r = json.load(open(path))["results"].get(method)
    if r is None: return None
    return (100 * r["2d"]["miou"], 100 * r["3d"]["miou"] if "3d" in r else None)
rows, table = [], []
head = ("building", "error", "baseline 2D", "baseline 3D", "ours 2D", "ours 3D", "ours+align 2D", "ours+align 3D",
        "labels 2D (given)", "labels 2D (aligned)")
fmt = lambda x: "-" if x is None else f"{x:.2f}"
for b in buildings:
    base = scores(f"{b}/run-0-off", "langsplat")
    for e in errors:
        off = scores(f"{b}/run-{e}-off", "citylangsplat")
        al = off if e == "0" else scores(f"{b}/run-{e}-align", "citylangsplat")
        lab = scores(f"{b}/run-{e}-off", "city-model-labels")
        lab_al = lab if e == "0" else scores(f"{b}/run-{e}-align", "city-model-labels")
        row = [b, e, base and base[0], base and base[1], off and off[0], off and off[1], al and al[0], al and al[1],
               lab and lab[0], lab_al and lab_al[0]]
        rows.append(row)
        table.append("| " + " | ".join([b, e] + [fmt(x) for x in row[2:]]) + " |")
md = ["| " + " | ".join(head) + " |", "|---|---|" + "---:|" * (len(head) - 2)] + table
open(os.path.join(work, "robustness.md"), "w").write("\n".join(md) + "\n")
json.dump({"header": head, "rows": rows}, open(os.path.join(work, "robustness.json"), "w"), indent=1)
print("\n".join(md))
# The plot: 3D mIoU against the error index, one line per method, a panel per building (plain SVG).
W, H, pad = 300, 220, 40
colours = {"baseline": "#888888", "ours": "#d62728", "ours+align": "#1f77b4"}
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W * len(buildings)}" height="{H + 40}" font-family="sans-serif" font-size="11">']
for i, b in enumerate(buildings):
    mine = [r for r in rows if r[0] == b]
    vals = [v for r in mine for v in (r[3], r[5], r[7]) if v is not None]
    if not vals: continue
    lo, hi = min(vals) - 2, max(vals) + 2
    x0 = i * W
    X = lambda k: x0 + pad + k * (W - 2 * pad) / max(1, len(mine) - 1)
    Y = lambda v: 10 + (H - pad) * (hi - v) / (hi - lo)
    svg.append(f'<text x="{x0 + W / 2}" y="{H + 30}" text-anchor="middle">{b}: 3D mIoU vs city-transform error</text>')
    svg.append(f'<line x1="{x0 + pad}" y1="{H - pad + 10}" x2="{x0 + W - pad}" y2="{H - pad + 10}" stroke="black"/>')
    for k, r in enumerate(mine):
        svg.append(f'<text x="{X(k)}" y="{H - pad + 24}" text-anchor="middle">{r[1]}</text>')
    for t in (lo + 2, (lo + hi) / 2, hi - 2):
        svg.append(f'<text x="{x0 + pad - 4}" y="{Y(t) + 4}" text-anchor="end">{t:.0f}</text>')
    for name, col in (("baseline", 3), ("ours", 5), ("ours+align", 7)):
        pts = [(X(k), Y(r[col])) for k, r in enumerate(mine) if r[col] is not None]
        svg.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' %
                   (colours[name], " ".join(f"{x:.1f},{y:.1f}" for x, y in pts)))
        if i == 0:
            svg.append(f'<text x="{x0 + pad + 6}" y="{22 + 13 * ["baseline", "ours", "ours+align"].index(name)}" fill="{colours[name]}">{name}</text>')
svg.append("</svg>")
open(os.path.join(work, "robustness.svg"), "w").write("\n".join(svg) + "\n")
print(f"wrote {work}/robustness.md, robustness.json, robustness.svg")
PY
