#!/usr/bin/env bash
# run-tiles on a real single-node Slurm (slurm_cluster.sh): a district of 8 LoD2 houses (the shared
# 100-building CityJSON cut to a 4 x 2 block) rendered by `synth --per-building`, cut into tiles,
# submitted as sbatch arrays; one running array task of the training phase is cancelled (scancel),
# the rerun submits only that task, then the tiles are merged (check_merge.py checks the seams from
# the PLYs) and the merged model is evaluated on the district's ground truth. Exit 77 (skipped) where
# Slurm cannot start.
#   bash slurm_tiles_test.sh BINARY WORK_DIR
set -euo pipefail
bin=$(readlink -f "$1")
work=$2
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
rm -rf "$work" && mkdir -p "$work"
work=$(readlink -f "$work")
cluster=$(mktemp -d /tmp/cls-slurm.XXXXXX)  # short: the munge socket path must stay < 108 bytes
trap 'bash "$here/slurm_cluster.sh" stop "$cluster"; rm -rf "$cluster"' EXIT
status=0
bash "$here/slurm_cluster.sh" start "$cluster" || status=$?
if [ "$status" -eq 77 ]; then
  echo "SKIPPED: Slurm cannot run here (see the line above; bash scripts/setup.sh --slurm installs it)"
  exit 77
fi
[ "$status" -eq 0 ] || { echo "FAIL: slurm_cluster.sh start exited $status"; exit 1; }
eval "$(bash "$here/slurm_cluster.sh" env "$cluster")"
sinfo

python3 "$here/cityjson_subset.py" "$repo/data/citygml/citygml4j/lod2_buildings_v2.json" --box 0,0,36,18 \
  --out "$work/district.city.json"
"$bin" -q synth --city "$work/district.city.json" --out "$work/district" --per-building --views 48 \
  --width 160 --height 120 --gt-density 50
"$bin" -q tile --scene "$work/district" --out "$work/tiles" --max-images 28 --min-share 0.2
tiles=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['tiles']))" "$work/tiles/tiles.json")
echo "tiles: $tiles"
[ "$tiles" -ge 2 ] || { echo "FAIL: expected several tiles, got $tiles"; exit 1; }
# Every image belongs to the tile whose cell its camera stands in (camera centre -R^T t from the
# district's images.txt, computed here, not by the code under test).
python3 - "$work/district/sparse/0/images.txt" "$work/tiles/tiles.json" <<'PY'
import json, sys
lines = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
tiles = json.load(open(sys.argv[2]))["tiles"]
inf = float("inf")
def inside(cell, x, y):
    x0, y0, x1, y1 = [(-inf if i < 2 else inf) if v is None else v for i, v in enumerate(cell)]
    return x0 <= x < x1 and y0 <= y < y1
for f in lines[0::2]:
    qw, qx, qy, qz, tx, ty, tz = map(float, f[1:8])
    R = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
         [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
         [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]
    c = [-(R[0][i] * tx + R[1][i] * ty + R[2][i] * tz) for i in range(3)]
    owners = [t["name"] for t in tiles if inside(t["cell"], c[0], c[1])]
    if len(owners) != 1 or f[9] not in next(t for t in tiles if t["name"] == owners[0])["images"]:
        sys.exit(f"FAIL: image {f[9]} (camera at {c[0]:.2f}, {c[1]:.2f}) is not in the tile whose cell holds it: {owners}")
print(f"every camera is in its cell's tile ({len(lines) // 2} images)")
PY

options=(--models synthetic --rgb-iterations 200 --language-iterations 40 --autoencoder-epochs 10 --baseline none)
"$bin" run-tiles "$work/tiles" --executor slurm --array-limit 2 "${options[@]}"
train=$(python3 -c "import json,sys; print([j['id'] for j in json.load(open(sys.argv[1])) if j['phase'] == 'train'][0])" \
  "$work/tiles/jobs/submitted.json")
# Cancel the second training task once it runs (its pipeline stops at SIGTERM, leaving no marker).
victim=""
for _ in $(seq 600); do
  victim=$(squeue -h -j "$train" -t RUNNING -o "%i" | grep -E "^${train}_1$" || true)
  [ -n "$victim" ] && break
  sleep 1
done
[ -n "$victim" ] || { echo "FAIL: array task ${train}_1 never ran"; squeue -t all; exit 1; }
# Cancel it inside its photometric training (which checkpoints on SIGTERM): RUNNING in squeue can come well
# before the pipeline gets there on a loaded machine.
for _ in $(seq 600); do
  grep -q "^train-rgb: " "$work/tiles/logs/train_1.log" 2>/dev/null && break
  sleep 1
done
grep -q "^train-rgb: " "$work/tiles/logs/train_1.log" || { echo "FAIL: task 1 never reached train-rgb"; exit 1; }
sleep 1
scancel "$victim"
echo "cancelled $victim"
while [ -n "$(squeue -h -o %i)" ]; do sleep 2; done
grep -q "^train_1.json$" <(ls "$work/tiles/status") && { echo "FAIL: task 1 finished before it could be cancelled"; exit 1; }
echo "--- the queue after the first submission (squeue -t all):"
squeue -t all -o "%.12i %.16j %.10T %.8M %r"
echo "--- job completions (jobcomp/filetxt: no slurmdbd, so no sacct):"
cut -d' ' -f1-2,4,6-7 "$cluster/jobcomp.txt" 2>/dev/null | sed 's/^/  /' || true
if "$bin" tiles status "$work/tiles"; then echo "FAIL: every task finished although one was cancelled"; exit 1; fi

# The rerun submits only what is missing: the training task that was cancelled.
"$bin" run-tiles "$work/tiles" --executor slurm --wait "${options[@]}" 2>&1 | tee "$work/rerun.log"
python3 - "$work/tiles/jobs/submitted.json" <<'PY'
import json, sys
jobs = json.load(open(sys.argv[1]))
if [(j["phase"], j["array"]) for j in jobs] != [("train", "1")]:
    sys.exit(f"FAIL: the rerun submitted {jobs}, not the train phase's task 1 alone")
PY
grep -q "train: job [0-9]* (array 1)" "$work/rerun.log" || { echo "FAIL: the rerun's array is not task 1 alone"; exit 1; }
"$bin" tiles status "$work/tiles"
# The cancelled task stopped at a checkpoint (SIGTERM) and its rerun went on from there.
grep -q "resuming at" "$work/tiles/logs/train_1.log" ||
  { echo "FAIL: the rerun of task 1 did not resume a checkpoint"; cat "$work/tiles/logs/train_1.log"; exit 1; }

"$bin" merge "$work/tiles" --out "$work/merged"
/usr/bin/python3 "$here/check_merge.py" --tiles "$work/tiles" --merged "$work/merged"
"$bin" -q evaluate --scene "$work/district" --model tiled="$work/merged/language/citylangsplat" --out "$work/eval"
python3 - "$work/eval/eval.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]["tiled"]
print(f"merged model: 2D mIoU {100 * r['2d']['miou']:.2f}, 3D mIoU {100 * r['3d']['miou']:.2f} "
      f"(best labelling of its Gaussians {100 * r['3d']['best_labelling']['miou']:.2f})")
# A merge that scrambled latents or Gaussians scores near chance (1 / 3 classes); the bench
# (bench/tiles.sh) compares with an untiled run.
if not r["3d"]["miou"] > 0.4:
    sys.exit("FAIL: the merged model's 3D mIoU is below 40%")
PY
echo "PASS"
