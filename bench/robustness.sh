#!/usr/bin/env bash
# Robustness to a wrong city model (docs/benchmarks.md "Robustness", issue 13): per LoD3 building a
# synthetic scene, then the same scene given city models that are wrong in known ways, the truth kept
# aside: a city transform off by growing errors (`synth --city-error`), and per variant a model that lacks
# openings (`drop=F`: `synth --drop-openings F`) or is the building's LoD2 model (`lod2`, where the data
# has one), and a scene whose photos show N extra trees just in front of the facades that the city model
# lacks (`occl=N`: `synth --occluders N`; new photos, so its own photometric model and its own baseline);
# `occl=N+drop=F` and `occl=N+lod2` give those photos a model that is also wrong (occl=N must be listed too:
# its baseline is theirs).
# Every run uses the image-segments provider (segments of the images, features from the exact ground
# truth under them: nothing comes from the label maps, so a wrong model shows), one photometric model per
# building and set of photos, and scores 2D on the held-out views and 3D on the ground-truth cloud, which
# `synth` renders from the true geometry and the method never sees.
# Rows: the LangSplat baselines (no CityGML: the same for every model; LangSplat's objective on the shared
# autoencoder, and LangSplat as published in the last columns), CityLangSplat with the given
# transform (--align off), CityLangSplat with the refinement (--align auto), and the label maps of the
# transform used; per building and the mean over the buildings.
# What it shows: how much a wrong model costs the CityGML terms, and whether `align` wins it back.
# What it does not: CLIP/SAM (ground-truth features plus noise), real SfM points.
# Also per building, on the exact scene: the mechanics benchmark (`--models synthetic`, docs/benchmarks.md
# "Mechanics benchmark") in its own columns.
#   bash bench/robustness.sh [--work DIR] [--buildings "fzk citygml4j texture4"] [--errors "0 t=0.25 ..."]
#                            [--variants "exact drop=0.3 lod2 occl=8 occl=8+drop=0.3"] [--rgb-iterations N]
#                            [--language-iterations N] [--field dense|sparse]
#                            [--report-only]   (the table, JSON and plot of the runs WORK already holds)
# --field: the language field every run trains (docs/language.md); give each field its own WORK (a link to
# another WORK's <building>/rgb reuses its photometric model).
# A building's photometric model is trained once per set of photos into WORK/<building>/rgb (rgb-occl=N)
# and reused when present (and `run` reuses every stage whose inputs did not change).
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
bin=${CLS_BIN:-$repo/build/citylangsplat}
work=/tmp/cls-bench-robustness; buildings="fzk citygml4j texture4"
errors="0 t=0.25 t=0.5,r=0.5 t=1,r=2"; variants="exact drop=0.3"; rgb_iterations=1500; language_iterations=300
field=dense
report_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --buildings) buildings=$2; shift 2 ;;
    --errors) errors=$2; shift 2 ;;
    --variants) variants=$2; shift 2 ;;
    --rgb-iterations) rgb_iterations=$2; shift 2 ;;
    --language-iterations) language_iterations=$2; shift 2 ;;
    --field) field=$2; shift 2 ;;
    --report-only) report_only=1; shift ;;
    *) echo "usage: $0 [--work DIR (/tmp/cls-bench-robustness)] [--buildings \"fzk citygml4j texture4\"]" \
            "[--errors \"0 t=0.25 t=0.5,r=0.5 t=1,r=2\"] [--variants \"exact drop=0.3\" (also lod2, occl=N, occl=N+drop=F, occl=N+lod2)]" \
            "[--rgb-iterations 1500] [--language-iterations 300] [--field dense|sparse (dense)] [--report-only]" >&2
       exit 2 ;;
  esac
done
case $field in dense|sparse) ;; *) echo "robustness.sh: --field must be dense or sparse, got $field" >&2; exit 2 ;; esac
case " $errors " in *" 0 "*) ;; *) echo "robustness.sh: --errors must include 0 (the baseline and the reference row run there)" >&2; exit 2 ;; esac
# The exact photos' baseline runs with the exact model; occl=N scenes have their own photos and baseline.
case " $variants " in
  *" exact "*) ;;
  *) for v in $variants; do
       case $v in occl=*) ;; *) echo "robustness.sh: --variants must include exact with $v (the baseline of its photos runs there)" >&2; exit 2 ;; esac
     done ;;
esac
for v in $variants; do
  case $v in
    exact|lod2|drop=0.*|drop=1|occl=[1-9]|occl=[1-9][0-9]) ;;
    occl=[1-9]+lod2|occl=[1-9][0-9]+lod2|occl=[1-9]+drop=0.*|occl=[1-9][0-9]+drop=0.*|occl=[1-9]+drop=1|occl=[1-9][0-9]+drop=1)
      [[ $v != *+*+* ]] || { echo "robustness.sh: $v: one occl=N and one model change at most" >&2; exit 2; }
      case " $variants " in *" ${v%%+*} "*) ;; *) echo "robustness.sh: $v needs ${v%%+*} in --variants (its baseline runs there)" >&2; exit 2 ;; esac ;;
    *) echo "robustness.sh: unknown variant $v (exact, lod2, drop=FRACTION, occl=COUNT in 1..99, occl=COUNT+drop=FRACTION, occl=COUNT+lod2)" >&2; exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "robustness.sh: $bin not found: build first (cmake --build build)" >&2; exit 1; }
data=$(cd "$repo/../shared/data/citygml" 2>/dev/null && pwd || echo "$repo/data/citygml")
declare -A city=([fzk]=$data/fzk-haus/fzk_haus_lod3_v2.gml [citygml4j]=$data/citygml4j/lod3_building_v2.gml
                 [texture4]=$data/cityjson/texture4.city.json)
declare -A lod2=([fzk]=$data/fzk-haus/fzk_haus_lod2_v2.gml)
mkdir -p "$work"
work=$(readlink -f "$work")
synth() {  # synth OUT VARIANT ERROR
  local args=(-q synth --city "${city[$b]}" --lod 3 --views 32 --width 240 --height 180 --seed 1 --out "$1" --skip-if-same)
  local part parts
  IFS=+ read -r -a parts <<< "$2"
  for part in "${parts[@]}"; do
    case $part in
      lod2) args+=(--given-city "${lod2[$b]}" --given-lod 2) ;;
      drop=*) args+=(--drop-openings "${part#drop=}") ;;
      occl=*) args+=(--occluders "${part#occl=}") ;;
    esac
  done
  [ "$3" = 0 ] || args+=(--city-error "$3")
  "$bin" "${args[@]}"
}
run() {  # [MODELS=...] run SCENE OUT [run options], with $rgb the photometric model of SCENE's photos
  local scene=$1 out=$2; shift 2
  echo "  run $(basename "$out") ($(date +%H:%M:%S))" >&2
  "$bin" -q run "$scene" --models "${MODELS:-image-segments}" --rgb-model "$rgb/point_cloud.ply" \
    --language-iterations "$language_iterations" --field "$field" --out "$out" "$@" > "$out.log" 2>&1 \
    || { echo "robustness.sh: run failed, see $out.log" >&2; tail -5 "$out.log" >&2; exit 1; }
}
for b in $buildings; do
  [ "$report_only" = 0 ] || break
  [ -n "${city[$b]:-}" ] || { echo "robustness.sh: unknown building $b (fzk, citygml4j, texture4)" >&2; exit 2; }
  mkdir -p "$work/$b"
  for v in $variants; do
    case +$v+ in *+lod2+*) [ -n "${lod2[$b]:-}" ] || { echo "$b: no LoD2 model in the data: $v skipped" >&2; continue; } ;; esac
    prefix=""; [ "$v" = exact ] || prefix="$v-"  # the exact model's folders keep their names
    # The photos: occluders change them, the other variants change only the city model they are given.
    case $v in occl=*) photos=${v%%+*} ;; *) photos=exact ;; esac
    photos_scene=$work/$b/scene-0 rgb=$work/$b/rgb
    [ "$photos" = exact ] || photos_scene=$work/$b/scene-$photos-0 rgb=$work/$b/rgb-$photos
    synth "$photos_scene" "$photos" 0
    if [ ! -f "$rgb/point_cloud.ply" ]; then
      echo "$b: train-rgb on $(basename "$photos_scene") ($rgb_iterations iterations)" >&2
      "$bin" -q train-rgb --scene "$photos_scene" --out "$rgb" --iterations "$rgb_iterations" \
        --densify-until $((rgb_iterations / 2)) > "$rgb.log" 2>&1 \
        || { echo "robustness.sh: train-rgb failed, see $rgb.log" >&2; tail -5 "$rgb.log" >&2; exit 1; }
    fi
    for e in $errors; do
      scene=$work/$b/scene-$prefix$e
      synth "$scene" "$v" "$e"
      if [ "$v" = exact ] && [ "$e" = 0 ]; then
        # With the baselines (they do not depend on the city model): LangSplat's objective on the shared
        # autoencoder, and LangSplat as published (its 3-d autoencoder, normalised splatting).
        # LangSplat as published has no sparse form (`run` refuses it with the sparse field).
        originals=langsplat,langsplat-original; [ "$field" = dense ] || originals=langsplat
        run "$scene" "$work/$b/run-0-off" --align off --baseline "$originals"
        # the mechanics benchmark, with run's default baseline (the sparse field has LangSplat's objective only)
        mech_baseline=(); [ "$field" = dense ] || mech_baseline=(--baseline langsplat)
        MODELS=synthetic run "$scene" "$work/$b/run-0-synthetic" --align off "${mech_baseline[@]}"
      elif [ "$photos" = "$v" ] && [ "$e" = 0 ]; then  # other photos: their own baseline
        run "$scene" "$work/$b/run-$prefix$e-off" --align off --baseline langsplat
      else
        run "$scene" "$work/$b/run-$prefix$e-off" --align off --baseline none
        [ "$e" = 0 ] || run "$scene" "$work/$b/run-$prefix$e-align" --align auto --baseline none
      fi
    done
  done
done
python3 - "$work" "$buildings" "$errors" "$variants" <<'PY'
import json, os, sys
work, buildings, errors, variants = sys.argv[1], sys.argv[2].split(), sys.argv[3].split(), sys.argv[4].split()
def scores(run, method):
    path = os.path.join(work, run, "eval", "eval.json")
    if not os.path.exists(path): return None
    r = json.load(open(path))["results"].get(method)
    if r is None: return None
    return (100 * r["2d"]["miou"], 100 * r["3d"]["miou"] if "3d" in r else None)
fmt = lambda x: "-" if x is None else f"{x:.2f}"
pair = lambda p: [p and p[0], p and p[1]]
def with_mean(rows, key_len):
    # The mean over the buildings, for each key every building has (a building's rows start with its name).
    keys = []
    for r in rows:
        if tuple(r[1:key_len]) not in keys: keys.append(tuple(r[1:key_len]))
    out = list(rows)
    for k in keys:
        mine = [r for r in rows if tuple(r[1:key_len]) == k]
        if len(buildings) < 2 or len(mine) != len(buildings): continue
        mean = lambda j: None if any(r[j] is None for r in mine) else sum(r[j] for r in mine) / len(mine)
        out.append(["mean", *k] + [mean(j) for j in range(key_len, len(rows[0]))])
    return out
def table(head, rows, key_len):
    md = ["| " + " | ".join(head) + " |", "|" + "---|" * key_len + "---:|" * (len(head) - key_len)]
    return md + ["| " + " | ".join([str(x) for x in r[:key_len]] + [fmt(x) for x in r[key_len:]]) + " |" for r in rows]
# Per building, what does not depend on the given model: the baselines, the mechanics benchmark, the labels.
head_a = ("building", "LangSplat 2D", "LangSplat 3D", "LangSplat original 2D", "LangSplat original 3D",
          "ours 2D", "ours 3D", "labels 2D", "mechanics: ours 2D", "ours 3D", "LangSplat 2D", "LangSplat 3D",
          "labels 2D")
rows_a = []
for b in buildings:
    if scores(f"{b}/run-0-off", "citylangsplat") is None: continue
    mech = f"{b}/run-0-synthetic"
    rows_a.append([b] + pair(scores(f"{b}/run-0-off", "langsplat")) + pair(scores(f"{b}/run-0-off", "langsplat-original"))
                  + pair(scores(f"{b}/run-0-off", "citylangsplat")) + [pair(scores(f"{b}/run-0-off", "city-model-labels"))[0]]
                  + pair(scores(mech, "citylangsplat")) + pair(scores(mech, "langsplat"))
                  + [pair(scores(mech, "city-model-labels"))[0]])
rows_a = with_mean(rows_a, 1) if rows_a else []
# Per building, given model and transform error: CityLangSplat without and with align, the label maps, and
# the LangSplat baseline on the same photos (occl=N has its own).
head_b = ("building", "model", "error", "ours 2D", "ours 3D", "ours+align 2D", "ours+align 3D", "labels 2D (given)",
          "labels 2D (aligned)", "ours+align 3D - exact zero-error 3D", "LangSplat 2D (same photos)",
          "LangSplat 3D (same photos)")
rows_b = []
for b in buildings:
    zero = scores(f"{b}/run-0-off", "citylangsplat")
    for v in variants:
        prefix = "" if v == "exact" else v + "-"
        for e in errors:
            run = "run-0-off" if (v, e) == ("exact", "0") else f"run-{prefix}{e}-off"
            off = scores(f"{b}/{run}", "citylangsplat")
            if off is None: continue  # not run
            al = off if e == "0" else scores(f"{b}/run-{prefix}{e}-align", "citylangsplat")
            lab = scores(f"{b}/{run}", "city-model-labels")
            lab_al = lab if e == "0" else scores(f"{b}/run-{prefix}{e}-align", "city-model-labels")
            gap = al[1] - zero[1] if al and zero and al[1] is not None and zero[1] is not None else None
            photos = v.split("+")[0] if v.startswith("occl=") else None
            base = scores(f"{b}/run-{photos}-0-off" if photos else f"{b}/run-0-off", "langsplat")
            rows_b.append([b, v, e] + pair(off) + pair(al) + [lab and lab[0], lab_al and lab_al[0], gap] + pair(base))
rows_b = with_mean(rows_b, 3) if rows_b else []
md = ["Per building (exact model, zero error):", ""] + table(head_a, rows_a, 1) + ["", "Given model x transform error:", ""] + table(head_b, rows_b, 3)
open(os.path.join(work, "robustness.md"), "w").write("\n".join(md) + "\n")
json.dump({"per_building": {"header": head_a, "rows": rows_a}, "matrix": {"header": head_b, "rows": rows_b}},
          open(os.path.join(work, "robustness.json"), "w"), indent=1)
print("\n".join(md))
# The plot: 3D mIoU against the error, a panel per building (and the mean): CityLangSplat without (red) and
# with align (blue), solid for the exact model, dashed for the others; the LangSplat baseline in grey (an
# occl=N variant's own baseline, on its photos, dashed as that variant).
W, H, pad = 300, 220, 40
colours = {"LangSplat": "#888888", "ours": "#d62728", "ours+align": "#1f77b4"}
dashes = ["", "6,4", "2,3", "8,3,2,3"]
panels = [r[0] for r in rows_a] or list(dict.fromkeys(r[0] for r in rows_b))  # the buildings' order, then the mean
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W * len(panels)}" height="{H + 40}" font-family="sans-serif" font-size="11">']
X = lambda x0, k: x0 + pad + k * (W - 2 * pad) / max(1, len(errors) - 1)
for i, b in enumerate(panels):
    mine = [r for r in rows_b if r[0] == b]
    base = next((r[2] for r in rows_a if r[0] == b), None)
    vals = [v for r in mine for v in (r[4], r[6], r[11]) if v is not None] + ([base] if base is not None else [])
    if not vals: continue
    lo, hi = min(vals) - 2, max(vals) + 2
    x0 = i * W
    top = 12 + 13 * max(len(colours), len(variants))  # the legend's band above the curves
    Y = lambda v: top + (H - pad - top) * (hi - v) / (hi - lo)
    svg.append(f'<text x="{x0 + W / 2}" y="{H + 30}" text-anchor="middle">{b}: 3D mIoU vs city-transform error</text>')
    svg.append(f'<line x1="{x0 + pad}" y1="{H - pad + 10}" x2="{x0 + W - pad}" y2="{H - pad + 10}" stroke="black"/>')
    for k, e in enumerate(errors):
        svg.append(f'<text x="{X(x0, k)}" y="{H - pad + 24}" text-anchor="middle">{e}</text>')
    for t in (lo + 2, (lo + hi) / 2, hi - 2):
        svg.append(f'<text x="{x0 + pad - 4}" y="{Y(t) + 4}" text-anchor="end">{t:.0f}</text>')
    if base is not None:
        svg.append(f'<line x1="{X(x0, 0)}" y1="{Y(base):.1f}" x2="{X(x0, len(errors) - 1)}" y2="{Y(base):.1f}" stroke="{colours["LangSplat"]}" stroke-width="2"/>')
    for j, v in enumerate(variants):  # the baseline of other photos (occl=N), in that variant's dashes
        other = next((r[11] for r in mine if r[1] == v and v.startswith("occl=") and "+" not in v and r[11] is not None), None)
        if other is None: continue
        dash = f' stroke-dasharray="{dashes[j % len(dashes)]}"' if dashes[j % len(dashes)] else ""
        svg.append(f'<line x1="{X(x0, 0)}" y1="{Y(other):.1f}" x2="{X(x0, len(errors) - 1)}" y2="{Y(other):.1f}" stroke="{colours["LangSplat"]}" stroke-width="2"{dash}/>')
    for j, v in enumerate(variants):
        for name, col in (("ours", 4), ("ours+align", 6)):
            pts = [(X(x0, errors.index(r[2])), Y(r[col])) for r in mine if r[1] == v and r[col] is not None]
            if not pts: continue
            dash = f' stroke-dasharray="{dashes[j % len(dashes)]}"' if dashes[j % len(dashes)] else ""
            svg.append('<polyline fill="none" stroke="%s" stroke-width="2"%s points="%s"/>' %
                       (colours[name], dash, " ".join(f"{x:.1f},{y:.1f}" for x, y in pts)))
            for x, y in pts: svg.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="2.5" fill="{colours[name]}"/>')
    if i == 0:
        for k, name in enumerate(colours):
            svg.append(f'<text x="{x0 + pad + 6}" y="{12 + 13 * k}" fill="{colours[name]}">{name}</text>')
        for j, v in enumerate(variants):
            style = "solid" if not dashes[j % len(dashes)] else "dashed " + dashes[j % len(dashes)]
            svg.append(f'<text x="{x0 + W - pad}" y="{12 + 13 * j}" text-anchor="end">{v}: {style}</text>')
svg.append("</svg>")
open(os.path.join(work, "robustness.svg"), "w").write("\n".join(svg) + "\n")
print(f"wrote {work}/robustness.md, robustness.json, robustness.svg")
PY
