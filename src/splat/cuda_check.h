#pragma once
// The status of a CUDA entry point of this library (rasterize_cuda.h, ssim_cuda.h: 0 or a cudaError_t)
// as an exception naming the operation and the error. For the torch-side callers of a CUDA build.
#include <cuda_runtime_api.h>

#include <string>

#include "core/error.h"

namespace cls {

inline void check_cuda(int rc, const char* what) {
  if (rc != 0)
    throw Error(std::string(what) + ": CUDA error " + std::to_string(rc) + " (" +
                cudaGetErrorString(static_cast<cudaError_t>(rc)) + ")");
}

}  // namespace cls
