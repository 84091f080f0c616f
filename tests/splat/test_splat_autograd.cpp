// The rasterizer as a LibTorch autograd function: gradients against central finite differences of
// the same function in float64, and the float32 path against the float64 one.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "core/error.h"
#include "omp_threads.h"
#include "splat/gaussians.h"
#include "splat/rasterize.h"
#include "splat_scene.h"
#include "torch_scene.h"

namespace cls {
namespace {

torch::Tensor loss_of(const TorchScene& t, const torch::Tensor& means2d, const RasterizeSettings& settings) {
  const RasterizeOutput o = t.sh ? rasterize_sh(t.means, t.scales, t.quats, t.opacities, t.values, 3, means2d, settings)
                                 : rasterize_features(t.means, t.scales, t.quats, t.opacities, t.values, means2d, settings);
  return (o.image * t.w_image).sum() + (o.alpha * t.w_alpha).sum() + (o.depth * t.w_depth).sum();
}

std::vector<torch::Tensor> analytic_grads(TorchScene& t, torch::Tensor* mean2d_grad, torch::Tensor* abs_grad) {
  std::vector<torch::Tensor*> params = {&t.means, &t.scales, &t.quats, &t.opacities, &t.values};
  for (auto* p : params) *p = p->detach().requires_grad_(true);
  torch::Tensor means2d = torch::zeros({t.means.size(0), 2}, t.means.options()).requires_grad_(true);
  RasterizeSettings settings = t.settings;
  settings.mean2d_abs_grad = torch::zeros({t.means.size(0), 2}, t.means.options());
  loss_of(t, means2d, settings).backward();
  std::vector<torch::Tensor> grads;
  for (auto* p : params) {
    grads.push_back(p->grad().clone());
    *p = p->detach();
  }
  *mean2d_grad = means2d.grad();
  *abs_grad = settings.mean2d_abs_grad;
  return grads;
}

void check_against_fd(bool use_sh, int channels, unsigned seed) {
  TorchScene t = torch_scene(use_sh, channels, seed, torch::kFloat64);
  torch::Tensor g2d, gabs;
  const auto grads = analytic_grads(t, &g2d, &gabs);
  std::vector<torch::Tensor*> params = {&t.means, &t.scales, &t.quats, &t.opacities, &t.values};
  const char* names[] = {"means", "scales", "quats", "opacities", "values"};
  const double h = 1e-6;
  for (size_t p = 0; p < params.size(); ++p) {
    torch::Tensor flat = params[p]->view({-1});
    const auto g = grads[p].reshape({-1});
    ASSERT_GT(g.abs().max().item<double>(), 1e-3) << names[p] << " gradient is all zero";
    for (int64_t k = 0; k < flat.numel(); ++k) {
      const double x0 = flat[k].item<double>();
      flat[k] = x0 + h;
      const double lp = loss_of(t, {}, t.settings).item<double>();
      flat[k] = x0 - h;
      const double lm = loss_of(t, {}, t.settings).item<double>();
      flat[k] = x0;
      const double fd = (lp - lm) / (2 * h), a = g[k].item<double>();
      EXPECT_LT(std::abs(a - fd) / std::max({std::abs(a), std::abs(fd), 1e-3}), 1e-4) << names[p] << "[" << k << "]";
    }
  }
  // dL/dmean2d summed over Gaussians is the derivative with respect to the principal point.
  for (int axis = 0; axis < 2; ++axis) {
    RasterizeSettings s = t.settings;
    double& c = axis == 0 ? s.camera.cx : s.camera.cy;
    c += h;
    const double lp = loss_of(t, {}, s).item<double>();
    c -= 2 * h;
    const double lm = loss_of(t, {}, s).item<double>();
    const double fd = (lp - lm) / (2 * h), a = g2d.select(1, axis).sum().item<double>();
    EXPECT_LT(std::abs(a - fd) / std::max({std::abs(a), std::abs(fd), 1e-3}), 1e-4) << "mean2d axis " << axis;
  }
  EXPECT_TRUE((gabs >= g2d.abs() - 1e-12).all().item<bool>());
  EXPECT_GT(gabs.sum().item<double>(), 0.0);
}

TEST(SplatAutograd, ShGradientsMatchFiniteDifferences) { check_against_fd(true, 3, 21); }
TEST(SplatAutograd, FeatureGradientsMatchFiniteDifferences) { check_against_fd(false, 4, 22); }

// The float32 fast path gives the float64 gradients up to float rounding.
TEST(SplatAutograd, Float32MatchesFloat64) {
  for (CpuKernels k : available_cpu_kernels())
  for (bool use_sh : {true, false}) {
    test::ScopedCpuKernels use(k);
    TorchScene td = torch_scene(use_sh, 32, 23, torch::kFloat64);
    TorchScene tf = torch_scene(use_sh, 32, 23, torch::kFloat32);
    torch::Tensor g2d_d, abs_d, g2d_f, abs_f;
    const auto gd = analytic_grads(td, &g2d_d, &abs_d);
    const auto gf = analytic_grads(tf, &g2d_f, &abs_f);
    for (size_t p = 0; p < gd.size(); ++p) {
      const double scale = gd[p].abs().max().item<double>();
      EXPECT_LT((gf[p].to(torch::kFloat64) - gd[p]).abs().max().item<double>(), 1e-3 * scale) << "param " << p;
    }
    EXPECT_LT((g2d_f.to(torch::kFloat64) - g2d_d).abs().max().item<double>(), 1e-3 * g2d_d.abs().max().item<double>());
  }
}

// With only the colours/features requiring a gradient (a language field on frozen Gaussians) the
// backward skips the alpha gradient: their gradient stays that of the full backward (checked above
// against finite differences), in every CPU build and on both the few-channel and the many-channel path.
TEST(SplatAutograd, ValueGradientsAloneEqualTheFullBackward) {
  for (CpuKernels k : available_cpu_kernels())
  for (const auto& [use_sh, channels] : {std::pair{true, 3}, std::pair{false, 1}, std::pair{false, 3}, std::pair{false, 5}, std::pair{false, 128}}) {
    test::ScopedCpuKernels use(k);
    TorchScene t = torch_scene(use_sh, channels, 31, torch::kFloat64);
    torch::Tensor g2d, gabs;
    const torch::Tensor full = analytic_grads(t, &g2d, &gabs)[4];
    ASSERT_GT(full.abs().max().item<double>(), 0.0);
    t.values = t.values.detach().requires_grad_(true);  // the geometry without a gradient
    loss_of(t, {}, t.settings).backward();
    ASSERT_FALSE(t.means.requires_grad());
    EXPECT_TRUE(torch::allclose(t.values.grad(), full, 1e-12, 1e-15))
        << cpu_kernels_name(k) << (use_sh ? " SH" : " features") << ", " << channels << " channels: max difference "
        << (t.values.grad() - full).abs().max().item<double>();
  }
}

// Sparse features: K weights per Gaussian at K of C channels. The reference is the dense path on the
// weights scattered into N x C (repeated channels add), itself checked against finite differences above:
// the image, alpha and depth, and every gradient (the weights' as the dense gradient at their channels),
// in float64 and float32 and every CPU build, with and without geometry gradients.
struct SparseCase {
  torch::Tensor weights, indices, dense;
};
SparseCase sparse_case(const TorchScene& t, int K, int C, unsigned seed) {
  torch::manual_seed(seed);
  SparseCase c;
  const int64_t n = t.means.size(0);
  c.weights = torch::randn({n, K}, torch::kFloat64).to(t.means.scalar_type());
  c.indices = torch::randint(0, C, {n, K}, torch::kInt32);
  c.indices[0][1] = c.indices[0][0];  // a repeated channel
  c.dense = torch::zeros({n, C}, c.weights.options()).scatter_add(1, c.indices.to(torch::kLong), c.weights);
  return c;
}

TEST(SplatAutograd, SparseFeaturesEqualTheirDenseScatter) {
  constexpr int K = 3, C = 20;
  for (CpuKernels k : available_cpu_kernels())
  for (torch::Dtype dtype : {torch::kFloat64, torch::kFloat32})
  for (bool geometry : {false, true})
  for (int threads : {1, 2, 3}) {  // without geometry, each thread sums the weights' gradients apart
    test::ScopedCpuKernels use(k);
    const test::ScopedOmpThreads use_threads(threads);
    TorchScene t = torch_scene(false, C, 41, dtype);
    t.settings.background = torch::linspace(0.1, 0.5, C, t.means.options());
    SparseCase sc = sparse_case(t, K, C, 42);
    t.w_image = torch::randn({t.settings.camera.height, t.settings.camera.width, C}, torch::kFloat64).to(dtype);
    const double tol = dtype == torch::kFloat64 ? 1e-12 : 1e-5;
    auto run = [&](bool sparse, torch::Tensor& values, std::vector<torch::Tensor>& grads) {
      std::vector<torch::Tensor*> geo = {&t.means, &t.scales, &t.quats, &t.opacities};
      for (auto* p : geo) *p = p->detach().requires_grad_(geometry);
      values = values.detach().requires_grad_(true);
      const RasterizeOutput o =
          sparse ? rasterize_sparse_features(t.means, t.scales, t.quats, t.opacities, values, sc.indices, C, {}, t.settings)
                 : rasterize_features(t.means, t.scales, t.quats, t.opacities, values, {}, t.settings);
      ((o.image * t.w_image).sum() + (o.alpha * t.w_alpha).sum() + (o.depth * t.w_depth).sum()).backward();
      grads.clear();
      for (auto* p : geo) grads.push_back(geometry ? p->grad().clone() : torch::Tensor());
      grads.push_back(values.grad().clone());
      return o;
    };
    std::vector<torch::Tensor> gs, gd;
    const RasterizeOutput os = run(true, sc.weights, gs);
    const RasterizeOutput od = run(false, sc.dense, gd);
    const std::string what = std::string(cpu_kernels_name(k)) + (dtype == torch::kFloat64 ? " double" : " float") +
                             (geometry ? " with geometry" : "");
    ASSERT_GT(od.alpha.max().item<double>(), 0.1) << "the scene must cover pixels";
    EXPECT_LT((os.image - od.image).abs().max().item<double>(), tol) << what;
    EXPECT_LT((os.alpha - od.alpha).abs().max().item<double>(), tol) << what;
    EXPECT_LT((os.depth - od.depth).abs().max().item<double>(), tol) << what;
    const torch::Tensor expected = gd[4].gather(1, sc.indices.to(torch::kLong));
    ASSERT_GT(expected.abs().max().item<double>(), 0.0);
    EXPECT_LT((gs[4] - expected).abs().max().item<double>(), tol * expected.abs().max().item<double>()) << what;
    if (geometry)
      for (int p = 0; p < 4; ++p)
        EXPECT_LT((gs[p] - gd[p]).abs().max().item<double>(), tol * std::max(1.0, gd[p].abs().max().item<double>()))
            << what << " geometry parameter " << p;
  }
}

// The sparse weights' gradient against central finite differences of the sparse path itself, in double.
TEST(SplatAutograd, SparseWeightGradientsMatchFiniteDifferences) {
  constexpr int K = 3, C = 7;
  TorchScene t = torch_scene(false, C, 45, torch::kFloat64);
  SparseCase sc = sparse_case(t, K, C, 46);
  t.w_image = torch::randn({t.settings.camera.height, t.settings.camera.width, C}, torch::kFloat64);
  auto loss = [&](const torch::Tensor& w) {
    const RasterizeOutput o = rasterize_sparse_features(t.means, t.scales, t.quats, t.opacities, w, sc.indices, C, {}, t.settings);
    return (o.image * t.w_image).sum();
  };
  const torch::Tensor w = sc.weights.clone().requires_grad_(true);
  loss(w).backward();
  const torch::Tensor g = w.grad().reshape({-1});
  ASSERT_GT(g.abs().max().item<double>(), 1e-3);
  torch::Tensor flat = sc.weights.view({-1});
  const double h = 1e-6;
  for (int64_t k = 0; k < flat.numel(); ++k) {
    const double x0 = flat[k].item<double>();
    flat[k] = x0 + h;
    const double lp = loss(sc.weights).item<double>();
    flat[k] = x0 - h;
    const double lm = loss(sc.weights).item<double>();
    flat[k] = x0;
    const double fd = (lp - lm) / (2 * h), a = g[k].item<double>();
    EXPECT_LT(std::abs(a - fd) / std::max({std::abs(a), std::abs(fd), 1e-3}), 1e-6) << "weight " << k;
  }
}

TEST(SplatAutograd, SparseFeaturesRejectBadIndices) {
  TorchScene t = torch_scene(false, 4, 43, torch::kFloat32);
  SparseCase sc = sparse_case(t, 2, 4, 44);
  auto call = [&](const torch::Tensor& w, const torch::Tensor& i, int C) {
    return rasterize_sparse_features(t.means, t.scales, t.quats, t.opacities, w, i, C, {}, t.settings);
  };
  EXPECT_NO_THROW(call(sc.weights, sc.indices, 4));
  EXPECT_THROW(call(sc.weights, sc.indices, 3), Error) << "an index past the channels";
  EXPECT_THROW(call(sc.weights, sc.indices - 1 - sc.indices.max(), 4), Error) << "a negative index";
  EXPECT_THROW(call(sc.weights, sc.indices.to(torch::kLong), 4), Error) << "int64 indices";
  EXPECT_THROW(call(sc.weights.slice(1, 0, 1), sc.indices, 4), Error) << "weights and indices of different shapes";
}

TEST(SplatAutograd, GradientsReachTheRawModelParameters) {
  GaussianModel g = make_gaussians(2, 1, 0);
  g.means = torch::tensor({0.0f, 0.0f, 4.0f, 0.3f, 0.1f, 5.0f}).reshape({2, 3});
  g.log_scales.fill_(std::log(0.2));
  g.log_scales.requires_grad_(true);
  g.opacity_logits.requires_grad_(true);
  g.sh_dc.fill_(0.5);
  g.sh_dc.requires_grad_(true);
  g.means.requires_grad_(true);
  RasterizeSettings s;
  s.camera = PinholeCamera{40, 40, 16, 16, 32, 32};
  const auto o = rasterize_sh(g.means, g.scales(), g.quats, g.opacities(), g.sh(), 1, {}, s);
  EXPECT_EQ(o.radii.scalar_type(), torch::kInt32);
  EXPECT_GT(o.radii.min().item<int>(), 0);
  o.image.sum().backward();
  for (const auto* t : {&g.means, &g.log_scales, &g.opacity_logits, &g.sh_dc}) {
    ASSERT_TRUE(t->grad().defined());
    EXPECT_GT(t->grad().abs().sum().item<double>(), 0.0);
  }
}

// lift_to_gaussians against its definition: the blend weights alpha_ip T_ip read off a render of one-hot
// features (channel i of the image is Gaussian i's weight at each pixel), times the values, summed.
TEST(SplatAutograd, LiftToGaussiansIsTheRendersTranspose) {
  constexpr int C = 4;
  TorchScene t = torch_scene(false, C - 1, 51, torch::kFloat64);  // its background: C - 1 values, not C
  const int64_t n = t.means.size(0), h = t.settings.camera.height, w = t.settings.camera.width;
  const torch::Tensor values = torch::randn({h, w, C}, torch::kFloat64);
  RasterizeSettings plain = t.settings;
  plain.background = torch::Tensor();
  const torch::Tensor blend =
      rasterize_features(t.means, t.scales, t.quats, t.opacities, torch::eye(n, torch::kFloat64), {}, plain).image;
  ASSERT_GT(blend.sum(2).max().item<double>(), 0.1) << "the scene must cover pixels";
  const torch::Tensor expected = blend.reshape({-1, n}).t().matmul(values.reshape({-1, C}));
  // The caller's background and densification statistics change nothing and are left alone; no gradient mode needed.
  t.settings.mean2d_abs_grad = torch::zeros({n, 2}, torch::kFloat64);
  const torch::NoGradGuard no_grad;
  const torch::Tensor lifted = lift_to_gaussians(t.means, t.scales, t.quats, t.opacities, values, t.settings);
  EXPECT_LT((lifted - expected).abs().max().item<double>(), 1e-12 * std::max(1.0, expected.abs().max().item<double>()));
  EXPECT_EQ(t.settings.mean2d_abs_grad.abs().sum().item<double>(), 0.0);
  EXPECT_THROW(lift_to_gaussians(t.means, t.scales, t.quats, t.opacities, values.slice(0, 1), t.settings), Error);
}

TEST(SplatAutograd, RejectsBadShapes) {
  RasterizeSettings s;
  s.camera = PinholeCamera{40, 40, 16, 16, 32, 32};
  const auto m = torch::zeros({3, 3});
  EXPECT_THROW(rasterize_features(m, torch::ones({3, 3}), torch::ones({3, 4}), torch::ones({2}), torch::ones({3, 5}), {}, s), Error);
  EXPECT_THROW(rasterize_sh(m, torch::ones({3, 3}), torch::ones({3, 4}), torch::ones({3}), torch::ones({3, 3, 3}), 2, {}, s), Error);
  EXPECT_THROW(rasterize_features(m, torch::ones({3, 3}), torch::ones({3, 4}), torch::ones({3}), torch::ones({3, 5}, torch::kFloat64), {}, s), Error);
}

}  // namespace
}  // namespace cls
