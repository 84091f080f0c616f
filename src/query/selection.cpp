#include "query/selection.h"

#include <torch/types.h>

#include <set>

#include "core/error.h"

namespace cls {
namespace {

void check_scores(const at::Tensor& scores) {
  if (!scores.defined() || scores.dim() != 1) throw Error("selection: scores must be a vector (one per Gaussian)");
}

}  // namespace

at::Tensor select_by_threshold(const at::Tensor& scores, double threshold) {
  check_scores(scores);
  return torch::nonzero(scores >= threshold).reshape({-1}).to(torch::kInt64);
}

at::Tensor select_top_k(const at::Tensor& scores, int64_t k) {
  check_scores(scores);
  if (k < 0) throw Error("selection: k must not be negative");
  k = std::min<int64_t>(k, scores.size(0));
  // A stable descending sort keeps equal scores in index order, so ties go to the lower index.
  const at::Tensor order = std::get<1>(scores.sort(/*stable=*/true, /*dim=*/0, /*descending=*/true));
  return std::get<0>(order.slice(0, 0, k).sort()).to(torch::kInt64);
}

GaussianModel subset_gaussians(const GaussianModel& model, const at::Tensor& indices) {
  auto take = [&](const at::Tensor& t) { return t.defined() ? t.index_select(0, indices.to(t.device())) : t; };
  GaussianModel s;
  s.means = take(model.means);
  s.log_scales = take(model.log_scales);
  s.quats = take(model.quats);
  s.opacity_logits = take(model.opacity_logits);
  s.sh_dc = take(model.sh_dc);
  s.sh_rest = take(model.sh_rest);
  s.features = take(model.features);
  for (const auto& e : model.extras) s.extras.push_back({e.name, take(e.values)});
  return s;
}

std::string query_slug(const std::string& text) {
  std::string slug;
  bool gap = false;
  for (unsigned char c : text) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z');
    if (!keep) {
      gap = !slug.empty();
      continue;
    }
    if (gap) slug += '_';
    gap = false;
    slug += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    if (slug.size() >= 40) break;
  }
  return slug.empty() ? "query" : slug;
}

std::vector<std::string> unique_slugs(const std::vector<std::string>& texts) {
  std::vector<std::string> out;
  std::set<std::string> used;
  for (const auto& t : texts) {
    const std::string base = query_slug(t);
    std::string s = base;
    for (int i = 2; used.count(s); ++i) s = base + "_" + std::to_string(i);
    used.insert(s);
    out.push_back(s);
  }
  return out;
}

}  // namespace cls
