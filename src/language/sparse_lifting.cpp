#include "language/sparse_lifting.h"

#include <ATen/ATen.h>
#include <torch/nn/functional/normalization.h>

#include <tuple>

#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "language/seg_loss_pixel.h"

namespace cls {
namespace {

// Rows scaled to unit length (torch's normalize: x / max(|x|, 1e-12), so zero rows stay zero).
at::Tensor unit_length(const at::Tensor& rows) {
  return torch::nn::functional::normalize(rows, torch::nn::functional::NormalizeFuncOptions().dim(1));
}

// What one view lifts: per pixel, the loss-weighted cosines of its targets with the bases (L channels) and
// the sum of those weights (one more): H x W x (L + 1).
at::Tensor pixel_values(const LiftingView& v, const at::Tensor& basis, const LanguageLossWeights& lw) {
  const int64_t h = v.coverage.size(0), w = v.coverage.size(1), n = h * w, bases = basis.size(0);
  const SegLossWeights sw{lw.lambda_sam, lw.lambda_citygml, lw.baseline, 1.0};
  const at::Tensor cover = v.coverage.to(at::kCPU, at::kFloat).contiguous();
  const float* m = cover.data_ptr<float>();
  at::Tensor cosines = at::zeros({n, bases}, basis.options());
  at::Tensor weight_sum = at::zeros({n}, at::kFloat);
  using Weigh = float (*)(const SegLossWeights&, int, float);
  for (const auto& [target, weigh, name] : {std::tuple{&v.sam, Weigh(sam_weight), "sparse lifting: SAM seg map"},
                                            std::tuple{&v.gml, Weigh(citygml_weight), "sparse lifting: CityGML seg map"}}) {
    if (!target->ids.defined() || (lw.baseline && target == &v.gml)) continue;  // the baseline has no CityGML term
    const at::Tensor ids = target->ids.to(at::kCPU, at::kInt).contiguous();
    if (ids.numel() != n) throw Error(cat(name, " is not ", h, " x ", w));
    const int32_t* id = ids.data_ptr<int32_t>();
    const at::Tensor table = at::matmul(unit_length(target->table.to(basis.device(), at::kFloat)), basis.t());
    const LatentTarget gathered = gather_latent_target(id, int(h), int(w), table, name);  // checks the ids
    at::Tensor weight = at::empty({n}, at::kFloat);
    float* wp = weight.data_ptr<float>();
    for (int64_t i = 0; i < n; ++i) wp[i] = weigh(sw, id[i], m[i]);
    cosines += gathered.latents.view({n, bases}) * weight.to(basis.device()).unsqueeze(1);
    weight_sum += weight;
  }
  return at::cat({cosines, weight_sum.to(basis.device()).unsqueeze(1)}, 1).view({h, w, bases + 1});
}

}  // namespace

at::Tensor lifted_logits(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                         const at::Tensor& opacities, int64_t views, const std::function<LiftingView(int64_t)>& view,
                         const at::Tensor& codebook, const LanguageLossWeights& weights, double temperature) {
  if (!(temperature > 0)) throw Error("sparse lifting: the temperature must be positive");
  const at::Tensor basis = unit_length(codebook.detach().to(means.device(), at::kFloat));
  const int64_t bases = basis.size(0);
  at::Tensor sums = at::zeros({means.size(0), bases + 1}, means.options());
  Progress progress("lifting the targets onto the Gaussians", uint64_t(views), "views");
  for (int64_t i = 0; i < views; ++i) {
    const LiftingView v = view(i);
    sums += lift_to_gaussians(means, scales, quats, opacities, pixel_values(v, basis, weights).to(means.scalar_type()),
                              v.settings);
    progress.advance();
  }
  progress.finish();
  return sums.slice(1, 0, bases) / (sums.slice(1, bases) + 1) / temperature;
}

}  // namespace cls
