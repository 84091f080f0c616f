#pragma once
// The one-pass language loss on CUDA (seg_loss_cuda.cu): language_loss_from_seg (language_loss.h) for
// float32 CUDA tensors, with the CPU loop's per-pixel math (seg_loss_pixel.h). One warp per pixel, its
// lanes over the channels; no dense H x W x L targets. No CUDA headers here; device pointers; `stream`
// is a cudaStream_t. Returns the first cudaError_t met (0 = success).
#include <cstdint>

#include "language/seg_loss_pixel.h"

namespace cls {

// `a`'s pointers in device memory; `sums`: 4 device doubles, zeroed here, then SegLossSums' three and the
// count of pixels whose ids lie outside their tables.
int seg_loss_cuda(const SegLossArgs& a, double* sums, void* stream);

}  // namespace cls
