#pragma once
// The device buffers a CUDA forward pass keeps for its backward (CUDA-only; included by .cu files).
#include <cuda_runtime.h>

#include <cstdint>

#include "splat/project_gaussian.h"

namespace cls {

struct CudaForwardState {
  int n = 0, width = 0, height = 0, channels = 0;
  int64_t instances = 0;
  ProjectedGaussian<float>* proj = nullptr;  // N
  float* colors = nullptr;                   // N x 3 (SH path)
  uint8_t* clamped = nullptr;                // N x 3 (SH path)
  uint32_t* tiles_touched = nullptr;         // N, then inclusive prefix sums
  uint64_t* keys = nullptr;                  // instances, sorted (tile << 32 | depth bits)
  uint32_t* ids = nullptr;                   // instances, sorted Gaussian ids
  uint2* ranges = nullptr;                   // per tile [begin, end)
  float* final_T = nullptr;                  // H x W
  int32_t* n_contrib = nullptr;              // H x W
};

constexpr int kCudaBlock = kTileSize * kTileSize;

}  // namespace cls
