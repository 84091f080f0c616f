#!/usr/bin/env bash
# Builds, on this machine, the CUDA build that scripts/device/gpu_checks.sh runs on a lent GPU machine,
# and packs it with the libraries that machine lacks into .gpu/bundle.tar.xz (scripts/device/README.md).
#   bash scripts/device/prepare.sh DUMP_DIR [BUILD_DIR] [TORCH_DIR]
# DUMP_DIR: what the device call of the README wrote (ti.tar.xz.*, syms.txt.xz, ldconfig.txt).
# BUILD_DIR (default ../gpubuild) and TORCH_DIR (default ../torchgpu: the device torch's headers and
# link stubs) sit beside the checkout.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
DUMP=$(cd "$1" && pwd)
BUILD=${2:-$ROOT/../gpubuild}
TORCH=${3:-$ROOT/../torchgpu}
HERE=$ROOT/scripts/device
mkdir -p "$TORCH" "$BUILD"
BUILD=$(cd "$BUILD" && pwd) TORCH=$(cd "$TORCH" && pwd)
if [ ! -d "$TORCH/include" ]; then
  cat "$DUMP"/ti.tar.xz.* | tar -xJf - -C "$TORCH"
fi
if [ ! -f "$TORCH/lib/libtorch_cpu.so" ]; then
  xz -dc "$DUMP/syms.txt.xz" > "$TORCH/syms.txt"
  python3 "$HERE/elf_stubs.py" from-dump "$TORCH/syms.txt" "$TORCH/lib"
  # The targets of torch's CMake files also name this one; nothing here calls into it.
  echo "" | gcc -shared -nostdlib -x c - -o "$TORCH/lib/libtorch_nvshmem.so" -Wl,-soname,libtorch_nvshmem.so
fi
# Debian's torch (1.13, CPU) is found first unless every torch path is given.
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCLS_SHARED_LIBS=ON -DCLS_TORCH_PCH=ON \
  -DTorch_DIR="$TORCH/share/cmake/Torch" -DCaffe2_DIR="$TORCH/share/cmake/Caffe2" \
  -DTORCH_LIBRARY="$TORCH/lib/libtorch.so" -Dc10_LIBRARY="$TORCH/lib/libc10.so" \
  -DC10_CUDA_LIBRARY="$TORCH/lib/libc10_cuda.so" -Dkineto_LIBRARY=IGNORE \
  -DTORCH_CUDA_ARCH_LIST=9.0 -DCMAKE_CUDA_ARCHITECTURES=90 > "$BUILD/configure.log"
# What gpu_checks.sh runs (each test program that includes torch costs ~40 s to compile here).
TARGETS=${GPU_TARGETS:-citylangsplat test_splat test_models test_query test_language bench_splat bench_clip bench_language bench_query bench_amg}
ninja -C "$BUILD" $TARGETS
STAGE=$(mktemp -d)
mkdir -p "$STAGE/build/bench" "$STAGE/lib"
cp "$BUILD"/lib*.so "$STAGE/build/"
for t in $TARGETS; do
  case $t in bench_*) cp "$BUILD/bench/$t" "$STAGE/build/bench/" ;; *) cp "$BUILD/$t" "$STAGE/build/" ;; esac
done
python3 "$HERE/runtime_bundle.py" "$STAGE/lib" "$DUMP/ldconfig.txt" $(find "$STAGE/build" -type f)
echo "$ROOT $BUILD" > "$STAGE/paths.txt"
mkdir -p "$ROOT/.gpu"
tar -C "$STAGE" -cf - . | xz -T0 -9 > "$ROOT/.gpu/bundle.tar.xz"
rm -rf "$STAGE"
ls -l "$ROOT/.gpu/bundle.tar.xz"
