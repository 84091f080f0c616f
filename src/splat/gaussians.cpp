#include "splat/gaussians.h"

#include <torch/types.h>

#include "core/error.h"

namespace cls {

int GaussianModel::sh_degree() const {
  const int64_t rest = sh_rest.defined() ? sh_rest.size(1) : 0;
  for (int d = 0; d <= 3; ++d)
    if (rest == (d + 1) * (d + 1) - 1) return d;
  throw Error("Gaussian model: " + std::to_string(rest) + " higher-order SH coefficients is no SH degree 0-3");
}

at::Tensor GaussianModel::scales() const { return log_scales.exp(); }
at::Tensor GaussianModel::opacities() const { return opacity_logits.sigmoid().reshape({-1}); }
at::Tensor GaussianModel::sh() const { return sh_rest.size(1) > 0 ? torch::cat({sh_dc, sh_rest}, 1) : sh_dc; }

const GaussianExtra* GaussianModel::extra(const std::string& name) const {
  for (const auto& e : extras)
    if (e.name == name) return &e;
  return nullptr;
}

void GaussianModel::validate(const std::string& what) const {
  const int64_t n = size();
  auto check = [&](const at::Tensor& t, const char* name, std::vector<int64_t> shape) {
    if (!t.defined()) fail(what, std::string("tensor ") + name + " is missing");
    if (t.scalar_type() != torch::kFloat32) fail(what, std::string("tensor ") + name + " is not float32");
    if (t.sizes() != at::IntArrayRef(shape))
      fail(what, std::string("tensor ") + name + " has shape " + c10::str(t.sizes()) + ", expected " + c10::str(shape));
  };
  check(means, "means", {n, 3});
  check(log_scales, "log_scales", {n, 3});
  check(quats, "quats", {n, 4});
  check(opacity_logits, "opacity_logits", {n, 1});
  check(sh_dc, "sh_dc", {n, 1, 3});
  if (!sh_rest.defined()) fail(what, "tensor sh_rest is missing");
  check(sh_rest, "sh_rest", {n, sh_rest.size(1), 3});
  sh_degree();
  if (features.defined()) check(features, "features", {n, features.size(1)});
  for (const auto& e : extras) {
    if (!e.values.defined() || e.values.dim() != 1 || e.values.size(0) != n)
      fail(what, "extra property " + e.name + " must have one value per Gaussian");
    if (e.values.scalar_type() != torch::kFloat32 && e.values.scalar_type() != torch::kInt32)
      fail(what, "extra property " + e.name + " must be float32 or int32");
  }
}

GaussianModel make_gaussians(int64_t n, int sh_degree, int features) {
  const auto f = torch::TensorOptions().dtype(torch::kFloat32);
  GaussianModel g;
  g.means = torch::zeros({n, 3}, f);
  g.log_scales = torch::zeros({n, 3}, f);
  g.quats = torch::zeros({n, 4}, f);
  g.quats.select(1, 0).fill_(1);
  g.opacity_logits = torch::zeros({n, 1}, f);
  g.sh_dc = torch::zeros({n, 1, 3}, f);
  g.sh_rest = torch::zeros({n, (sh_degree + 1) * (sh_degree + 1) - 1, 3}, f);
  if (features > 0) g.features = torch::zeros({n, features}, f);
  return g;
}

}  // namespace cls
