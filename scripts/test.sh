#!/usr/bin/env bash
# Set-up (packages + build, no example scene) and the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --no-example --slurm  # --slurm: the tiles test runs a private Slurm cluster
cd build && ctest --output-on-failure --parallel "$(nproc)" --timeout 2400
