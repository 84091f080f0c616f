#pragma once
// Tile-based CPU rasterizer of 3D Gaussians (the 3DGS pipeline: project, bin into 16x16 tiles sorted
// by depth, blend front to back per tile) and its backward pass. Plain arrays, no LibTorch, templated
// on the scalar type: float for speed, double for finite-difference gradient checks.
// Multithreaded over Gaussians and tiles with OpenMP (omp_get_max_threads()).
#include <cstdint>
#include <vector>

#include "splat/project_gaussian.h"

namespace cls {

// Cosines in place of the channels (forward only; the sparse language field's relevance maps, issue 36): a
// pixel's C blended channels w are the coordinates of a feature F = B^T w in a basis B (C x D, the codebook),
// and the image holds cos(F, p) for P directions p instead of w: cos = <a_p, w> / |R w| with a_p = B p / |p|
// and R (k x C, zero below the diagonal) from B B^T = R^T R (B^T = Q R, k = min(C, D)), so |F| = |R w|; 0
// where R w = 0. Taken from the blended w while it is in registers: C^2 / 2 + P C multiply-adds per pixel,
// where the C channels would be written, read back and multiplied by C x C in a separate pass.
template <class T>
struct ChannelCosines {
  const T* directions = nullptr;  // P x C: the a_p
  const T* factor = nullptr;      // k x C: R
  int count = 0;                  // P; 0: no cosines, the image holds the channels
  int factor_rows = 0;            // k
};

// Inputs, Gaussian-major, activated (as the original's rasterizer takes them):
// means N x 3, scales N x 3 (positive), quats N x 4 (w, x, y, z; normalised inside),
// opacities N (in (0, 1)), and either SH coefficients N x (degree+1)^2 x 3 (colour, 3 channels)
// or features N x C (C arbitrary channels; SH is skipped entirely).
template <class T>
struct SplatInputs {
  int n = 0;
  const T* means = nullptr;
  const T* scales = nullptr;
  const T* quats = nullptr;
  const T* opacities = nullptr;
  const T* sh = nullptr;  // with sh_degree >= 0
  int sh_degree = -1;
  const T* features = nullptr;  // with channels = C
  int channels = 3;
  // Sparse features: `features` holds N x nnz weights and feature_index their channels in [0, C) (a
  // Gaussian's weights at other channels are zero), so blending costs nnz per Gaussian and pixel, not C.
  const int32_t* feature_index = nullptr;
  int nnz = 0;
  const T* background = nullptr;  // C values, or null for zero
  // With cosines.count = P > 0 the forward's image is H x W x P cosines (features only, no background);
  // rasterize_backward_cpu rejects such inputs.
  ChannelCosines<T> cosines;
  bool use_sh() const { return sh != nullptr; }
};

// What the forward keeps for the backward: per-Gaussian projections, per-tile ranges of the sorted
// instance list, and per pixel only the final transmittance and the number of list entries walked up
// to the last contributor (no per-pixel id lists).
template <class T>
struct SplatForwardState {
  SplatCamera<T> cam;
  std::vector<ProjectedGaussian<T>> proj;  // N
  std::vector<T> colors;                   // N x C values blended (SH colours or a copy-free view)
  std::vector<uint8_t> clamped;            // N x 3, SH path only
  std::vector<int32_t> tile_begin, tile_end;  // per tile, into ids
  std::vector<int32_t> ids;                // Gaussian ids, grouped by tile, front to back
  std::vector<T> final_T;                  // H x W
  std::vector<int32_t> n_contrib;          // H x W
};

// The blend weights of frozen Gaussians in one view: what a language field trained on a photometric model that
// no longer moves (paper 3.3) would otherwise recompute every iteration. Per 16x16 tile the Gaussians of its
// list that add to any of its pixels (in list order), and per 4x4 sub-tile the entries that do, front to back,
// each with its 16 pixels' weights w = alpha T (0 in the pixels it does not add to; pixel l of the sub-tile at
// column l % 4, row l / 4); per pixel the final transmittance and depth; per Gaussian its screen radius. A
// forward records them (rasterize_forward_cpu's `record`); forwards and backwards of other features on the same
// Gaussians and camera then read them (rasterize_*_recorded_cpu) instead of projecting, sorting and testing
// every entry of every list: bench_language's 480x360 view of 50k Gaussians walks 130 list entries per pixel, of
// which 66 add. The walk's image and gradients, to the bit on one thread (tests), but for dense features of 1 or 3
// channels (the walk's fixed-channel builds: within rounding); 4 + 16 sizeof(T) bytes
// per entry (64 % of the lanes non-zero there): 74 MiB for that view, 337 MiB for 1080p with 200k Gaussians.
template <class T>
struct BlendWeights {
  static constexpr int kSubTiles = 16;  // per tile
  static constexpr int kLanes = 16;     // pixels per sub-tile
  struct Tile {
    std::vector<int32_t> ids;     // the Gaussians that add to a pixel, in the tile list's (depth) order
    std::vector<int32_t> slot;    // per entry: its Gaussian's index in ids
    std::vector<T> weights;       // per entry: kLanes weights
    int32_t begin[kSubTiles] = {}, end[kSubTiles] = {};  // sub-tile q's entries (empty outside the image)
  };
  SplatCamera<T> cam;  // the camera recorded (its size and pose)
  int n = 0;           // the Gaussians' count
  std::vector<Tile> tiles;
  std::vector<T> final_T, depth;  // H x W
  std::vector<int32_t> radii;     // N, 0 where culled
  size_t bytes() const;           // the memory held
};

// Outputs: image H x W x C (channel-last; H x W x P with in.cosines), alpha = 1 - T_final (H x W),
// depth = sum_i alpha_i T_i z_i (H x W, the expected camera z of the blended surface, not normalised by alpha).
// With `record` the forward also fills it (for features or SH alike: the weights do not depend on the values).
template <class T>
void rasterize_forward_cpu(const SplatCamera<T>& cam, const SplatInputs<T>& in, T* image, T* alpha, T* depth,
                           SplatForwardState<T>& state, BlendWeights<T>* record = nullptr);

// radii[i]: Gaussian i's screen radius in pixels from a forward's projection, 0 where culled (N values).
template <class T>
void screen_radii(const SplatForwardState<T>& state, int32_t* radii);

// The forward of features (dense or sparse, optional background and cosines; no SH) from recorded blend
// weights: image, alpha and depth as rasterize_forward_cpu's. std::invalid_argument for SH or another
// Gaussian count than recorded.
template <class T>
void rasterize_forward_recorded_cpu(const BlendWeights<T>& weights, const SplatInputs<T>& in, T* image, T* alpha,
                                    T* depth);

// The features' gradient (zero-initialised by the caller, N x C or N x nnz) from recorded blend weights for
// dL_dimage H x W x C: rasterize_backward_cpu's without geometry gradients (the alpha and depth images do not
// depend on the features). std::invalid_argument as rasterize_forward_recorded_cpu, or for cosines.
template <class T>
void rasterize_backward_recorded_cpu(const BlendWeights<T>& weights, const SplatInputs<T>& in, const T* dL_dimage,
                                     T* features_grad);

// A loss of the image, taken a tile at a time inside rasterize_recorded_loss_cpu: for a tile's `rows` pixels
// (pixels[r]: row r's index in the H x W image, the tile's pixels row by row) their image rows x C in, their
// dL/dimage rows x C out. Called for every tile, from several threads at once (omp_get_thread_num() tells
// them apart; the calls of one thread do not overlap).
template <class T>
struct TileLoss {
  virtual ~TileLoss() = default;
  virtual void tile(const int64_t* pixels, int rows, const T* image, T* dL_dimage) = 0;
};

// rasterize_forward_recorded_cpu, `loss` on its image and rasterize_backward_recorded_cpu of the loss's
// dL/dimage in one pass over the tiles: each tile's image and gradient stay in the thread's cache and its
// recorded weights are read a second time from there (separately, the H x W x C image and its gradient are
// written and read back through memory, and every weight is read from memory twice). The same features'
// gradient (zero-initialised by the caller, N x C or N x nnz) as the three steps, within rounding (the loss
// sees tiles, not the whole image, so sums it keeps over pixels may add in another order). Features without
// background or cosines; std::invalid_argument as rasterize_forward_recorded_cpu, or for those.
template <class T>
void rasterize_recorded_loss_cpu(const BlendWeights<T>& weights, const SplatInputs<T>& in, TileLoss<T>& loss,
                                 T* features_grad);

// Gradients (each zero-initialised by the caller, shapes as the inputs): means, scales, quats,
// opacities, sh or features; mean2d N x 2 (screen space, pixels) and its absolute per-pixel sum.
template <class T>
struct SplatGradients {
  T* means = nullptr;
  T* scales = nullptr;
  T* quats = nullptr;
  T* opacities = nullptr;
  T* sh = nullptr;
  T* features = nullptr;  // N x C, or N x nnz for sparse features
  T* mean2d = nullptr;
  T* mean2d_abs = nullptr;
};

// dL_dimage H x W x C, dL_dalpha and dL_ddepth H x W (each may be null for zero). std::invalid_argument
// for inputs with cosines (ChannelCosines has no backward).
template <class T>
void rasterize_backward_cpu(const SplatInputs<T>& in, const SplatForwardState<T>& state, const T* dL_dimage,
                            const T* dL_dalpha, const T* dL_ddepth, SplatGradients<T>& grads);

// Instruction-set builds of the per-tile blending (forward and backward): the x86-64 baseline (SSE2),
// x86-64-v3 (AVX2, FMA) and x86-64-v4 (AVX-512). The best one the CPU runs is used, unless the environment
// variable CITYLANGSPLAT_CPU_KERNELS names a lower one (baseline, x86-64-v3); results differ between builds
// by float rounding only (FMA contraction), each within the reference renderer's tolerances (tests).
#if defined(__x86_64__) && defined(__GNUC__)
#define CLS_X86_KERNELS 1
#else
#define CLS_X86_KERNELS 0
#endif
enum class CpuKernels { Baseline = 0, X86_64_V3 = 1, X86_64_V4 = 2 };
CpuKernels best_cpu_kernels();
CpuKernels cpu_kernels();                        // the build in use
std::vector<CpuKernels> available_cpu_kernels();  // every build this CPU runs, baseline first
// Uses `k` from now on in this process (tests, benchmarks); std::invalid_argument above best_cpu_kernels().
void set_cpu_kernels(CpuKernels k);
const char* cpu_kernels_name(CpuKernels k);

// The SplatCamera of a pinhole camera and world-to-camera pose (src/scene/camera.h).
struct PinholeCamera;
struct Pose;
template <class T>
SplatCamera<T> make_splat_camera(const PinholeCamera& cam, const Pose& pose);

}  // namespace cls
