#!/usr/bin/env bash
# Georeferencing from the photos' GPS (`georef`, docs/alignment.md "From the photos' GPS", issue 34):
# synthetic scenes of three LoD3 buildings (FZK-Haus, the citygml4j LoD3 building, the CityJSON texture4
# station) and an official LoD2 district (the NRW tile, views shared out over its buildings) whose
# photos carry EXIF GPS spoilt as phones spoil it (`synth --gps`: horizontal noise per axis, vertical
# noise, a vertical datum offset, a share of outliers), and no city transform. `georef` finds the
# transform from the GPS, the city mesh and ICP; it is compared with the exact one synth keeps aside
# (city/transform_true.json). Prints one row per scene and GPS error and whether it meets issue 34's
# goal (within 3 cm at every vertex of the model and 0.05 deg), then the capture range.
# What it shows: the robust GPS fit, the datum / yaw search and ICP on synth's geometry, each seed a
# new draw of the GPS errors and of which photos are outliers.
# What it does not: real phone GPS (its errors are correlated in time and along streets, not
# independent draws), real SfM points (synth's are surface samples with 1 cm noise), city models that
# differ from the buildings photographed.
#   bash bench/georef.sh [--work DIR] [--seeds "1 2 3"] [--errors "on h=5 ..."]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
bin=${CLS_BIN:-$repo/build/citylangsplat}
work=/tmp/cls-bench-georef; seeds="1 2 3"
errors="on h=1,v=1,outliers=0 h=5,v=5 h=8,v=8 h=3,v=3,datum=-30,outliers=0.3"
while [ $# -gt 0 ]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --errors) errors=$2; shift 2 ;;
    *) echo "usage: $0 [--work DIR] [--seeds \"1 2 3\"] [--errors \"on h=5 ...\"] (defaults: /tmp/cls-bench-georef, 1 2 3, $errors)" >&2; exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "georef.sh: $bin not found: build first (cmake --build build)" >&2; exit 1; }
data=$repo/data/citygml
scenes="fzk:$data/fzk-haus/fzk_haus_lod3_v2.gml:3 citygml4j:$data/citygml4j/lod3_building_v2.gml:3 \
texture4:$data/cityjson/texture4.city.json:3 nrw-lod2:$data/nrw/LoD2_32_329_5730_1_NW.gml:2"
# Only a folder this script made is cleared (its marker file), never one the user named by mistake.
if [ -e "$work" ] && [ ! -f "$work/.cls-bench-georef" ]; then
  echo "georef.sh: $work exists and was not made by this script; pass another --work" >&2; exit 2
fi
rm -rf "$work" && mkdir -p "$work" && touch "$work/.cls-bench-georef"
printf '%-10s %-4s %-36s %9s %9s %9s %9s %6s %6s %7s\n' scene seed "gps error" "gps (m)" "search" "final (m)" "final deg" pass warned time_s
fails=0; rows=0; warned_misses=0; warned_passes=0
for s in $scenes; do
  IFS=: read -r name city lod <<<"$s"
  rig="--views 32"; [ "$lod" = 2 ] && rig="--views 64 --per-building"
  for seed in $seeds; do
    for e in $errors; do
      scene=$work/$name-$seed-$e
      # shellcheck disable=SC2086
      "$bin" -q synth --city "$city" --lod "$lod" $rig --width 240 --height 180 --seed "$seed" --out "$scene" --gps "$e"
      model=$(ls "$scene"/city/ | grep -v '^transform' | head -1)
      start=$(date +%s.%N)
      if out=$("$bin" -q georef --scene "$scene" --city "$scene/city/$model" --lod "$lod" \
                 --truth "$scene/city/transform_true.json" --out "$scene/georef.json" --json 2>"$scene/georef.err"); then
        secs=$(python3 -c "import time; print(f'{time.time() - $start:.1f}')")
        rc=0
        python3 - "$name" "$seed" "$e" "$secs" "$out" <<'PY' || rc=$?
import json, sys
name, seed, err, secs, out = sys.argv[1:6]
j = json.loads(out)["error_to_truth"]
g, s, f = j["start"], j["searched"], j["final"]
ok = f["max_displacement"] <= 0.03 and f["rotation_deg"] <= 0.05
# Whether georef said it could not be trusted: a warning after ICP, or ICP refused.
warned = bool(json.loads(out).get("warnings")) or "icp_problem" in json.loads(out)
print(f'{name:<10} {seed:<4} {err:<36} {g["max_displacement"]:9.3f} {s["max_displacement"]:9.3f} '
      f'{f["max_displacement"]:9.4f} {f["rotation_deg"]:9.4f} {"yes" if ok else "NO":>6} {"yes" if warned else "-":>6} {secs:>7}')
sys.exit((0 if ok else 3) + (4 if warned else 0))
PY
      else
        printf '%-10s %-4s %-36s %9s %9s %9s %9s %6s\n' "$name" "$seed" "$e" "-" "-" "failed" "-" "NO"
        sed 's/^/    /' "$scene/georef.err" | tail -2
        rc=1
      fi
      # rc: 0 met, 3 missed, +4 when georef warned; 1 georef failed
      rows=$((rows + 1))
      case $rc in 0) ;; 4) warned_passes=$((warned_passes + 1)) ;; 7) fails=$((fails + 1)); warned_misses=$((warned_misses + 1)) ;; *) fails=$((fails + 1)) ;; esac
    done
  done
done
echo "$((rows - fails)) of $rows within 3 cm and 0.05 deg; georef warned on $warned_misses of the $fails misses and on $warned_passes of the rows that met the goal"
[ "$fails" = 0 ]  # the exit status says whether every scene met the goal
