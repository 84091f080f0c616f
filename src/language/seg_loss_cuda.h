#pragma once
// The one-pass language loss on CUDA (seg_loss_cuda.cu): language_loss_from_seg (language_loss.h) for
// float32 CUDA tensors, with the CPU loop's per-pixel math (seg_loss_pixel.h). One warp per pixel, its
// lanes over the channels; no dense H x W x L targets. No CUDA headers here; device pointers; `stream`
// is a cudaStream_t. Returns the first cudaError_t met (0 = success).
#include <cstdint>

#include "language/seg_loss_pixel.h"

namespace cls {

struct SegLossCudaArgs {
  const float* rendered = nullptr;  // Z^: n x l
  const int32_t* sam_ids = nullptr;  // n, -1 = no segment; null = no pixel has one
  const float* sam_table = nullptr;  // ks x l
  int32_t ks = 0;
  const int32_t* gml_ids = nullptr;  // n, -1 = no region; null = none (and the baseline passes null)
  const float* gml_table = nullptr;  // kg x l
  int32_t kg = 0;
  const float* coverage = nullptr;  // n, 0/1
  int64_t n = 0;
  int l = 0;
  SegLossWeights weights;
  float* grad = nullptr;   // n x l: dL/dZ^
  double* sums = nullptr;  // 4 values, zeroed here: SegLossSums' three, then the count of ids outside their table
};

int seg_loss_cuda(const SegLossCudaArgs& a, void* stream);

}  // namespace cls
