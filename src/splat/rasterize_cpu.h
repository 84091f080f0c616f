#pragma once
// Tile-based CPU rasterizer of 3D Gaussians (the 3DGS pipeline: project, bin into 16x16 tiles sorted
// by depth, blend front to back per tile) and its backward pass. Plain arrays, no LibTorch, templated
// on the scalar type: float for speed, double for finite-difference gradient checks.
// Multithreaded over Gaussians and tiles with OpenMP (omp_get_max_threads()).
#include <cstdint>
#include <vector>

#include "splat/project_gaussian.h"

namespace cls {

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

// Outputs: image H x W x C (channel-last), alpha = 1 - T_final (H x W), depth = sum_i alpha_i T_i z_i
// (H x W, the expected camera z of the blended surface, not normalised by alpha).
template <class T>
void rasterize_forward_cpu(const SplatCamera<T>& cam, const SplatInputs<T>& in, T* image, T* alpha, T* depth,
                           SplatForwardState<T>& state);

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

// dL_dimage H x W x C, dL_dalpha and dL_ddepth H x W (each may be null for zero).
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
