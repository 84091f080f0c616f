#pragma once
// Host entry point of the CUDA ray generator (no CUDA headers here, so C++ code can include it).
#include "core/math.h"

namespace cls {

struct PixelRayParams {
  float fx, fy, cx, cy;
  int width, height;
  Mat3f R;  // world-to-camera rotation
};

// Writes width*height world-space ray directions (xyz, row-major pixels) to device memory.
// Returns the cudaError_t of the launch (0 = success).
int pixel_rays_cuda(const PixelRayParams& p, float* device_dirs, void* stream = nullptr);

}  // namespace cls
