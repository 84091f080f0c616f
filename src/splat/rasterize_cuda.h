#pragma once
// Host entry points of the CUDA rasterizer (no CUDA headers here, so C++ code can include it).
// The kernels (rasterize_forward.cu) use the same per-Gaussian and per-pixel math as the CPU path
// (project_gaussian.h, blend_pixel.h, sh.h) and the same order of blending (per tile, by depth, ties
// by Gaussian index), so CPU and GPU agree up to float rounding of exp.
#include <cstdint>
#include <memory>

#include "splat/project_gaussian.h"

namespace cls {

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
  const float* features = nullptr;  // N x channels
  int channels = 3;
  const float* background = nullptr;  // channels values or null
  float* image = nullptr;
  float* alpha = nullptr;
  float* depth = nullptr;
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

// Screen radii (N int32, 0 where culled) of the last forward, copied to device memory `radii`.
int cuda_forward_radii(const CudaForwardState& state, int32_t* radii, void* stream = nullptr);

}  // namespace cls
