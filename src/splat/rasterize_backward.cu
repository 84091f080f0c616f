// CUDA backward rasterizer: per-tile blocks re-walk each pixel's list backwards from its last
// contributor (the original 3DGS renderCUDA backward), with the per-pixel math of blend_pixel.h and
// the per-Gaussian backward of project_gaussian.h / sh.h, shared with the CPU path. Gradients of a
// Gaussian are summed over each warp's pixels before the atomic add.
#include <cuda_runtime.h>

#include "splat/blend_pixel.h"
#include "splat/rasterize_cuda.h"
#include "splat/rasterize_cuda_state.cuh"
#include "splat/sh.h"

namespace cls {
namespace {

struct BackwardArgs {
  int width, height, tiles_x, channels;
  const uint2* ranges;
  const uint32_t* ids;
  const ProjectedGaussian<float>* proj;
  const float* opacities;
  const float* values;  // N x channels (SH colours or features)
  const float* background;
  const float* final_T;
  const int32_t* n_contrib;
  const float *dL_dimage, *dL_dalpha, *dL_ddepth;
  float* geom_grad;   // N x 9: mean2d 2, |mean2d| 2, conic 3, opacity, depth
  float* value_grad;  // N x channels
};

// Sum of v over the warp, in lane 0 (the other lanes' results are partial).
__device__ __forceinline__ float warp_sum(float v) {
  for (int offset = 16; offset > 0; offset >>= 1) v += __shfl_down_sync(0xffffffffu, v, offset);
  return v;
}

// Each warp (two rows of a tile's pixels) walks the list in step, so its lanes meet each Gaussian
// together: their gradients are summed over the warp with shuffles and added by one lane, instead of
// one atomic add per pixel and value on the same address (which serialised 32 ways).
__global__ void __launch_bounds__(kCudaBlock) render_backward_kernel(BackwardArgs r) {
  const int tile = blockIdx.y * r.tiles_x + blockIdx.x;
  const int tid = threadIdx.y * kTileSize + threadIdx.x;
  const bool lane0 = (tid & 31) == 0;
  const int px = blockIdx.x * kTileSize + threadIdx.x, py = blockIdx.y * kTileSize + threadIdx.y;
  const bool inside = px < r.width && py < r.height;
  const float cx = px + 0.5f, cy = py + 0.5f;
  const size_t pix = inside ? static_cast<size_t>(py) * r.width + px : 0;
  const uint2 range = r.ranges[tile];
  const int total = static_cast<int>(range.y - range.x);
  __shared__ uint32_t s_id[kCudaBlock];
  __shared__ float s_mean[kCudaBlock][2];
  __shared__ float s_conic[kCudaBlock][3];
  __shared__ float s_op[kCudaBlock], s_cut[kCudaBlock], s_depth[kCudaBlock];

  const int C = r.channels;
  const float* dpix = r.dL_dimage ? r.dL_dimage + pix * C : nullptr;  // null: no image gradient
  const int last = inside ? r.n_contrib[pix] : 0;
  const float T_final = inside ? r.final_T[pix] : 0.f;
  const float dA = inside && r.dL_dalpha ? r.dL_dalpha[pix] : 0.f;
  const float dD = inside && r.dL_ddepth ? r.dL_ddepth[pix] : 0.f;
  float bg_dot = 0.f;
  if (inside && r.background && dpix)
    for (int c = 0; c < C; ++c) bg_dot += r.background[c] * dpix[c];
  float T = T_final, last_alpha = 0.f, rec_dot = 0.f, last_v_dot = 0.f, rec_d = 0.f, last_d = 0.f;
  for (int start = 0; start < total; start += kCudaBlock) {
    __syncthreads();  // the previous batch is consumed
    if (start + tid < total) {  // batches from the back of the list
      const uint32_t id = r.ids[range.x + total - 1 - (start + tid)];
      const ProjectedGaussian<float>& p = r.proj[id];
      s_id[tid] = id;
      s_mean[tid][0] = p.mean2d[0], s_mean[tid][1] = p.mean2d[1];
      s_conic[tid][0] = p.conic[0], s_conic[tid][1] = p.conic[1], s_conic[tid][2] = p.conic[2];
      s_op[tid] = r.opacities[id];
      s_cut[tid] = alpha_cutoff_power(s_op[tid]);
      s_depth[tid] = p.depth;
    }
    __syncthreads();
    const int batch = min(kCudaBlock, total - start);
    for (int j = 0; j < batch; ++j) {  // every lane of the warp, so that the sums below meet
      const int k = total - 1 - (start + j);  // index in the tile list
      bool contributes = inside && k < last;  // not behind the pixel's last contributor
      float power = 0.f, G = 0.f, a = 0.f;
      if (contributes) {
        power = gaussian_power(s_mean[j], s_conic[j], cx, cy);
        contributes = power >= s_cut[j];
      }
      if (contributes) {
        a = alpha_from_power(power, s_op[j], G);
        contributes = a != 0.f;
      }
      if (!__any_sync(0xffffffffu, contributes)) continue;
      const uint32_t id = s_id[j];
      const float* v = r.values + static_cast<size_t>(id) * C;
      float w = 0.f, d_op = 0.f;
      float g[7] = {0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f};
      if (contributes) {
        T = T / (1.f - a);
        w = a * T;
        float v_dot = 0.f;
        for (int c = 0; dpix && c < C; ++c) v_dot += v[c] * dpix[c];
        // the same recurrences as rasterize_cpu.cpp backward_tile
        rec_dot = last_alpha * last_v_dot + (1.f - last_alpha) * rec_dot;
        last_v_dot = v_dot;
        float dL_da = v_dot - rec_dot;
        rec_d = last_alpha * last_d + (1.f - last_alpha) * rec_d;
        last_d = s_depth[j];
        dL_da += (s_depth[j] - rec_d) * dD;
        dL_da *= T;
        dL_da += (dA - bg_dot) * T_final / (1.f - a);
        last_alpha = a;
        d_op = gaussian_alpha_backward(s_mean[j], s_conic[j], s_op[j], cx, cy, G, dL_da, g, g + 2, g + 4);
      }
      float* vg = r.value_grad + static_cast<size_t>(id) * C;
      for (int c = 0; dpix && c < C; ++c) {
        const float sum = warp_sum(contributes ? w * dpix[c] : 0.f);
        if (lane0) atomicAdd(vg + c, sum);
      }
      float* gg = r.geom_grad + static_cast<size_t>(id) * 9;
      for (int q = 0; q < 7; ++q) {
        const float sum = warp_sum(g[q]);
        if (lane0) atomicAdd(gg + q, sum);
      }
      const float op_sum = warp_sum(d_op), depth_sum = warp_sum(contributes ? w * dD : 0.f);
      if (lane0) atomicAdd(gg + 7, op_sum), atomicAdd(gg + 8, depth_sum);
    }
  }
}

__global__ void preprocess_backward_kernel(CudaSplatArgs a, const ProjectedGaussian<float>* proj,
                                           const uint8_t* clamped, const float* geom_grad, const float* color_grad,
                                           CudaSplatGrads g) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n || !proj[i].visible) return;
  const float* gg = geom_grad + static_cast<size_t>(i) * 9;
  if (g.mean2d) g.mean2d[2 * i] += gg[0], g.mean2d[2 * i + 1] += gg[1];
  if (g.mean2d_abs) g.mean2d_abs[2 * i] += gg[2], g.mean2d_abs[2 * i + 1] += gg[3];
  if (g.opacities) g.opacities[i] += gg[7];
  const Vec3f mean{a.means[3 * i], a.means[3 * i + 1], a.means[3 * i + 2]};
  const Mat3f Sigma = covariance_3d(a.scales + 3 * i, a.quats + 4 * i);
  Mat3f dSigma;
  Vec3f dmean = project_gaussian_backward(a.cam, mean, Sigma, gg, gg + 4, gg[8], dSigma);
  if (a.sh) {
    const bool cl[3] = {clamped[3 * i] != 0, clamped[3 * i + 1] != 0, clamped[3 * i + 2] != 0};
    float scratch[3 * kMaxShCoeffs] = {};
    const size_t K = sh_coeff_count(a.sh_degree);
    float* dsh = g.sh ? g.sh + i * K * 3 : scratch;
    dmean = dmean + sh_to_rgb_backward(a.sh_degree, a.sh + i * K * 3, mean - a.cam.center(), cl, color_grad + 3 * i, dsh);
  }
  if (g.means)
    for (int k = 0; k < 3; ++k) g.means[3 * i + k] += dmean[k];
  float dscale[3] = {0.f, 0.f, 0.f}, dq[4] = {0.f, 0.f, 0.f, 0.f};
  covariance_3d_backward(a.scales + 3 * i, a.quats + 4 * i, dSigma, dscale, dq);
  if (g.scales)
    for (int k = 0; k < 3; ++k) g.scales[3 * i + k] += dscale[k];
  if (g.quats)
    for (int k = 0; k < 4; ++k) g.quats[4 * i + k] += dq[k];
}

}  // namespace

int rasterize_backward_cuda(const CudaSplatArgs& a, const CudaForwardState& s, const float* dL_dimage,
                            const float* dL_dalpha, const float* dL_ddepth, const CudaSplatGrads& grads,
                            void* stream_ptr) {
  const cudaStream_t stream = static_cast<cudaStream_t>(stream_ptr);
  if (a.n == 0) return 0;
  const int C = s.channels;
  float *geom = nullptr, *color_grad = nullptr;
  cudaError_t err = cudaMalloc(&geom, sizeof(float) * 9 * static_cast<size_t>(a.n));
  if (err == cudaSuccess) err = cudaMemsetAsync(geom, 0, sizeof(float) * 9 * static_cast<size_t>(a.n), stream);
  float* value_grad = a.sh ? nullptr : grads.features;
  if (err == cudaSuccess && !value_grad) {
    err = cudaMalloc(&color_grad, sizeof(float) * C * static_cast<size_t>(a.n));
    if (err == cudaSuccess) err = cudaMemsetAsync(color_grad, 0, sizeof(float) * C * static_cast<size_t>(a.n), stream);
    value_grad = color_grad;
  }
  if (err == cudaSuccess && s.instances > 0) {
    const int tiles_x = a.cam.tiles_x(), tiles_y = a.cam.tiles_y();
    BackwardArgs r{a.cam.width, a.cam.height, tiles_x, C, s.ranges, s.ids, s.proj, a.opacities,
                   a.sh ? s.colors : a.features, a.background, s.final_T, s.n_contrib, dL_dimage, dL_dalpha,
                   dL_ddepth, geom, value_grad};
    render_backward_kernel<<<dim3(tiles_x, tiles_y), dim3(kTileSize, kTileSize), 0, stream>>>(r);
    err = cudaGetLastError();
  }
  if (err == cudaSuccess) {
    preprocess_backward_kernel<<<(a.n + 255) / 256, 256, 0, stream>>>(a, s.proj, s.clamped, geom, color_grad, grads);
    err = cudaGetLastError();
  }
  if (err == cudaSuccess) err = cudaStreamSynchronize(stream);
  cudaFree(geom);
  if (color_grad) cudaFree(color_grad);
  return int(err);
}

}  // namespace cls
