// CPU rasterizer: see rasterize_cpu.h. The per-Gaussian and per-pixel math lives in the shared
// headers (project_gaussian.h, blend_pixel.h, sh.h) that the CUDA kernels use as well.
#include "splat/rasterize_cpu.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "scene/camera.h"
#include "splat/blend_pixel.h"
#include "splat/sh.h"

namespace cls {
namespace {

template <class T>
Vec3<T> vec3_at(const T* p, int i) {
  return {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
}

// Striped spin locks: a tile's backward adds its per-Gaussian sums into the global gradients under
// the lock of the Gaussian's stripe (one lock per entry instead of one atomic per value).
class StripedLocks {
 public:
  static constexpr int kStripes = 4096;
  StripedLocks() : flags_(new std::atomic_flag[kStripes]) {
    for (int i = 0; i < kStripes; ++i) flags_[i].clear();
  }
  void lock(int id) {
    while (flags_[id % kStripes].test_and_set(std::memory_order_acquire)) {
    }
  }
  void unlock(int id) { flags_[id % kStripes].clear(std::memory_order_release); }

 private:
  std::unique_ptr<std::atomic_flag[]> flags_;
};

// A tile's Gaussians gathered contiguously (front to back) before its pixels walk them.
template <class T>
struct TileGaussian {
  T mean2d[2];
  T conic[3];
  T opacity;
  T cutoff;  // alpha_cutoff_power(opacity)
  T depth;
  T box[4];  // xmin, xmax, ymin, ymax: a conservative bound of where power >= cutoff
  int32_t id;
};

// Pixels walk only the Gaussians whose cutoff ellipse box overlaps their 4x4 sub-tile: the others
// would all be skipped by the cutoff test, so results are the same, with ~16x fewer evaluations.
constexpr int kSubTile = 4;

// Bounding box of {d : -0.5 d^T Q d >= cutoff}: half-widths sqrt(R (Q^-1)_xx), sqrt(R (Q^-1)_yy) with
// R = -2 cutoff, widened by a margin far beyond rounding.
template <class T>
void cutoff_box(TileGaussian<T>& g) {
  const T R = T(-2) * g.cutoff;
  const T det = g.conic[0] * g.conic[2] - g.conic[1] * g.conic[1];
  if (!(R > T(0)) || !(det > T(0))) {
    g.box[0] = g.box[2] = T(1e30), g.box[1] = g.box[3] = T(-1e30);  // never passes
    return;
  }
  const T hx = std::sqrt(R * g.conic[2] / det) * T(1.001) + T(0.01);
  const T hy = std::sqrt(R * g.conic[0] / det) * T(1.001) + T(0.01);
  g.box[0] = g.mean2d[0] - hx, g.box[1] = g.mean2d[0] + hx;
  g.box[2] = g.mean2d[1] - hy, g.box[3] = g.mean2d[1] + hy;
}

// Indices into the tile list of the Gaussians that can reach pixel centres of the sub-tile whose
// first pixel is (sx, sy), in list (depth) order.
template <class T>
void subtile_list(const std::vector<TileGaussian<T>>& list, int sx, int sy, std::vector<int32_t>& out) {
  const T x_lo = T(sx) + T(0.5), x_hi = T(sx + kSubTile) - T(0.5);
  const T y_lo = T(sy) + T(0.5), y_hi = T(sy + kSubTile) - T(0.5);
  out.clear();
  for (int k = 0; k < static_cast<int>(list.size()); ++k) {
    const T* b = list[k].box;
    if (b[1] >= x_lo && b[0] <= x_hi && b[3] >= y_lo && b[2] <= y_hi) out.push_back(k);
  }
}

template <class T>
void gather_tile(const SplatForwardState<T>& st, const T* opacities, int tile, std::vector<TileGaussian<T>>& out) {
  const int begin = st.tile_begin[tile], end = st.tile_end[tile];
  out.resize(end - begin);
  for (int k = begin; k < end; ++k) {
    const int id = st.ids[k];
    const ProjectedGaussian<T>& p = st.proj[id];
    TileGaussian<T>& g = out[k - begin];
    g.mean2d[0] = p.mean2d[0], g.mean2d[1] = p.mean2d[1];
    g.conic[0] = p.conic[0], g.conic[1] = p.conic[1], g.conic[2] = p.conic[2];
    g.opacity = opacities[id];
    g.cutoff = alpha_cutoff_power(g.opacity);
    g.depth = p.depth;
    g.id = id;
    cutoff_box(g);
  }
}

// What every tile of a pass reads.
template <class T>
struct TileInputs {
  const SplatCamera<T>& cam;
  const SplatForwardState<T>& st;
  const T* opacities;
  const T* values;
  int C;
  const T* bg;
};

// What every tile of a forward pass writes.
template <class T>
struct ForwardTileJob : TileInputs<T> {
  T *image, *alpha_out, *depth_out, *final_T;
  int32_t* n_contrib;
};

// What every tile of a backward pass reads besides, and writes.
template <class T>
struct BackwardTileJob : TileInputs<T> {
  const T *dL_dimage, *dL_dalpha, *dL_ddepth;
  T *geom_grad, *value_grad;
  StripedLocks& locks;
};

// A thread's buffers, reused from tile to tile.
template <class T>
struct TileScratch {
  std::vector<T> acc, buf;
  std::vector<uint8_t> touched;
  std::vector<TileGaussian<T>> list;
  std::vector<int32_t> sub;
};

// Front-to-back blending of one tile (renderCUDA). kC > 0 fixes the channel count at compile time
// (RGB), kC = 0 loops over C at run time (the inner loop over contiguous channels vectorises).
// Always inlined: the kernel builds below compile it once per instruction set.
template <class T, int kC>
[[gnu::always_inline]] inline void forward_tile(const ForwardTileJob<T>& j, int tile, TileScratch<T>& s) {
  const SplatCamera<T>& cam = j.cam;
  const T* const values = j.values;
  std::vector<T>& acc = s.acc;
  std::vector<TileGaussian<T>>& list = s.list;
  std::vector<int32_t>& sub = s.sub;
  const int nc = kC > 0 ? kC : j.C;
  const int tx = tile % cam.tiles_x(), ty = tile / cam.tiles_x();
  const int x0 = tx * kTileSize, y0 = ty * kTileSize;
  const int x1 = std::min(x0 + kTileSize, cam.width), y1 = std::min(y0 + kTileSize, cam.height);
  gather_tile(j.st, j.opacities, tile, list);
  // fixed-size channels live on the stack (registers for RGB)
  T acc_fixed[kC > 0 ? kC : 1];
  if (kC == 0) acc.resize(nc);
  T* const acc_p = kC > 0 ? acc_fixed : acc.data();
  for (int sy = y0; sy < y1; sy += kSubTile)
  for (int sx = x0; sx < x1; sx += kSubTile) {
  subtile_list(list, sx, sy, sub);
  const int L = static_cast<int>(sub.size());
  for (int py = sy; py < std::min(sy + kSubTile, y1); ++py) {
    for (int px = sx; px < std::min(sx + kSubTile, x1); ++px) {
      const T cx = T(px) + T(0.5), cy = T(py) + T(0.5);
      T Tr = T(1), d = T(0);
      std::fill(acc_p, acc_p + nc, T(0));
      int last = 0;
      for (int k = 0; k < L; ++k) {
        const TileGaussian<T>& g = list[sub[k]];
        const T power = gaussian_power(g.mean2d, g.conic, cx, cy);
        if (power < g.cutoff) continue;
        T G;
        const T a = alpha_from_power(power, g.opacity, G);
        if (a == T(0)) continue;
        const T test_T = Tr * (T(1) - a);
        if (test_T < T(kTransmittanceMin)) break;
        const T w = a * Tr;
        const T* v = values + static_cast<size_t>(g.id) * nc;
        T* ac = acc_p;
#pragma omp simd
        for (int c = 0; c < nc; ++c) ac[c] += w * v[c];
        d += w * g.depth;
        Tr = test_T;
        last = k + 1;
      }
      const size_t pix = static_cast<size_t>(py) * cam.width + px;
      T* out = j.image + pix * nc;
      for (int c = 0; c < nc; ++c) out[c] = acc_p[c] + (j.bg ? Tr * j.bg[c] : T(0));
      j.alpha_out[pix] = T(1) - Tr;
      j.depth_out[pix] = d;
      j.final_T[pix] = Tr;
      j.n_contrib[pix] = last;  // entries of the sub-tile list walked
    }
  }
  }
}


// Backward of one tile: re-walks each pixel's list backwards from its last contributor (the original's
// renderCUDA backward), summing per-entry gradients in `buf` (stride 9 + C: mean2d 2, |mean2d| 2,
// conic 3, opacity, depth, values C), then adds them to the per-Gaussian sums under striped locks.
template <class T, int kC>
[[gnu::always_inline]] inline void backward_tile(const BackwardTileJob<T>& j, int tile, TileScratch<T>& s) {
  const SplatCamera<T>& cam = j.cam;
  const SplatForwardState<T>& st = j.st;
  const T* const values = j.values;
  const T *const dL_dimage = j.dL_dimage, *const dL_dalpha = j.dL_dalpha, *const dL_ddepth = j.dL_ddepth;
  const T* const bg = j.bg;
  std::vector<T>& buf = s.buf;
  std::vector<uint8_t>& touched = s.touched;
  std::vector<TileGaussian<T>>& list = s.list;
  std::vector<int32_t>& sub = s.sub;
  const int nc = kC > 0 ? kC : j.C;
  const int S = 9 + nc;
  const int tx = tile % cam.tiles_x(), ty = tile / cam.tiles_x();
  const int x0 = tx * kTileSize, y0 = ty * kTileSize;
  const int x1 = std::min(x0 + kTileSize, cam.width), y1 = std::min(y0 + kTileSize, cam.height);
  gather_tile(st, j.opacities, tile, list);
  const int L = static_cast<int>(list.size());
  if (L == 0) return;
  buf.assign(static_cast<size_t>(L) * S, T(0));
  touched.assign(L, 0);
  for (int sy = y0; sy < y1; sy += kSubTile)
  for (int sx = x0; sx < x1; sx += kSubTile) {
  subtile_list(list, sx, sy, sub);
  for (int py = sy; py < std::min(sy + kSubTile, y1); ++py) {
    for (int px = sx; px < std::min(sx + kSubTile, x1); ++px) {
      const size_t pix = static_cast<size_t>(py) * cam.width + px;
      const int n = st.n_contrib[pix];
      if (n == 0) continue;
      const T cx = T(px) + T(0.5), cy = T(py) + T(0.5);
      const T* dpix = dL_dimage + pix * nc;
      const T dA = dL_dalpha ? dL_dalpha[pix] : T(0);
      const T dD = dL_ddepth ? dL_ddepth[pix] : T(0);
      const T T_final = st.final_T[pix];
      T bg_dot = T(0);
      if (bg)
        for (int c = 0; c < nc; ++c) bg_dot += bg[c] * dpix[c];
      T Tr = T_final, last_alpha = T(0), rec_d = T(0), last_d = T(0);
      T rec_dot = T(0), last_v_dot = T(0);
      for (int j = n - 1; j >= 0; --j) {
        const int k = sub[j];
        const TileGaussian<T>& g = list[k];
        const T power = gaussian_power(g.mean2d, g.conic, cx, cy);
        if (power < g.cutoff) continue;
        T G;
        const T a = alpha_from_power(power, g.opacity, G);
        if (a == T(0)) continue;
        const int id = g.id;
        Tr = Tr / (T(1) - a);
        const T w = a * Tr;
        T* e = buf.data() + static_cast<size_t>(k) * S;
        touched[k] = 1;
        const T* v = values + static_cast<size_t>(id) * nc;
        T* ev = e + 9;
        // dC/dalpha_i . dL/dC = T_i (v_i - rec_i) . dpix, where rec_i = sum over later contributors j of
        // v_j alpha_j prod_{i<l<j} (1 - alpha_l). rec is linear in the values, so only its dot product
        // with dpix is carried: rec_dot_i = a_{i+1} (v_{i+1} . dpix) + (1 - a_{i+1}) rec_dot_{i+1}.
        T v_dot = T(0);
#pragma omp simd reduction(+ : v_dot)
        for (int c = 0; c < nc; ++c) {
          v_dot += v[c] * dpix[c];
          ev[c] += w * dpix[c];
        }
        rec_dot = last_alpha * last_v_dot + (T(1) - last_alpha) * rec_dot;
        last_v_dot = v_dot;
        T dL_da = v_dot - rec_dot;
        rec_d = last_alpha * last_d + (T(1) - last_alpha) * rec_d;
        last_d = g.depth;
        dL_da += (g.depth - rec_d) * dD;
        e[8] += w * dD;
        dL_da *= Tr;
        // alpha = 1 - T_final and the background term T_final * bg: dT_final/dalpha = -T_final/(1-alpha)
        dL_da += (dA - bg_dot) * T_final / (T(1) - a);
        last_alpha = a;
        e[7] += gaussian_alpha_backward(g.mean2d, g.conic, g.opacity, cx, cy, G, dL_da, e, e + 2, e + 4);
      }
    }
  }
  }
  for (int k = 0; k < L; ++k) {
    if (!touched[k]) continue;
    const int id = list[k].id;
    const T* e = buf.data() + static_cast<size_t>(k) * S;
    j.locks.lock(id);
    T* gg = j.geom_grad + static_cast<size_t>(id) * 9;
    for (int c = 0; c < 9; ++c) gg[c] += e[c];
    T* vg = j.value_grad + static_cast<size_t>(id) * nc;
#pragma omp simd
    for (int c = 0; c < nc; ++c) vg[c] += e[9 + c];
    j.locks.unlock(id);
  }
}

// The tile kernels per instruction set. The per-channel loops (128 latent channels in language training
// and queries) run 4 wide in the x86-64 baseline (SSE2), 8 with AVX2 and 16 with AVX-512; the CPU's best
// build is picked at run time (cpu_kernels()). Only these wrappers carry a target: what they call and do
// not inline stays baseline code, so no AVX instruction runs on a CPU without it.
template <class T>
using ForwardTileFn = void (*)(const ForwardTileJob<T>&, int, TileScratch<T>&);
template <class T>
using BackwardTileFn = void (*)(const BackwardTileJob<T>&, int, TileScratch<T>&);

#define CLS_TILE_KERNELS(NAME, ATTRIBUTE)                                                                \
  template <class T, int kC>                                                                             \
  ATTRIBUTE void forward_tile_##NAME(const ForwardTileJob<T>& j, int tile, TileScratch<T>& s) {          \
    forward_tile<T, kC>(j, tile, s);                                                                     \
  }                                                                                                      \
  template <class T, int kC>                                                                             \
  ATTRIBUTE void backward_tile_##NAME(const BackwardTileJob<T>& j, int tile, TileScratch<T>& s) {        \
    backward_tile<T, kC>(j, tile, s);                                                                    \
  }
CLS_TILE_KERNELS(baseline, )
#if CLS_X86_KERNELS
CLS_TILE_KERNELS(v3, [[gnu::target("arch=x86-64-v3")]])
CLS_TILE_KERNELS(v4, [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]])
#endif
#undef CLS_TILE_KERNELS

template <class T, int kC>
std::pair<ForwardTileFn<T>, BackwardTileFn<T>> tile_kernels_for(CpuKernels k) {
#if CLS_X86_KERNELS
  if (k == CpuKernels::X86_64_V4) return {&forward_tile_v4<T, kC>, &backward_tile_v4<T, kC>};
  if (k == CpuKernels::X86_64_V3) return {&forward_tile_v3<T, kC>, &backward_tile_v3<T, kC>};
#endif
  (void)k;
  return {&forward_tile_baseline<T, kC>, &backward_tile_baseline<T, kC>};
}

// RGB and one channel have their own fixed-size builds; other counts loop at run time.
template <class T>
std::pair<ForwardTileFn<T>, BackwardTileFn<T>> tile_kernels(int C) {
  const CpuKernels k = cpu_kernels();
  return C == 1 ? tile_kernels_for<T, 1>(k) : C == 3 ? tile_kernels_for<T, 3>(k) : tile_kernels_for<T, 0>(k);
}

std::atomic<int>& kernels_override() {
  static std::atomic<int> value{-1};
  return value;
}

}  // namespace

CpuKernels best_cpu_kernels() {
#if CLS_X86_KERNELS
  if (__builtin_cpu_supports("x86-64-v4")) return CpuKernels::X86_64_V4;
  if (__builtin_cpu_supports("x86-64-v3")) return CpuKernels::X86_64_V3;
#endif
  return CpuKernels::Baseline;
}

CpuKernels cpu_kernels() {
  const int forced = kernels_override().load(std::memory_order_relaxed);
  if (forced >= 0) return static_cast<CpuKernels>(forced);
  static const CpuKernels chosen = [] {
    const CpuKernels best = best_cpu_kernels();
    const char* env = std::getenv("CITYLANGSPLAT_CPU_KERNELS");
    if (!env || !*env) return best;
    for (CpuKernels k : {CpuKernels::Baseline, CpuKernels::X86_64_V3, CpuKernels::X86_64_V4})
      if (std::string(env) == cpu_kernels_name(k)) return k <= best ? k : best;
    return best;
  }();
  return chosen;
}

void set_cpu_kernels(CpuKernels k) {
  if (k > best_cpu_kernels()) throw std::invalid_argument(std::string("this CPU cannot run the ") + cpu_kernels_name(k) + " kernels");
  kernels_override().store(static_cast<int>(k), std::memory_order_relaxed);
}

std::vector<CpuKernels> available_cpu_kernels() {
  std::vector<CpuKernels> out;
  for (CpuKernels k : {CpuKernels::Baseline, CpuKernels::X86_64_V3, CpuKernels::X86_64_V4})
    if (k <= best_cpu_kernels()) out.push_back(k);
  return out;
}

const char* cpu_kernels_name(CpuKernels k) {
  switch (k) {
    case CpuKernels::Baseline: return "baseline";
    case CpuKernels::X86_64_V3: return "x86-64-v3";
    case CpuKernels::X86_64_V4: return "x86-64-v4";
  }
  return "?";
}

template <class T>
SplatCamera<T> make_splat_camera(const PinholeCamera& cam, const Pose& pose) {
  SplatCamera<T> c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c.R.m[i][j] = T(pose.R.m[i][j]);
  c.t = {T(pose.t.x), T(pose.t.y), T(pose.t.z)};
  c.fx = T(cam.fx), c.fy = T(cam.fy), c.cx = T(cam.cx), c.cy = T(cam.cy);
  c.width = cam.width, c.height = cam.height;
  return c;
}

template <class T>
void rasterize_forward_cpu(const SplatCamera<T>& cam, const SplatInputs<T>& in, T* image, T* alpha, T* depth,
                           SplatForwardState<T>& st) {
  const int N = in.n;
  const bool sh = in.use_sh();
  const int C = sh ? 3 : in.channels;
  const int K = sh ? sh_coeff_count(in.sh_degree) : 0;
  const Vec3<T> campos = cam.center();
  st.cam = cam;
  st.proj.resize(N);
  if (sh) {
    st.colors.resize(static_cast<size_t>(N) * 3);
    st.clamped.assign(static_cast<size_t>(N) * 3, 0);
  } else {
    st.colors.clear();
    st.clamped.clear();
  }
  // 1. project every Gaussian (preprocessCUDA)
#pragma omp parallel for schedule(static)
  for (int i = 0; i < N; ++i) {
    const Vec3<T> mean = vec3_at(in.means, i);
    const Mat3<T> Sigma = covariance_3d(in.scales + 3 * i, in.quats + 4 * i);
    st.proj[i] = project_gaussian(cam, mean, Sigma);
    if (sh && st.proj[i].visible) {
      bool cl[3];
      sh_to_rgb(in.sh_degree, in.sh + static_cast<size_t>(i) * K * 3, mean - campos, &st.colors[3 * i], cl);
      for (int c = 0; c < 3; ++c) st.clamped[3 * i + c] = cl[c];
    }
  }
  // 2. depth order (ties by id), then a stable counting sort by tile: per-tile lists front to back
  std::vector<int32_t> order;
  order.reserve(N);
  for (int i = 0; i < N; ++i)
    if (st.proj[i].visible) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
    return st.proj[a].depth < st.proj[b].depth || (st.proj[a].depth == st.proj[b].depth && a < b);
  });
  const int tiles_x = cam.tiles_x(), n_tiles = tiles_x * cam.tiles_y();
  std::vector<int32_t> count(n_tiles + 1, 0);
  for (int32_t id : order) {
    const auto& p = st.proj[id];
    for (int y = p.rect_min[1]; y < p.rect_max[1]; ++y)
      for (int x = p.rect_min[0]; x < p.rect_max[0]; ++x) ++count[y * tiles_x + x];
  }
  st.tile_begin.assign(n_tiles, 0);
  st.tile_end.assign(n_tiles, 0);
  int32_t total = 0;
  for (int t = 0; t < n_tiles; ++t) {
    st.tile_begin[t] = st.tile_end[t] = total;
    total += count[t];
  }
  st.ids.resize(total);
  for (int32_t id : order) {
    const auto& p = st.proj[id];
    for (int y = p.rect_min[1]; y < p.rect_max[1]; ++y)
      for (int x = p.rect_min[0]; x < p.rect_max[0]; ++x) st.ids[st.tile_end[y * tiles_x + x]++] = id;
  }
  // 3. blend per tile
  const size_t n_pix = static_cast<size_t>(cam.width) * cam.height;
  st.final_T.resize(n_pix);
  st.n_contrib.resize(n_pix);
  const T* values = sh ? st.colors.data() : in.features;
  const ForwardTileJob<T> job{{cam, st, in.opacities, values, C, in.background}, image, alpha, depth,
                              st.final_T.data(), st.n_contrib.data()};
  const ForwardTileFn<T> forward_tile_fn = tile_kernels<T>(C).first;
#pragma omp parallel
  {
    TileScratch<T> scratch;
#pragma omp for schedule(dynamic, 1)
    for (int t = 0; t < n_tiles; ++t) forward_tile_fn(job, t, scratch);
  }
}

template <class T>
void rasterize_backward_cpu(const SplatInputs<T>& in, const SplatForwardState<T>& st, const T* dL_dimage,
                            const T* dL_dalpha, const T* dL_ddepth, SplatGradients<T>& grads) {
  const SplatCamera<T>& cam = st.cam;
  const int N = in.n;
  const bool sh = in.use_sh();
  const int C = sh ? 3 : in.channels;
  const int K = sh ? sh_coeff_count(in.sh_degree) : 0;
  const int n_tiles = cam.tiles_x() * cam.tiles_y();
  const size_t n_pix = static_cast<size_t>(cam.width) * cam.height;
  std::vector<T> zero_image;
  if (!dL_dimage) {
    zero_image.assign(n_pix * C, T(0));
    dL_dimage = zero_image.data();
  }
  // per Gaussian: mean2d 2, |mean2d| 2, conic 3, opacity, depth; and values C
  std::vector<T> geom(static_cast<size_t>(N) * 9, T(0));
  std::vector<T> color_grad;
  T* value_grad = grads.features;
  if (sh || !value_grad) {
    color_grad.assign(static_cast<size_t>(N) * C, T(0));
    value_grad = color_grad.data();
  }
  const T* values = sh ? st.colors.data() : in.features;
  StripedLocks locks;
  const BackwardTileJob<T> job{{cam, st, in.opacities, values, C, in.background}, dL_dimage, dL_dalpha, dL_ddepth,
                               geom.data(), value_grad, locks};
  const BackwardTileFn<T> backward_tile_fn = tile_kernels<T>(C).second;
#pragma omp parallel
  {
    TileScratch<T> scratch;
#pragma omp for schedule(dynamic, 1)
    for (int t = 0; t < n_tiles; ++t) backward_tile_fn(job, t, scratch);
  }
  // per Gaussian: screen-space gradients -> 3D parameters (preprocess backward)
  const Vec3<T> campos = cam.center();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < N; ++i) {
    if (!st.proj[i].visible) continue;
    const T* g = geom.data() + static_cast<size_t>(i) * 9;
    if (grads.mean2d) grads.mean2d[2 * i] += g[0], grads.mean2d[2 * i + 1] += g[1];
    if (grads.mean2d_abs) grads.mean2d_abs[2 * i] += g[2], grads.mean2d_abs[2 * i + 1] += g[3];
    if (grads.opacities) grads.opacities[i] += g[7];
    const Vec3<T> mean = vec3_at(in.means, i);
    const Mat3<T> Sigma = covariance_3d(in.scales + 3 * i, in.quats + 4 * i);
    Mat3<T> dSigma;
    Vec3<T> dmean = project_gaussian_backward(cam, mean, Sigma, g, g + 4, g[8], dSigma);
    if (sh) {
      bool cl[3] = {st.clamped[3 * i] != 0, st.clamped[3 * i + 1] != 0, st.clamped[3 * i + 2] != 0};
      T* dsh = grads.sh ? grads.sh + static_cast<size_t>(i) * K * 3 : nullptr;
      T scratch[3 * kMaxShCoeffs] = {};
      dmean = dmean + sh_to_rgb_backward(in.sh_degree, in.sh + static_cast<size_t>(i) * K * 3, mean - campos, cl,
                                         value_grad + 3 * static_cast<size_t>(i), dsh ? dsh : scratch);
    }
    if (grads.means)
      for (int k = 0; k < 3; ++k) grads.means[3 * i + k] += dmean[k];
    T dscale[3] = {}, dq[4] = {};
    covariance_3d_backward(in.scales + 3 * i, in.quats + 4 * i, dSigma, dscale, dq);
    if (grads.scales)
      for (int k = 0; k < 3; ++k) grads.scales[3 * i + k] += dscale[k];
    if (grads.quats)
      for (int k = 0; k < 4; ++k) grads.quats[4 * i + k] += dq[k];
  }
}

#define CLS_INSTANTIATE_SPLAT(T)                                                                         \
  template SplatCamera<T> make_splat_camera<T>(const PinholeCamera&, const Pose&);                       \
  template void rasterize_forward_cpu<T>(const SplatCamera<T>&, const SplatInputs<T>&, T*, T*, T*,       \
                                         SplatForwardState<T>&);                                         \
  template void rasterize_backward_cpu<T>(const SplatInputs<T>&, const SplatForwardState<T>&, const T*, \
                                          const T*, const T*, SplatGradients<T>&);
CLS_INSTANTIATE_SPLAT(float)
CLS_INSTANTIATE_SPLAT(double)

}  // namespace cls
