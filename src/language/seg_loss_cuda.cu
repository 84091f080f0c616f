// The one-pass language loss on CUDA: see seg_loss_cuda.h.
#include <cuda_runtime.h>

#include "language/seg_loss_cuda.h"

namespace cls {
namespace {

constexpr int kWarp = 32;
constexpr int kWarpsPerBlock = 8;
constexpr unsigned kFullWarp = 0xffffffffu;

__device__ float warp_sum(float v) {
  for (int offset = kWarp / 2; offset > 0; offset /= 2) v += __shfl_xor_sync(kFullWarp, v, offset);
  return v;
}

// Warp w of the grid takes pixels w, w + (all warps), ...; lane c takes channels c, c + 32, ...
// Lane 0 keeps the warp's sums; the block adds its warps' sums to out.
__global__ void seg_loss_kernel(SegLossArgs a, double* out) {
  const int lane = threadIdx.x % kWarp, warp = threadIdx.x / kWarp;
  const int64_t warps = static_cast<int64_t>(gridDim.x) * kWarpsPerBlock;
  SegLossSums sums;
  double bad = 0;
  for (int64_t p = static_cast<int64_t>(blockIdx.x) * kWarpsPerBlock + warp; p < a.n; p += warps) {
    const int s = a.sam_ids ? a.sam_ids[p] : -1;
    const int g = a.gml_ids ? a.gml_ids[p] : -1;
    float* gv = a.grad + p * a.l;
    if (!ids_in_tables(s, g, a.ks, a.kg)) {
      bad += 1;
      continue;
    }
    const float m = a.coverage[p];
    const float ws = sam_weight(a.weights, s, m), wg = citygml_weight(a.weights, g, m);
    const float* zv = a.rendered + p * a.l;
    const float* ts = s >= 0 ? a.sam_table + static_cast<int64_t>(s) * a.l : nullptr;
    const float* tg = g >= 0 ? a.gml_table + static_cast<int64_t>(g) * a.l : nullptr;
    float abs_s = 0.f, abs_g = 0.f;
    for (int c = lane; c < a.l; c += kWarp) {
      const float z = zv[c];
      float grad = 0.f;
      if (ts) grad += l1_channel(z, ts[c], ws, abs_s);
      if (tg) grad += l1_channel(z, tg[c], wg, abs_g);
      gv[c] = grad;
    }
    abs_s = warp_sum(abs_s);
    abs_g = warp_sum(abs_g);
    add_pixel(sums, m, abs_s, abs_g);  // every lane holds the warp's sums; lane 0's are added below
  }
  __shared__ double block[kWarpsPerBlock][4];
  if (lane == 0) {
    block[warp][0] = sums.sam, block[warp][1] = sums.sam_gml, block[warp][2] = sums.citygml, block[warp][3] = bad;
  }
  __syncthreads();
  if (threadIdx.x < 4) {
    double t = 0;
    for (int w = 0; w < kWarpsPerBlock; ++w) t += block[w][threadIdx.x];
    if (t != 0) atomicAdd(out + threadIdx.x, t);
  }
}

}  // namespace

int seg_loss_cuda(const SegLossArgs& a, double* sums, void* stream_ptr) {
  const cudaStream_t stream = static_cast<cudaStream_t>(stream_ptr);
  cudaError_t err = cudaMemsetAsync(sums, 0, 4 * sizeof(double), stream);
  if (err != cudaSuccess || a.n == 0) return err;
  int device = 0, sms = 0;
  err = cudaGetDevice(&device);
  if (err == cudaSuccess) err = cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, device);
  if (err != cudaSuccess) return err;
  // Enough blocks to fill the device a few times over; each warp then walks its pixels.
  const int64_t needed = (a.n + kWarpsPerBlock - 1) / kWarpsPerBlock;
  const int blocks = static_cast<int>(needed < 16LL * sms ? needed : 16LL * sms);
  seg_loss_kernel<<<blocks, kWarpsPerBlock * kWarp, 0, stream>>>(a, sums);
  return cudaGetLastError();
}

}  // namespace cls
