#pragma once
// The rasterizer as LibTorch autograd functions: CPU tensors (float32 or float64) run
// rasterize_cpu.h; CUDA float32 tensors run the kernels of rasterize_cuda.h where the build links the
// CUDA backend (CLS_WITH_CUDA). All tensors on the means' device.
//
// Inputs are activated parameters as in 3DGS's GaussianRasterizer: means N x 3, scales N x 3 (> 0),
// quats N x 4 (w, x, y, z; normalised inside, gradients flow to the raw values), opacities N,
// and either SH coefficients N x K x 3 (colour, K >= (degree+1)^2) or features N x C.
// GaussianModel supplies them (scales(), opacities(), quats, sh() / features).
#include <ATen/core/Tensor.h>

#include <cstddef>
#include <memory>

#include "scene/camera.h"

namespace cls {

// The blend weights of Gaussians that do not move, kept between calls (rasterize_cpu.h's BlendWeights): a loop
// that trains features on frozen geometry (language training) keeps one per view in RasterizeSettings. The
// first call given an empty one records into it; later calls read it instead of projecting, sorting and
// blending. For CPU tensors, features dense or sparse, and no gradient to the geometry (cls::Error otherwise);
// the same images and gradients as without it (to the bit on one thread, but within rounding for dense features
// of 1 or 3 channels). It holds the geometry tensors it was recorded with and remembers their versions, the
// camera and the dtype: a call with others is a cls::Error, not a silently wrong image.
struct BlendCache;
std::shared_ptr<BlendCache> make_blend_cache();
std::size_t blend_cache_bytes(const BlendCache& cache);  // 0 until a call records it

struct RasterizeSettings {
  PinholeCamera camera;
  Pose pose;  // world to camera
  at::Tensor background;  // C values, or undefined for zero (not differentiated)
  // Densification statistics: when defined (N x 2, same dtype), the backward adds the per-pixel sum
  // of |dL/dmean2d| (AbsGS / gsplat absgrad) to it.
  at::Tensor mean2d_abs_grad;
  // When set: the view's blend weights, recorded on the first call and read on later ones (BlendCache).
  std::shared_ptr<BlendCache> blend_cache;
};

// The weights settings.blend_cache holds (rasterize_cpu.h), checked to be of these Gaussians (CPU, contiguous, dtype
// T), this camera and pose as a call through the cache checks them, and no gradient to the geometry (cls::Error
// otherwise); null without a cache or before a call recorded it. For passes of their own over the weights (rasterize_recorded_loss_cpu).
template <class T>
struct BlendWeights;
template <class T>
const BlendWeights<T>* recorded_blend_weights(const at::Tensor& means, const at::Tensor& scales,
                                              const at::Tensor& quats, const at::Tensor& opacities,
                                              const RasterizeSettings& settings);

struct RasterizeOutput {
  at::Tensor image;  // H x W x C (channel-last)
  at::Tensor alpha;  // H x W, 1 - final transmittance
  at::Tensor depth;  // H x W, sum_i alpha_i T_i z_i (not normalised by alpha)
  at::Tensor radii;  // N int32 screen radius in pixels, 0 where culled (not differentiable)
};

// `means2d`: optional N x 2 tensor (zeros, requires_grad) that receives dL/dmean2d in pixels, the
// screen-space gradient densification thresholds (3DGS's screenspace_points). May be undefined.
// `sh_degree` uses the first (degree+1)^2 coefficients of `sh` (the active degree during training).
RasterizeOutput rasterize_sh(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                             const at::Tensor& opacities, const at::Tensor& sh, int sh_degree,
                             const at::Tensor& means2d, const RasterizeSettings& settings);

// C feature channels (e.g. 128 language latents); no SH, no view dependence.
RasterizeOutput rasterize_features(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                   const at::Tensor& opacities, const at::Tensor& features,
                                   const at::Tensor& means2d, const RasterizeSettings& settings);

// Sparse features (LangSplatV2's sparse coefficient splatting): Gaussian i holds K weights (weights N x K)
// at channels indices N x K (int32, each in [0, C), repeats add) of a C-channel image, zero elsewhere.
// The image equals rasterize_features of the weights scattered into N x C (the reference the tests
// compare), at a cost per Gaussian and pixel of K instead of C. Gradients flow to the weights (and the
// geometry). On CUDA tensors the sparse kernels take up to kCudaSparseMaxNnz (16) weights on frozen geometry;
// with more, or with a geometry gradient, the weights are scattered and rasterize_features runs.
RasterizeOutput rasterize_sparse_features(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                          const at::Tensor& opacities, const at::Tensor& weights,
                                          const at::Tensor& indices, int channels, const at::Tensor& means2d,
                                          const RasterizeSettings& settings);

// The cosines of rasterize_sparse_features' image with P directions, the image read as coordinates in a
// basis B (C x D, e.g. the sparse language field's codebook): image H x W x P of cos(w B, p) in place of the
// C-channel w (0 where w B = 0); alpha, depth and radii as rasterize_sparse_features. `directions` P x C holds
// a_p = B p / |p|, `factor` k x C the R of B^T = Q R (zero below the diagonal; k = min(C, D)), so that
// |w B| = |R w| (rasterize_cpu.h's ChannelCosines). What a relevance map needs, C^2 / 2 + P C multiply-adds per
// pixel taken while the pixel's w is in registers, without the C-channel image. No background, no gradients.
// CPU tensors only (cls::Error on others: a GPU renders the weights and takes their cosines with LibTorch).
// settings.blend_cache, when set, is read or recorded as by rasterize_sparse_features.
RasterizeOutput rasterize_sparse_cosines(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                         const at::Tensor& opacities, const at::Tensor& weights,
                                         const at::Tensor& indices, int channels, const at::Tensor& directions,
                                         const at::Tensor& factor, const RasterizeSettings& settings);

// cls::Error from `what` (the caller) unless weights and indices are N x K for the means' N, the weights of the
// means' dtype, the indices int32 on the means' device, each in [0, channels): rasterize_sparse_features' checks.
void check_sparse_inputs(const char* what, const at::Tensor& means, const at::Tensor& weights, const at::Tensor& indices,
                         int channels);

// Sparse features as dense ones: weights N x K scattered into N x C at their indices (zero elsewhere; repeats
// add). The image of rasterize_features on it is rasterize_sparse_features' image.
at::Tensor scatter_sparse_features(const at::Tensor& weights, const at::Tensor& indices, int channels);

// The transpose of rasterize_features: per Gaussian, the values of the pixels it is blended into, weighted
// by its alpha T there: sum_p alpha_ip T_ip values(p), N x C for `values` H x W x C (the means' dtype and
// device). For every X, <rasterize_features(X).image, values> = <X, lift_to_gaussians(values)> on a zero
// background: how per-pixel quantities are lifted onto the Gaussians. The features' backward on the given
// geometry (no gradient reaches it, nor settings.mean2d_abs_grad, nor the background); works under a
// NoGradGuard too.
at::Tensor lift_to_gaussians(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                             const at::Tensor& opacities, const at::Tensor& values, const RasterizeSettings& settings);

}  // namespace cls
