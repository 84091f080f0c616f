#pragma once
// The pictures `render` writes besides plain RGB: expected depth colour-mapped, relevance over the
// render, and images side by side.
#include <ATen/core/Tensor.h>
#include <opencv2/core.hpp>

#include <vector>

#include "query/relevance_image.h"

namespace cls {

// Pixels whose rendered alpha reaches this count as covered by the model (depth, PCA fits).
constexpr double kCoveredAlpha = 0.5;

// Expected depth: the rasterizer's alpha-weighted depth / alpha where alpha > 0, else 0 (H x W float32).
at::Tensor expected_depth(const at::Tensor& depth, const at::Tensor& alpha);

// The 2nd and 98th percentiles of `depth` where `covered` holds (lo = hi - 1 below / at a single value);
// {0, 1} when nothing is covered.
MapRange depth_range(const at::Tensor& depth, const at::Tensor& covered);

// Turbo over `range` (near = dark blue, far = dark red), black where not covered.
cv::Mat colour_depth(const at::Tensor& depth, const at::Tensor& covered, MapRange range);

// The relevancy (H x W, [0, 1]) as turbo colours blended over the render: weight 0 up to 0.5 (LangSplat's
// relevancy of a query no better than the canonical phrases), rising linearly to kOverlayMaxWeight at 1.
constexpr double kOverlayMaxWeight = 0.7;
cv::Mat relevance_overlay(const cv::Mat& render_bgr, const at::Tensor& relevancy);

// Images of the same height side by side, left to right, with a 4-pixel white gap between them.
cv::Mat side_by_side(const std::vector<cv::Mat>& images);

}  // namespace cls
