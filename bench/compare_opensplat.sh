#!/usr/bin/env bash
# train-rgb beside OpenSplat, the CPU peer (docs/benchmarks.md, "train-rgb vs OpenSplat"). For each size:
# one synthetic scene of the bundled example's city model (synth), every 8th view by name held out;
# OpenSplat gets a binary COLMAP model (`scene convert`) of the training views only, so both train on the
# same views. Both run the same iterations at full resolution, one after the other in this job, each timed
# as a whole process (wall, CPU, peak memory); then OUR renderer renders both PLYs on the held-out views.
# OpenSplat 1.1.5 is built once from its unmodified sources by ../shared/bench/opensplat/build.sh (a
# benchmark peer only: its code is never copied or linked).
# What it shows: wall time, ms/iteration, Gaussians and held-out PSNR/SSIM of both, and the wall ratio.
# What it does not: GPU speed, a real capture (synthetic scene), or equal schedules in every detail
# (--help and docs/benchmarks.md list what differs).
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)

iterations=600; sizes=480x360,960x720; views=28; work=/tmp/compare_opensplat; keep=0; densify_from=500
usage() {
  cat <<EOF
usage: bash bench/compare_opensplat.sh [options]

Times citylangsplat train-rgb and OpenSplat (CPU, --num-downscales 0) on the same synthetic scene,
same training views, same iterations, one after the other, and renders both models with our renderer
on the held-out views (every 8th by name). Prints a table per size and a summary at the end.

options:
  --iterations N     training iterations of both (default: $iterations)
  --sizes LIST       comma-separated WxH image sizes, one scene each (default: $sizes)
  --views N          views of each synthetic scene (default: $views)
  --densify-from N   densification warm-up of both: train-rgb --densify-from, OpenSplat
                     --warmup-length (default: $densify_from, both programs' default)
  --work DIR         work directory; OpenSplat is built once into DIR/opensplat (default: $work)
  --keep             keep the scenes, models and renders (default: only logs and summary.md stay)
  -h, --help         show this help

environment:
  CLS_BIN            citylangsplat binary (default: build/citylangsplat, relative to the repo root)
  OPENSPLAT_BIN      an already built opensplat binary (default: DIR/opensplat/build/opensplat,
                     built by ../shared/bench/opensplat/build.sh when missing)

Schedules: OpenSplat stops densifying at half the iterations (hard-coded), so train-rgb gets
--densify-until N/2; both densify every 100 iterations after the warm-up, raise the SH degree every
1000 iterations and use L1 + 0.2 D-SSIM. Neither densifies unless N/2 > warm-up + 100 (the default
600 iterations compare both at the initial Gaussians; try --densify-from 100). What still differs: OpenSplat composites over a fixed
background (0.613, 0.010, 0.398) and its position learning rate is relative to its normalised frame;
train-rgb uses black and the 3DGS scene extent (the run prints both in scene units).
EOF
}
die() { echo "compare_opensplat: $*" >&2; exit 1; }
while [ $# -gt 0 ]; do
  case $1 in
    --iterations) iterations=${2:?--iterations needs a value}; shift 2 ;;
    --sizes) sizes=${2:?--sizes needs a value}; shift 2 ;;
    --views) views=${2:?--views needs a value}; shift 2 ;;
    --densify-from) densify_from=${2:?--densify-from needs a value}; shift 2 ;;
    --work) work=${2:?--work needs a value}; shift 2 ;;
    --keep) keep=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
  esac
done
[[ $iterations =~ ^[1-9][0-9]*$ ]] || die "--iterations must be a positive integer, not '$iterations'"
if ! [[ $views =~ ^[1-9][0-9]*$ ]] || [ "$views" -lt 2 ]; then die "--views must be an integer >= 2, not '$views'"; fi
[[ $densify_from =~ ^[0-9]+$ ]] || die "--densify-from must be an integer >= 0, not '$densify_from'"
IFS=, read -r -a size_list <<< "$sizes"
for s in "${size_list[@]}"; do
  [[ $s =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || die "--sizes: '$s' is not WxH (e.g. 480x360)"
done

bin=${CLS_BIN:-build/citylangsplat}
case $bin in /*) ;; *) bin=$repo/$bin ;; esac
[ -x "$bin" ] || die "$bin not found or not executable: build citylangsplat or set CLS_BIN"
command -v python3 >/dev/null || die "python3 not found (it reads the COLMAP text model and the results)"
[ -x /usr/bin/time ] || die "/usr/bin/time not found (GNU time: apt-get install time)"
# shellcheck source=../examples/fzk-haus/synth.conf
source examples/fzk-haus/synth.conf
[ -f "$CITY" ] || die "$repo/$CITY not found (the bundled example's city model)"

mkdir -p "$work"
work=$(readlink -f "$work")
opensplat=${OPENSPLAT_BIN:-$work/opensplat/build/opensplat}
if [ ! -x "$opensplat" ]; then
  [ -z "${OPENSPLAT_BIN:-}" ] || die "OPENSPLAT_BIN=$OPENSPLAT_BIN is not executable"
  builder=$repo/../shared/bench/opensplat/build.sh
  [ -f "$builder" ] || die "$builder not found (it builds the peer from its unmodified sources)"
  echo "building OpenSplat into $work/opensplat (once; log: $work/opensplat-build.log)"
  bash "$builder" "$work/opensplat" > "$work/opensplat-build.log" 2>&1 \
    || { tail -20 "$work/opensplat-build.log" >&2; die "the OpenSplat build failed (log: $work/opensplat-build.log)"; }
  [ -x "$opensplat" ] || die "the OpenSplat build did not produce $opensplat"
fi
os_version=$("$opensplat" --version 2>/dev/null | tail -1 || true)

summary=$work/summary.md
{
  echo "# train-rgb vs OpenSplat, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo
  echo "- machine: $(nproc) cores, $(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)"
  echo "- citylangsplat: $bin ($("$bin" --version 2>/dev/null | head -1 || true))"
  echo "- OpenSplat: $opensplat (version ${os_version:-unknown})"
  echo "- $iterations iterations, $views views per scene (every 8th by name held out), densification warm-up $densify_from"
  echo
} > "$summary"

# Runs a command with GNU time (wall s, user s, sys s, max RSS KiB into TIMEFILE), output into LOG.
timed() {
  local timefile=$1 log=$2; shift 2
  /usr/bin/time -f '%e %U %S %M' -o "$timefile" "$@" > "$log" 2>&1
}

for size in "${size_list[@]}"; do
  width=${size%x*}; height=${size#*x}
  run=$work/$size
  rm -rf "$run" && mkdir -p "$run"
  echo "== $size: $views views, $iterations iterations ($run)"

  "$bin" -q synth --city "$CITY" --lod "$LOD" --seed "$SEED" --views "$views" --width "$width" --height "$height" \
    --out "$run/scene"

  # OpenSplat's own hold-out is one image (--val); instead it gets a model of the training views only,
  # the ones train-rgb trains on (every 8th view sorted by name held out). All sparse points stay, so
  # both start from the same points; track entries of the held-out images are dropped.
  python3 - "$run/scene/sparse/0" "$run/opensplat_txt/sparse/0" "$run/split.json" <<'PY'
import json, os, sys
src, dst, split_path = sys.argv[1:]
os.makedirs(dst)
lines = open(f"{src}/images.txt").read().splitlines()
header = [l for l in lines if l.startswith("#")]
body = [l for l in lines if not l.startswith("#")]
images = [(body[i], body[i + 1] if i + 1 < len(body) else "") for i in range(0, len(body), 2) if body[i].strip()]
names = sorted(l.split()[9] for l, _ in images)
test = {n for i, n in enumerate(names) if i % 8 == 0}
keep, dropped_ids, centres = [], set(), []
for l, pts in images:
    f = l.split()
    if f[9] in test:
        dropped_ids.add(f[0]); continue
    keep.append((l, pts))
    qw, qx, qy, qz, tx, ty, tz = map(float, f[1:8])
    # camera centre C = -R^T t (R from the world-to-camera quaternion)
    R = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qw * qz), 2 * (qx * qz + qw * qy)],
         [2 * (qx * qy + qw * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qw * qx)],
         [2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)]]
    centres.append([-sum(R[r][c] * t for r, t in zip(range(3), (tx, ty, tz))) for c in range(3)])
with open(f"{dst}/images.txt", "w") as o:
    o.write("\n".join(h for h in header if not h.startswith("# Number of images")) + "\n")
    for l, pts in keep:
        o.write(l + "\n" + pts + "\n")
with open(f"{dst}/points3D.txt", "w") as o:
    for l in open(f"{src}/points3D.txt"):
        if l.startswith("#"):
            if not l.startswith("# Number of points"): o.write(l)
            continue
        f = l.split()
        track = [(f[i], f[i + 1]) for i in range(8, len(f), 2) if f[i] not in dropped_ids]
        o.write(" ".join(f[:8] + [x for p in track for x in p]) + "\n")
with open(f"{dst}/cameras.txt", "w") as o:
    o.write(open(f"{src}/cameras.txt").read())
# OpenSplat normalises the training cameras: centre = their mean, scale = 1 / max |coordinate offset|;
# its position learning rate (0.00016 -> 0.0000016) is in that frame.
mean = [sum(c[k] for c in centres) / len(centres) for k in range(3)]
spread = max(abs(c[k] - mean[k]) for c in centres for k in range(3))
json.dump({"train": sorted(l.split()[9] for l, _ in keep), "test": sorted(test),
           "opensplat_scale": 1.0 / spread, "opensplat_centre": mean}, open(split_path, "w"), indent=1)
print(f"split: {len(keep)} training views, {len(test)} held out ({', '.join(sorted(test))})")
PY
  "$bin" -q scene convert "$run/opensplat_txt" --out "$run/opensplat_scene/sparse/0" --format bin
  mkdir -p "$run/opensplat_scene/images"
  python3 -c "import json,sys; print('\n'.join(json.load(open(sys.argv[1]))['train']))" "$run/split.json" \
    | while read -r name; do cp "$run/scene/images/$name" "$run/opensplat_scene/images/"; done

  echo "train-rgb: $(date -u +%H:%M:%S) UTC, load average $(cut -d' ' -f1-3 /proc/loadavg) (log: $run/train-rgb.log)"
  timed "$run/train-rgb.time" "$run/train-rgb.log" "$bin" train-rgb --scene "$run/scene" --out "$run/train-rgb" \
    --iterations "$iterations" -r 1 --densify-from "$densify_from" --densify-until $((iterations / 2)) \
    --checkpoint-every 0 \
    || { tail -20 "$run/train-rgb.log" >&2; die "train-rgb failed (log: $run/train-rgb.log)"; }
  echo "OpenSplat: $(date -u +%H:%M:%S) UTC, load average $(cut -d' ' -f1-3 /proc/loadavg) (log: $run/opensplat.log)"
  mkdir -p "$run/opensplat"
  # --keep-crs: the PLY is written in the input frame (means / scale + centre, log-scales - log scale);
  # the normalisation has no rotation, so this is the exact inverse similarity.
  timed "$run/opensplat.time" "$run/opensplat.log" "$opensplat" "$run/opensplat_scene" --cpu -n "$iterations" \
    --num-downscales 0 --warmup-length "$densify_from" --keep-crs -o "$run/opensplat/splat.ply" \
    || { tail -20 "$run/opensplat.log" >&2; die "OpenSplat failed (log: $run/opensplat.log)"; }
  # OpenSplat reports "Wrote" even when it could not open the output file.
  [ -s "$run/opensplat/splat.ply" ] || die "OpenSplat wrote no $run/opensplat/splat.ply (log: $run/opensplat.log)"
  echo "rendering both PLYs on the held-out views with citylangsplat render"
  for m in train-rgb:"$run/train-rgb/point_cloud.ply" opensplat:"$run/opensplat/splat.ply"; do
    name=${m%%:*}; ply=${m#*:}
    if ! "$bin" -q render "$ply" --scene "$run/scene" --out "$run/render-$name" --views test --what rgb \
        > "$run/render-$name.log" 2>&1; then
      echo "compare_opensplat: rendering $name's PLY failed; its PSNR is left out. The error:" >&2
      cat "$run/render-$name.log" >&2
    fi
  done

  python3 - "$run" "$size" "$iterations" "$summary" <<'PY'
import json, os, sys
run, size, iterations, summary = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
split = json.load(open(f"{run}/split.json"))
def gaussians(ply):
    with open(ply, "rb") as f:
        for line in f:
            if line.startswith(b"element vertex"): return int(line.split()[2])
            if line.startswith(b"end_header"): break
    raise SystemExit(f"{ply}: no 'element vertex' in the header")
rows, notes = [], []
for name, ply in (("train-rgb", f"{run}/train-rgb/point_cloud.ply"), ("OpenSplat", f"{run}/opensplat/splat.ply")):
    key = name.lower()
    wall, user, sys_, rss = open(f"{run}/{key}.time").read().split()[-4:]
    r = {"name": name, "wall": float(wall), "cpu": float(user) + float(sys_), "rss": int(rss) / 1024,
         "gaussians": gaussians(ply), "psnr": None, "ssim": None}
    rj = f"{run}/render-{key}/render.json"
    if os.path.exists(rj):
        j = json.load(open(rj))
        names = sorted(v["name"] for v in j["views"])
        if names != split["test"]:
            raise SystemExit(f"{rj}: rendered views {names} are not the held-out views {split['test']}")
        r["psnr"], r["ssim"] = j["mean_psnr"], j["mean_ssim"]
    rows.append(r)
cls, osp = rows
s = json.load(open(f"{run}/train-rgb/summary.json"))
fmt = lambda v, f: "failed" if v is None else format(v, f)
out = [f"## {size}: {len(split['train'])} training views, {len(split['test'])} held out "
       f"({', '.join(split['test'])}), {iterations} iterations", "",
       "| trainer | wall (s) | ms/iteration (wall / iterations) | CPU (s) | peak RSS (MiB) | Gaussians | held-out PSNR (dB) | SSIM |",
       "|---|---:|---:|---:|---:|---:|---:|---:|"]
for r in rows:
    out.append(f"| {r['name']} | {r['wall']:.1f} | {1000 * r['wall'] / iterations:.0f} | {r['cpu']:.1f} | {r['rss']:.0f} | "
               f"{r['gaussians']:,} | {fmt(r['psnr'], '.2f')} | {fmt(r['ssim'], '.4f')} |")
out += ["", f"ratio OpenSplat / train-rgb: wall {osp['wall'] / cls['wall']:.2f}x, CPU time {osp['cpu'] / cls['cpu']:.2f}x",
        f"(train-rgb's own loop timing: {s['ms_per_iteration']:.0f} ms/iteration; position learning rate in scene units "
        f"at the start: train-rgb {0.00016 * s['extent']:.5f} (0.00016 x extent {s['extent']:.2f}), "
        f"OpenSplat {0.00016 / split['opensplat_scale']:.5f} (0.00016 / its scale {split['opensplat_scale']:.4f}))", ""]
print("\n".join(out))
with open(summary, "a") as f:
    f.write("\n".join(out) + "\n")
PY
  if [ "$keep" = 0 ]; then
    find "$run" -mindepth 1 -maxdepth 1 ! -name '*.log' ! -name '*.time' ! -name split.json -exec rm -rf {} +
  fi
done

echo
echo "==================== summary ($summary) ===================="
cat "$summary"
