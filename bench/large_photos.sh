#!/usr/bin/env bash
# Memory and time of `run` on many large photos (issue 34 §4: 200 photos of 4000x3000, as phones take
# them): synth renders 8 views of FZK-Haus LoD3 at 4000x3000, and the scene lists them N times (each view
# under N/8 names, the photos linked), so that every stage holds and processes N large photos. `run`
# trains at --max-side 1600 (1600x1200) and the language stages at --feature-height 1080 (1440x1080), a
# short schedule with the synthetic features; /usr/bin/time gives the peak resident memory, run.json each
# stage's time.
# What it shows: whether memory stays bounded with N photos of that size (what grows with N, and by how
# much), and the time per stage on this machine.
# What it does not: real CLIP/SAM (their weights cannot be downloaded here; SAM holds one photo at a time),
# quality (repeated views), a 30,000-iteration schedule (memory does not grow with iterations, time does).
#   bash bench/large_photos.sh [--work DIR] [--views N] [--width W --height H]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
bin=${CLS_BIN:-$repo/build/citylangsplat}
work=/tmp/cls-bench-large; views=200; width=4000; height=3000
while [ $# -gt 0 ]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --views) views=$2; shift 2 ;;
    --width) width=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    *) echo "usage: $0 [--work DIR] [--views N] [--width W --height H] (defaults: /tmp/cls-bench-large, 200, 4000 x 3000)" >&2; exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "large_photos.sh: $bin not found: build first (cmake --build build)" >&2; exit 1; }
if [ -e "$work" ] && [ ! -f "$work/.cls-bench-large" ]; then
  echo "large_photos.sh: $work exists and was not made by this script; pass another --work" >&2; exit 2
fi
rm -rf "$work" && mkdir -p "$work" && touch "$work/.cls-bench-large"
"$bin" -q synth --city data/citygml/fzk-haus/fzk_haus_lod3_v2.gml --lod 3 --views 8 --width "$width" \
  --height "$height" --seed 1 --out "$work/synth"
scene=$work/scene
mkdir -p "$scene/sparse/0" "$scene/images"
cp -r "$work/synth/city" "$work/synth/scene.json" "$scene/"
"$bin" -q scene convert "$work/synth" --out "$work/text" --format txt
# Each of the 8 views N/8 times (rounded up), under its own name, its photo linked.
python3 - "$work/text" "$scene" "$views" "$work/synth/images" <<'PY'
import os, sys
text, scene, n, photos = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
lines = [l for l in open(os.path.join(text, "images.txt")) if not l.startswith("#")]
base = [lines[i].split() for i in range(0, len(lines), 2)]
with open(os.path.join(scene, "sparse/0/images.txt"), "w") as out:
    for k in range(n):
        f = base[k % len(base)]
        name = f"{k:04d}_{f[9]}"
        out.write(" ".join([str(k + 1)] + f[1:9] + [name]) + "\n\n")
        os.symlink(os.path.join(photos, f[9]), os.path.join(scene, "images", name))
for f in ("cameras.txt", "points3D.txt"):
    with open(os.path.join(text, f)) as src, open(os.path.join(scene, "sparse/0", f), "w") as dst:
        dst.write(src.read())
PY
echo "scene: $views views of ${width}x${height} ($(ls "$scene/images" | wc -l) photos linked)"
/usr/bin/time -v "$bin" run "$scene" --models synthetic --rgb-iterations 100 --language-iterations 20 \
  --autoencoder-epochs 2 --out "$work/out" > "$work/run.log" 2> "$work/time.txt" || { tail -20 "$work/run.log" "$work/time.txt"; exit 1; }
grep -E "loaded at|language fields use" "$work/time.txt" || true
python3 - "$work/out/run.json" "$work/time.txt" <<'PY'
import json, re, sys
run = json.load(open(sys.argv[1]))
rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(sys.argv[2]).read())
wall = re.search(r"Elapsed \(wall clock\) time.*: (\S+)", open(sys.argv[2]).read())
print(f"peak resident memory: {int(rss.group(1)) / 1024 / 1024:.2f} GiB; wall {wall.group(1)}")
def stages(node, prefix=""):
    for k, v in node.items():
        if isinstance(v, dict) and "status" in v:
            yield prefix + k, v
        elif isinstance(v, dict):
            yield from stages(v, prefix + k + "/")
for name, v in stages(run):
    print(f"  {name:<32} {v.get('status', ''):<8} {v.get('seconds', 0):8.1f} s")
PY
