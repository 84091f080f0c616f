#!/usr/bin/env bash
# The GPU checks, on a lent device machine, in a copy of this repository that carries .gpu/ (made by
# scripts/device/prepare.sh). Appends every step's output to $OUT/gpu.log and prints one line per step.
#   bash scripts/device/gpu_checks.sh [STEP...] [debug PROGRAM ARGS...]   (default: the steps of ALL, in order)
# Steps: splat_tests (the CUDA rasterizer against the CPU path), query_tests (relevance cosines on CUDA
# against the CPU path), language_tests (the language loss's CUDA kernel against its reference),
# models_tests (CLIP/SAM fixture parity on CUDA), bench_* (rasterizer, CLIP, language field, relevance
# maps, SAM AMG on the GPU; the sparse field's training iterations and maps too), run (`run --models
# clip-tiny` on the bundled example), query_gpu (after run: `query --device cuda` on its model against
# run's CPU query, scripts/device/compare_query.py), train_rgb
# (densification, the cap and resuming on the GPU), suite (every test program carried, 16 at a time, one
# OpenMP thread each), profile_splat / profile_language (every kernel's duration under Nsight Compute: one
# photometric and 128-channel iteration at 1M Gaussians, 1600x1000; one language iteration at 200k,
# 800x600 and a 1080p relevance map; profile_query: relevance_maps at 1080p as `query` calls it;
# $OUT/ncu_*.csv).
# GPU_LIB_OVERRIDE=DIR: libraries in DIR (e.g. an earlier commit's libcls.so) load before the build's,
# so one call can time before and after on the same machine.
set -uo pipefail
ROOT=$PWD
LOG=${OUT:-/tmp}/gpu.log
mkdir -p /tmp/gpu && tar -xJf .gpu/bundle.tar.xz -C /tmp/gpu || exit 1
# The build's compiled-in paths (fixtures, the CLI for CLI tests, the tokenizer's data) name the
# source and build folders of the machine that built it: the same paths point here.
read -r SRC BLD < /tmp/gpu/paths.txt
mkdir -p "$(dirname "$SRC")" "$(dirname "$BLD")"
[ -e "$SRC" ] || ln -s "$ROOT" "$SRC"
if [ -e "$BLD" ] && [ ! -L "$BLD" ]; then echo "gpu_checks: $BLD exists and is not a link: cannot place the build there" >&2; exit 1; fi
ln -sfn /tmp/gpu/build "$BLD"
TORCH=$(cd / && python3 -c 'import torch, os; print(os.path.dirname(torch.__file__))')
export LD_LIBRARY_PATH=${GPU_LIB_OVERRIDE:+$GPU_LIB_OVERRIDE:}$BLD:/tmp/gpu/lib:$TORCH/lib:$TORCH/../nvidia/cu13/lib:/usr/local/cuda/lib64
[ -z "${GPU_LIB_OVERRIDE:-}" ] || { echo; echo "=== GPU_LIB_OVERRIDE=$GPU_LIB_OVERRIDE: $(cd "$GPU_LIB_OVERRIDE" && ls)"; } >> "$LOG"
B=$BLD
SUMMARY=()
make_example() {  # the bundled example scene in /tmp/example, once per call
  [ -d /tmp/example ] || step make_example 60 env CITYLANGSPLAT="$B/citylangsplat" bash scripts/make_example.sh /tmp/example
}
step() {  # step NAME LIMIT_S COMMAND...
  local name=$1 limit=$2 t0 rc
  shift 2
  t0=$EPOCHREALTIME
  { echo; echo "=== $name: $*"; } >> "$LOG"
  timeout "$limit" "$@" >> "$LOG" 2>&1
  rc=$?
  SUMMARY+=("$(awk -v n="$name" -v rc=$rc -v t0="$t0" -v t1="$EPOCHREALTIME" \
    'BEGIN { printf "%-28s rc=%-3s %7.1f s", n, rc, t1 - t0 }')")
  echo "${SUMMARY[-1]}"
}

{ nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.sm --format=csv; nproc
  ldd "$B/citylangsplat" "$B"/test_* "$B"/bench/bench_* | grep "not found"; } >> "$LOG" 2>&1
# Each case is one step; the default order puts what matters most first, so that a call cut short
# by its time limit still brings back the rest's log.
ALL=(splat_tests query_tests language_tests bench_splat models_tests bench_clip_bf16 bench_language bench_query run bench_amg
     amg_fixture bench_clip_other bench_splat_200k)
# `gpu_checks.sh debug PROGRAM ARGS...`: PROGRAM of the build under cuda-gdb (the machine has no gdb),
# its backtrace where it stops; after the steps named before `debug`, which takes the rest of the line.
steps=() debug=()
while [ $# -gt 0 ]; do
  if [ "$1" = debug ]; then
    shift
    debug=("$@")
    break
  fi
  steps+=("$1")
  shift
done
[ ${#steps[@]} -gt 0 ] || [ ${#debug[@]} -gt 0 ] || steps=("${ALL[@]}")
for s in "${steps[@]}"; do
  case " ${ALL[*]} query_gpu train_rgb suite profile_splat profile_language profile_query " in
    *" $s "*) ;;
    *) echo "gpu_checks: unknown step $s (steps: ${ALL[*]} query_gpu train_rgb suite profile_splat profile_language" \
         "profile_query)" >&2
       exit 2 ;;
  esac
done
for s in "${steps[@]}"; do
  case $s in
    splat_tests) step "$s" 90 "$B/test_splat" --gtest_filter='*Cuda*:*CUDA*' ;;
    query_tests) step "$s" 60 "$B/test_query" --gtest_filter='*Cuda*' ;;
    language_tests) step "$s" 60 "$B/test_language" --gtest_filter='*Cuda*' ;;
    models_tests)
      step "$s" 150 env CLS_TEST_DEVICE=cuda "$B/test_models" \
        --gtest_filter='ClipParity*:ClipModel.ReducedPrecision*:SamPredictor.*:SamAmgRun.*' ;;
    bench_splat)
      step "$s" 90 "$B/bench/bench_splat" --device cuda --threads 16 --gaussians 1000000 --width 1600 --height 1000 \
        --iters 10 ;;
    bench_splat_200k) step "$s" 45 "$B/bench/bench_splat" --device cuda --threads 16 --iters 10 ;;
    bench_clip_bf16) step "$s" 45 "$B/bench/bench_clip" --device cuda --dtype bfloat16 --batch 256 --batches 5 --texts 512 \
      --threads 16 ;;
    bench_clip_other)
      for dt in float16 float32; do
        step "bench_clip_$dt" 45 "$B/bench/bench_clip" --device cuda --dtype $dt --batch 256 --batches 5 --texts 512 \
          --threads 16
      done ;;
    bench_language)
      step "$s" 180 "$B/bench/bench_language" --device cuda --threads 16 --repeats 10 --blend-cache off \
        --train-scenes 50000@480x360,200000@800x600,1000000@1600x1000 --loss l1,dense,seg,sparse,sparse-warmup,sparse-cosine,sparse-cosine-warmup \
        --query-scene 200000@1920x1080 --matmul-precision highest,high
      step bench_language_chunk256k 60 "$B/bench/bench_language" --device cuda --threads 16 --repeats 10 \
        --train-scenes none --query-scene 200000@1920x1080 --chunk 262144 ;;
    bench_query)  # relevance_maps as `query` calls it, 1080p, per decode chunk (0: the device's default)
      for c in 8192 65536 0 1048576; do
        step "bench_query_chunk$c" 90 "$B/bench/bench_query" --device cuda --threads 16 --sizes 1920x1080 --iters 5 --chunk $c
      done
      # the sparse field (issue 36): K = 4 of 64 bases through the sparse kernels
      step bench_query_sparse 90 "$B/bench/bench_query" --device cuda --threads 16 --sizes 1920x1080 --iters 5 --field sparse ;;
    bench_amg) step "$s" 120 "$B/bench/bench_amg" --device cuda --masks '' --model vit_h --threads 16 ;;
    amg_fixture)
      step "$s" 90 "$B/bench/bench_amg" --device cuda --masks '' --fixture "$ROOT/tests/fixtures/sam" --threads 16 ;;
    run)
      make_example
      step run_tiny 300 "$B/citylangsplat" run /tmp/example --models clip-tiny
      cat /tmp/example/citylangsplat/run.json >> "$LOG" 2>&1 ;;
    query_gpu)  # `query --device cuda` on the run step's model, against the query that run made on the CPU
      Q=/tmp/example/citylangsplat/query/citylangsplat
      if [ ! -f "$Q/query.json" ]; then
        echo "gpu_checks: query_gpu needs the run step first (no $Q/query.json)" | tee -a "$LOG" >&2
        SUMMARY+=("$(printf '%-28s rc=%-3s' query_gpu skip)")
        continue
      fi
      mapfile -t texts < <(python3 -c 'import json, sys; [print(q["text"]) for q in json.load(open(sys.argv[1]))["queries"]]' \
        "$Q/query.json")
      views=$(python3 -c 'import json, sys; print(",".join(v["name"] for v in json.load(open(sys.argv[1]))["views"]))' \
        "$Q/query.json")
      step "$s" 120 "$B/citylangsplat" query /tmp/example/citylangsplat/language/citylangsplat "${texts[@]}" --scene /tmp/example \
        --views "$views" --device cuda --out /tmp/query_gpu
      step query_compare 60 python3 scripts/device/compare_query.py "$Q" /tmp/query_gpu ;;
    train_rgb)  # densification, the Gaussian cap and resuming on the GPU; the compare scene's PSNR
      make_example
      step train_rgb_3000 180 "$B/citylangsplat" train-rgb --scene /tmp/example --out /tmp/rgb --iterations 3000 --device cuda
      step train_rgb_cap 120 "$B/citylangsplat" train-rgb --scene /tmp/example --out /tmp/rgb_cap --iterations 1500 \
        --max-gaussians 12000 --device cuda
      step train_rgb_1000 120 "$B/citylangsplat" train-rgb --scene /tmp/example --out /tmp/rgb_resume --iterations 1000 \
        --device cuda
      step train_rgb_resume 120 "$B/citylangsplat" train-rgb --scene /tmp/example --out /tmp/rgb_resume --iterations 1500 \
        --resume --device cuda
      step synth_compare 60 "$B/citylangsplat" -q synth --city data/citygml/fzk-haus/fzk_haus_lod3_v2.gml --lod 3 --seed 1 \
        --views 28 --width 480 --height 360 --out /tmp/compare
      step train_rgb_compare 120 "$B/citylangsplat" train-rgb --scene /tmp/compare --out /tmp/rgb_compare --iterations 600 \
        -r 1 --densify-from 500 --densify-until 300 --checkpoint-every 0 --device cuda
      for d in rgb rgb_cap rgb_resume rgb_compare; do echo "== $d"; cat /tmp/$d/summary.json; done >> "$LOG" 2>&1 ;;
    profile_splat | profile_language | profile_query)  # each kernel's duration (Nsight Compute), one CSV row per launch
      NCU=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
      if [ "$s" = profile_splat ]; then
        args=(bench/bench_splat --device cuda --threads 16 --gaussians 1000000 --width 1600 --height 1000 --iters 1)
      elif [ "$s" = profile_query ]; then
        args=(bench/bench_query --device cuda --threads 16 --sizes 1920x1080 --iters 1)
      else
        args=(bench/bench_language --device cuda --threads 16 --repeats 1 --train-scenes 200000@800x600 --loss seg
              --blend-cache off --query-scene 200000@1920x1080)
      fi
      step "$s" 240 "$NCU" --clock-control none --metrics gpu__time_duration.sum --csv --log-file "${OUT:-/tmp}/ncu_$s.csv" \
        "$B/${args[0]}" "${args[@]:1}" ;;
    suite)  # in the build folder, as ctest runs them; one row per test program in the log
      step "$s" 300 sh -c 'cd "$1" && for t in ./test_*; do echo "$t"; done | OMP_NUM_THREADS=1 xargs -P 16 -I{} sh -c \
        "{} --gtest_brief=1 > /tmp/\$(basename {}).log 2>&1; echo \"\$(basename {}) rc=\$?\""' suite "$B"
      cat /tmp/test_*.log >> "$LOG" ;;
  esac
done
# GDB_SCRIPT: a cuda-gdb command file (breakpoints, run, bt, continue...) instead of `run` then `bt`.
if [ ${#debug[@]} -gt 0 ]; then
  if [ -n "${GDB_SCRIPT:-}" ]; then gdb_args=(-x "$GDB_SCRIPT"); else gdb_args=(-ex run -ex bt); fi
  step debug 120 cuda-gdb -batch "${gdb_args[@]}" --args "$B/${debug[0]}" "${debug[@]:1}"
fi
echo; printf '%s\n' "${SUMMARY[@]}"
