#pragma once
// The device buffers a CUDA forward pass keeps for its backward (CUDA-only; included by .cu files).
#include <cuda_runtime.h>

#include <cstdint>

#include "splat/project_gaussian.h"
#include "splat/rasterize_cuda.h"

namespace cls {

struct CudaForwardState {
  CudaAllocator allocator;  // what the buffers below came from
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

// count elements of T (at least one) from the caller's allocator, or cudaMalloc without one.
template <class T>
cudaError_t device_alloc(const CudaAllocator& al, T** p, size_t count, cudaStream_t stream) {
  const size_t bytes = sizeof(T) * (count > 0 ? count : 1);
  if (!al.alloc) return cudaMalloc(reinterpret_cast<void**>(p), bytes);
  *p = static_cast<T*>(al.alloc(bytes, stream));
  return *p ? cudaSuccess : cudaErrorMemoryAllocation;
}

// Frees what device_alloc gave: the caching allocator reuses it in stream order; without one the
// device is drained first, since work queued on any stream may still read it.
inline void device_free(const CudaAllocator& al, void* p) {
  if (!p) return;
  if (al.free) {
    al.free(p);
  } else {
    cudaDeviceSynchronize();
    cudaFree(p);
  }
}

}  // namespace cls
