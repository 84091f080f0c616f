#!/usr/bin/env bash
# Set-up (packages + build, no example scene) and the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --no-example --slurm  # --slurm: the tiles test runs a private Slurm cluster
# ctest runs one test per core: each gets one thread unless the caller says otherwise (two 2-thread
# OpenMP processes on two cores spend their barriers waiting for each other's time slices).
# The core count is taken first: nproc itself obeys OMP_NUM_THREADS.
jobs=$(nproc)
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
cd build && ctest --output-on-failure --parallel "$jobs" --timeout 2400
