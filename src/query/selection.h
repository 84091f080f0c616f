#pragma once
// Selecting Gaussians by query score (paper 3.3: "threshold-based selection or ranking over the
// Gaussian set") and naming queries in file and property names.
#include <ATen/core/Tensor.h>

#include <string>
#include <vector>

#include "splat/gaussians.h"

namespace cls {

// Indices (int64, ascending) of the Gaussians with score >= threshold.
at::Tensor select_by_threshold(const at::Tensor& scores, double threshold);
// Indices (int64, ascending) of the k highest scores; ties go to the lower index; k >= N selects all.
at::Tensor select_top_k(const at::Tensor& scores, int64_t k);

// The Gaussians at `indices` (every tensor and extra; features too when defined).
GaussianModel subset_gaussians(const GaussianModel& model, const at::Tensor& indices);

// A file/property-safe name of a query text: lower-case ASCII letters and digits, other runs as '_',
// at most 40 characters ("a red roof!" -> "a_red_roof"); "query" when nothing is left.
std::string query_slug(const std::string& text);
// query_slug of each text, made unique with suffixes _2, _3 ... in order.
std::vector<std::string> unique_slugs(const std::vector<std::string>& texts);

}  // namespace cls
