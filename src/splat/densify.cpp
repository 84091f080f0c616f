#include "splat/densify.h"

#include <torch/torch.h>

#include <algorithm>
#include <numeric>

#include "core/error.h"

namespace cls {
namespace {

bool has_group(Adam& adam, const std::string& name) {
  for (const auto& g : adam.groups())
    if (g.name == name) return true;
  return false;
}

// Rotation matrices of (w, x, y, z) quaternions (normalised), N x 3 x 3 (3DGS build_rotation).
at::Tensor rotation_matrices(const at::Tensor& quats) {
  const at::Tensor q = quats / quats.norm(2, 1, true);
  const at::Tensor r = q.select(1, 0), x = q.select(1, 1), y = q.select(1, 2), z = q.select(1, 3);
  const at::Tensor R = torch::stack({1 - 2 * (y * y + z * z), 2 * (x * y - r * z), 2 * (x * z + r * y),
                                     2 * (x * y + r * z), 1 - 2 * (x * x + z * z), 2 * (y * z - r * x),
                                     2 * (x * z - r * y), 2 * (y * z + r * x), 1 - 2 * (x * x + y * y)},
                                    1);
  return R.reshape({-1, 3, 3});
}

}  // namespace

void DensifyStats::reset(int64_t n, const c10::Device& device) {
  const auto f = torch::TensorOptions().dtype(torch::kFloat).device(device);
  grad_accum = torch::zeros({n}, f);
  count = torch::zeros({n}, f);
  max_radii = torch::zeros({n}, f);
}

void add_densification_stats(DensifyStats& stats, const at::Tensor& mean2d_grad, const at::Tensor& radii) {
  torch::NoGradGuard no_grad;
  if (mean2d_grad.size(0) != stats.size() || radii.size(0) != stats.size())
    throw Error("densification statistics: " + std::to_string(stats.size()) + " Gaussians, gradient for " +
                std::to_string(mean2d_grad.size(0)));
  const at::Tensor visible = (radii > 0).to(torch::kFloat);
  stats.grad_accum += mean2d_grad.to(torch::kFloat).norm(2, 1) * visible;
  stats.count += visible;
  stats.max_radii = torch::maximum(stats.max_radii, radii.to(torch::kFloat) * visible);
}

GaussianModel model_from_adam(Adam& adam) {
  GaussianModel m;
  m.means = adam.group("means").param;
  m.log_scales = adam.group("log_scales").param;
  m.quats = adam.group("quats").param;
  m.opacity_logits = adam.group("opacity_logits").param;
  m.sh_dc = adam.group("sh_dc").param;
  m.sh_rest = adam.group("sh_rest").param;
  if (has_group(adam, "features")) m.features = adam.group("features").param;
  return m;
}

DensifyResult densify_and_prune(Adam& adam, DensifyStats& stats, const DensifyOptions& options,
                                std::mt19937_64& rng) {
  torch::NoGradGuard no_grad;
  DensifyResult result;
  const int64_t n0 = adam.group("means").param.size(0);
  if (stats.size() != n0) throw Error("densify: statistics and parameters disagree on the Gaussian count");

  // grads = xyz_gradient_accum / denom, NaN (never visible) -> 0.
  at::Tensor grads = stats.grad_accum / stats.count;
  grads.masked_fill_(grads.isnan(), 0);
  const at::Tensor max_scale = std::get<0>(adam.group("log_scales").param.detach().exp().max(1));
  const double dense_limit = options.percent_dense * options.extent;
  at::Tensor candidates = grads >= options.grad_threshold;
  at::Tensor clone_mask = candidates & (max_scale <= dense_limit);
  at::Tensor split_mask = candidates & (max_scale > dense_limit);

  // The cap: a clone adds one Gaussian, a split N - 1; keep the highest-gradient candidates that fit.
  if (options.max_gaussians > 0) {
    int64_t budget = std::max<int64_t>(0, options.max_gaussians - n0);
    const auto g = grads.cpu().contiguous();
    const auto clone_cpu = clone_mask.cpu().contiguous(), split_cpu = split_mask.cpu().contiguous();
    const float* gp = g.data_ptr<float>();
    const bool* cp = clone_cpu.data_ptr<bool>();
    const bool* sp = split_cpu.data_ptr<bool>();
    std::vector<int64_t> order;
    for (int64_t i = 0; i < n0; ++i)
      if (cp[i] || sp[i]) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](int64_t a, int64_t b) { return gp[a] > gp[b]; });
    at::Tensor keep_clone = torch::zeros({n0}, torch::kBool), keep_split = torch::zeros({n0}, torch::kBool);
    bool* kc = keep_clone.data_ptr<bool>();
    bool* ks = keep_split.data_ptr<bool>();
    for (int64_t i : order) {
      const int64_t cost = cp[i] ? 1 : options.split_n - 1;
      if (cost > budget) continue;
      budget -= cost;
      (cp[i] ? kc : ks)[i] = true;
    }
    clone_mask = keep_clone.to(grads.device());
    split_mask = keep_split.to(grads.device());
  }

  // densify_and_clone: exact copies of small Gaussians with a large gradient.
  result.cloned = clone_mask.sum().item<int64_t>();
  if (result.cloned > 0) {
    std::map<std::string, at::Tensor> rows;
    for (auto& g : adam.groups()) rows[g.name] = g.param.detach().index({clone_mask});
    adam.append_rows(rows);
  }

  // densify_and_split: N children sampled from each large Gaussian, scale / (0.8 N); parents removed.
  const int64_t n1 = adam.group("means").param.size(0);
  const auto no_rows = [&](int64_t k) { return torch::zeros({k}, split_mask.options()); };  // bool, on the device
  at::Tensor split_full = torch::cat({split_mask, no_rows(n1 - n0)});
  result.split = split_mask.sum().item<int64_t>();
  if (result.split > 0) {
    const int n = options.split_n;
    const at::Tensor scales = adam.group("log_scales").param.detach().index({split_full}).exp();
    const at::Tensor stds = scales.repeat({n, 1});
    // Standard normal samples from the checkpointed generator, in a fixed order.
    at::Tensor normal = torch::empty(stds.sizes(), torch::kFloat);
    std::normal_distribution<double> gauss(0.0, 1.0);
    float* np = normal.data_ptr<float>();
    for (int64_t i = 0; i < normal.numel(); ++i) np[i] = float(gauss(rng));
    const at::Tensor samples = normal.to(stds.options()) * stds;
    const at::Tensor rots = rotation_matrices(adam.group("quats").param.detach().index({split_full})).repeat({n, 1, 1});
    const at::Tensor parent_means = adam.group("means").param.detach().index({split_full}).repeat({n, 1});
    std::map<std::string, at::Tensor> rows;
    for (auto& g : adam.groups()) {
      const at::Tensor parent = g.param.detach().index({split_full});
      std::vector<int64_t> reps(size_t(parent.dim()), 1);
      reps[0] = n;
      rows[g.name] = parent.repeat(reps);
    }
    rows["means"] = torch::bmm(rots, samples.unsqueeze(-1)).squeeze(-1) + parent_means;
    rows["log_scales"] = (stds / (0.8 * n)).log();
    adam.append_rows(rows);
    const int64_t n2 = adam.group("means").param.size(0);
    adam.keep_rows(~torch::cat({split_full, no_rows(n2 - n1)}));
  }

  // Prune: transparent, and (after the first opacity reset) too large in the world / on screen.
  // Screen radii of rows that were just created are zero (they have not been rendered yet).
  const at::Tensor opacity = adam.group("opacity_logits").param.detach().sigmoid().reshape({-1});
  at::Tensor prune = opacity < options.min_opacity;
  if (options.prune_large) {
    const at::Tensor world_scale = std::get<0>(adam.group("log_scales").param.detach().exp().max(1));
    prune = prune | (world_scale > 0.1 * options.extent);
  }
  if (options.max_screen_radius > 0) {
    const auto zero_radii = [&](int64_t k) { return torch::zeros({k}, stats.max_radii.options()); };
    at::Tensor radii = torch::cat({stats.max_radii, zero_radii(result.cloned)});
    radii = torch::cat({radii, zero_radii(options.split_n * result.split)})
                .index({~torch::cat({split_full, no_rows(options.split_n * result.split)})});
    prune = prune | (radii > options.max_screen_radius);
  }
  result.pruned = prune.sum().item<int64_t>();
  if (result.pruned > 0) adam.keep_rows(~prune);
  stats.reset(adam.group("means").param.size(0), adam.group("means").param.device());
  return result;
}

void reset_opacity(Adam& adam, double max_opacity) {
  torch::NoGradGuard no_grad;
  const at::Tensor logits = adam.group("opacity_logits").param.detach();
  const at::Tensor capped = torch::clamp_max(logits.sigmoid(), max_opacity);
  adam.replace("opacity_logits", torch::log(capped / (1 - capped)));  // inverse_sigmoid
}

}  // namespace cls
