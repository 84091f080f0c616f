// The sparse field's lifted first logits (language/sparse_lifting.h) against their definition computed
// here by hand: the blend weights read off a render of one-hot features, the targets' cosines with the
// bases and the loss's weights per pixel (paper 3.3) written out pixel by pixel, in double.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>
#include <vector>

#include "core/error.h"
#include "language/sparse_lifting.h"
#include "query/latent_scene.h"

namespace cls {
namespace {

struct LiftCase {
  test::LatentScene scene;
  at::Tensor means, scales, quats, opacities;
  std::vector<LiftingView> views;
  at::Tensor codebook;
};

constexpr int kSegments = 4, kRegions = 3;  // rows of each view's SAM and CityGML tables

LiftCase lift_case() {
  LiftCase c;
  c.scene = test::latent_scene(12, 36, 34, 1, 61);
  c.means = c.scene.g.means.detach().clone();
  c.means[c.means.size(0) - 1] += at::tensor({1000.f, 0.f, 0.f});  // far outside the view: no pixel sees it
  c.scales = c.scene.g.scales().detach(), c.quats = c.scene.g.quats.detach(), c.opacities = c.scene.g.opacities().detach();
  const int64_t h = c.scene.camera.height, w = c.scene.camera.width, d = 5;
  torch::manual_seed(62);
  c.codebook = torch::randn({3, d});
  for (int v = 0; v < 2; ++v) {  // the same camera twice with other maps: the views' sums add
    LiftingView lv;
    lv.settings.camera = c.scene.camera;
    lv.settings.pose = c.scene.pose;
    lv.sam = {torch::randint(-1, kSegments, {h, w}, torch::kInt), torch::randn({kSegments, d})};
    lv.gml = {torch::randint(-1, kRegions, {h, w}, torch::kInt), torch::randn({kRegions, d})};
    lv.coverage = torch::randint(0, 2, {h, w}, torch::kFloat);
    c.views.push_back(lv);
  }
  return c;
}

// The definition, in double: sum_p a_ip sum_t w_t cos(t, b_j) / (sum_p a_ip sum_t w_t + 1) / temperature.
at::Tensor expected_logits(const LiftCase& c, const LanguageLossWeights& lw, double temperature) {
  const int64_t n = c.means.size(0), bases = c.codebook.size(0);
  const at::Tensor book = c.codebook.to(torch::kFloat64);
  std::vector<double> num(size_t(n * bases), 0.0), den(size_t(n), 0.0);
  for (const LiftingView& v : c.views) {
    RasterizeSettings s = v.settings;
    const at::Tensor blend = rasterize_features(c.means.to(torch::kFloat64), c.scales.to(torch::kFloat64),
                                                c.quats.to(torch::kFloat64), c.opacities.to(torch::kFloat64),
                                                torch::eye(n, torch::kFloat64), {}, s).image.contiguous();
    const int64_t h = blend.size(0), w = blend.size(1);
    auto cosine = [&](const at::Tensor& row, int64_t j) {
      const at::Tensor a = row.to(torch::kFloat64), b = book[j];
      return (a.dot(b) / (a.norm() * b.norm())).item<double>();
    };
    for (int64_t y = 0; y < h; ++y)
      for (int64_t x = 0; x < w; ++x) {
        const double m = v.coverage[y][x].item<double>();
        const int s_id = v.sam.ids[y][x].item<int>(), g_id = v.gml.ids[y][x].item<int>();
        const double ws = s_id < 0 ? 0 : (lw.baseline ? 1.0 : (1 - m) + lw.lambda_sam * m);
        const double wg = g_id < 0 || lw.baseline ? 0 : lw.lambda_citygml * m;
        std::vector<double> value(size_t(bases), 0.0);
        for (int64_t j = 0; j < bases; ++j)
          value[size_t(j)] = (ws > 0 ? ws * cosine(v.sam.table[s_id], j) : 0) + (wg > 0 ? wg * cosine(v.gml.table[g_id], j) : 0);
        for (int64_t i = 0; i < n; ++i) {
          const double a = blend[y][x][i].item<double>();
          if (a == 0) continue;
          for (int64_t j = 0; j < bases; ++j) num[size_t(i * bases + j)] += a * value[size_t(j)];
          den[size_t(i)] += a * (ws + wg);
        }
      }
  }
  at::Tensor out = torch::zeros({n, bases}, torch::kFloat64);
  for (int64_t i = 0; i < n; ++i)
    for (int64_t j = 0; j < bases; ++j) out[i][j] = num[size_t(i * bases + j)] / (den[size_t(i)] + 1) / temperature;
  return out;
}

TEST(SparseLifting, LogitsAreTheBlendWeightedCosinesOfTheTargets) {
  const LiftCase c = lift_case();
  // The baseline with lambda_sam != 1: its SAM weight is 1 inside coverage too, whatever lambda_sam says.
  for (const LanguageLossWeights lw : {LanguageLossWeights{0.7, 0.4, false}, LanguageLossWeights{0.7, 0.4, true}}) {
    SCOPED_TRACE(lw.baseline ? "LangSplat's objective" : "CityLangSplat's objective");
    const double temperature = 0.2;
    const at::Tensor got = lifted_logits(c.means, c.scales, c.quats, c.opacities, int64_t(c.views.size()),
                                         [&](int64_t i) { return c.views[size_t(i)]; }, c.codebook, lw, temperature);
    const at::Tensor expected = expected_logits(c, lw, temperature);
    ASSERT_EQ(got.sizes(), expected.sizes());
    ASSERT_GT(expected.abs().max().item<double>(), 1.0) << "the case must lift something";
    EXPECT_LT((got.to(torch::kFloat64) - expected).abs().max().item<double>(), 1e-4 * expected.abs().max().item<double>());
    EXPECT_EQ(got[got.size(0) - 1].abs().sum().item<double>(), 0.0) << "a Gaussian no pixel sees starts at zero";
  }
}

TEST(SparseLifting, RejectsAnIdOutsideItsTable) {
  LiftCase c = lift_case();
  c.views[1].gml.ids[3][4] = int(c.views[1].gml.table.size(0));  // one past the table's last row
  EXPECT_THROW(lifted_logits(c.means, c.scales, c.quats, c.opacities, int64_t(c.views.size()),
                             [&](int64_t i) { return c.views[size_t(i)]; }, c.codebook, LanguageLossWeights{}, 0.1),
               Error);
}

}  // namespace
}  // namespace cls
