// CUDA SSIM: see ssim_cuda.h. The window's taps travel as a kernel argument (constant memory).
#include <cuda_runtime.h>

#include "splat/ssim_cpu.h"
#include "splat/ssim_cuda.h"
#include "splat/ssim_pixel.h"

namespace cls {
namespace {

constexpr int kRadius = kSsimWindow / 2;
constexpr int kThreads = 256;

struct Taps {
  float w[kSsimWindow];
};

Taps window_taps(const float* w) {
  Taps taps;
  for (int i = 0; i < kSsimWindow; ++i) taps.w[i] = w[i];
  return taps;
}

// The sizes of one pass: thread i is pixel (x, y) of channel c, planes [q][c][y][x].
struct Grid {
  int H, W, C;
  __device__ bool locate(int& x, int& y, int& c) const {
    const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
    if (i >= static_cast<size_t>(C) * H * W) return false;
    x = static_cast<int>(i % W), y = static_cast<int>(i / W % H), c = static_cast<int>(i / (static_cast<size_t>(W) * H));
    return true;
  }
  __device__ size_t plane() const { return static_cast<size_t>(H) * W; }
  __device__ size_t at(int q, int c, int y, int x) const {
    return (static_cast<size_t>(q) * C + c) * plane() + static_cast<size_t>(y) * W + x;
  }
};

// Rows of a, b, a^2, b^2, ab, zero outside the image.
__global__ void moments_along_rows(Grid g, Taps t, const float* a, const float* b, float* h) {
  int x, y, c;
  if (!g.locate(x, y, c)) return;
  float m[5] = {0.f, 0.f, 0.f, 0.f, 0.f};
  for (int d = 0; d < kSsimWindow; ++d) {
    const int xs = x + d - kRadius;
    if (xs < 0 || xs >= g.W) continue;
    const size_t i = (static_cast<size_t>(y) * g.W + xs) * g.C + c;
    const float va = a[i], vb = b[i], w = t.w[d];
    m[0] += w * va, m[1] += w * vb, m[2] += w * va * va, m[3] += w * vb * vb, m[4] += w * va * vb;
  }
  for (int q = 0; q < 5; ++q) h[g.at(q, c, y, x)] = m[q];
}

// Columns of the row-blurred moments, then each pixel's SSIM and (dm not null) its derivatives.
__global__ void ssim_along_columns(Grid g, Taps t, const float* h, float* map, float* dm) {
  int x, y, c;
  if (!g.locate(x, y, c)) return;
  float m[5] = {0.f, 0.f, 0.f, 0.f, 0.f};
  for (int d = 0; d < kSsimWindow; ++d) {
    const int ys = y + d - kRadius;
    if (ys < 0 || ys >= g.H) continue;
    for (int q = 0; q < 5; ++q) m[q] += t.w[d] * h[g.at(q, c, ys, x)];
  }
  float dv[3];
  map[g.at(0, c, y, x)] = ssim_pixel(m[0], m[1], m[2], m[3], m[4], dm ? dv : nullptr);
  if (dm)  // C x 3 x H x W, as ssim_forward_cpu's
    for (int k = 0; k < 3; ++k) dm[(static_cast<size_t>(c) * 3 + k) * g.plane() + static_cast<size_t>(y) * g.W + x] = dv[k];
}

// Rows of the three derivative planes (dm: C x 3 x H x W; out: 3 x C x H x W).
__global__ void derivatives_along_rows(Grid g, Taps t, const float* dm, float* out) {
  int x, y, c;
  if (!g.locate(x, y, c)) return;
  const size_t row = static_cast<size_t>(c) * 3 * g.plane() + static_cast<size_t>(y) * g.W;
  float m[3] = {0.f, 0.f, 0.f};
  for (int d = 0; d < kSsimWindow; ++d) {
    const int xs = x + d - kRadius;
    if (xs < 0 || xs >= g.W) continue;
    for (int k = 0; k < 3; ++k) m[k] += t.w[d] * dm[row + k * g.plane() + xs];
  }
  for (int k = 0; k < 3; ++k) out[g.at(k, c, y, x)] = m[k];
}

// Columns of the row-blurred derivatives, combined into the gradient of the mean SSIM times scale.
__global__ void gradient_along_columns(Grid g, Taps t, const float* a, const float* b, const float* hd,
                                       const float* scale, float* grad) {
  int x, y, c;
  if (!g.locate(x, y, c)) return;
  float m[3] = {0.f, 0.f, 0.f};
  for (int d = 0; d < kSsimWindow; ++d) {
    const int ys = y + d - kRadius;
    if (ys < 0 || ys >= g.H) continue;
    for (int k = 0; k < 3; ++k) m[k] += t.w[d] * hd[g.at(k, c, ys, x)];
  }
  const size_t i = (static_cast<size_t>(y) * g.W + x) * g.C + c;
  const float s = scale[0] / (static_cast<float>(g.C) * g.plane());
  grad[i] = s * (m[0] + 2.f * a[i] * m[1] + b[i] * m[2]);
}

unsigned blocks(const Grid& g) {
  return static_cast<unsigned>((static_cast<size_t>(g.C) * g.H * g.W + kThreads - 1) / kThreads);
}

}  // namespace

int ssim_forward_cuda(const float* taps, const float* a, const float* b, int H, int W, int C, float* map, float* dm,
                      float* work, void* stream_ptr) {
  const cudaStream_t stream = static_cast<cudaStream_t>(stream_ptr);
  const Grid g{H, W, C};
  if (static_cast<size_t>(C) * H * W == 0) return 0;
  const Taps t = window_taps(taps);
  moments_along_rows<<<blocks(g), kThreads, 0, stream>>>(g, t, a, b, work);
  ssim_along_columns<<<blocks(g), kThreads, 0, stream>>>(g, t, work, map, dm);
  return int(cudaGetLastError());
}

int ssim_backward_cuda(const float* taps, const float* a, const float* b, const float* dm, int H, int W, int C,
                       const float* scale, float* grad_a, float* work, void* stream_ptr) {
  const cudaStream_t stream = static_cast<cudaStream_t>(stream_ptr);
  const Grid g{H, W, C};
  if (static_cast<size_t>(C) * H * W == 0) return 0;
  const Taps t = window_taps(taps);
  derivatives_along_rows<<<blocks(g), kThreads, 0, stream>>>(g, t, dm, work);
  gradient_along_columns<<<blocks(g), kThreads, 0, stream>>>(g, t, a, b, work, scale, grad_a);
  return int(cudaGetLastError());
}

}  // namespace cls
