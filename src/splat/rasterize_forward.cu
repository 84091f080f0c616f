// CUDA forward rasterizer (the 3DGS pipeline: preprocess, duplicate per tile, radix sort by
// (tile, depth), tile ranges, per-tile blending with shared-memory batches). Channel count is
// processed in compile-time chunks (CHUNK channels per block, gridDim.z chunks), so RGB runs one
// chunk of 3 and 128 latent channels run two chunks of 64 (on an H100, 64 with the backward's 64 took
// a language iteration at 200k Gaussians from 8.9 to 8.4 ms; docs/benchmarks.md). Sparse features (nnz
// weights per Gaussian at channels of its own) blend nnz values per Gaussian and pixel into the chunk's
// channels, as the CPU tile kernels do.
#include <cuda_runtime.h>

#include <cub/cub.cuh>

#include "splat/blend_pixel.h"
#include "splat/rasterize_cuda.h"
#include "splat/rasterize_cuda_state.cuh"
#include "splat/sh.h"

namespace cls {

void CudaForwardStateDeleter::operator()(CudaForwardState* s) const {
  if (!s) return;
  for (void* p : {(void*)s->proj, (void*)s->colors, (void*)s->clamped, (void*)s->tiles_touched, (void*)s->keys,
                  (void*)s->ids, (void*)s->ranges, (void*)s->final_T, (void*)s->n_contrib})
    device_free(s->allocator, p);
  delete s;
}

namespace {

constexpr int kBlock = kTileSize * kTileSize;

__global__ void preprocess_kernel(CudaSplatArgs a, ProjectedGaussian<float>* proj, float* colors, uint8_t* clamped,
                                  uint32_t* tiles_touched) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n) return;
  tiles_touched[i] = 0;
  const Vec3f mean{a.means[3 * i], a.means[3 * i + 1], a.means[3 * i + 2]};
  const Mat3f Sigma = covariance_3d(a.scales + 3 * i, a.quats + 4 * i);
  const ProjectedGaussian<float> p = project_gaussian(a.cam, mean, Sigma);
  proj[i] = p;
  if (!p.visible) return;
  if (a.sh) {
    bool cl[3];
    sh_to_rgb(a.sh_degree, a.sh + static_cast<size_t>(i) * sh_coeff_count(a.sh_degree) * 3, mean - a.cam.center(),
              colors + 3 * i, cl);
    for (int c = 0; c < 3; ++c) clamped[3 * i + c] = cl[c];
  }
  tiles_touched[i] = (p.rect_max[0] - p.rect_min[0]) * (p.rect_max[1] - p.rect_min[1]);
}

// One (tile << 32 | depth) key per overlapped tile, written in Gaussian order so the stable radix
// sort breaks depth ties by index, as the CPU path does.
__global__ void duplicate_kernel(int n, const ProjectedGaussian<float>* proj, const uint32_t* offsets, int tiles_x,
                                 uint64_t* keys, uint32_t* ids) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n || !proj[i].visible) return;
  const ProjectedGaussian<float>& p = proj[i];
  uint32_t off = i == 0 ? 0 : offsets[i - 1];
  const uint64_t depth_bits = __float_as_uint(p.depth);  // positive floats order as their bits
  for (int y = p.rect_min[1]; y < p.rect_max[1]; ++y)
    for (int x = p.rect_min[0]; x < p.rect_max[0]; ++x) {
      keys[off] = (static_cast<uint64_t>(y * tiles_x + x) << 32) | depth_bits;
      ids[off] = i;
      ++off;
    }
}

__global__ void tile_ranges_kernel(int m, const uint64_t* keys, uint2* ranges) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= m) return;
  const uint32_t tile = static_cast<uint32_t>(keys[k] >> 32);
  if (k == 0) {
    ranges[tile].x = 0;
  } else {
    const uint32_t prev = static_cast<uint32_t>(keys[k - 1] >> 32);
    if (tile != prev) {
      ranges[prev].y = k;
      ranges[tile].x = k;
    }
  }
  if (k == m - 1) ranges[tile].y = m;
}

struct RenderArgs {
  int width, height, tiles_x, channels;
  const uint2* ranges;
  const uint32_t* ids;
  const ProjectedGaussian<float>* proj;
  const float* opacities;
  const float* values;  // N x channels, or N x nnz with index
  const int32_t* index;  // N x nnz channels of the values, or null
  int nnz;
  const float* background;
  float *image, *alpha, *depth, *final_T;
  int32_t* n_contrib;
};

template <int CHUNK, bool SPARSE>
__global__ void __launch_bounds__(kBlock) render_kernel(RenderArgs r) {
  const int tile = blockIdx.y * r.tiles_x + blockIdx.x;
  const int c0 = blockIdx.z * CHUNK;
  const int tid = threadIdx.y * kTileSize + threadIdx.x;
  const int px = blockIdx.x * kTileSize + threadIdx.x, py = blockIdx.y * kTileSize + threadIdx.y;
  const bool inside = px < r.width && py < r.height;
  const float cx = px + 0.5f, cy = py + 0.5f;  // pixel centre (docs/conventions.md)
  const uint2 range = r.ranges[tile];
  // each Gaussian's values as 16-byte loads where every row starts 16-byte aligned
  const bool vector_values = r.channels % 4 == 0 && reinterpret_cast<uintptr_t>(r.values) % 16 == 0;
  __shared__ float s_mean[kBlock][2];
  __shared__ float s_conic[kBlock][3];
  __shared__ float s_op[kBlock], s_cut[kBlock], s_depth[kBlock];
  // kBlock x CHUNK values (dynamic: 64 KB at 64 channels); SPARSE: kBlock x nnz weights, then their channels
  extern __shared__ __align__(16) float s_val[];
  int32_t* const s_idx = reinterpret_cast<int32_t*>(s_val + kBlock * r.nnz);
  bool done = !inside;
  float T = 1.f, d = 0.f, acc[CHUNK];
  for (int c = 0; c < CHUNK; ++c) acc[c] = 0.f;
  int contributor = 0, last = 0;
  const int total = static_cast<int>(range.y - range.x);
  for (int start = 0; start < total; start += kBlock) {
    if (__syncthreads_count(done) == kBlock) break;
    const int k = start + tid;
    if (k < total) {
      const uint32_t id = r.ids[range.x + k];
      const ProjectedGaussian<float>& p = r.proj[id];
      s_mean[tid][0] = p.mean2d[0], s_mean[tid][1] = p.mean2d[1];
      s_conic[tid][0] = p.conic[0], s_conic[tid][1] = p.conic[1], s_conic[tid][2] = p.conic[2];
      s_op[tid] = r.opacities[id];
      s_cut[tid] = alpha_cutoff_power(s_op[tid]);
      s_depth[tid] = p.depth;
      if constexpr (SPARSE) {
        const size_t row = static_cast<size_t>(id) * r.nnz;
        for (int q = 0; q < r.nnz; ++q) s_val[tid * r.nnz + q] = r.values[row + q], s_idx[tid * r.nnz + q] = r.index[row + q];
      } else if (const float* v = r.values + static_cast<size_t>(id) * r.channels + c0;
                 CHUNK % 4 == 0 && vector_values && c0 + CHUNK <= r.channels) {
        for (int q = 0; q < CHUNK / 4; ++q)
          reinterpret_cast<float4*>(s_val + tid * CHUNK)[q] = __ldg(reinterpret_cast<const float4*>(v) + q);
      } else {
        for (int c = 0; c < CHUNK; ++c) s_val[tid * CHUNK + c] = c0 + c < r.channels ? v[c] : 0.f;
      }
    }
    __syncthreads();
    const int batch = min(kBlock, total - start);
    for (int j = 0; !done && j < batch; ++j) {
      ++contributor;
      const float power = gaussian_power(s_mean[j], s_conic[j], cx, cy);
      if (power < s_cut[j]) continue;
      float G;
      const float a = alpha_from_power(power, s_op[j], G);
      if (a == 0.f) continue;
      const float test_T = T * (1.f - a);
      if (test_T < float(kTransmittanceMin)) {
        done = true;
        continue;
      }
      const float w = a * T;
      if constexpr (SPARSE) {  // acc indexed at run time (local memory): the weights in this chunk's channels
        for (int q = 0; q < r.nnz; ++q) {
          const int c = s_idx[j * r.nnz + q] - c0;
          if (c >= 0 && c < CHUNK) acc[c] += w * s_val[j * r.nnz + q];
        }
      } else if constexpr (CHUNK % 4 == 0) {  // one 16-byte shared load per four channels
        const float4* v4 = reinterpret_cast<const float4*>(s_val + j * CHUNK);
#pragma unroll
        for (int q = 0; q < CHUNK / 4; ++q) {
          const float4 v = v4[q];
          acc[4 * q] += w * v.x, acc[4 * q + 1] += w * v.y, acc[4 * q + 2] += w * v.z, acc[4 * q + 3] += w * v.w;
        }
      } else {
        for (int c = 0; c < CHUNK; ++c) acc[c] += w * s_val[j * CHUNK + c];
      }
      d += w * s_depth[j];
      T = test_T;
      last = contributor;
    }
  }
  if (!inside) return;
  const size_t pix = static_cast<size_t>(py) * r.width + px;
  for (int c = 0; c < CHUNK && c0 + c < r.channels; ++c)
    r.image[pix * r.channels + c0 + c] = acc[c] + (r.background ? T * r.background[c0 + c] : 0.f);
  if (blockIdx.z == 0) {
    r.alpha[pix] = 1.f - T;
    r.depth[pix] = d;
    r.final_T[pix] = T;
    r.n_contrib[pix] = last;
  }
}

// False, launching nothing, where the GPU cannot give a block the CHUNK's shared memory (64 channels
// take 72 KB: beyond sm_75's 64 KB).
template <int CHUNK, bool SPARSE = false>
bool launch_render(const RenderArgs& r, int tiles_y, cudaStream_t stream) {
  const dim3 grid(r.tiles_x, tiles_y, (r.channels + CHUNK - 1) / CHUNK), block(kTileSize, kTileSize);
  const size_t shared = SPARSE ? (sizeof(float) + sizeof(int32_t)) * kBlock * r.nnz : sizeof(float) * kBlock * CHUNK;
  if (shared > 48 * 1024 && cudaFuncSetAttribute(render_kernel<CHUNK, SPARSE>, cudaFuncAttributeMaxDynamicSharedMemorySize,
                                                 int(shared)) != cudaSuccess) {
    cudaGetLastError();  // clear it: the caller takes a smaller chunk
    return false;
  }
  render_kernel<CHUNK, SPARSE><<<grid, block, shared, stream>>>(r);
  return true;
}

#define CLS_CUDA_TRY(expr)             \
  do {                                 \
    const cudaError_t e_ = (expr);     \
    if (e_ != cudaSuccess) return int(e_); \
  } while (0)

}  // namespace

int rasterize_forward_cuda(const CudaSplatArgs& a, CudaForwardStatePtr& state, void* stream_ptr) {
  const cudaStream_t stream = static_cast<cudaStream_t>(stream_ptr);
  // sparse features: at most kCudaSparseMaxNnz weights (32 KB of shared memory per block)
  if (!a.sh && a.feature_index && (a.nnz < 1 || a.nnz > kCudaSparseMaxNnz)) return int(cudaErrorInvalidValue);
  state.reset(new CudaForwardState());
  CudaForwardState& s = *state;
  const CudaAllocator& al = a.allocator;
  s.allocator = al;
  const int C = a.sh ? 3 : a.channels;
  s.n = a.n, s.width = a.cam.width, s.height = a.cam.height, s.channels = C;
  const int tiles_x = a.cam.tiles_x(), tiles_y = a.cam.tiles_y(), n_tiles = tiles_x * tiles_y;
  const size_t n_pix = static_cast<size_t>(a.cam.width) * a.cam.height;
  CLS_CUDA_TRY(device_alloc(al, &s.proj, a.n, stream));
  CLS_CUDA_TRY(device_alloc(al, &s.tiles_touched, a.n, stream));
  if (a.sh) {
    CLS_CUDA_TRY(device_alloc(al, &s.colors, 3 * static_cast<size_t>(a.n), stream));
    CLS_CUDA_TRY(device_alloc(al, &s.clamped, 3 * static_cast<size_t>(a.n), stream));
  }
  CLS_CUDA_TRY(device_alloc(al, &s.ranges, n_tiles, stream));
  CLS_CUDA_TRY(device_alloc(al, &s.final_T, n_pix, stream));
  CLS_CUDA_TRY(device_alloc(al, &s.n_contrib, n_pix, stream));
  const int threads = 256;
  const int blocks_n = (a.n + threads - 1) / threads;
  if (a.n > 0) {
    preprocess_kernel<<<blocks_n, threads, 0, stream>>>(a, s.proj, s.colors, s.clamped, s.tiles_touched);
    CLS_CUDA_TRY(cudaGetLastError());
    // inclusive prefix sum of the tile counts, in place
    size_t temp_bytes = 0;
    CLS_CUDA_TRY(cub::DeviceScan::InclusiveSum(nullptr, temp_bytes, s.tiles_touched, s.tiles_touched, a.n, stream));
    uint8_t* temp = nullptr;
    CLS_CUDA_TRY(device_alloc(al, &temp, temp_bytes, stream));
    const cudaError_t scan = cub::DeviceScan::InclusiveSum(temp, temp_bytes, s.tiles_touched, s.tiles_touched, a.n, stream);
    device_free(al, temp);
    CLS_CUDA_TRY(scan);
    uint32_t m = 0;  // the one wait of the pass: the host sizes the sort by it
    CLS_CUDA_TRY(cudaMemcpyAsync(&m, s.tiles_touched + a.n - 1, sizeof(m), cudaMemcpyDeviceToHost, stream));
    CLS_CUDA_TRY(cudaStreamSynchronize(stream));
    s.instances = m;
  }
  CLS_CUDA_TRY(cudaMemsetAsync(s.ranges, 0, sizeof(uint2) * n_tiles, stream));
  if (s.instances > 0) {
    const int m = static_cast<int>(s.instances);
    uint64_t* keys_unsorted = nullptr;
    uint32_t* ids_unsorted = nullptr;
    CLS_CUDA_TRY(device_alloc(al, &s.keys, m, stream));
    CLS_CUDA_TRY(device_alloc(al, &s.ids, m, stream));
    cudaError_t err = device_alloc(al, &keys_unsorted, m, stream);
    if (err == cudaSuccess) err = device_alloc(al, &ids_unsorted, m, stream);
    if (err == cudaSuccess) {
      duplicate_kernel<<<blocks_n, threads, 0, stream>>>(a.n, s.proj, s.tiles_touched, tiles_x, keys_unsorted,
                                                         ids_unsorted);
      err = cudaGetLastError();
    }
    int tile_bits = 1;
    while ((1 << tile_bits) < n_tiles) ++tile_bits;
    size_t temp_bytes = 0;
    if (err == cudaSuccess)
      err = cub::DeviceRadixSort::SortPairs(nullptr, temp_bytes, keys_unsorted, s.keys, ids_unsorted, s.ids, m, 0,
                                            32 + tile_bits, stream);
    uint8_t* temp = nullptr;
    if (err == cudaSuccess) err = device_alloc(al, &temp, temp_bytes, stream);
    if (err == cudaSuccess)
      err = cub::DeviceRadixSort::SortPairs(temp, temp_bytes, keys_unsorted, s.keys, ids_unsorted, s.ids, m, 0,
                                            32 + tile_bits, stream);
    device_free(al, temp);
    device_free(al, keys_unsorted);
    device_free(al, ids_unsorted);
    CLS_CUDA_TRY(err);
    tile_ranges_kernel<<<(m + threads - 1) / threads, threads, 0, stream>>>(m, s.keys, s.ranges);
    CLS_CUDA_TRY(cudaGetLastError());
  }
  RenderArgs r{a.cam.width, a.cam.height, tiles_x, C, s.ranges, s.ids, s.proj, a.opacities,
               a.sh ? s.colors : a.features, a.sh ? nullptr : a.feature_index, a.sh ? 0 : a.nnz, a.background,
               a.image, a.alpha, a.depth, s.final_T, s.n_contrib};
  if (r.index) {
    if (C <= 16) launch_render<16, true>(r, tiles_y, stream);
    else launch_render<64, true>(r, tiles_y, stream);
  } else if (C == 1) launch_render<1>(r, tiles_y, stream);
  else if (C == 2) launch_render<2>(r, tiles_y, stream);
  else if (C == 3) launch_render<3>(r, tiles_y, stream);
  else if (C == 4) launch_render<4>(r, tiles_y, stream);
  else if (C <= 8) launch_render<8>(r, tiles_y, stream);
  else if (C <= 16) launch_render<16>(r, tiles_y, stream);
  else if (C <= 32 || !launch_render<64>(r, tiles_y, stream)) launch_render<32>(r, tiles_y, stream);
  return int(cudaGetLastError());
}

namespace {
__global__ void radii_kernel(int n, const ProjectedGaussian<float>* proj, int32_t* radii) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) radii[i] = proj[i].visible ? proj[i].radius : 0;
}
}  // namespace

int cuda_forward_radii(const CudaForwardState& s, int32_t* radii, void* stream) {
  if (s.n == 0) return 0;
  radii_kernel<<<(s.n + 255) / 256, 256, 0, static_cast<cudaStream_t>(stream)>>>(s.n, s.proj, radii);
  return int(cudaGetLastError());
}

}  // namespace cls
