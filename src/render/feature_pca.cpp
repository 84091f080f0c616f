#include "render/feature_pca.h"

#include <torch/torch.h>

#include "core/error.h"

namespace cls {

FeaturePca fit_feature_pca(const at::Tensor& features, const at::Tensor& mask, int64_t max_samples) {
  if (features.dim() != 3) throw Error("feature PCA: expected an H x W x C map, got " + c10::str(features.sizes()));
  const int64_t C = features.size(2);
  at::Tensor x = features.reshape({-1, C}).to(torch::kCPU, torch::kFloat64);
  if (mask.defined()) x = x.index({mask.reshape({-1}).to(torch::kCPU, torch::kBool)});
  if (x.size(0) == 0) throw Error("feature PCA: no pixel to fit the components on");
  if (max_samples > 0 && x.size(0) > max_samples) x = x.slice(0, 0, x.size(0), (x.size(0) + max_samples - 1) / max_samples);

  FeaturePca pca;
  pca.mean = x.mean(0);
  const at::Tensor centred = x - pca.mean;
  const at::Tensor cov = centred.t().matmul(centred) / double(std::max<int64_t>(1, x.size(0) - 1));
  const at::Tensor vectors = std::get<1>(at::linalg_eigh(cov, "L"));  // ascending eigenvalues
  const int64_t k = std::min<int64_t>(3, C);
  pca.components = torch::zeros({C, 3}, torch::kFloat64);
  pca.components.slice(1, 0, k).copy_(vectors.flip(1).slice(1, 0, k));
  const at::Tensor biggest = pca.components.abs().argmax(0);
  const at::Tensor sign = pca.components.gather(0, biggest.unsqueeze(0)).sign().squeeze(0);
  pca.components *= torch::where(sign == 0, torch::ones_like(sign), sign);

  const at::Tensor proj = centred.matmul(pca.components);
  const at::Tensor q = torch::quantile(proj, torch::tensor({0.01, 0.99}, torch::kFloat64), 0);  // 2 x 3
  pca.lo = q[0];
  pca.hi = q[1];
  return pca;
}

at::Tensor apply_feature_pca(const FeaturePca& pca, const at::Tensor& features) {
  if (features.dim() != 3 || features.size(2) != pca.mean.size(0))
    throw Error("feature PCA: the map has " + c10::str(features.sizes()) + ", the components expect " +
                std::to_string(pca.mean.size(0)) + " channels");
  const at::Tensor proj = (features.reshape({-1, features.size(2)}).to(torch::kCPU, torch::kFloat64) - pca.mean).matmul(pca.components);
  const at::Tensor span = (pca.hi - pca.lo).clamp_min(1e-12);  // a flat component maps to 0
  return ((proj - pca.lo) / span).clamp(0, 1).reshape({features.size(0), features.size(1), 3}).to(torch::kFloat32);
}

}  // namespace cls
