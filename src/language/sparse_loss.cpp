#include "language/sparse_loss.h"

#include <ATen/ATen.h>

#include <string>

#include "core/error.h"

namespace cls {

LanguageLoss sparse_cosine_loss(const at::Tensor& weight_map, const at::Tensor& codebook, const SegMapTarget& sam,
                                const SegMapTarget& gml, const at::Tensor& coverage, const LanguageLossWeights& weights) {
  if (!weight_map.defined() || weight_map.dim() != 3 || weight_map.numel() == 0)
    throw Error("sparse cosine loss: the weight map must be a non-empty H x W x L tensor");
  if (!codebook.defined() || codebook.dim() != 2 || codebook.size(0) != weight_map.size(2))
    throw Error("sparse cosine loss: the codebook must be L x D with L = " + std::to_string(weight_map.size(2)) +
                ", the weight map's channels");
  if (!coverage.defined() || coverage.dim() != 2 || coverage.size(0) != weight_map.size(0) ||
      coverage.size(1) != weight_map.size(1))
    throw Error("sparse cosine loss: the coverage must be H x W as the weight map");
  check_seg_target(sam, weight_map, codebook.size(1), "sparse cosine loss", "SAM");
  check_seg_ids(sam, "SAM");
  if (!weights.baseline) {  // the baseline reads no CityGML map
    check_seg_target(gml, weight_map, codebook.size(1), "sparse cosine loss", "CityGML");
    check_seg_ids(gml, "CityGML");
  }

  const int64_t n = weight_map.size(0) * weight_map.size(1);
  const at::TensorOptions opts = weight_map.options().requires_grad(false);
  const at::Tensor flat = weight_map.reshape({n, weight_map.size(2)});
  const at::Tensor book = codebook.to(weight_map.device(), weight_map.scalar_type());
  // |F(v)|^2 = W(v)^T (B B^T) W(v): the L x L Gram matrix instead of the D-d features.
  const at::Tensor norm2 = (at::matmul(flat, at::matmul(book, book.t())) * flat).sum(1);
  // 1 - cos(F(v), t(v)) where the map has a target, else 0. A pixel no Gaussian reaches (W = 0) has cosine 0
  // and a gradient of (B t) / 1e-8 that no weight receives: nothing is blended there.
  const auto distance = [&](const SegMapTarget& t) {
    if (!t.ids.defined() || t.table.size(0) == 0) return at::zeros({n}, opts);
    const at::Tensor ids = t.ids.reshape({n}).to(weight_map.device(), at::kLong);
    const at::Tensor valid = ids.ge(0).to(weight_map.scalar_type());
    const at::Tensor index = ids.clamp_min(0);
    const at::Tensor table = t.table.to(weight_map.device(), weight_map.scalar_type());
    const at::Tensor projected = at::matmul(table, book.t()).index_select(0, index);  // B t(v): n x L
    const at::Tensor target2 = table.pow(2).sum(1).index_select(0, index);
    const at::Tensor cosine = (flat * projected).sum(1) / (norm2 * target2).clamp_min(1e-16).sqrt();
    return (1 - cosine) * valid;
  };
  const at::Tensor m = coverage.reshape({n}).to(weight_map.device(), weight_map.scalar_type());
  const at::Tensor d_sam = distance(sam);
  LanguageLoss out;
  out.sam = (d_sam * (1 - m)).sum() / double(n);
  out.sam_gml = (d_sam * m).sum() / double(n);
  if (weights.baseline) {
    out.citygml = at::zeros({}, opts);
    out.total = out.sam + out.sam_gml;
    return out;
  }
  out.citygml = (distance(gml) * m).sum() / double(n);
  out.total = out.sam + weights.lambda_sam * out.sam_gml + weights.lambda_citygml * out.citygml;
  return out;
}

}  // namespace cls
