#pragma once
// The Gaussian scene model (3DGS's GaussianModel): raw, unconstrained parameters as LibTorch tensors;
// the activations (exp, sigmoid, normalise) give what the rasterizer takes.
#include <ATen/core/Tensor.h>

#include <string>
#include <vector>

namespace cls {

// An extra per-Gaussian value written to the PLY as its own property (class id, score ...).
struct GaussianExtra {
  std::string name;
  at::Tensor values;  // N, float32 or int32
};

struct GaussianModel {
  at::Tensor means;           // N x 3
  at::Tensor log_scales;      // N x 3 (scale = exp)
  at::Tensor quats;           // N x 4, (w, x, y, z), unit after normalisation
  at::Tensor opacity_logits;  // N x 1 (opacity = sigmoid)
  at::Tensor sh_dc;           // N x 1 x 3
  at::Tensor sh_rest;         // N x ((degree+1)^2 - 1) x 3, coefficient-major as in 3DGS
  at::Tensor features;        // N x F language latents, or undefined
  std::vector<GaussianExtra> extras;

  int64_t size() const { return means.defined() ? means.size(0) : 0; }
  int sh_degree() const;  // from sh_rest: 0, 3, 8, 15 coefficients -> 0..3
  int feature_channels() const { return features.defined() ? int(features.size(1)) : 0; }

  at::Tensor scales() const;     // exp(log_scales)
  at::Tensor opacities() const;  // sigmoid(opacity_logits), N
  at::Tensor sh() const;         // N x (degree+1)^2 x 3
  const GaussianExtra* extra(const std::string& name) const;

  // Shapes and dtypes (float32; extras float32 or int32) consistent; cls::Error naming `what` otherwise.
  void validate(const std::string& what) const;
};

// N Gaussians with SH degree `sh_degree` and `features` latent channels, all parameters zero except
// unit quaternions (for building models in code and tests).
GaussianModel make_gaussians(int64_t n, int sh_degree, int features = 0);

}  // namespace cls
