#include "language/language_loss.h"

#include <ATen/ATen.h>

#include <string>

#include "core/error.h"

namespace cls {

LatentTarget gather_latent_target(const int32_t* ids, int height, int width, const at::Tensor& table,
                                  const char* what) {
  if (table.dim() != 2) throw Error(std::string(what) + ": latent table must be K x L");
  const int64_t k = table.size(0);
  const int64_t n = int64_t(height) * width;
  at::Tensor index = at::empty({n}, at::kLong);
  at::Tensor valid = at::empty({n}, at::kFloat);
  int64_t* ip = index.data_ptr<int64_t>();
  float* vp = valid.data_ptr<float>();
  for (int64_t i = 0; i < n; ++i) {
    const int32_t id = ids[i];
    if (id < -1 || id >= k)
      throw Error(std::string(what) + ": segment id " + std::to_string(id) + " outside [-1, " + std::to_string(k) + ")");
    // Invalid pixels gather row 0 (or a zero row when the table is empty) and are zeroed below.
    ip[i] = id < 0 ? 0 : id;
    vp[i] = id < 0 ? 0.f : 1.f;
  }
  const at::Tensor src = table.to(at::kFloat);
  LatentTarget t;
  if (k == 0) {
    t.latents = at::zeros({height, width, table.size(1)}, src.options());
  } else {
    t.latents = src.index_select(0, index.to(src.device())).mul_(valid.to(src.device()).unsqueeze(1))
                    .view({height, width, table.size(1)});
  }
  t.valid = valid.to(src.device()).view({height, width});
  return t;
}

namespace {

// sum_v w(v) |a(v) - b(v)|_1 / (H W L)
at::Tensor masked_l1(const at::Tensor& a, const at::Tensor& b, const at::Tensor& w) {
  return ((a - b).abs() * w.unsqueeze(-1)).sum() / double(a.numel());
}

void check_map(const at::Tensor& t, const at::Tensor& rendered, const char* name, bool channels) {
  const bool ok = t.defined() && t.dim() == (channels ? 3 : 2) && t.size(0) == rendered.size(0) &&
                  t.size(1) == rendered.size(1) && (!channels || t.size(2) == rendered.size(2));
  if (!ok) throw Error(std::string("language loss: ") + name + " does not match the rendered H x W x L map");
}

}  // namespace

LanguageLoss language_loss(const LanguageLossInputs& in, const LanguageLossWeights& w) {
  if (!in.rendered.defined() || in.rendered.dim() != 3)
    throw Error("language loss: rendered latents must be H x W x L");
  check_map(in.sam.latents, in.rendered, "SAM target", true);
  check_map(in.sam.valid, in.rendered, "SAM validity", false);
  check_map(in.coverage, in.rendered, "coverage", false);
  const at::Tensor& z = in.rendered;
  const at::Tensor m = in.coverage.to(z.scalar_type());
  const at::Tensor sam_valid = in.sam.valid.to(z.scalar_type());
  const at::Tensor sam_abs = (z - in.sam.latents.to(z.scalar_type())).abs();
  LanguageLoss out;
  const double denom = double(z.numel());
  out.sam = (sam_abs * (sam_valid * (1 - m)).unsqueeze(-1)).sum() / denom;
  out.sam_gml = (sam_abs * (sam_valid * m).unsqueeze(-1)).sum() / denom;
  if (w.baseline) {
    out.citygml = at::zeros({}, z.options().requires_grad(false));
    out.total = out.sam + out.sam_gml;
    return out;
  }
  check_map(in.gml.latents, in.rendered, "CityGML target", true);
  check_map(in.gml.valid, in.rendered, "CityGML validity", false);
  out.citygml = masked_l1(z, in.gml.latents.to(z.scalar_type()), m * in.gml.valid.to(z.scalar_type()));
  out.total = out.sam + w.lambda_sam * out.sam_gml + w.lambda_citygml * out.citygml;
  return out;
}

}  // namespace cls
