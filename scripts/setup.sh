#!/usr/bin/env bash
# One-command set-up on a fresh Debian 12 machine: installs the Debian packages the project needs
# (idempotent), configures and builds into build/, installs the viewer page's npm packages
# (scripts/install_web.sh) and generates the bundled example scene.
#   bash scripts/setup.sh [--no-example] [--slurm] [--slurm-accounting]
# --slurm also installs Slurm and MUNGE for the tests that run a private cluster
# (tests/tiles/slurm_cluster.sh); without them those tests are skipped.
# --slurm-accounting installs what --slurm does plus slurmdbd and MariaDB, for
# `slurm_cluster.sh start DIR --accounting` (a private cluster with sacct).
set -euo pipefail
cd "$(dirname "$0")/.."

EXAMPLE=1; SLURM=0; SLURM_ACCOUNTING=0
for arg in "$@"; do
  case $arg in
    --no-example) EXAMPLE=0 ;;
    --slurm) SLURM=1 ;;
    --slurm-accounting) SLURM=1; SLURM_ACCOUNTING=1 ;;
    *) echo "usage: $0 [--no-example] [--slurm] [--slurm-accounting]" >&2; exit 2 ;;
  esac
done

PACKAGES=(build-essential cmake ninja-build pkg-config
          libembree-dev libpugixml-dev nlohmann-json3-dev libopencv-dev libglu1-mesa-dev
          libgtest-dev libtorch-dev libopenblas0-pthread libcurl4-openssl-dev zlib1g-dev libicu-dev
          libcpp-httplib-dev                                          # the viewer's server
          libexiv2-dev libproj-dev                                    # the photos' EXIF GPS, in the model's CRS
          chromium chromium-driver python3-selenium python3-pil      # the browser tests (report, viewer)
          python3-jsonschema)                                         # enrich's CityJSON against the official schemas
# npm installs the viewer page's packages (three, Spark); Debian's when no npm is on the PATH.
command -v npm >/dev/null 2>&1 || PACKAGES+=(npm)
[ "$SLURM" = 0 ] || PACKAGES+=(slurm-wlm munge)
[ "$SLURM_ACCOUNTING" = 0 ] || PACKAGES+=(slurmdbd mariadb-server)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO=sudo
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"
bash scripts/install_web.sh

if [ "$EXAMPLE" = 1 ]; then
  bash scripts/make_example.sh
fi
