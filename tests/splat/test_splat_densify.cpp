// Densification on hand-made Gaussians: which clone, split and are pruned, counts, moments of new
// rows zero, old moments carried, the cap, opacity reset, and reproducible split samples.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>

#include "splat/densify.h"

namespace {

// Six Gaussians at x = 0..5, extent 1 (clone/split limit 0.01):
//   0 small, large gradient -> clone      3 transparent (0.001) -> pruned
//   1 large (0.05), large gradient -> split 4 never visible (count 0) -> kept
//   2 small, small gradient -> kept        5 huge (0.2 > 0.1 x extent) -> pruned when prune_large
struct Fixture {
  cls::Adam adam;
  cls::DensifyStats stats;
  Fixture() {
    const int64_t n = 6;
    at::Tensor means = torch::zeros({n, 3});
    for (int i = 0; i < n; ++i) means[i][0] = float(i);
    at::Tensor log_scales = torch::full({n, 3}, std::log(0.001f));
    log_scales[1].fill_(std::log(0.05f));
    log_scales[5].fill_(std::log(0.2f));
    at::Tensor quats = torch::zeros({n, 4});
    quats.select(1, 0).fill_(1);
    quats[1] = torch::tensor({0.9f, 0.1f, 0.3f, -0.2f});
    at::Tensor opacity = torch::full({n, 1}, 2.0f);  // sigmoid 0.88
    opacity[3][0] = std::log(0.001f / 0.999f);
    at::Tensor dc = torch::arange(n * 3, torch::kFloat).reshape({n, 1, 3});
    at::Tensor rest = torch::zeros({n, 3, 3});
    auto leaf = [](at::Tensor t) { return t.set_requires_grad(true); };
    adam.add("means", leaf(means), 0.0);
    adam.add("log_scales", leaf(log_scales), 0.0);
    adam.add("quats", leaf(quats), 0.0);
    adam.add("opacity_logits", leaf(opacity), 0.0);
    adam.add("sh_dc", leaf(dc), 0.0);
    adam.add("sh_rest", leaf(rest), 0.0);
    // Non-zero moments everywhere: one step (lr 0, values unchanged) with a gradient of ones.
    for (auto& g : adam.groups()) g.param.mutable_grad() = torch::ones_like(g.param);
    adam.step();
    adam.zero_grad();
    stats.reset(n);
    // Accumulated over two views: mean gradients 0.001, 0.001, 0.0001, 0.0001, -, 0.0001.
    stats.grad_accum = torch::tensor({0.002f, 0.002f, 0.0002f, 0.0002f, 0.0f, 0.0002f});
    stats.count = torch::tensor({2.0f, 2.0f, 2.0f, 2.0f, 0.0f, 2.0f});
  }
};

cls::DensifyOptions options() {
  cls::DensifyOptions o;
  o.grad_threshold = 0.0002;
  o.extent = 1.0;
  o.prune_large = true;
  return o;
}

TEST(Densify, StatsAccumulateVisibleOnly) {
  cls::DensifyStats s;
  s.reset(3);
  const at::Tensor grad = torch::tensor({3.0f, 4.0f, 1.0f, 0.0f, 6.0f, 8.0f}).reshape({3, 2});
  cls::add_densification_stats(s, grad, torch::tensor({2, 0, 5}, torch::kInt32));
  cls::add_densification_stats(s, grad, torch::tensor({7, 1, 0}, torch::kInt32));
  EXPECT_TRUE(torch::allclose(s.grad_accum, torch::tensor({10.0f, 1.0f, 10.0f})));
  EXPECT_TRUE(torch::equal(s.count, torch::tensor({2.0f, 1.0f, 1.0f})));
  EXPECT_TRUE(torch::equal(s.max_radii, torch::tensor({7.0f, 1.0f, 5.0f})));
}

TEST(Densify, CloneSplitPrune) {
  Fixture f;
  std::mt19937_64 rng(42);
  const at::Tensor avg_before = f.adam.group("means").exp_avg.clone();
  const cls::DensifyResult r = cls::densify_and_prune(f.adam, f.stats, options(), rng);
  EXPECT_EQ(r.cloned, 1);
  EXPECT_EQ(r.split, 1);
  EXPECT_EQ(r.pruned, 2);
  const cls::GaussianModel m = cls::model_from_adam(f.adam);
  ASSERT_EQ(m.size(), 6);  // 6 + 1 clone + 2 children - 1 parent - 2 pruned
  // Order: kept originals 0, 2, 4; the clone of 0; the two children of 1.
  const at::Tensor x = m.means.select(1, 0);
  EXPECT_EQ(x[0].item<float>(), 0.0f);
  EXPECT_EQ(x[1].item<float>(), 2.0f);
  EXPECT_EQ(x[2].item<float>(), 4.0f);
  EXPECT_TRUE(torch::equal(m.means[3], m.means[0]));
  EXPECT_TRUE(torch::equal(m.sh_dc[3], m.sh_dc[0]));
  for (int c = 4; c < 6; ++c) {
    EXPECT_NEAR((m.means[c] - torch::tensor({1.0f, 0.0f, 0.0f})).norm().item<float>(), 0.0f, 0.3f);  // 6 sigma
    EXPECT_NEAR(m.log_scales[c][0].item<float>(), std::log(0.05f / 1.6f), 1e-5f);
    EXPECT_TRUE(torch::equal(m.sh_dc[c], torch::tensor({3.0f, 4.0f, 5.0f}).reshape({1, 3})));
  }
  EXPECT_FALSE(torch::equal(m.means[4], m.means[5]));
  // Moments: carried for kept rows, zero for the three new ones.
  for (const auto& g : f.adam.groups()) {
    ASSERT_EQ(g.exp_avg.size(0), 6) << g.name;
    EXPECT_EQ(g.exp_avg.slice(0, 3).abs().sum().item<float>(), 0.0f) << g.name;
    EXPECT_EQ(g.exp_avg_sq.slice(0, 3).abs().sum().item<float>(), 0.0f) << g.name;
    EXPECT_GT(g.exp_avg_sq.slice(0, 0, 3).abs().min().item<float>(), 0.0f) << g.name;
    EXPECT_TRUE(g.param.is_leaf() && g.param.requires_grad()) << g.name;
  }
  EXPECT_TRUE(torch::equal(f.adam.group("means").exp_avg.slice(0, 0, 3),
                           avg_before.index_select(0, torch::tensor({0, 2, 4}))));
  EXPECT_EQ(f.stats.size(), 6);
  EXPECT_EQ(f.stats.grad_accum.abs().sum().item<float>(), 0.0f);
}

TEST(Densify, WithoutLargePruningKeepsHugeGaussian) {
  Fixture f;
  std::mt19937_64 rng(42);
  cls::DensifyOptions o = options();
  o.prune_large = false;
  const cls::DensifyResult r = cls::densify_and_prune(f.adam, f.stats, o, rng);
  EXPECT_EQ(r.pruned, 1);
  EXPECT_EQ(cls::model_from_adam(f.adam).size(), 7);
}

TEST(Densify, ScreenRadiusPruning) {
  Fixture f;
  std::mt19937_64 rng(42);
  f.stats.max_radii = torch::tensor({1.0f, 1.0f, 30.0f, 1.0f, 1.0f, 1.0f});
  cls::DensifyOptions o = options();
  o.max_screen_radius = 20;
  const cls::DensifyResult r = cls::densify_and_prune(f.adam, f.stats, o, rng);
  EXPECT_EQ(r.pruned, 3);  // 2 (radius 30), 3, 5
  const at::Tensor x = cls::model_from_adam(f.adam).means.select(1, 0);
  EXPECT_EQ(x.size(0), 5);
  EXPECT_EQ(x[1].item<float>(), 4.0f);
}

TEST(Densify, CapKeepsHighestGradientCandidates) {
  Fixture f;
  f.stats.grad_accum[1] = 0.004f;  // the split candidate now has the larger gradient
  std::mt19937_64 rng(42);
  cls::DensifyOptions o = options();
  o.max_gaussians = 7;  // room for one more: the split (+1) fits, then the clone does not
  const cls::DensifyResult r = cls::densify_and_prune(f.adam, f.stats, o, rng);
  EXPECT_EQ(r.split, 1);
  EXPECT_EQ(r.cloned, 0);
  Fixture g;
  o.max_gaussians = 6;  // no room at all
  const cls::DensifyResult r2 = cls::densify_and_prune(g.adam, g.stats, o, rng);
  EXPECT_EQ(r2.split + r2.cloned, 0);
}

TEST(Densify, SplitSamplesFollowTheGenerator) {
  Fixture a, b, c;
  std::mt19937_64 ra(9), rb(9), rc(10);
  cls::densify_and_prune(a.adam, a.stats, options(), ra);
  cls::densify_and_prune(b.adam, b.stats, options(), rb);
  cls::densify_and_prune(c.adam, c.stats, options(), rc);
  EXPECT_TRUE(torch::equal(a.adam.group("means").param, b.adam.group("means").param));
  EXPECT_FALSE(torch::equal(a.adam.group("means").param, c.adam.group("means").param));
}

TEST(Densify, ResetOpacityCapsAndZeroesMoments) {
  Fixture f;
  cls::reset_opacity(f.adam, 0.01);
  const at::Tensor o = f.adam.group("opacity_logits").param.detach().sigmoid().reshape({-1});
  EXPECT_NEAR(o[0].item<float>(), 0.01f, 1e-6f);
  EXPECT_NEAR(o[3].item<float>(), 0.001f, 1e-6f);  // already below: unchanged
  EXPECT_EQ(f.adam.group("opacity_logits").exp_avg.abs().sum().item<float>(), 0.0f);
  EXPECT_GT(f.adam.group("means").exp_avg.abs().sum().item<float>(), 0.0f);
}

}  // namespace
