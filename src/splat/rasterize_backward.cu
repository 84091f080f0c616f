// CUDA backward rasterizer: per-tile blocks re-walk each pixel's list backwards from its last
// contributor (the original 3DGS renderCUDA backward), with the per-pixel math of blend_pixel.h and
// the per-Gaussian backward of project_gaussian.h / sh.h, shared with the CPU path. Gradients of a
// Gaussian are summed over each warp's pixels before the atomic add. Sparse features get their weights'
// gradient only: per Gaussian nnz products of w = alpha T with the image gradient at its channels.
#include <cuda_runtime.h>

#include "splat/blend_pixel.h"
#include "splat/rasterize_cuda.h"
#include "splat/rasterize_cuda_state.cuh"
#include "splat/sh.h"

namespace cls {
namespace {

constexpr int kGeomEntries = 9;  // per Gaussian: mean2d 2, |mean2d| 2, conic 3, opacity, depth

struct BackwardArgs {
  int width, height, tiles_x, channels;
  const uint2* ranges;
  const uint32_t* ids;
  const ProjectedGaussian<float>* proj;
  const float* opacities;
  const float* values;  // N x channels (SH colours or features)
  const int32_t* index;  // sparse features: N x nnz channels of the weights, or null
  int nnz;
  const float* background;
  const float* final_T;
  const int32_t* n_contrib;
  const float *dL_dimage, *dL_dalpha, *dL_ddepth;
  float* geom_grad;   // N x kGeomEntries, or null without geometry gradients
  float* value_grad;  // N x channels, or N x nnz
};

constexpr unsigned kFullWarp = 0xffffffffu;

// One step of warp_transpose_sum: entries [0, 2H) become H, exchanged with the lane H apart. The
// steps are template recursion rather than a loop, which nvcc left partly rolled (the array then went
// to local memory).
template <int H, int K>
__device__ __forceinline__ void transpose_sum_step(float (&v)[K], int lane) {
  if constexpr (H > 0) {
    const bool upper = (lane & H) != 0;
#pragma unroll
    for (int i = 0; i < H; ++i) {
      const float send = upper ? v[i] : v[i + H];
      const float keep = upper ? v[i + H] : v[i];
      v[i] = keep + __shfl_xor_sync(kFullWarp, send, H);
    }
    transpose_sum_step<H / 2>(v, lane);
  }
}

// Sums K entries (K a power of two, at most 32) over the warp so that lane l receives the total of
// entry l % K: the warp's halves are first added for every entry down to K lanes, then each step keeps
// half of a lane's entries and swaps the other half with its partner (31 shuffles for 32 entries,
// where 32 separate sums take 160). Every lane of the warp calls it.
template <int K>
__device__ __forceinline__ float warp_transpose_sum(float (&v)[K], int lane) {
#pragma unroll
  for (int offset = 16; offset >= K; offset >>= 1)
#pragma unroll
    for (int i = 0; i < K; ++i) v[i] += __shfl_xor_sync(kFullWarp, v[i], offset);
  transpose_sum_step<K / 2>(v, lane);
  return v[0];
}

// Each warp (two rows of a tile's pixels) walks the list in step, so its lanes meet each Gaussian
// together and its gradients are summed over the warp before one atomic add per entry.
// CMAX: the pixel's image gradient is held in registers for CMAX channels (a power of two, at least 4).
// GEOMETRY: the alpha gradient and all that follows from it, which needs every channel in one pass
// (channels beyond 128 are read from global memory). Without it (features on frozen geometry) only
// w = alpha T is needed per pixel, and each blockIdx.z takes its own CMAX channels.
// SPARSE (without GEOMETRY): CMAX is nnz rounded up to a power of two, the entries summed per Gaussian.
template <int CMAX, bool GEOMETRY, bool SPARSE = false>
__global__ void __launch_bounds__(kCudaBlock) render_backward_kernel(BackwardArgs r) {
  static_assert(!(SPARSE && GEOMETRY), "sparse features take no geometry gradient");
  constexpr int kGroup = CMAX < 32 ? CMAX : 32;  // value-gradient entries reduced together
  // with few channels, the value gradients ride in the geometry's reduction (9 + 4 <= 16 entries)
  constexpr bool kJoint = GEOMETRY && CMAX <= 4;
  const int tile = blockIdx.y * r.tiles_x + blockIdx.x;
  const int tid = threadIdx.y * kTileSize + threadIdx.x;
  const int lane = tid & 31;
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
  __shared__ int32_t s_idx[SPARSE ? kCudaBlock * CMAX : 1];  // a batch's channels of the sparse weights

  const int C = r.channels;
  const int cz = GEOMETRY ? 0 : blockIdx.z * CMAX;  // the first channel in registers
  const bool has_image = r.dL_dimage != nullptr;  // the same for the whole grid
  const float* dpix = has_image && inside ? r.dL_dimage + pix * C : nullptr;
  float dp[CMAX];  // this pixel's image gradient from channel cz, zero beyond C and outside the image
#pragma unroll
  for (int c = 0; c < CMAX; ++c) dp[c] = !SPARSE && dpix && cz + c < C ? dpix[cz + c] : 0.f;
  const int last = inside ? r.n_contrib[pix] : 0;
  const float T_final = inside ? r.final_T[pix] : 0.f;
  const float dA = inside && r.dL_dalpha ? r.dL_dalpha[pix] : 0.f;
  const float dD = inside && r.dL_ddepth ? r.dL_ddepth[pix] : 0.f;
  float bg_dot = 0.f;
  if (GEOMETRY && r.background && dpix) {
#pragma unroll
    for (int c = 0; c < CMAX; ++c) bg_dot += c < C ? r.background[c] * dp[c] : 0.f;
    for (int c = CMAX; c < C; ++c) bg_dot += r.background[c] * dpix[c];
  }
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
      if constexpr (SPARSE)
        for (int q = 0; q < r.nnz; ++q) s_idx[tid * CMAX + q] = r.index[static_cast<size_t>(id) * r.nnz + q];
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
      if (!__any_sync(kFullWarp, contributes)) continue;
      const uint32_t id = s_id[j];
      const size_t row = static_cast<size_t>(id) * (SPARSE ? r.nnz : C);
      const float* v = r.values + row;
      float* vg = r.value_grad + row;
      float w = 0.f;
      if (contributes) {
        T = T / (1.f - a);
        w = a * T;
      }
      if constexpr (GEOMETRY) {
        float e[16];  // kGeomEntries, then (kJoint) the value gradients
#pragma unroll
        for (int q = 0; q < 16; ++q) e[q] = 0.f;
        if (contributes) {
          float v_dot = 0.f;
          if (dpix) {
#pragma unroll
            for (int c = 0; c < CMAX; ++c) v_dot += c < C ? __ldg(v + c) * dp[c] : 0.f;
            for (int c = CMAX; c < C; ++c) v_dot += __ldg(v + c) * dpix[c];
          }
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
          e[7] = gaussian_alpha_backward(s_mean[j], s_conic[j], s_op[j], cx, cy, G, dL_da, e, e + 2, e + 4);
          e[8] = w * dD;
        }
        if constexpr (kJoint) {
#pragma unroll
          for (int c = 0; c < CMAX; ++c) e[kGeomEntries + c] = w * dp[c];
        }
        const float sum = warp_transpose_sum<16>(e, lane);
        if (lane < kGeomEntries) atomicAdd(r.geom_grad + static_cast<size_t>(id) * kGeomEntries + lane, sum);
        else if (kJoint && has_image && lane < kGeomEntries + C) atomicAdd(vg + (lane - kGeomEntries), sum);
      }
      if constexpr (SPARSE) {
        if (has_image) {
          float t[CMAX];
#pragma unroll
          for (int q = 0; q < CMAX; ++q) t[q] = contributes && q < r.nnz ? w * dpix[s_idx[j * CMAX + q]] : 0.f;
          const float sum = warp_transpose_sum<CMAX>(t, lane);
          if (lane < r.nnz) atomicAdd(vg + lane, sum);
        }
      } else if constexpr (!kJoint) {
        if (has_image) {
#pragma unroll
          for (int c0 = 0; c0 < CMAX; c0 += kGroup) {
            if (cz + c0 >= C) break;
            float t[kGroup];
#pragma unroll
            for (int i = 0; i < kGroup; ++i) t[i] = w * dp[c0 + i];
            const float sum = warp_transpose_sum<kGroup>(t, lane);
            if (lane < kGroup && cz + c0 + lane < C) atomicAdd(vg + cz + c0 + lane, sum);
          }
          if constexpr (GEOMETRY) {
            for (int c0 = CMAX; c0 < C; c0 += 32) {  // channels beyond the registers (C > 128)
              float t[32];
#pragma unroll
              for (int i = 0; i < 32; ++i) t[i] = dpix && c0 + i < C ? w * dpix[c0 + i] : 0.f;
              const float sum = warp_transpose_sum<32>(t, lane);
              if (c0 + lane < C) atomicAdd(vg + c0 + lane, sum);
            }
          }
        }
      }
    }
  }
}

template <int CMAX, bool GEOMETRY, bool SPARSE = false>
void launch_backward(const BackwardArgs& r, int tiles_y, cudaStream_t stream) {
  const dim3 grid(r.tiles_x, tiles_y, GEOMETRY || SPARSE ? 1 : (r.channels + CMAX - 1) / CMAX), block(kTileSize, kTileSize);
  render_backward_kernel<CMAX, GEOMETRY, SPARSE><<<grid, block, 0, stream>>>(r);
}

// geom_grad is null when no geometry gradient is asked for (then only SH coefficients get one).
__global__ void preprocess_backward_kernel(CudaSplatArgs a, const ProjectedGaussian<float>* proj,
                                           const uint8_t* clamped, const float* geom_grad, const float* color_grad,
                                           CudaSplatGrads g) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n || !proj[i].visible) return;
  const Vec3f mean{a.means[3 * i], a.means[3 * i + 1], a.means[3 * i + 2]};
  Vec3f dmean{0.f, 0.f, 0.f};
  if (geom_grad) {
    const float* gg = geom_grad + static_cast<size_t>(i) * kGeomEntries;
    if (g.mean2d) g.mean2d[2 * i] += gg[0], g.mean2d[2 * i + 1] += gg[1];
    if (g.mean2d_abs) g.mean2d_abs[2 * i] += gg[2], g.mean2d_abs[2 * i + 1] += gg[3];
    if (g.opacities) g.opacities[i] += gg[7];
    const Mat3f Sigma = covariance_3d(a.scales + 3 * i, a.quats + 4 * i);
    Mat3f dSigma;
    dmean = project_gaussian_backward(a.cam, mean, Sigma, gg, gg + 4, gg[8], dSigma);
    float dscale[3] = {0.f, 0.f, 0.f}, dq[4] = {0.f, 0.f, 0.f, 0.f};
    covariance_3d_backward(a.scales + 3 * i, a.quats + 4 * i, dSigma, dscale, dq);
    if (g.scales)
      for (int k = 0; k < 3; ++k) g.scales[3 * i + k] += dscale[k];
    if (g.quats)
      for (int k = 0; k < 4; ++k) g.quats[4 * i + k] += dq[k];
  }
  if (a.sh) {
    const bool cl[3] = {clamped[3 * i] != 0, clamped[3 * i + 1] != 0, clamped[3 * i + 2] != 0};
    float scratch[3 * kMaxShCoeffs];  // zeroed only when used: it would cost every thread the stores
    const size_t K = sh_coeff_count(a.sh_degree);
    float* dsh = g.sh ? g.sh + i * K * 3 : scratch;
    if (!g.sh)
      for (int k = 0; k < 3 * kMaxShCoeffs; ++k) scratch[k] = 0.f;
    dmean = dmean + sh_to_rgb_backward(a.sh_degree, a.sh + i * K * 3, mean - a.cam.center(), cl, color_grad + 3 * i, dsh);
  }
  if (g.means)
    for (int k = 0; k < 3; ++k) g.means[3 * i + k] += dmean[k];
}

}  // namespace

int rasterize_backward_cuda(const CudaSplatArgs& a, const CudaForwardState& s, const float* dL_dimage,
                            const float* dL_dalpha, const float* dL_ddepth, const CudaSplatGrads& grads,
                            void* stream_ptr) {
  const cudaStream_t stream = static_cast<cudaStream_t>(stream_ptr);
  if (a.n == 0) return 0;
  const int C = s.channels;
  const CudaAllocator& al = a.allocator;
  const bool geometry = grads.means || grads.scales || grads.quats || grads.opacities || grads.mean2d ||
                        grads.mean2d_abs;
  const bool sparse = !a.sh && a.feature_index;
  if (sparse && (geometry || a.nnz < 1 || a.nnz > kCudaSparseMaxNnz)) return int(cudaErrorInvalidValue);
  float *geom = nullptr, *color_grad = nullptr;
  cudaError_t err = cudaSuccess;
  if (geometry) {
    err = device_alloc(al, &geom, kGeomEntries * static_cast<size_t>(a.n), stream);
    if (err == cudaSuccess) err = cudaMemsetAsync(geom, 0, sizeof(float) * kGeomEntries * static_cast<size_t>(a.n), stream);
  }
  float* value_grad = a.sh ? nullptr : grads.features;
  if (err == cudaSuccess && !value_grad) {  // SH colours, or features whose gradient is not asked for
    err = device_alloc(al, &color_grad, C * static_cast<size_t>(a.n), stream);
    if (err == cudaSuccess) err = cudaMemsetAsync(color_grad, 0, sizeof(float) * C * static_cast<size_t>(a.n), stream);
    value_grad = color_grad;
  }
  if (err == cudaSuccess && s.instances > 0 && (geometry || grads.sh || grads.features)) {
    const int tiles_x = a.cam.tiles_x(), tiles_y = a.cam.tiles_y();
    BackwardArgs r{a.cam.width, a.cam.height, tiles_x, C, s.ranges, s.ids, s.proj, a.opacities,
                   a.sh ? s.colors : a.features, sparse ? a.feature_index : nullptr, sparse ? a.nnz : 0, a.background,
                   s.final_T, s.n_contrib, dL_dimage, dL_dalpha, dL_ddepth, geom, value_grad};
    if (sparse) {
      if (r.nnz == 1) launch_backward<1, false, true>(r, tiles_y, stream);
      else if (r.nnz == 2) launch_backward<2, false, true>(r, tiles_y, stream);
      else if (r.nnz <= 4) launch_backward<4, false, true>(r, tiles_y, stream);
      else if (r.nnz <= 8) launch_backward<8, false, true>(r, tiles_y, stream);
      else launch_backward<16, false, true>(r, tiles_y, stream);
    } else if (!geometry) {  // value gradients alone: up to 64 channels per block (128 in one was slower)
      if (C <= 4) launch_backward<4, false>(r, tiles_y, stream);
      else if (C <= 8) launch_backward<8, false>(r, tiles_y, stream);
      else if (C <= 16) launch_backward<16, false>(r, tiles_y, stream);
      else if (C <= 32) launch_backward<32, false>(r, tiles_y, stream);
      else launch_backward<64, false>(r, tiles_y, stream);
    } else if (C <= 4) launch_backward<4, true>(r, tiles_y, stream);
    else if (C <= 8) launch_backward<8, true>(r, tiles_y, stream);
    else if (C <= 16) launch_backward<16, true>(r, tiles_y, stream);
    else if (C <= 32) launch_backward<32, true>(r, tiles_y, stream);
    else if (C <= 64) launch_backward<64, true>(r, tiles_y, stream);
    else launch_backward<128, true>(r, tiles_y, stream);
    err = cudaGetLastError();
  }
  if (err == cudaSuccess && (geometry || grads.sh)) {
    preprocess_backward_kernel<<<(a.n + 255) / 256, 256, 0, stream>>>(a, s.proj, s.clamped, geom, color_grad, grads);
    err = cudaGetLastError();
  }
  device_free(al, geom);
  device_free(al, color_grad);
  return int(err);
}

}  // namespace cls
