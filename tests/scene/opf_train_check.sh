#!/usr/bin/env bash
# An OPF project through `scene info` and `train-rgb` (issue 34 §3): the viewer's sample scene (COLMAP)
# written as an OPF 1.0 project by colmap_to_opf.py (which follows the specification, not our reader),
# then read back: the same views and tie points, and train-rgb from it must reach the COLMAP scene's
# held-out PSNR and SSIM to within 0.01 (the same cameras, points and colours give the same training).
#   bash tests/scene/opf_train_check.sh CITYLANGSPLAT SCENE OUT
set -euo pipefail
BIN=$1 SCENE=$2 OUT=$3
rm -rf "$OUT" && mkdir -p "$OUT"
"$BIN" -q scene convert "$SCENE" --out "$OUT/txt" --format txt
/usr/bin/python3 "$(dirname "$0")/colmap_to_opf.py" --colmap "$OUT/txt" --images "$SCENE/images" --out "$OUT/opf"
"$BIN" scene info "$OUT/opf" | tee "$OUT/info.txt"
views=$(grep -c '\.png$' "$OUT/txt/images.txt" || true)
points=$(grep -vc '^#' "$OUT/txt/points3D.txt")
grep -q "^views: *$views\$" "$OUT/info.txt" || { echo "FAIL: scene info does not list the $views views"; exit 1; }
grep -q "^points: *$points\$" "$OUT/info.txt" || { echo "FAIL: scene info does not list the $points tie points"; exit 1; }
for s in colmap opf; do
  src=$SCENE; [ $s = opf ] && src=$OUT/opf
  "$BIN" train-rgb --scene "$src" --out "$OUT/rgb_$s" --iterations 100 2>&1 | tail -1 | tee "$OUT/$s.txt"
done
/usr/bin/python3 - "$OUT/colmap.txt" "$OUT/opf.txt" <<'PY'
import re, sys
a, b = (re.search(r"test PSNR ([\d.]+) dB, SSIM ([\d.]+)", open(f).read()).groups() for f in sys.argv[1:3])
ok = all(abs(float(x) - float(y)) <= 0.01 for x, y in zip(a, b))
print(f"train-rgb, 100 iterations: COLMAP {a[0]} dB / SSIM {a[1]}, the same scene as OPF {b[0]} dB / SSIM {b[1]}: "
      + ("PASS" if ok else "FAIL"))
sys.exit(0 if ok else 1)
PY
