#include "splat/adam.h"

#include <torch/torch.h>

#include <cmath>

#include "core/error.h"

namespace cls {
namespace {

// A fresh leaf parameter with the given values (densification replaces the tensor object, as
// 3DGS's nn.Parameter(...) does, so autograd never sees an in-place change of a graph input).
at::Tensor new_leaf(const at::Tensor& values) {
  return values.detach().clone().contiguous().set_requires_grad(true);
}

}  // namespace

Adam::Adam(double beta1, double beta2, double eps) : beta1_(beta1), beta2_(beta2), eps_(eps) {}

void Adam::add(const std::string& name, const at::Tensor& param, double lr) {
  for (const auto& g : groups_)
    if (g.name == name) throw Error("Adam: parameter '" + name + "' added twice");
  AdamGroup g;
  g.name = name;
  g.param = param;
  g.lr = lr;
  g.exp_avg = torch::zeros_like(param.detach());
  g.exp_avg_sq = torch::zeros_like(param.detach());
  groups_.push_back(std::move(g));
}

AdamGroup& Adam::group(const std::string& name) {
  for (auto& g : groups_)
    if (g.name == name) return g;
  throw Error("Adam: no parameter '" + name + "'");
}

// torch.optim.Adam (amsgrad off, weight decay 0), the single-tensor path:
//   m = b1 m + (1 - b1) g;  v = b2 v + (1 - b2) g^2
//   p -= lr / (1 - b1^t) * m / (sqrt(v) / sqrt(1 - b2^t) + eps)
void Adam::step() {
  torch::NoGradGuard no_grad;
  for (auto& g : groups_) {
    const at::Tensor& grad = g.param.grad();
    if (!grad.defined()) continue;
    g.step += 1;
    g.exp_avg.mul_(beta1_).add_(grad, 1 - beta1_);
    g.exp_avg_sq.mul_(beta2_).addcmul_(grad, grad, 1 - beta2_);
    const double bias_correction1 = 1 - std::pow(beta1_, double(g.step));
    const double bias_correction2 = 1 - std::pow(beta2_, double(g.step));
    const double step_size = g.lr / bias_correction1;
    const double bias_correction2_sqrt = std::sqrt(bias_correction2);
    at::Tensor denom = (g.exp_avg_sq.sqrt() / bias_correction2_sqrt).add_(eps_);
    g.param.addcdiv_(g.exp_avg, denom, -step_size);
  }
}

void Adam::zero_grad() {
  for (auto& g : groups_) {
    if (g.param.grad().defined()) g.param.mutable_grad() = at::Tensor();
  }
}

void Adam::keep_rows(const at::Tensor& mask) {
  const at::Tensor keep = mask.to(torch::kBool);
  for (auto& g : groups_) {
    if (keep.size(0) != g.param.size(0))
      throw Error("Adam::keep_rows: mask has " + std::to_string(keep.size(0)) + " rows, parameter '" + g.name +
                  "' " + std::to_string(g.param.size(0)));
    g.param = new_leaf(g.param.detach().index({keep}));
    g.exp_avg = g.exp_avg.index({keep}).contiguous();
    g.exp_avg_sq = g.exp_avg_sq.index({keep}).contiguous();
  }
}

void Adam::append_rows(const std::map<std::string, at::Tensor>& rows) {
  for (const auto& [name, values] : rows) {
    AdamGroup& g = group(name);
    const at::Tensor v = values.detach().to(g.param.dtype());
    if (v.dim() != g.param.dim() || v.sizes().slice(1) != g.param.sizes().slice(1))
      throw Error("Adam::append_rows: rows for '" + name + "' do not match the parameter's shape");
    g.param = new_leaf(torch::cat({g.param.detach(), v}, 0));
    g.exp_avg = torch::cat({g.exp_avg, torch::zeros_like(v)}, 0);
    g.exp_avg_sq = torch::cat({g.exp_avg_sq, torch::zeros_like(v)}, 0);
  }
}

void Adam::replace(const std::string& name, const at::Tensor& values) {
  AdamGroup& g = group(name);
  g.param = new_leaf(values.to(g.param.dtype()));
  g.exp_avg = torch::zeros_like(g.param.detach());
  g.exp_avg_sq = torch::zeros_like(g.param.detach());
}

std::map<std::string, at::Tensor> Adam::state_tensors() const {
  std::map<std::string, at::Tensor> out;
  for (const auto& g : groups_) {
    out["adam." + g.name + ".exp_avg"] = g.exp_avg.contiguous();
    out["adam." + g.name + ".exp_avg_sq"] = g.exp_avg_sq.contiguous();
  }
  return out;
}

std::map<std::string, double> Adam::state_scalars() const {
  std::map<std::string, double> out;
  for (const auto& g : groups_) {
    out[g.name + ".step"] = double(g.step);
    out[g.name + ".lr"] = g.lr;
  }
  return out;
}

void Adam::restore(const std::map<std::string, at::Tensor>& tensors, const std::map<std::string, double>& scalars,
                   const std::string& source) {
  for (auto& g : groups_) {
    for (const char* which : {"exp_avg", "exp_avg_sq"}) {
      const std::string key = "adam." + g.name + "." + which;
      auto it = tensors.find(key);
      if (it == tensors.end()) fail(source, "no tensor '" + key + "'");
      if (it->second.sizes() != g.param.sizes())
        fail(source, "tensor '" + key + "' has the wrong shape for parameter '" + g.name + "'");
      (std::string(which) == "exp_avg" ? g.exp_avg : g.exp_avg_sq) =
          it->second.to(g.param.options()).clone().contiguous();
    }
    auto step = scalars.find(g.name + ".step");
    auto lr = scalars.find(g.name + ".lr");
    if (step == scalars.end() || lr == scalars.end()) fail(source, "no Adam step/lr for '" + g.name + "'");
    g.step = int64_t(step->second);
    g.lr = lr->second;
  }
}

}  // namespace cls
