#pragma once
// Feature maps as colour pictures (LangSplat's and nerfstudio's feature images): the three principal
// components of the per-pixel features become R, G and B.
#include <ATen/core/Tensor.h>

#include <cstdint>

namespace cls {

struct FeaturePca {
  at::Tensor mean;        // C, float64
  at::Tensor components;  // C x 3, float64, unit columns by decreasing variance (zero columns if C < 3)
  at::Tensor lo, hi;      // 3, the 1st and 99th percentiles of the fit pixels' projections
};

// Principal components of the pixels of `features` (H x W x C) where `mask` (H x W bool; undefined = all)
// holds, from at most `max_samples` of them taken at an even stride. Each component's sign makes its
// largest-magnitude entry positive, so the colours do not flip between runs. cls::Error if no pixel is
// selected.
FeaturePca fit_feature_pca(const at::Tensor& features, const at::Tensor& mask = {}, int64_t max_samples = 1 << 16);

// H x W x 3 float32 in [0, 1]: the projections on the components, mapped [lo, hi] -> [0, 1] and clamped.
// Fitting once and applying to many views keeps one colour per feature across them.
at::Tensor apply_feature_pca(const FeaturePca& pca, const at::Tensor& features);

}  // namespace cls
