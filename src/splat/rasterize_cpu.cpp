// CPU rasterizer: see rasterize_cpu.h. The per-Gaussian and per-pixel math lives in the shared
// headers (project_gaussian.h, blend_pixel.h, sh.h) that the CUDA kernels use as well.
// -Wpsabi: see blend_lanes.h (its lane vectors never cross a call).
#pragma GCC diagnostic ignored "-Wpsabi"
#include "splat/rasterize_cpu.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "scene/camera.h"
#include "splat/blend_lanes.h"
#include "splat/blend_pixel.h"
#include "splat/cosine_lanes.h"
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
  T depth;
  T box[4];  // xmin, xmax, ymin, ymax: a conservative bound of where alpha >= 1/255
  int32_t id;
};

// Pixels walk only the Gaussians whose cutoff ellipse box overlaps their 4x4 sub-tile: the others
// would all have alpha < 1/255 there, so results are the same, with ~16x fewer evaluations.
constexpr int kSubTile = 4;

// Bounding box of {d : -0.5 d^T Q d >= cutoff}: half-widths sqrt(R (Q^-1)_xx), sqrt(R (Q^-1)_yy) with
// R = -2 cutoff (alpha_cutoff_power), widened by a margin far beyond rounding.
template <class T>
void cutoff_box(TileGaussian<T>& g, T cutoff) {
  const T R = T(-2) * cutoff;
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

constexpr int kSubTilesPerSide = kTileSize / kSubTile;
constexpr int kSubTilesPerTile = kSubTilesPerSide * kSubTilesPerSide;

// The sub-tile lists of one tile: for sub-tile q (column i, row j: q = j * kSubTilesPerSide + i), the
// indices into the tile's list of the Gaussians whose box reaches one of its pixel centres, in list
// (depth) order. Each row has room for the whole list, so filling one needs no capacity check.
struct SubTileLists {
  std::vector<int32_t> index;  // kSubTilesPerTile rows of `stride`
  int stride = 0;
  int count[kSubTilesPerTile] = {};
  const int32_t* row(int q) const { return index.data() + static_cast<size_t>(q) * stride; }
};

// Fills `out` for the tile whose first pixel is (x0, y0) in one pass over its list. The overlap tests
// are combined as bits, not branches: which sub-tiles a Gaussian reaches is unpredictable, and the
// branches' mispredictions were most of this pass's time.
template <class T>
void subtile_lists(const std::vector<TileGaussian<T>>& list, int x0, int y0, SubTileLists& out) {
  const int L = static_cast<int>(list.size());
  out.stride = L;
  if (out.index.size() < static_cast<size_t>(kSubTilesPerTile) * L) out.index.resize(static_cast<size_t>(kSubTilesPerTile) * L);
  int32_t* const index = out.index.data();
  int* const count = out.count;
  for (int q = 0; q < kSubTilesPerTile; ++q) count[q] = 0;
  static_assert(kSubTilesPerSide == 4, "a row of sub-tiles is a 4-bit group of the mask");
  for (int k = 0; k < L; ++k) {
    const T* b = list[k].box;
    unsigned cols = 0, rows = 0;
    for (int i = 0; i < kSubTilesPerSide; ++i) {
      const int sx = x0 + i * kSubTile, sy = y0 + i * kSubTile;
      cols |= unsigned((b[1] >= T(sx) + T(0.5)) & (b[0] <= T(sx + kSubTile) - T(0.5))) << i;
      rows |= unsigned((b[3] >= T(sy) + T(0.5)) & (b[2] <= T(sy + kSubTile) - T(0.5))) << i;
    }
    // bit j * 4 + i: row j and column i (row j's bit moved to bit 4 j, times the column bits)
    unsigned mask = cols * ((rows & 1u) | (rows & 2u) << 3 | (rows & 4u) << 6 | (rows & 8u) << 9);
    while (mask) {
      const int q = __builtin_ctz(mask);
      index[static_cast<size_t>(q) * L + count[q]++] = k;
      mask &= mask - 1;
    }
  }
}

// What the tiles read of every visible Gaussian, made once per pass rather than once per tile it
// touches (1.4 M tile instances of 200k Gaussians in bench_splat).
template <class T>
std::vector<TileGaussian<T>> tile_gaussians(const SplatForwardState<T>& st, const T* opacities) {
  const int N = static_cast<int>(st.proj.size());
  std::vector<TileGaussian<T>> out(N);
#pragma omp parallel for schedule(static)
  for (int id = 0; id < N; ++id) {
    const ProjectedGaussian<T>& p = st.proj[id];
    if (!p.visible) continue;
    TileGaussian<T>& g = out[id];
    g.mean2d[0] = p.mean2d[0], g.mean2d[1] = p.mean2d[1];
    g.conic[0] = p.conic[0], g.conic[1] = p.conic[1], g.conic[2] = p.conic[2];
    g.opacity = opacities[id];
    g.depth = p.depth;
    g.id = id;
    cutoff_box(g, alpha_cutoff_power(g.opacity));
  }
  return out;
}

template <class T>
void gather_tile(const SplatForwardState<T>& st, const TileGaussian<T>* gaussians, int tile,
                 std::vector<TileGaussian<T>>& out) {
  const int begin = st.tile_begin[tile], end = st.tile_end[tile];
  out.resize(end - begin);
  for (int k = begin; k < end; ++k) out[k - begin] = gaussians[st.ids[k]];
}

// Values per Gaussian: the channels, or a sparse Gaussian's weights.
template <class T>
int value_count(const SplatInputs<T>& in) {
  return in.feature_index ? in.nnz : in.use_sh() ? 3 : in.channels;
}

// What every tile of a pass reads.
template <class T>
struct TileInputs {
  const SplatCamera<T>& cam;
  const SplatForwardState<T>& st;
  const TileGaussian<T>* gaussians;  // tile_gaussians()
  const T* values;
  int C;
  const T* bg;
  const int32_t* index;  // sparse values: their channels (SplatInputs::feature_index), else null
  int nv;                // values per Gaussian: C, or the sparse values' count
};

// What every tile of a forward pass writes.
template <class T>
struct ForwardTileJob : TileInputs<T> {
  T *image, *alpha_out, *depth_out, *final_T;
  int32_t* n_contrib;
  ChannelCosines<T> cosines;  // count > 0: the image holds these instead of the channels
  BlendWeights<T>* record;    // non-null: the weights recorded here (tiles sized)
};

// Where the per-Gaussian sums of a tile go: each thread's own copy of the values' gradients (thread t's at
// thread_value_grad + t * thread_stride; no geometry), or the global sums under striped locks.
template <class T>
struct GradientSink {
  T *geom_grad, *value_grad;  // geom_grad null: only the values' gradients
  StripedLocks& locks;
  T* thread_value_grad;
  size_t thread_stride;
};
// What every tile of a backward pass reads besides, and writes.
template <class T>
struct BackwardTileJob : TileInputs<T> {
  const T *dL_dimage, *dL_dalpha, *dL_ddepth;
  GradientSink<T> sink;  // sink.geom_grad null: only the values' gradients (no alpha gradient)
};

// A thread's buffers, reused from tile to tile.
// One vector of lanes as a struct: std::vector drops a vector type's alignment from its template
// argument, a struct's alignment it keeps.
template <class T>
struct alignas(sizeof(Lanes<T>)) LaneRow {
  Lanes<T> v;
};
static_assert(sizeof(LaneRow<float>) == sizeof(Lanes<float>), "LaneRow arrays are arrays of lanes");

template <class T>
struct TileScratch {
  std::vector<LaneRow<T>> acc, dpix;  // C rows each, with a run-time channel count
  std::vector<LaneRow<T>> cosine;     // the forward's ChannelCosines, P rows
  std::vector<T> buf;
  std::vector<LaneRow<T>> value_buf;  // the backward's value sums with a run-time channel count
  std::vector<uint8_t> touched;
  std::vector<int32_t> slot_of;       // recording: a list entry's index in the tile's ids
  std::vector<TileGaussian<T>> list;
  SubTileLists sub;
  std::vector<int64_t> tile_pixels;      // rasterize_recorded_loss_cpu: the tile's pixels,
  std::vector<T> tile_image, tile_grad;  // its image and dL/dimage (TileLoss's rows)
};

// The pixel of lane l of the sub-tile whose first pixel is (sx, sy), or -1 outside the image.
[[gnu::always_inline]] inline int64_t lane_pixel(const int sx, const int sy, const int l, const int x1, const int y1, const int width) {
  const int px = sx + l % kLaneSide, py = sy + l / kLaneSide;
  return px < x1 && py < y1 ? static_cast<int64_t>(py) * width + px : -1;
}

// The pixels of a tile: [x0, x1) x [y0, y1), clipped to the image.
struct TileRect {
  int x0, y0, x1, y1;
};
template <class T>
TileRect tile_rect(const SplatCamera<T>& cam, int tile) {
  const int x0 = tile % cam.tiles_x() * kTileSize, y0 = tile / cam.tiles_x() * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, cam.width), std::min(y0 + kTileSize, cam.height)};
}

// Lane l's row among a tile's own pixels, row by row (TileLoss's rows), or -1 outside the image.
[[gnu::always_inline]] inline int64_t lane_tile_row(const int sx, const int sy, const int l, const int x0, const int y0,
                                                    const int x1, const int y1) {
  const int px = sx + l % kLaneSide, py = sy + l / kLaneSide;
  return px < x1 && py < y1 ? static_cast<int64_t>(py - y0) * (x1 - x0) + (px - x0) : -1;
}

// Pixel centres of the sub-tile's lanes.
template <class T>
[[gnu::always_inline]] inline void lane_centres(const int sx, const int sy, Lanes<T>& cx, Lanes<T>& cy) {
  for (int l = 0; l < kLanes; ++l) cx[l] = T(sx + l % kLaneSide) + T(0.5), cy[l] = T(sy + l / kLaneSide) + T(0.5);
}

// acc[c] += sum over k of w[k] values[k][c], in order of k, for many channels: a register of lanes of eight
// channels stays in registers while the n contributions are added (each would otherwise load and store all
// of acc); kBytes: the build's register size (blend_lanes.h).
template <int kBytes, class T>
[[gnu::always_inline]] inline void add_weighted_values(Lanes<T>* acc, const Lanes<T>* w, const T* const* values, int n,
                                                       int nc) {
  using P = typename NativeVector<T, kBytes>::V;
  constexpr int R = 8;
  int c = 0;
  for (; c + R <= nc; c += R)
    for (std::size_t at = 0; at < sizeof(Lanes<T>); at += kBytes) {
      P sum[R];
      for (int r = 0; r < R; ++r) sum[r] = lane_register<kBytes>(acc[c + r], at);
      for (int k = 0; k < n; ++k) {
        const P wk = lane_register<kBytes>(w[k], at);
        for (int r = 0; r < R; ++r) sum[r] += wk * values[k][c + r];
      }
      for (int r = 0; r < R; ++r) set_lane_register<kBytes>(acc[c + r], at, sum[r]);
    }
  for (; c < nc; ++c)
    for (int k = 0; k < n; ++k) lane_add_scaled<kBytes>(acc[c], w[k], values[k][c]);
}

// The forward's sum of a sub-tile's entries with a run-time channel count, acc[c] += w v[c] per entry (w: its
// lanes' alpha T, 0 where it does not add): sparse values into their channels; many channels wait in a batch and
// are added eight entries at a time (add_weighted_values; finish_value_sums adds the rest). The walk and the
// recorded weights' forward share it, so their images agree to the bit.
template <class T>
struct ValueSums {
  static constexpr int kBatch = 8;
  ValueSums(Lanes<T>* acc_, int nc_, const T* values_, const int32_t* index_, int nv_)
      : acc(acc_), nc(nc_), values(values_), index(index_), nv(nv_) {}
  Lanes<T>* acc;
  int nc;
  const T* values;
  const int32_t* index;  // sparse: the values' channels, else null
  int nv;
  Lanes<T> batch_w[kBatch];
  const T* batch_v[kBatch];
  int batched = 0;
};
template <int kBytes, class T>
[[gnu::always_inline]] inline void add_value_sums(ValueSums<T>& a, const Lanes<T>& w, int32_t id) {
  const T* v = a.values + static_cast<size_t>(id) * a.nv;
  if (a.index) {
    const int32_t* idx = a.index + static_cast<size_t>(id) * a.nv;
    for (int k = 0; k < a.nv; ++k) lane_add_scaled<kBytes>(a.acc[idx[k]], w, v[k]);
  } else {  // (a NaN value reaches the sub-tile's other lanes here: NaN features are an error upstream)
    a.batch_w[a.batched] = w, a.batch_v[a.batched++] = v;
    if (a.batched == ValueSums<T>::kBatch) add_weighted_values<kBytes>(a.acc, a.batch_w, a.batch_v, a.batched, a.nc), a.batched = 0;
  }
}
template <int kBytes, class T>
[[gnu::always_inline]] inline void finish_value_sums(ValueSums<T>& a) {
  add_weighted_values<kBytes>(a.acc, a.batch_w, a.batch_v, a.batched, a.nc);
  a.batched = 0;
}

// A sub-tile's pixels of the image from its blended channels acc and final transmittance Tr: the channels plus
// Tr times the background, or their cosines (`blended`: anything was blended here, else the cosines are 0).
template <int kBytes, class T>
[[gnu::always_inline]] inline void write_subtile_image(const Lanes<T>* acc, int nc, const Lanes<T>& Tr, const T* bg,
                                                       const ChannelCosines<T>& cosines, bool blended,
                                                       TileScratch<T>& s, const int64_t* pixel, T* image) {
  const int n_cos = cosines.count;
  if (n_cos > 0) {
    s.cosine.resize(n_cos);
    if (blended)
      lane_cosines<kBytes>(acc, nc, cosines, &s.cosine[0].v);
    else
      for (int q = 0; q < n_cos; ++q) s.cosine[q].v = Lanes<T>{};
  }
  for (int l = 0; l < kLanes; ++l) {
    const int64_t pix = pixel[l];
    if (pix < 0) continue;
    if (n_cos > 0) {
      T* out = image + pix * n_cos;
      for (int q = 0; q < n_cos; ++q) out[q] = s.cosine[q].v[l];
    } else {
      T* out = image + pix * nc;
      for (int c = 0; c < nc; ++c) out[c] = acc[c][l] + (bg ? Tr[l] * bg[c] : T(0));
    }
  }
}

// Recording: entry k of the tile's list adds w to the sub-tile's pixels (slot holds list indices until
// finish_recorded_tile numbers them).
template <class T>
void record_entry(typename BlendWeights<T>::Tile& rec, int k, const Lanes<T>& w) {
  rec.slot.push_back(k);
  const size_t at = rec.weights.size();
  rec.weights.resize(at + kLanes);
  std::memcpy(rec.weights.data() + at, &w, sizeof(w));
}

// The tile's Gaussians that added (ids in list order) and each entry's slot among them.
template <class T>
void finish_recorded_tile(typename BlendWeights<T>::Tile& rec, const std::vector<TileGaussian<T>>& list,
                          std::vector<int32_t>& slot_of) {
  slot_of.assign(list.size(), -1);
  for (int32_t k : rec.slot) slot_of[k] = 0;
  rec.ids.clear();
  for (size_t k = 0; k < list.size(); ++k)
    if (slot_of[k] == 0) slot_of[k] = static_cast<int32_t>(rec.ids.size()), rec.ids.push_back(list[k].id);
  for (int32_t& k : rec.slot) k = slot_of[k];
  // kept for many iterations: no spare capacity (BlendWeights::bytes counts sizes)
  rec.ids.shrink_to_fit();
  rec.slot.shrink_to_fit();
  rec.weights.shrink_to_fit();
}

// Front-to-back blending of one tile (renderCUDA), a 4x4 sub-tile at a time with one lane per pixel
// (blend_lanes.h). kC > 0 fixes the channel count at compile time (RGB), kC = 0 loops over C at run time.
// Always inlined: the kernel builds below compile it once per instruction set.
template <class T, int kC, int kBytes>
[[gnu::always_inline]] inline void forward_tile(const ForwardTileJob<T>& j, int tile, TileScratch<T>& s) {
  using V = Lanes<T>;
  using M = LaneMask<T>;
  static_assert(kLaneSide == kSubTile, "one lane per pixel of a sub-tile");
  const SplatCamera<T>& cam = j.cam;
  const T* const values = j.values;
  std::vector<TileGaussian<T>>& list = s.list;
  const int nc = kC > 0 ? kC : j.C;
  const auto [x0, y0, x1, y1] = tile_rect(cam, tile);
  gather_tile(j.st, j.gaussians, tile, list);
  subtile_lists(list, x0, y0, s.sub);
  typename BlendWeights<T>::Tile* const rec = j.record ? &j.record->tiles[tile] : nullptr;
  // fixed-size channels live on the stack (registers for RGB)
  V acc_fixed[kC > 0 ? kC : 1];
  if (kC == 0) s.acc.resize(nc);
  V* const acc = kC > 0 ? acc_fixed : &s.acc[0].v;
  for (int sy = y0; sy < y1; sy += kSubTile)
  for (int sx = x0; sx < x1; sx += kSubTile) {
    const int q = (sy - y0) / kSubTile * kSubTilesPerSide + (sx - x0) / kSubTile;
    const int32_t* const sub = s.sub.row(q);
    const int L = s.sub.count[q];
    V cx, cy;
    lane_centres<T>(sx, sy, cx, cy);
    int64_t pixel[kLanes];
    M live;  // lanes inside the image that have not stopped
    for (int l = 0; l < kLanes; ++l) live[l] = (pixel[l] = lane_pixel(sx, sy, l, x1, y1, cam.width)) >= 0 ? -1 : 0;
    V Tr = V{} + T(1), d = V{};
    M last = M{};
    for (int c = 0; c < nc; ++c) acc[c] = V{};
    ValueSums<T> sums{acc, nc, values, j.index, j.nv};
    if (rec) rec->begin[q] = static_cast<int32_t>(rec->slot.size());
    for (int k = 0; k < L; ++k) {
      const TileGaussian<T>& g = list[sub[k]];
      const V power = gaussian_power(g.mean2d, g.conic, cx, cy);
      M pass = live;  // nearly every entry of a sub-tile list has a lane within its cutoff
      V G;
      const V a = lane_alpha<kBytes>(power, g.opacity, pass, G);
      // An entry no lane passes adds zeros. Sparse values are not worth the test: their few adds cost less (the
      // sparse field's 1080p map ran 8-12 % faster without it); RGB ran as fast either way.
      if (!j.index && !any_lane(pass)) continue;
      const V test_T = Tr * (T(1) - a);
      const M stop = pass & lane_less<kBytes>(test_T, V{} + T(kTransmittanceMin));
      pass &= ~stop;
      const V w = lane_select<kBytes>(pass, a * Tr, V{});
      if (kC > 0) {
        const T* v = values + static_cast<size_t>(g.id) * j.nv;
        for (int c = 0; c < nc; ++c) acc[c] += lane_select<kBytes>(pass, w * v[c], V{});
      } else {
        add_value_sums<kBytes>(sums, w, g.id);
      }
      if (rec && any_lane(pass)) record_entry<T>(*rec, sub[k], w);
      d += w * g.depth;
      Tr = lane_select<kBytes>(pass, test_T, Tr);
      last = lane_select<kBytes>(pass, M{} + (k + 1), last);
      if (any_lane(stop)) {
        live &= ~stop;
        if (!any_lane(live)) break;
      }
    }
    if (kC == 0) finish_value_sums<kBytes>(sums);
    if (rec) rec->end[q] = static_cast<int32_t>(rec->slot.size());
    write_subtile_image<kBytes>(acc, nc, Tr, j.bg, kC > 0 ? ChannelCosines<T>{} : j.cosines, L > 0, s, pixel, j.image);
    for (int l = 0; l < kLanes; ++l) {
      const int64_t pix = pixel[l];
      if (pix < 0) continue;
      j.alpha_out[pix] = T(1) - Tr[l];
      j.depth_out[pix] = d[l];
      j.final_T[pix] = Tr[l];
      j.n_contrib[pix] = static_cast<int32_t>(last[l]);  // entries of the sub-tile list walked
    }
  }
  if (rec) finish_recorded_tile<T>(*rec, list, s.slot_of);
}

// The forward of one tile from recorded weights (forward_tile's sums without the walk) into j.image, or with
// `tile_image` into the tile's own rows (lane_tile_row). Run-time channel counts only.
template <class T>
struct RecordedForwardJob {
  const BlendWeights<T>& bw;
  const T* values;
  int C;
  const T* bg;
  const int32_t* index;
  int nv;
  ChannelCosines<T> cosines;
  T* image;
};

template <class T, int kBytes>
[[gnu::always_inline]] inline void recorded_forward_tile(const RecordedForwardJob<T>& j, int tile, TileScratch<T>& s,
                                                        T* tile_image = nullptr) {
  using V = Lanes<T>;
  const SplatCamera<T>& cam = j.bw.cam;
  const typename BlendWeights<T>::Tile& rec = j.bw.tiles[tile];
  const auto [x0, y0, x1, y1] = tile_rect(cam, tile);
  s.acc.resize(j.C);
  V* const acc = &s.acc[0].v;
  for (int sy = y0; sy < y1; sy += kSubTile)
  for (int sx = x0; sx < x1; sx += kSubTile) {
    const int q = (sy - y0) / kSubTile * kSubTilesPerSide + (sx - x0) / kSubTile;
    int64_t pixel[kLanes], row[kLanes];
    V Tr;
    for (int l = 0; l < kLanes; ++l) {
      pixel[l] = lane_pixel(sx, sy, l, x1, y1, cam.width);
      row[l] = tile_image ? lane_tile_row(sx, sy, l, x0, y0, x1, y1) : pixel[l];
      Tr[l] = pixel[l] < 0 ? T(1) : j.bw.final_T[pixel[l]];
    }
    for (int c = 0; c < j.C; ++c) acc[c] = V{};
    ValueSums<T> sums{acc, j.C, j.values, j.index, j.nv};
    for (int e = rec.begin[q]; e < rec.end[q]; ++e) {
      V w;
      std::memcpy(&w, rec.weights.data() + static_cast<size_t>(e) * kLanes, sizeof(w));
      add_value_sums<kBytes>(sums, w, rec.ids[rec.slot[e]]);
    }
    finish_value_sums<kBytes>(sums);
    write_subtile_image<kBytes>(acc, j.C, Tr, j.bg, j.cosines, rec.end[q] > rec.begin[q], s, row,
                                tile_image ? tile_image : j.image);
  }
}

// Backward of one tile: re-walks each sub-tile's list backwards from its pixels' last contributors (the
// original's renderCUDA backward, one lane per pixel), summing per-entry gradients over the lanes in `buf`
// (stride 9 + kC: mean2d 2, |mean2d| 2, conic 3, opacity, depth, and a fixed count of values), or with a
// run-time channel count the values in `value_buf` (rows of whole vectors, so their vector loads and
// stores do not straddle cache lines), then adds them to the per-Gaussian sums under striped locks. Sparse
// values keep a row of lanes per value, summed over the lanes once per entry and tile: a sum over the lanes
// per entry and sub-tile (a 16-vector transpose for four values) was the sparse backward's largest part.
// value_grad += sum over the lanes where `pass` of w_l dL/dimage(pixel_l), for many channels: eight
// registers of channels stay in registers while the lanes are added (one sum would otherwise be loaded
// and stored per lane), then one register and single channels for the rest.
template <int kBytes, class T>
[[gnu::always_inline]] inline void add_lane_rows(const Lanes<T>& w, const LaneMask<T>& pass, const T* dL_dimage,
                                                 const int64_t* pixel, int nc, T* value_grad) {
  using P = typename NativeVector<T, kBytes>::V;
  constexpr int kPer = kBytes / sizeof(T), R = 8;
  const T* rows[kLanes];
  T weights[kLanes];
  int n = 0;
  for (int l = 0; l < kLanes; ++l)
    if (pass[l]) rows[n] = dL_dimage + pixel[l] * nc, weights[n++] = w[l];
  auto add_block = [&](int c, auto regs) {  // `regs` registers of channels from c
    constexpr int kRegs = decltype(regs)::value;
    P sum[kRegs];
    std::memcpy(sum, value_grad + c, sizeof(sum));
    for (int k = 0; k < n; ++k)
      for (int r = 0; r < kRegs; ++r) {
        P d;
        std::memcpy(&d, rows[k] + c + r * kPer, kBytes);
        sum[r] += weights[k] * d;
      }
    std::memcpy(value_grad + c, sum, sizeof(sum));
  };
  int c = 0;
  for (; c + R * kPer <= nc; c += R * kPer) add_block(c, std::integral_constant<int, R>{});
  for (; c + kPer <= nc; c += kPer) add_block(c, std::integral_constant<int, 1>{});
  for (; c < nc; ++c)
    for (int k = 0; k < n; ++k) value_grad[c] += weights[k] * rows[k][c];
}

// dL/dimage of a sub-tile's pixels per channel across the lanes (dpix[c][l]), 0 in the pixels outside the
// image or nothing was blended into (`covered`): the lane sums multiply by w = 0 there rather than select (a
// select per sum costs the RGB backward ~20 %), and an inf or NaN there (a loss divided by alpha) would reach
// the Gaussians of the other lanes.
template <class T>
[[gnu::always_inline]] inline void load_pixel_grads(const T* dL_dimage, int nc, int l, int64_t pix, bool covered,
                                                    Lanes<T>* dpix) {
  for (int c = 0; c < nc; ++c) dpix[c][l] = covered ? dL_dimage[pix * nc + c] : T(0);
}

// Where a backward's per-entry value sums go (run-time channel counts): value_buf rows per entry, each value's
// lanes for sparse values (summed over the lanes once per entry and tile by finish_entry_value_grads), else
// the sums themselves (add_lane_rows). The walk and the recorded weights' backward share these, so their
// gradients agree to the bit on one thread.
template <class T>
struct EntryValueGrads {
  const T* dL_dimage;
  const int32_t* index;  // sparse: the values' channels, else null
  int nv, nc;
  LaneRow<T>* rows;      // TileScratch::value_buf
  int VS;                // rows per entry
  T* sums(int k) const { return reinterpret_cast<T*>(rows + static_cast<size_t>(k) * VS); }
};
template <class T>
EntryValueGrads<T> entry_value_grads(const T* dL_dimage, const int32_t* index, int nv, int nc, int entries,
                                     TileScratch<T>& s) {
  const int VS = index ? nv : (nv + kLanes - 1) / kLanes;
  if (index)  // an entry's rows are set when it is first touched
    s.value_buf.resize(static_cast<size_t>(entries) * VS);
  else
    s.value_buf.assign(static_cast<size_t>(entries) * VS, LaneRow<T>{});
  return {dL_dimage, index, nv, nc, s.value_buf.data(), VS};
}
// Entry k of Gaussian `id` with weights w (0 outside `pass`) in a sub-tile whose pixels' gradients are dpix.
template <int kBytes, class T>
[[gnu::always_inline]] inline void add_entry_value_grads(const EntryValueGrads<T>& g, int k, int32_t id, bool first,
                                                         const Lanes<T>& w, const LaneMask<T>& pass,
                                                         const Lanes<T>* dpix, const int64_t* pixel) {
  if (g.index) {  // each value's channel per lane (w = 0 where not passing)
    const int32_t* idx = g.index + static_cast<size_t>(id) * g.nv;
    LaneRow<T>* rows = g.rows + static_cast<size_t>(k) * g.nv;
    for (int c = 0; c < g.nv; ++c) rows[c].v = (first ? Lanes<T>{} : rows[c].v) + w * dpix[idx[c]];
  } else {
    add_lane_rows<kBytes>(w, pass, g.dL_dimage, pixel, g.nc, g.sums(k));
  }
}
// Entry k's value gradients, summed over the lanes (sparse: each value's lanes, into the entry's first rows).
template <class T>
[[gnu::always_inline]] inline const T* finish_entry_value_grads(const EntryValueGrads<T>& g, int k) {
  T* sums = g.sums(k);
  if (g.index) {
    const LaneRow<T>* rows = g.rows + static_cast<size_t>(k) * g.nv;
    for (int c0 = 0; c0 < g.nv; c0 += kLanes) {
      Lanes<T> r[kLanes] = {};
      const int n = std::min(kLanes, g.nv - c0);
      for (int c = 0; c < n; ++c) r[c] = rows[c0 + c].v;
      const Lanes<T> total = lane_sums(r);
      for (int c = 0; c < n; ++c) sums[c0 + c] = total[c];
    }
  }
  return sums;
}

// Adds Gaussian id's sums: geometry (9; null without geometry gradients) and nv values.
template <class T>
[[gnu::always_inline]] inline void add_gaussian_grads(const GradientSink<T>& out, int32_t id, const T* geom, const T* values,
                                                      int nv) {
  if (out.thread_value_grad) {  // no geometry: this thread's own sums
    T* vg = out.thread_value_grad + omp_get_thread_num() * out.thread_stride + static_cast<size_t>(id) * nv;
#pragma omp simd
    for (int c = 0; c < nv; ++c) vg[c] += values[c];
    return;
  }
  out.locks.lock(id);
  if (geom) {
    T* gg = out.geom_grad + static_cast<size_t>(id) * 9;
    for (int c = 0; c < 9; ++c) gg[c] += geom[c];
  }
  T* vg = out.value_grad + static_cast<size_t>(id) * nv;
#pragma omp simd
  for (int c = 0; c < nv; ++c) vg[c] += values[c];
  out.locks.unlock(id);
}

// A thread's own sums of Gaussian id (GradientSink::thread_value_grad), fetched ahead of add_gaussian_grads: read
// by Gaussian id, scattered over N rows, they missed the cache (a fifth of rasterize_recorded_loss_cpu waited for
// them; prefetching the forward's values the same way gained nothing). Backwards prefetch kPrefetchAhead
// Gaussians ahead.
constexpr int kPrefetchAhead = 8;
template <class T>
[[gnu::always_inline]] inline void prefetch_gaussian_grads(const GradientSink<T>& out, int32_t id, int nv) {
  if (out.thread_value_grad)
    __builtin_prefetch(out.thread_value_grad + omp_get_thread_num() * out.thread_stride + static_cast<size_t>(id) * nv, 1);
}

template <class T, int kC, int kBytes>
[[gnu::always_inline]] inline void backward_tile(const BackwardTileJob<T>& j, int tile, TileScratch<T>& s) {
  using V = Lanes<T>;
  using M = LaneMask<T>;
  const SplatCamera<T>& cam = j.cam;
  const SplatForwardState<T>& st = j.st;
  const T* const values = j.values;
  const T* const dL_dimage = j.dL_dimage;
  const T* const bg = j.bg;
  const bool geometry = j.sink.geom_grad != nullptr;
  std::vector<T>& buf = s.buf;
  std::vector<uint8_t>& touched = s.touched;
  std::vector<TileGaussian<T>>& list = s.list;
  static_assert(9 + kC <= kLanes, "buf's fixed-channel entries are summed as one vector of lanes");
  const int nc = kC > 0 ? kC : j.C;
  const int S = 9 + kC;
  const int nv = j.nv;
  const auto [x0, y0, x1, y1] = tile_rect(cam, tile);
  gather_tile(st, j.gaussians, tile, list);
  const int L = static_cast<int>(list.size());
  if (L == 0) return;
  subtile_lists(list, x0, y0, s.sub);
  buf.assign(static_cast<size_t>(L) * S, T(0));
  const EntryValueGrads<T> vgrads =
      kC == 0 ? entry_value_grads(dL_dimage, j.index, nv, nc, L, s) : EntryValueGrads<T>{};
  touched.assign(L, 0);
  // dL/dimage per channel across the lanes (registers for RGB)
  V dpix_fixed[kC > 0 ? kC : 1];
  if (kC == 0) s.dpix.resize(nc);
  V* const dpix = kC > 0 ? dpix_fixed : &s.dpix.data()->v;
  for (int sy = y0; sy < y1; sy += kSubTile)
  for (int sx = x0; sx < x1; sx += kSubTile) {
    V cx, cy, T_final, dA, dD, bg_dot;
    lane_centres<T>(sx, sy, cx, cy);
    M n_lane;
    int64_t pixel[kLanes];
    int n_max = 0;
    for (int l = 0; l < kLanes; ++l) {
      const int64_t pix = pixel[l] = lane_pixel(sx, sy, l, x1, y1, cam.width);
      n_lane[l] = pix < 0 ? 0 : st.n_contrib[pix];
      n_max = std::max(n_max, static_cast<int>(n_lane[l]));
      T_final[l] = pix < 0 ? T(1) : st.final_T[pix];
      const bool covered = n_lane[l] > 0;
      dA[l] = covered && j.dL_dalpha ? j.dL_dalpha[pix] : T(0);
      dD[l] = covered && j.dL_ddepth ? j.dL_ddepth[pix] : T(0);
      load_pixel_grads(dL_dimage, nc, l, pix, covered, dpix);
      bg_dot[l] = T(0);
      if (bg && geometry)  // the background's part of dL/dalpha (only the geometry's gradients read it)
        for (int c = 0; c < nc; ++c) bg_dot[l] += bg[c] * dpix[c][l];
    }
    if (n_max == 0) continue;
    const int32_t* const sub = s.sub.row((sy - y0) / kSubTile * kSubTilesPerSide + (sx - x0) / kSubTile);
    // The values' part of entry k's gradients, w its lanes' alpha T (0 outside pass).
    auto add_values = [&](int k, const TileGaussian<T>& g, const V& w, const M& pass, V* q) {
      const bool first = !touched[k];
      touched[k] = 1;
      if (kC > 0) {  // summed over the lanes with the geometry's
        for (int c = 0; c < kC; ++c) q[9 + c] = w * dpix[c];
        const V sums = lane_sums(q);
        T* e = buf.data() + static_cast<size_t>(k) * S;
        for (int i = 0; i < 9 + kC; ++i) e[i] += sums[i];
      } else {
        add_entry_value_grads<kBytes>(vgrads, k, g.id, first, w, pass, dpix, pixel);
      }
    };
    if (!geometry) {
      // Only w = alpha T per lane: front to back as the forward blended, with its arithmetic (the same w, so
      // recorded weights give the same gradients), to each lane's last contributor (no stop before it).
      V Tr = V{} + T(1);
      for (int jj = 0; jj < n_max; ++jj) {
        const int k = sub[jj];
        const TileGaussian<T>& g = list[k];
        const V power = gaussian_power(g.mean2d, g.conic, cx, cy);
        M pass = (jj - n_lane) >> 31;  // jj < n_lane (a sign bit: see below)
        V G;
        const V a = lane_alpha<kBytes>(power, g.opacity, pass, G);
        if (!any_lane(pass)) continue;
        const V w = lane_select<kBytes>(pass, a * Tr, V{});
        Tr = lane_select<kBytes>(pass, Tr * (T(1) - a), Tr);
        V q[kLanes] = {};
        add_values(k, g, w, pass, q);
      }
      continue;
    }
    V Tr = T_final, last_alpha = V{}, rec_d = V{}, last_d = V{}, rec_dot = V{}, last_v_dot = V{};
    for (int jj = n_max - 1; jj >= 0; --jj) {
      const int k = sub[jj];
      const TileGaussian<T>& g = list[k];
      const V power = gaussian_power(g.mean2d, g.conic, cx, cy);
      // jj < n_lane as a sign bit, not a comparison: GCC 12 scalarises an integer and a float comparison combined
      // into one mask (lane_alpha's) in the AVX-512 build, one compare per lane
      M pass = (jj - n_lane) >> 31;
      V G;
      const V a = lane_alpha<kBytes>(power, g.opacity, pass, G);
      if (!any_lane(pass)) continue;
      // a = 0 in the other lanes, so these leave them as they are
      const V one_minus_a = T(1) - a;
      const V inv_one_minus_a = T(1) / one_minus_a;
      Tr = Tr * inv_one_minus_a;
      const V w = a * Tr;
      V q[kLanes] = {};  // this entry's gradients per lane in buf's order (a few channels included)
      const T* v = values + static_cast<size_t>(g.id) * nv;
      // dC/dalpha_i . dL/dC = T_i (v_i - rec_i) . dpix, where rec_i = sum over later contributors j of
      // v_j alpha_j prod_{i<l<j} (1 - alpha_l). rec is linear in the values, so only its dot product
      // with dpix is carried: rec_dot_i = a_{i+1} (v_{i+1} . dpix) + (1 - a_{i+1}) rec_dot_{i+1}.
      V v_dot = V{};
      if (kC > 0) {
        for (int c = 0; c < nc; ++c) lane_add_scaled<kBytes>(v_dot, dpix[c], v[c]);
      } else if (j.index) {
        const int32_t* idx = j.index + static_cast<size_t>(g.id) * nv;
        for (int c = 0; c < nv; ++c) lane_add_scaled<kBytes>(v_dot, dpix[idx[c]], v[c]);
      } else {  // four partial sums: one would wait on the previous multiply-add every channel
        V part[4] = {};
        int c = 0;
        for (; c + 4 <= nc; c += 4)
          for (int q = 0; q < 4; ++q) lane_add_scaled<kBytes>(part[q], dpix[c + q], v[c + q]);
        for (; c < nc; ++c) lane_add_scaled<kBytes>(part[0], dpix[c], v[c]);
        v_dot = (part[0] + part[1]) + (part[2] + part[3]);
      }
      rec_dot = lane_select<kBytes>(pass, last_alpha * last_v_dot + (T(1) - last_alpha) * rec_dot, rec_dot);
      last_v_dot = lane_select<kBytes>(pass, v_dot, last_v_dot);
      V dL_da = v_dot - rec_dot;
      rec_d = lane_select<kBytes>(pass, last_alpha * last_d + (T(1) - last_alpha) * rec_d, rec_d);
      last_d = lane_select<kBytes>(pass, V{} + g.depth, last_d);
      dL_da += (g.depth - rec_d) * dD;
      dL_da *= Tr;
      // alpha = 1 - T_final and the background term T_final * bg: dT_final/dalpha = -T_final/(1-alpha)
      dL_da += (dA - bg_dot) * T_final * inv_one_minus_a;
      last_alpha = lane_select<kBytes>(pass, a, last_alpha);
      lane_alpha_backward<kBytes>(g.mean2d, g.conic, g.opacity, cx, cy, G, dL_da, pass, q);
      q[8] = w * dD;  // w = 0 where the lane does not contribute
      if (kC == 0) {  // the geometry's sums; the values' below
        const V sums = lane_sums(q);
        T* e = buf.data() + static_cast<size_t>(k) * S;
        for (int i = 0; i < 9; ++i) e[i] += sums[i];
      }
      add_values(k, g, w, pass, q);
    }
  }
  for (int k = 0; k < L; ++k) {
    if (k + kPrefetchAhead < L) prefetch_gaussian_grads(j.sink, list[k + kPrefetchAhead].id, nv);
    if (!touched[k]) continue;
    const T* e = buf.data() + static_cast<size_t>(k) * S;
    add_gaussian_grads(j.sink, list[k].id, geometry ? e : nullptr, kC > 0 ? e + 9 : finish_entry_value_grads(vgrads, k),
                       nv);
  }
}

// The backward of one tile from recorded weights (backward_tile's value gradients without the walk) of
// j.dL_dimage, or with `tile_grad` of the tile's own rows (lane_tile_row). Run-time channel counts only.
template <class T>
struct RecordedBackwardJob {
  const BlendWeights<T>& bw;
  int C;
  const int32_t* index;
  int nv;
  const T* dL_dimage;
  GradientSink<T> sink;
};

template <class T, int kBytes>
[[gnu::always_inline]] inline void recorded_backward_tile(const RecordedBackwardJob<T>& j, int tile, TileScratch<T>& s,
                                                         const T* tile_grad = nullptr) {
  using V = Lanes<T>;
  const SplatCamera<T>& cam = j.bw.cam;
  const typename BlendWeights<T>::Tile& rec = j.bw.tiles[tile];
  const int n_ids = static_cast<int>(rec.ids.size());
  if (n_ids == 0) return;
  const auto [x0, y0, x1, y1] = tile_rect(cam, tile);
  const T* const dL_dimage = tile_grad ? tile_grad : j.dL_dimage;
  const EntryValueGrads<T> vgrads = entry_value_grads(dL_dimage, j.index, j.nv, j.C, n_ids, s);
  s.touched.assign(n_ids, 0);
  s.dpix.resize(j.C);
  V* const dpix = &s.dpix.data()->v;
  for (int sy = y0; sy < y1; sy += kSubTile)
  for (int sx = x0; sx < x1; sx += kSubTile) {
    const int q = (sy - y0) / kSubTile * kSubTilesPerSide + (sx - x0) / kSubTile;
    if (rec.end[q] == rec.begin[q]) continue;
    int64_t row[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      const int64_t pix = lane_pixel(sx, sy, l, x1, y1, cam.width);
      row[l] = tile_grad ? lane_tile_row(sx, sy, l, x0, y0, x1, y1) : pix;
      // blended into (the walk's n_contrib > 0): each entry that adds lowers T below 1; dense values' sums read
      // dL/dimage's rows themselves (add_lane_rows)
      if (j.index) load_pixel_grads(dL_dimage, j.C, l, row[l], pix >= 0 && j.bw.final_T[pix] < T(1), dpix);
    }
    for (int e = rec.begin[q]; e < rec.end[q]; ++e) {
      V w;
      std::memcpy(&w, rec.weights.data() + static_cast<size_t>(e) * kLanes, sizeof(w));
      const int k = rec.slot[e];
      const bool first = !s.touched[k];
      s.touched[k] = 1;
      add_entry_value_grads<kBytes>(vgrads, k, rec.ids[k], first, w, lane_less<kBytes>(V{}, w), dpix, row);
    }
  }
  for (int k = 0; k < n_ids; ++k) {
    if (k + kPrefetchAhead < n_ids) prefetch_gaussian_grads(j.sink, rec.ids[k + kPrefetchAhead], j.nv);
    add_gaussian_grads(j.sink, rec.ids[k], static_cast<const T*>(nullptr), finish_entry_value_grads(vgrads, k), j.nv);
  }
}

// rasterize_recorded_loss_cpu's tile: its forward into the tile's rows, the loss, its backward from them.
template <class T>
struct RecordedLossJob {
  RecordedForwardJob<T> forward;    // image: none
  RecordedBackwardJob<T> backward;  // dL_dimage: none
  TileLoss<T>& loss;
};

template <class T, int kBytes>
[[gnu::always_inline]] inline void recorded_loss_tile(const RecordedLossJob<T>& j, int tile, TileScratch<T>& s) {
  const SplatCamera<T>& cam = j.forward.bw.cam;
  const auto [x0, y0, x1, y1] = tile_rect(cam, tile);
  const int rows = (x1 - x0) * (y1 - y0);
  s.tile_pixels.resize(rows);
  for (int y = y0, r = 0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) s.tile_pixels[r++] = static_cast<int64_t>(y) * cam.width + x;
  s.tile_image.resize(static_cast<size_t>(rows) * j.forward.C);
  s.tile_grad.resize(s.tile_image.size());
  recorded_forward_tile<T, kBytes>(j.forward, tile, s, s.tile_image.data());
  j.loss.tile(s.tile_pixels.data(), rows, s.tile_image.data(), s.tile_grad.data());
  recorded_backward_tile<T, kBytes>(j.backward, tile, s, s.tile_grad.data());
}

// The tile kernels per instruction set. The 16 pixel lanes run as 4 registers in the x86-64 baseline (SSE2),
// 2 with AVX2 and 1 with AVX-512 (float), as do the per-channel loops of many channels; the CPU's best
// build is picked at run time (cpu_kernels()). Only these wrappers carry a target: what they call and do
// not inline stays baseline code, so no AVX instruction runs on a CPU without it.
template <class T>
using ForwardTileFn = void (*)(const ForwardTileJob<T>&, int, TileScratch<T>&);
template <class T>
using BackwardTileFn = void (*)(const BackwardTileJob<T>&, int, TileScratch<T>&);

#define CLS_TILE_KERNELS(NAME, ATTRIBUTE, REGISTER_BYTES)                                                \
  template <class T, int kC>                                                                             \
  ATTRIBUTE void forward_tile_##NAME(const ForwardTileJob<T>& j, int tile, TileScratch<T>& s) {          \
    forward_tile<T, kC, REGISTER_BYTES>(j, tile, s);                                                     \
  }                                                                                                      \
  template <class T, int kC>                                                                             \
  ATTRIBUTE void backward_tile_##NAME(const BackwardTileJob<T>& j, int tile, TileScratch<T>& s) {        \
    backward_tile<T, kC, REGISTER_BYTES>(j, tile, s);                                                    \
  }                                                                                                      \
  template <class T>                                                                                     \
  ATTRIBUTE void recorded_forward_tile_##NAME(const RecordedForwardJob<T>& j, int tile, TileScratch<T>& s) { \
    recorded_forward_tile<T, REGISTER_BYTES>(j, tile, s);                                                \
  }                                                                                                      \
  template <class T>                                                                                     \
  ATTRIBUTE void recorded_backward_tile_##NAME(const RecordedBackwardJob<T>& j, int tile, TileScratch<T>& s) { \
    recorded_backward_tile<T, REGISTER_BYTES>(j, tile, s);                                               \
  }                                                                                                      \
  template <class T>                                                                                     \
  ATTRIBUTE void recorded_loss_tile_##NAME(const RecordedLossJob<T>& j, int tile, TileScratch<T>& s) {   \
    recorded_loss_tile<T, REGISTER_BYTES>(j, tile, s);                                                   \
  }
CLS_TILE_KERNELS(baseline, , 16)
#if CLS_X86_KERNELS
CLS_TILE_KERNELS(v3, [[gnu::target("arch=x86-64-v3")]], 32)
CLS_TILE_KERNELS(v4, [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]], 64)
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

template <class T>
struct RecordedTileKernels {
  void (*forward)(const RecordedForwardJob<T>&, int, TileScratch<T>&);
  void (*backward)(const RecordedBackwardJob<T>&, int, TileScratch<T>&);
  void (*loss)(const RecordedLossJob<T>&, int, TileScratch<T>&);
};

template <class T>
RecordedTileKernels<T> recorded_tile_kernels() {
#if CLS_X86_KERNELS
  const CpuKernels k = cpu_kernels();
  if (k == CpuKernels::X86_64_V4)
    return {&recorded_forward_tile_v4<T>, &recorded_backward_tile_v4<T>, &recorded_loss_tile_v4<T>};
  if (k == CpuKernels::X86_64_V3)
    return {&recorded_forward_tile_v3<T>, &recorded_backward_tile_v3<T>, &recorded_loss_tile_v3<T>};
#endif
  return {&recorded_forward_tile_baseline<T>, &recorded_backward_tile_baseline<T>, &recorded_loss_tile_baseline<T>};
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

// Runs a tile kernel over every tile of the image, on every thread, each with its own scratch. The order:
// column by column along strips kStripTiles tiles high, so the tiles below a tile run a few tiles after
// it (not a whole row of tiles later) and the Gaussians they share (their tile records, value rows and
// gradient sums) are still in cache.
constexpr int kStripTiles = 4;
template <class T, class Job>
void run_tiles(const SplatCamera<T>& cam, void (*tile_fn)(const Job&, int, TileScratch<T>&), const Job& job) {
  const int tiles_x = cam.tiles_x(), tiles_y = cam.tiles_y();
  std::vector<int32_t> order;
  order.reserve(static_cast<size_t>(tiles_x) * tiles_y);
  for (int y0 = 0; y0 < tiles_y; y0 += kStripTiles)
    for (int x = 0; x < tiles_x; ++x)
      for (int y = y0; y < std::min(y0 + kStripTiles, tiles_y); ++y) order.push_back(y * tiles_x + x);
  const int n = static_cast<int>(order.size());
  // An exception may not leave a parallel region (std::terminate): the first one (e.g. std::bad_alloc of a
  // recording or a scratch buffer) is kept, the remaining tiles are skipped, and it is thrown after.
  std::exception_ptr failed;
  std::atomic<bool> stop{false};
#pragma omp parallel
  {
    TileScratch<T> scratch;
#pragma omp for schedule(dynamic, 1)
    for (int t = 0; t < n; ++t) {
      if (stop.load(std::memory_order_relaxed)) continue;
      try {
        tile_fn(job, order[t], scratch);
      } catch (...) {
#pragma omp critical(cls_run_tiles_failed)
        if (!failed) failed = std::current_exception();
        stop = true;
      }
    }
  }
  if (failed) std::rethrow_exception(failed);
}

// Step 2 of the forward: st.ids grouped by tile (st.tile_begin/end), each tile's ids front to back (by
// depth, ties by id). The sort runs on (depth, id) pairs held together (not ids that look their depth
// up); the counting sort by tile runs on every thread, each over a slice of the depth order, with
// per-thread offsets so that a tile's ids keep that order.
template <class T>
void bin_by_tile(SplatForwardState<T>& st) {
  const int N = static_cast<int>(st.proj.size());
  std::vector<std::pair<T, int32_t>> keyed;
  keyed.reserve(N);
  for (int i = 0; i < N; ++i)
    if (st.proj[i].visible) keyed.emplace_back(st.proj[i].depth, i);
  std::sort(keyed.begin(), keyed.end());
  const int V = static_cast<int>(keyed.size());
  const int tiles_x = st.cam.tiles_x(), n_tiles = tiles_x * st.cam.tiles_y();
  st.tile_begin.assign(n_tiles, 0);
  st.tile_end.assign(n_tiles, 0);
  std::vector<int32_t> offset(static_cast<size_t>(omp_get_max_threads()) * n_tiles, 0);
  // the tiles of one Gaussian's rectangle, y then x
  auto for_tiles = [&](int id, auto&& f) {
    const ProjectedGaussian<T>& p = st.proj[id];
    for (int y = p.rect_min[1]; y < p.rect_max[1]; ++y)
      for (int x = p.rect_min[0]; x < p.rect_max[0]; ++x) f(y * tiles_x + x);
  };
  std::exception_ptr failed;  // (an exception may not leave a parallel region)
#pragma omp parallel
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    const int begin = static_cast<int>(static_cast<int64_t>(V) * t / nt);
    const int end = static_cast<int>(static_cast<int64_t>(V) * (t + 1) / nt);
    int32_t* const mine = offset.data() + static_cast<size_t>(t) * n_tiles;
    for (int k = begin; k < end; ++k) for_tiles(keyed[k].second, [&](int tile) { ++mine[tile]; });
#pragma omp barrier
#pragma omp single
    {
      int32_t total = 0;
      for (int tile = 0; tile < n_tiles; ++tile) {
        st.tile_begin[tile] = total;
        for (int u = 0; u < nt; ++u) {
          const int32_t c = offset[static_cast<size_t>(u) * n_tiles + tile];
          offset[static_cast<size_t>(u) * n_tiles + tile] = total;
          total += c;
        }
        st.tile_end[tile] = total;
      }
      try {
        st.ids.resize(total);
      } catch (...) {
        failed = std::current_exception();
      }
    }  // (the single's implied barrier: offsets, ids and `failed` ready)
    if (!failed)
      for (int k = begin; k < end; ++k) {
        const int32_t id = keyed[k].second;
        for_tiles(id, [&](int tile) { st.ids[mine[tile]++] = id; });
      }
  }
  if (failed) std::rethrow_exception(failed);
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
                           SplatForwardState<T>& st, BlendWeights<T>* record) {
  const int N = in.n;
  const bool sh = in.use_sh();
  const int C = sh ? 3 : in.channels;
  const int K = sh ? sh_coeff_count(in.sh_degree) : 0;
  const Vec3<T> campos = cam.center();
  if (in.cosines.count > 0 && (sh || in.background))
    throw std::invalid_argument("rasterize_forward_cpu: cosines are of features on a zero background only");
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
  // 2. per-tile lists front to back
  bin_by_tile(st);
  // 3. blend per tile
  const size_t n_pix = static_cast<size_t>(cam.width) * cam.height;
  st.final_T.resize(n_pix);
  st.n_contrib.resize(n_pix);
  const T* values = sh ? st.colors.data() : in.features;
  const std::vector<TileGaussian<T>> gaussians = tile_gaussians(st, in.opacities);
  if (record) {
    record->cam = cam;
    record->n = N;
    record->tiles.assign(static_cast<size_t>(cam.tiles_x()) * cam.tiles_y(), {});
  }
  const ForwardTileJob<T> job{{cam, st, gaussians.data(), values, C, in.background, in.feature_index, value_count(in)},
                              image, alpha, depth, st.final_T.data(), st.n_contrib.data(), in.cosines, record};
  const ForwardTileFn<T> forward_tile_fn = tile_kernels<T>(in.feature_index || in.cosines.count > 0 ? 0 : C).first;
  run_tiles(cam, forward_tile_fn, job);
  if (record) {
    record->final_T = st.final_T;
    record->depth.assign(depth, depth + n_pix);
    record->radii.resize(N);
    screen_radii(st, record->radii.data());
  }
}

template <class T>
void screen_radii(const SplatForwardState<T>& state, int32_t* radii) {
  for (size_t i = 0; i < state.proj.size(); ++i) radii[i] = state.proj[i].visible ? state.proj[i].radius : 0;
}

template <class T>
size_t BlendWeights<T>::bytes() const {
  size_t b = (final_T.size() + depth.size()) * sizeof(T) + radii.size() * sizeof(int32_t) + tiles.size() * sizeof(Tile);
  for (const Tile& t : tiles) b += (t.ids.size() + t.slot.size()) * sizeof(int32_t) + t.weights.size() * sizeof(T);
  return b;
}

namespace {

// The inputs recorded weights can serve: features of the recorded Gaussians.
template <class T>
void check_recorded(const BlendWeights<T>& bw, const SplatInputs<T>& in, const char* what) {
  static_assert(BlendWeights<T>::kLanes == kLanes && BlendWeights<T>::kSubTiles == kSubTilesPerTile,
                "recorded lanes are the tile kernels' lanes");
  if (in.use_sh() || !in.features) throw std::invalid_argument(std::string(what) + ": features only, not SH");
  if (in.cosines.count > 0 && in.background)
    throw std::invalid_argument(std::string(what) + ": cosines are of features on a zero background only");
  if (in.n != bw.n)
    throw std::invalid_argument(std::string(what) + ": the weights were recorded for " + std::to_string(bw.n) +
                                " Gaussians, not " + std::to_string(in.n));
}

// Where a backward without geometry gradients sums sparse values: a copy of the values' gradients per thread.
// Taking a striped lock per entry and tile took a fifth of the sparse backward (not the flags' sharing of
// cache lines: a cache line per flag ran no faster, docs/benchmarks.md). Up to kThreadCopiesBytes of copies
// (2M Gaussians of K 4 on 2 threads): their memory, zeroing and sum grow with threads x Gaussians, the locks'
// cost with the entries (beyond it the locks, not measured against copies). Empty: the locks.
template <class T>
std::vector<T> thread_value_copies(bool geometry, const SplatInputs<T>& in) {
  constexpr size_t kThreadCopiesBytes = size_t(64) << 20;
  const size_t value_rows = static_cast<size_t>(in.n) * value_count(in);
  const int threads = omp_get_max_threads();
  const bool copies = !geometry && in.feature_index && threads > 1 &&
                      threads * value_rows * sizeof(T) <= kThreadCopiesBytes;
  return std::vector<T>(copies ? threads * value_rows : 0, T(0));
}

// value_grad += the threads' copies.
template <class T>
void add_thread_copies(const std::vector<T>& copies, size_t value_rows, T* value_grad) {
  if (copies.empty()) return;
  const int threads = static_cast<int>(copies.size() / value_rows);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < value_rows; ++i)
    for (int t = 0; t < threads; ++t) value_grad[i] += copies[t * value_rows + i];
}

}  // namespace

template <class T>
void rasterize_forward_recorded_cpu(const BlendWeights<T>& bw, const SplatInputs<T>& in, T* image, T* alpha,
                                    T* depth) {
  check_recorded(bw, in, "rasterize_forward_recorded_cpu");
  const size_t n_pix = bw.final_T.size();
  for (size_t p = 0; p < n_pix; ++p) alpha[p] = T(1) - bw.final_T[p];
  std::copy(bw.depth.begin(), bw.depth.end(), depth);
  const RecordedForwardJob<T> job{bw, in.features, in.channels, in.background, in.feature_index, value_count(in),
                                  in.cosines, image};
  run_tiles(bw.cam, recorded_tile_kernels<T>().forward, job);
}

template <class T>
void rasterize_backward_recorded_cpu(const BlendWeights<T>& bw, const SplatInputs<T>& in, const T* dL_dimage,
                                     T* features_grad) {
  check_recorded(bw, in, "rasterize_backward_recorded_cpu");
  if (in.cosines.count > 0) throw std::invalid_argument("rasterize_backward_recorded_cpu: cosines have no backward");
  StripedLocks locks;
  std::vector<T> copies = thread_value_copies(false, in);
  const size_t value_rows = static_cast<size_t>(in.n) * value_count(in);
  const RecordedBackwardJob<T> job{bw, in.channels, in.feature_index, value_count(in), dL_dimage,
                                   {nullptr, features_grad, locks, copies.empty() ? nullptr : copies.data(), value_rows}};
  run_tiles(bw.cam, recorded_tile_kernels<T>().backward, job);
  add_thread_copies(copies, value_rows, features_grad);
}

template <class T>
void rasterize_recorded_loss_cpu(const BlendWeights<T>& bw, const SplatInputs<T>& in, TileLoss<T>& loss,
                                 T* features_grad) {
  check_recorded(bw, in, "rasterize_recorded_loss_cpu");
  if (in.cosines.count > 0 || in.background)
    throw std::invalid_argument("rasterize_recorded_loss_cpu: a loss of the features on a zero background only");
  StripedLocks locks;
  std::vector<T> copies = thread_value_copies(false, in);
  const size_t value_rows = static_cast<size_t>(in.n) * value_count(in);
  const RecordedLossJob<T> job{
      {bw, in.features, in.channels, nullptr, in.feature_index, value_count(in), {}, nullptr},
      {bw, in.channels, in.feature_index, value_count(in), nullptr,
       {nullptr, features_grad, locks, copies.empty() ? nullptr : copies.data(), value_rows}},
      loss};
  run_tiles(bw.cam, recorded_tile_kernels<T>().loss, job);
  add_thread_copies(copies, value_rows, features_grad);
}

template <class T>
void rasterize_backward_cpu(const SplatInputs<T>& in, const SplatForwardState<T>& st, const T* dL_dimage,
                            const T* dL_dalpha, const T* dL_ddepth, SplatGradients<T>& grads) {
  if (in.cosines.count > 0) throw std::invalid_argument("rasterize_backward_cpu: cosines have no backward");
  const SplatCamera<T>& cam = st.cam;
  const int N = in.n;
  const bool sh = in.use_sh();
  const int C = sh ? 3 : in.channels;
  const int K = sh ? sh_coeff_count(in.sh_degree) : 0;
  const size_t n_pix = static_cast<size_t>(cam.width) * cam.height;
  std::vector<T> zero_image;
  if (!dL_dimage) {
    zero_image.assign(n_pix * C, T(0));
    dL_dimage = zero_image.data();
  }
  // Without any geometry gradient (a language field on frozen Gaussians) only w = alpha T is needed per
  // pixel and Gaussian, not the alpha gradient.
  const bool geometry = grads.means || grads.scales || grads.quats || grads.opacities || grads.mean2d ||
                        grads.mean2d_abs;
  // per Gaussian: mean2d 2, |mean2d| 2, conic 3, opacity, depth; and values C
  std::vector<T> geom(geometry ? static_cast<size_t>(N) * 9 : 0, T(0));
  std::vector<T> color_grad;
  T* value_grad = grads.features;
  if (sh || !value_grad) {
    color_grad.assign(static_cast<size_t>(N) * value_count(in), T(0));
    value_grad = color_grad.data();
  }
  const T* values = sh ? st.colors.data() : in.features;
  StripedLocks locks;
  std::vector<T> copies = thread_value_copies(geometry, in);
  const size_t value_rows = static_cast<size_t>(N) * value_count(in);
  const std::vector<TileGaussian<T>> gaussians = tile_gaussians(st, in.opacities);
  const BackwardTileJob<T> job{{cam, st, gaussians.data(), values, C, in.background, in.feature_index, value_count(in)},
                               dL_dimage, dL_dalpha, dL_ddepth,
                               {geometry ? geom.data() : nullptr, value_grad, locks,
                                copies.empty() ? nullptr : copies.data(), value_rows}};
  const BackwardTileFn<T> backward_tile_fn = tile_kernels<T>(in.feature_index ? 0 : C).second;
  run_tiles(cam, backward_tile_fn, job);
  add_thread_copies(copies, value_rows, value_grad);
  // per Gaussian: screen-space gradients -> 3D parameters (preprocess backward)
  const Vec3<T> campos = cam.center();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < N; ++i) {
    if (!st.proj[i].visible || !(geometry || (sh && grads.sh))) continue;
    const Vec3<T> mean = vec3_at(in.means, i);
    Vec3<T> dmean{};
    if (sh) {
      bool cl[3] = {st.clamped[3 * i] != 0, st.clamped[3 * i + 1] != 0, st.clamped[3 * i + 2] != 0};
      T* dsh = grads.sh ? grads.sh + static_cast<size_t>(i) * K * 3 : nullptr;
      T scratch[3 * kMaxShCoeffs] = {};
      dmean = sh_to_rgb_backward(in.sh_degree, in.sh + static_cast<size_t>(i) * K * 3, mean - campos, cl,
                                 value_grad + 3 * static_cast<size_t>(i), dsh ? dsh : scratch);
    }
    if (!geometry) continue;
    const T* g = geom.data() + static_cast<size_t>(i) * 9;
    if (grads.mean2d) grads.mean2d[2 * i] += g[0], grads.mean2d[2 * i + 1] += g[1];
    if (grads.mean2d_abs) grads.mean2d_abs[2 * i] += g[2], grads.mean2d_abs[2 * i + 1] += g[3];
    if (grads.opacities) grads.opacities[i] += g[7];
    const Mat3<T> Sigma = covariance_3d(in.scales + 3 * i, in.quats + 4 * i);
    Mat3<T> dSigma;
    dmean = dmean + project_gaussian_backward(cam, mean, Sigma, g, g + 4, g[8], dSigma);
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
                                         SplatForwardState<T>&, BlendWeights<T>*);                       \
  template struct BlendWeights<T>;                                                                       \
  template void screen_radii<T>(const SplatForwardState<T>&, int32_t*);                                  \
  template void rasterize_forward_recorded_cpu<T>(const BlendWeights<T>&, const SplatInputs<T>&, T*, T*, T*); \
  template void rasterize_backward_recorded_cpu<T>(const BlendWeights<T>&, const SplatInputs<T>&, const T*, T*); \
  template void rasterize_recorded_loss_cpu<T>(const BlendWeights<T>&, const SplatInputs<T>&, TileLoss<T>&, T*); \
  template void rasterize_backward_cpu<T>(const SplatInputs<T>&, const SplatForwardState<T>&, const T*, \
                                          const T*, const T*, SplatGradients<T>&);
CLS_INSTANTIATE_SPLAT(float)
CLS_INSTANTIATE_SPLAT(double)

}  // namespace cls
