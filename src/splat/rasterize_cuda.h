#pragma once
// Host entry points of the CUDA rasterizer (no CUDA headers here, so C++ code can include it).
// The kernels (rasterize_forward.cu) use the same per-Gaussian and per-pixel math as the CPU path
// (project_gaussian.h, blend_pixel.h, sh.h) and the same order of blending (per tile, by depth, ties
// by Gaussian index), so CPU and GPU agree up to float rounding of exp.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "splat/project_gaussian.h"

namespace cls {

// Device memory for the rasterizer's own buffers. A torch build passes LibTorch's caching allocator
// (rasterize.cpp), so that an iteration reuses the last one's memory in stream order instead of paying
// cudaMalloc and cudaFree, which waits for the device; null functions fall back to those two.
struct CudaAllocator {
  void* (*alloc)(size_t bytes, void* stream) = nullptr;  // null when out of memory
  void (*free)(void* p) = nullptr;
};

constexpr int kCudaSparseMaxNnz = 16;

// Every pointer is device memory, layouts as SplatInputs (rasterize_cpu.h); outputs H x W x C image,
// H x W alpha and depth.
struct CudaSplatArgs {
  SplatCamera<float> cam;
  int n = 0;
  const float* means = nullptr;
  const float* scales = nullptr;
  const float* quats = nullptr;
  const float* opacities = nullptr;
  const float* sh = nullptr;  // N x (degree+1)^2 x 3, or null for features
  int sh_degree = -1;
  const float* features = nullptr;  // N x channels, or N x nnz with feature_index
  int channels = 3;
  // Sparse features (as SplatInputs): nnz weights per Gaussian at the channels feature_index (N x nnz) gives,
  // at most kCudaSparseMaxNnz; the backward then gives the weights' gradient only (no geometry).
  const int32_t* feature_index = nullptr;
  int nnz = 0;
  const float* background = nullptr;  // channels values or null
  float* image = nullptr;
  float* alpha = nullptr;
  float* depth = nullptr;
  CudaAllocator allocator;
};

// Device buffers of one forward pass (projections, sorted tile lists, per-pixel final T and
// contributor counts), kept for a backward pass.
struct CudaForwardState;
struct CudaForwardStateDeleter {
  void operator()(CudaForwardState* s) const;
};
using CudaForwardStatePtr = std::unique_ptr<CudaForwardState, CudaForwardStateDeleter>;

// Runs the forward pass on `stream` (a cudaStream_t, null for the default stream). Returns the first
// cudaError_t met (0 = success); `state` receives the buffers.
int rasterize_forward_cuda(const CudaSplatArgs& args, CudaForwardStatePtr& state, void* stream = nullptr);

// Gradients of the backward pass, device memory, zero-initialised by the caller; shapes as the inputs
// (sh or features by the path of the forward), mean2d and mean2d_abs N x 2. Null entries are skipped;
// when every entry but sh/features is null (a language field on frozen geometry), the per-pixel alpha
// gradient is not computed at all.
struct CudaSplatGrads {
  float* means = nullptr;
  float* scales = nullptr;
  float* quats = nullptr;
  float* opacities = nullptr;
  float* sh = nullptr;
  float* features = nullptr;
  float* mean2d = nullptr;
  float* mean2d_abs = nullptr;
};

// Backward of the forward that produced `state` with the same `args` (its output pointers are not
// read). dL_dimage H x W x C; dL_dalpha, dL_ddepth H x W or null. The math is the CPU path's (shared
// headers); the scheduling is the original's (per-pixel backward walk, sums over each warp, atomic
// accumulation). It does not wait for its kernels: a fault inside them surfaces at the stream's next
// synchronisation, as with LibTorch's own operations.
int rasterize_backward_cuda(const CudaSplatArgs& args, const CudaForwardState& state, const float* dL_dimage,
                            const float* dL_dalpha, const float* dL_ddepth, const CudaSplatGrads& grads,
                            void* stream = nullptr);

// Screen radii (N int32, 0 where culled) of the last forward, copied to device memory `radii`.
int cuda_forward_radii(const CudaForwardState& state, int32_t* radii, void* stream = nullptr);

}  // namespace cls
