// The sparse field's cosine objective (language/sparse_loss.h) against the paper's three terms written out
// pixel by pixel in double: each pixel's D-d feature formed from its weights and the codebook, its cosine
// with the target taken directly; gradients against central differences of that definition.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/error.h"
#include "error_of.h"
#include "language/sparse_loss.h"
#include "omp_threads.h"
#include "splat/rasterize.h"
#include "splat/torch_scene.h"

namespace cls {
namespace {

struct CosineCase {
  at::Tensor weights, codebook;  // H x W x L, L x D (double)
  SegMapTarget sam, gml;         // D-d tables (double)
  at::Tensor coverage;           // H x W 0/1
};

CosineCase cosine_case(int64_t h, int64_t w, int64_t l, int64_t d, int64_t segments, int64_t regions) {
  torch::manual_seed(71);
  CosineCase c;
  // Weights away from zero: a feature of norm 0 has no direction (its cosine is 0 by the 1e-8 floor).
  c.weights = torch::rand({h, w, l}, torch::kFloat64) + 0.05;
  c.codebook = torch::randn({l, d}, torch::kFloat64);
  c.sam = {torch::randint(-1, segments, {h, w}, torch::kInt), torch::randn({segments, d}, torch::kFloat64)};
  c.gml = {torch::randint(-1, regions, {h, w}, torch::kInt), torch::randn({regions, d}, torch::kFloat64)};
  c.coverage = torch::randint(0, 2, {h, w}, torch::kFloat64);
  return c;
}

// The definition: L_SAM, L_SAM-GML, L_CityGML of sparse_loss.h, each over H W.
std::array<double, 3> definition(const CosineCase& c, const at::Tensor& weights, const at::Tensor& codebook) {
  const int64_t h = weights.size(0), w = weights.size(1), l = weights.size(2), d = codebook.size(1);
  const auto wa = weights.accessor<double, 3>();
  const auto ba = codebook.accessor<double, 2>();
  const auto cosine = [&](const std::vector<double>& f, const SegMapTarget& t, int id) {
    const auto ta = t.table.accessor<double, 2>();
    double dot = 0, ff = 0, tt = 0;
    for (int64_t k = 0; k < d; ++k) dot += f[k] * ta[id][k], ff += f[k] * f[k], tt += ta[id][k] * ta[id][k];
    return dot / std::sqrt(std::max(ff * tt, 1e-16));  // the 1e-8 floor of sparse_loss.h
  };
  std::array<double, 3> terms{0, 0, 0};
  for (int64_t y = 0; y < h; ++y)
    for (int64_t x = 0; x < w; ++x) {
      std::vector<double> f(size_t(d), 0.0);
      for (int64_t j = 0; j < l; ++j)
        for (int64_t k = 0; k < d; ++k) f[k] += wa[y][x][j] * ba[j][k];
      const double m = c.coverage[y][x].item<double>();
      const int s = c.sam.ids[y][x].item<int>(), g = c.gml.ids[y][x].item<int>();
      if (s >= 0) terms[0] += (1 - m) * (1 - cosine(f, c.sam, s)), terms[1] += m * (1 - cosine(f, c.sam, s));
      if (g >= 0) terms[2] += m * (1 - cosine(f, c.gml, g));
    }
  for (double& t : terms) t /= double(h * w);
  return terms;
}

double total_of(const std::array<double, 3>& t, const LanguageLossWeights& w) {
  return w.baseline ? t[0] + t[1] : t[0] + w.lambda_sam * t[1] + w.lambda_citygml * t[2];
}

// Both forms: the CPU's one pass (sparse_cosine_loss) and the LibTorch operations a GPU runs.
using CosineLossFn = LanguageLoss (*)(const at::Tensor&, const at::Tensor&, const SegMapTarget&, const SegMapTarget&,
                                      const at::Tensor&, const LanguageLossWeights&);
const std::pair<const char*, CosineLossFn> kForms[] = {{"one pass", &sparse_cosine_loss},
                                                       {"reference", &sparse_cosine_loss_reference}};

TEST(SparseCosineLoss, EqualsTheDefinitionAndItsDifferences) {
  const CosineCase c = cosine_case(5, 6, 4, 7, 3, 2);
  for (const auto& [form, loss_fn] : kForms)
  for (const LanguageLossWeights lw : {LanguageLossWeights{1.0, 0.5, false}, LanguageLossWeights{2.0, 0.7, false},
                                       LanguageLossWeights{2.0, 0.7, true}}) {
    SCOPED_TRACE(form);
    const at::Tensor weights = c.weights.clone().requires_grad_(true), codebook = c.codebook.clone().requires_grad_(true);
    const LanguageLoss loss = loss_fn(weights, codebook, c.sam, c.gml, c.coverage, lw);
    const std::array<double, 3> expected = definition(c, c.weights, c.codebook);
    EXPECT_NEAR(loss.sam.item<double>(), expected[0], 1e-12);
    EXPECT_NEAR(loss.sam_gml.item<double>(), expected[1], 1e-12);
    EXPECT_NEAR(loss.citygml.item<double>(), lw.baseline ? 0.0 : expected[2], 1e-12);
    EXPECT_NEAR(loss.total.item<double>(), total_of(expected, lw), 1e-12);
    loss.total.backward();
    // Central differences of the definition, at every weight of two pixels and every codebook entry.
    const double step = 1e-6;
    const auto difference = [&](at::Tensor plus, at::Tensor minus) {
      const bool in_weights = plus.dim() == 3;
      const auto at = [&](const at::Tensor& t) {
        return total_of(in_weights ? definition(c, t, c.codebook) : definition(c, c.weights, t), lw);
      };
      return (at(plus) - at(minus)) / (2 * step);
    };
    // Two pixels with a SAM segment: one with a CityGML region, one without.
    const at::Tensor sam_ids = c.sam.ids.flatten(), gml_ids = c.gml.ids.flatten();
    const int64_t both = ((sam_ids >= 0) & (gml_ids >= 0)).nonzero()[0].item<int64_t>();
    const int64_t sam_only = ((sam_ids >= 0) & (gml_ids < 0)).nonzero()[0].item<int64_t>();
    for (const int64_t pixel : {both, sam_only})
      for (int64_t j = 0; j < c.weights.size(2); ++j) {
        at::Tensor plus = c.weights.clone(), minus = c.weights.clone();
        plus.view({-1, c.weights.size(2)})[pixel][j] += step;
        minus.view({-1, c.weights.size(2)})[pixel][j] -= step;
        EXPECT_NEAR(weights.grad().view({-1, c.weights.size(2)})[pixel][j].item<double>(), difference(plus, minus), 1e-7)
            << "pixel " << pixel << " basis " << j;
      }
    for (int64_t j = 0; j < c.codebook.size(0); ++j)
      for (int64_t k = 0; k < c.codebook.size(1); ++k) {
        at::Tensor plus = c.codebook.clone(), minus = c.codebook.clone();
        plus[j][k] += step;
        minus[j][k] -= step;
        EXPECT_NEAR(codebook.grad()[j][k].item<double>(), difference(plus, minus), 1e-7) << "basis " << j << ", " << k;
      }
  }
}

// The one pass against the reference on a view of many pixels (three chunks of the pass, the last one short;
// on one, two and three threads: every thread's share of the per-target sums and of the Gram term), float32
// and both weightings, every CPU build: the terms and both gradients. L 70: the pass's products
// (row_products.h) in register panels and the columns and rows after them.
TEST(SparseCosineLoss, OnePassEqualsTheReferenceOnALargerView) {
  for (CpuKernels kernels : available_cpu_kernels())
  for (const int64_t l : {16, 70})
  for (const int threads : {1, 2, 3})
  for (const torch::Dtype dtype : {torch::kFloat64, torch::kFloat32})
  for (const LanguageLossWeights lw : {LanguageLossWeights{1.0, 0.5, false}, LanguageLossWeights{1.0, 0.5, true}}) {
    const test::ScopedCpuKernels use_kernels(kernels);
    const test::ScopedOmpThreads use(threads);
    const CosineCase c = cosine_case(53, 47, l, 24, 9, 5);
    const SegMapTarget sam{c.sam.ids, c.sam.table.to(dtype)}, gml{c.gml.ids, c.gml.table.to(dtype)};
    at::Tensor grads[2][2];
    LanguageLoss losses[2];
    for (int f = 0; f < 2; ++f) {
      const at::Tensor weights = c.weights.to(dtype).clone().requires_grad_(true),
                       codebook = c.codebook.to(dtype).clone().requires_grad_(true);
      losses[f] = kForms[f].second(weights, codebook, sam, gml, c.coverage.to(dtype), lw);
      losses[f].total.backward();
      grads[f][0] = weights.grad(), grads[f][1] = codebook.grad();
    }
    const double tol = dtype == torch::kFloat64 ? 1e-12 : 1e-5;
    const std::string what = std::string(dtype == torch::kFloat64 ? "double" : "float") + (lw.baseline ? ", baseline" : "") +
                             ", L " + std::to_string(l);
    EXPECT_NEAR(losses[0].total.item<double>(), losses[1].total.item<double>(), tol) << what;
    EXPECT_NEAR(losses[0].sam_gml.item<double>(), losses[1].sam_gml.item<double>(), tol) << what;
    EXPECT_NEAR(losses[0].citygml.item<double>(), losses[1].citygml.item<double>(), tol) << what;
    for (int g = 0; g < 2; ++g) {
      const double scale = grads[1][g].abs().max().item<double>();
      ASSERT_GT(scale, 0.0) << what;
      EXPECT_LT((grads[0][g] - grads[1][g]).abs().max().item<double>(), tol * scale * 10) << what << (g ? ", codebook" : ", weights");
    }
  }
}

TEST(SparseCosineLoss, FloatAgreesWithDouble) {
  const CosineCase c = cosine_case(9, 11, 8, 16, 5, 4);
  const LanguageLossWeights lw;
  const LanguageLoss exact = sparse_cosine_loss(c.weights, c.codebook, c.sam, c.gml, c.coverage, lw);
  const SegMapTarget sam{c.sam.ids, c.sam.table.to(torch::kFloat)}, gml{c.gml.ids, c.gml.table.to(torch::kFloat)};
  const LanguageLoss single = sparse_cosine_loss(c.weights.to(torch::kFloat), c.codebook.to(torch::kFloat), sam, gml,
                                                 c.coverage.to(torch::kFloat), lw);
  EXPECT_EQ(single.total.scalar_type(), torch::kFloat);
  EXPECT_NEAR(single.total.item<double>(), exact.total.item<double>(), 1e-5);
}

TEST(SparseCosineLoss, ScaleOfTheWeightsAndTargetsDoesNotMatter) {
  // A cosine: scaling a pixel's weights (its blend's alpha) or a target leaves the loss as it is.
  const CosineCase c = cosine_case(4, 5, 3, 6, 3, 2);
  const LanguageLossWeights lw;
  const double base = sparse_cosine_loss(c.weights, c.codebook, c.sam, c.gml, c.coverage, lw).total.item<double>();
  const at::Tensor scale = torch::rand({4, 5, 1}, torch::kFloat64) * 3 + 0.1;
  const SegMapTarget sam{c.sam.ids, c.sam.table * 4};
  EXPECT_NEAR(sparse_cosine_loss(c.weights * scale, c.codebook, sam, c.gml, c.coverage, lw).total.item<double>(), base,
              1e-12);
  // ... and a target pointing elsewhere changes it.
  const SegMapTarget other{c.sam.ids, -c.sam.table};
  EXPECT_GT(std::abs(sparse_cosine_loss(c.weights, c.codebook, other, c.gml, c.coverage, lw).total.item<double>() - base),
            1e-3);
}

TEST(SparseCosineLoss, PixelsNoGaussianReachesStayFinite) {
  // W = 0 (nothing blended): cosine 0 there, so 1 - 0 counts, and every value and gradient is finite.
  CosineCase c = cosine_case(3, 4, 3, 5, 2, 2);
  c.weights[1][2].zero_();
  c.sam.ids[1][2] = 0;
  c.coverage[1][2] = 0;
  const at::Tensor weights = c.weights.clone().requires_grad_(true), codebook = c.codebook.clone().requires_grad_(true);
  const LanguageLoss loss = sparse_cosine_loss(weights, codebook, c.sam, c.gml, c.coverage, {1.0, 0.5, false});
  EXPECT_NEAR(loss.sam.item<double>(), definition(c, c.weights, c.codebook)[0], 1e-12);
  loss.total.backward();
  EXPECT_TRUE(torch::isfinite(weights.grad()).all().item<bool>());
  EXPECT_TRUE(torch::isfinite(codebook.grad()).all().item<bool>());
}

// The loss taken in one pass with the map from a view's recorded blend weights (sparse_cosine_loss_recorded) against
// the map rendered from them, then the one-pass loss: the terms and the gradients of the splatted weights and the
// codebook, every CPU build, double and float, one and two threads, both weightings; uncovered pixels included (few
// Gaussians at the edges) and tiles clipped by the image's edge (70 x 50). Before a call recorded the weights, for
// another view and with a background, an error.
TEST(SparseCosineLoss, RecordedPassEqualsTheRenderedMapsLoss) {
  constexpr int L = 70, D = 12, K = 3;  // L: register panels of the products and the columns after them
  for (CpuKernels kernels : available_cpu_kernels())
  for (const torch::Dtype dtype : {torch::kFloat64, torch::kFloat32})
  for (const int threads : {1, 2})
  for (const LanguageLossWeights lw : {LanguageLossWeights{1.0, 0.5, false}, LanguageLossWeights{1.0, 0.5, true}}) {
    const test::ScopedCpuKernels use_kernels(kernels);
    const test::ScopedOmpThreads use(threads);
    const std::string what = std::string(dtype == torch::kFloat64 ? "double" : "float") + (lw.baseline ? ", baseline" : "");
    TorchScene t = torch_scene(false, L, 72, dtype, 40, 70, 50);
    t.settings.background = torch::Tensor();
    t.settings.blend_cache = make_blend_cache();
    torch::manual_seed(73);
    const int64_t n = t.means.size(0), h = t.settings.camera.height, w = t.settings.camera.width;
    const at::Tensor weights = torch::rand({n, K}, torch::kFloat64).to(dtype) + 0.05;
    const at::Tensor indices = torch::randint(0, L, {n, K}, torch::kInt32);
    const at::Tensor codebook = torch::randn({L, D}, torch::kFloat64).to(dtype);
    const SegMapTarget sam{torch::randint(-1, 6, {h, w}, torch::kInt), torch::randn({6, D}, torch::kFloat64).to(dtype)};
    const SegMapTarget gml{torch::randint(-1, 4, {h, w}, torch::kInt), torch::randn({4, D}, torch::kFloat64).to(dtype)};
    const at::Tensor coverage = torch::randint(0, 2, {h, w}, torch::kFloat64).to(dtype);
    auto recorded = [&](const at::Tensor& x, const at::Tensor& book, const RasterizeSettings& s) {
      return sparse_cosine_loss_recorded(t.means, t.scales, t.quats, t.opacities, x, indices, s, book, sam, gml,
                                         coverage, lw);
    };
    EXPECT_NE(test::error_of([&] { recorded(weights, codebook, t.settings); }).find("holds no weights yet"),
              std::string::npos) << what;
    LanguageLoss losses[2];
    at::Tensor grads[2][2];
    for (int f = 0; f < 2; ++f) {  // the map rendered (and the weights recorded), then the pass
      const at::Tensor x = weights.clone().requires_grad_(true), book = codebook.clone().requires_grad_(true);
      if (f == 0) {
        const at::Tensor map = rasterize_sparse_features(t.means, t.scales, t.quats, t.opacities, x, indices, L, {},
                                                         t.settings).image;
        ASSERT_GT((map.abs().sum(2) == 0).sum().item<int64_t>(), 0) << "the scene must leave pixels uncovered";
        losses[f] = sparse_cosine_loss(map, book, sam, gml, coverage, lw);
      } else {
        losses[f] = recorded(x, book, t.settings);
      }
      losses[f].total.backward();
      grads[f][0] = x.grad(), grads[f][1] = book.grad();
    }
    const double tol = dtype == torch::kFloat64 ? 1e-12 : 1e-5;
    EXPECT_NEAR(losses[1].total.item<double>(), losses[0].total.item<double>(), tol) << what;
    EXPECT_NEAR(losses[1].sam.item<double>(), losses[0].sam.item<double>(), tol) << what;
    EXPECT_NEAR(losses[1].sam_gml.item<double>(), losses[0].sam_gml.item<double>(), tol) << what;
    EXPECT_NEAR(losses[1].citygml.item<double>(), losses[0].citygml.item<double>(), tol) << what;
    for (int g = 0; g < 2; ++g) {
      const double scale = grads[0][g].abs().max().item<double>();
      ASSERT_GT(scale, 0.0) << what;
      EXPECT_LT((grads[1][g] - grads[0][g]).abs().max().item<double>(), tol * scale * 10)
          << what << (g ? ", codebook" : ", weights");
    }
    RasterizeSettings moved = t.settings;
    moved.pose.t.x += 0.1;
    EXPECT_NE(test::error_of([&] { recorded(weights, codebook, moved); }).find("another camera"), std::string::npos)
        << what;
    const at::Tensor moving = t.means.clone().requires_grad_(true);
    EXPECT_NE(test::error_of([&] {
                sparse_cosine_loss_recorded(moving, t.scales, t.quats, t.opacities, weights, indices, t.settings,
                                            codebook, sam, gml, coverage, lw);
              }).find("frozen Gaussians"),
              std::string::npos) << what;
    RasterizeSettings with_background = t.settings;
    with_background.background = torch::ones({L}, dtype);
    EXPECT_NE(test::error_of([&] { recorded(weights, codebook, with_background); }).find("zero background"),
              std::string::npos) << what;
  }
}

TEST(SparseCosineLoss, BadInputsAreErrorsNamingWhat) {
  CosineCase c = cosine_case(3, 4, 3, 5, 2, 2);
  const LanguageLossWeights lw;
  at::Tensor bad = c.sam.ids.clone();
  bad[1][2] = 2;  // the table has 2 rows
  EXPECT_NE(test::error_of([&] { sparse_cosine_loss(c.weights, c.codebook, {bad, c.sam.table}, c.gml, c.coverage, lw); })
                .find("SAM seg map holds id 2 at pixel (2, 1), outside [-1, 2)"),
            std::string::npos);
  const SegMapTarget bad_gml{bad, c.gml.table};
  EXPECT_NE(test::error_of([&] { sparse_cosine_loss(c.weights, c.codebook, c.sam, bad_gml, c.coverage, lw); }).find("CityGML"),
            std::string::npos);
  EXPECT_NO_THROW(sparse_cosine_loss(c.weights, c.codebook, c.sam, bad_gml, c.coverage, {1.0, 0.5, true}));  // not read
  EXPECT_NE(test::error_of([&] { sparse_cosine_loss(c.weights, c.codebook.slice(0, 1), c.sam, c.gml, c.coverage, lw); })
                .find("codebook must be L x D with L = 3"),
            std::string::npos);
  EXPECT_NE(test::error_of([&] {
              sparse_cosine_loss(c.weights, c.codebook, {c.sam.ids, c.sam.table.slice(1, 1)}, c.gml, c.coverage, lw);
            }).find("SAM table must be K x 5"),
            std::string::npos);
  EXPECT_THROW(sparse_cosine_loss(c.weights, c.codebook, c.sam, c.gml, c.coverage.slice(0, 1), lw), Error);
}

}  // namespace
}  // namespace cls
