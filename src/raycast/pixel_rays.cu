// CUDA ray generation for the raycaster: one thread per pixel, the math is pixel_ray.h, shared with
// the CPU path. Compiled in every build where nvcc exists (the cls_cuda_check target), so a CUDA
// compile error fails CI even on machines without a GPU.
#include <cuda_runtime.h>

#include "raycast/pixel_rays_cuda.h"
#include "raycast/pixel_ray.h"

namespace cls {
namespace {

__global__ void pixel_rays_kernel(float fx, float fy, float cx, float cy, int width, int height,
                                  Mat3f R, float* dirs) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  const int j = blockIdx.y * blockDim.y + threadIdx.y;
  if (i >= width || j >= height) return;
  const Vec3f d = camera_to_world_dir(R, pixel_ray_camera(fx, fy, cx, cy, i, j));
  float* out = dirs + 3 * (static_cast<size_t>(j) * width + i);
  out[0] = d.x;
  out[1] = d.y;
  out[2] = d.z;
}

}  // namespace

int pixel_rays_cuda(const PixelRayParams& p, float* device_dirs, void* stream) {
  const dim3 block(16, 16);
  const dim3 grid((p.width + block.x - 1) / block.x, (p.height + block.y - 1) / block.y);
  pixel_rays_kernel<<<grid, block, 0, static_cast<cudaStream_t>(stream)>>>(
      p.fx, p.fy, p.cx, p.cy, p.width, p.height, p.R, device_dirs);
  return static_cast<int>(cudaGetLastError());
}

}  // namespace cls
