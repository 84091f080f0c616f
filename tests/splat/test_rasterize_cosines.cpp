// rasterize_sparse_cosines (ChannelCosines in the tile kernels) against its reference: the sparse image
// rendered as channels (itself checked against the dense path and finite differences), read as coordinates
// in a basis B, the features w B formed and their cosines with the directions taken in double.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <string>

#include "core/error.h"
#include "splat/rasterize.h"
#include "splat/rasterize_cpu.h"
#include "splat_scene.h"
#include "torch_scene.h"

namespace cls {
namespace {

struct CosineCase {
  TorchScene scene;               // geometry and settings (no background: the cosines have none)
  at::Tensor weights, indices;    // N x 3 weights at channels of C
  at::Tensor basis, directions;   // C x D, P x D (feature space)
};

// K = 3 weights per Gaussian over C channels, a C x D basis, P directions (the last one zero). The camera is
// wider than the scene, so that some pixels have nothing blended.
CosineCase cosine_case(int C, int D, int P, unsigned seed, torch::Dtype dtype) {
  CosineCase c;
  c.scene = torch_scene(false, 1, seed, dtype);
  c.scene.settings.camera.width += 14;
  c.scene.settings.background = at::Tensor();
  const int64_t n = c.scene.means.size(0);
  torch::manual_seed(seed);
  c.weights = torch::rand({n, 3}, torch::kFloat64).to(dtype);
  c.indices = torch::randint(0, C, {n, 3}, torch::kInt32);
  c.basis = torch::randn({C, D}, torch::kFloat64);
  c.directions = torch::randn({P, D}, torch::kFloat64);
  c.directions[P - 1].zero_();
  return c;
}

// The inputs of rasterize_sparse_cosines from the basis, computed independently of the query layer:
// a_p = B p / |p| and R of B^T's QR.
std::pair<at::Tensor, at::Tensor> in_basis(const CosineCase& c, torch::Dtype dtype) {
  const at::Tensor norm = c.directions.norm(2, {1}, true);
  const at::Tensor unit = torch::where(norm > 0, c.directions / norm.clamp_min(1e-300), torch::zeros_like(c.directions));
  const auto qr = at::linalg_qr(c.basis.t(), "reduced");
  return {unit.matmul(c.basis.t()).to(dtype), std::get<1>(qr).to(dtype)};
}

TEST(RasterizeCosines, EqualTheCosinesOfTheRenderedFeatures) {
  // (C, D, P): k = min(C, D) rows of R and P directions, each as whole blocks of eight rows and a rest,
  // and a basis with fewer dimensions than channels (R wider than tall)
  const int shapes[][3] = {{6, 10, 7}, {20, 12, 11}, {16, 24, 9}};
  for (const auto& shape : shapes)
  for (CpuKernels k : available_cpu_kernels())
  for (torch::Dtype dtype : {torch::kFloat64, torch::kFloat32}) {
    const int C = shape[0], D = shape[1], P = shape[2];
    test::ScopedCpuKernels use(k);
    const CosineCase c = cosine_case(C, D, P, 7 + C, dtype);
    const auto [a, r] = in_basis(c, dtype);
    const TorchScene& t = c.scene;
    const RasterizeOutput got =
        rasterize_sparse_cosines(t.means, t.scales, t.quats, t.opacities, c.weights, c.indices, C, a, r, t.settings);
    const RasterizeOutput w =
        rasterize_sparse_features(t.means, t.scales, t.quats, t.opacities, c.weights, c.indices, C, {}, t.settings);
    // the reference in double: F = w B per pixel, cos = <F, p> / (|F| |p|), 0 where either is zero
    const at::Tensor F = w.image.to(torch::kFloat64).reshape({-1, C}).matmul(c.basis);
    const at::Tensor fn = F.norm(2, {1}, true), pn = c.directions.norm(2, {1}, true).t();
    const at::Tensor expected = torch::where(fn * pn > 0, F.matmul(c.directions.t()) / (fn * pn).clamp_min(1e-300),
                                             torch::zeros({F.size(0), P}, torch::kFloat64));
    const std::string what = std::string(cpu_kernels_name(k)) + (dtype == torch::kFloat64 ? " double" : " float") +
                             ", C " + std::to_string(C) + ", D " + std::to_string(D) + ", P " + std::to_string(P);
    ASSERT_EQ(got.image.sizes(), at::IntArrayRef({t.settings.camera.height, t.settings.camera.width, P})) << what;
    ASSERT_GT((w.alpha == 0).sum().item<int64_t>(), 0) << "some pixels must have nothing blended";
    ASSERT_GT(expected.abs().max().item<double>(), 0.2) << what;  // cosines of random directions in D dimensions
    const double tol = dtype == torch::kFloat64 ? 1e-10 : 2e-5;
    EXPECT_LT((got.image.to(torch::kFloat64).reshape({-1, P}) - expected).abs().max().item<double>(), tol) << what;
    EXPECT_TRUE(torch::equal(got.alpha, w.alpha)) << what;
    EXPECT_TRUE(torch::equal(got.depth, w.depth)) << what;
    EXPECT_TRUE(torch::equal(got.radii, w.radii)) << what;
  }
}

TEST(RasterizeCosines, RejectsWhatItCannotTake) {
  const int C = 5, D = 8, P = 3;
  CosineCase c = cosine_case(C, D, P, 3, torch::kFloat32);
  const auto [a, r] = in_basis(c, torch::kFloat32);
  auto call = [&](const at::Tensor& dirs, const at::Tensor& factor, const RasterizeSettings& s) {
    const TorchScene& t = c.scene;
    return rasterize_sparse_cosines(t.means, t.scales, t.quats, t.opacities, c.weights, c.indices, C, dirs, factor, s);
  };
  const RasterizeSettings& settings = c.scene.settings;
  EXPECT_NO_THROW(call(a, r, settings));
  EXPECT_THROW(call(a.slice(1, 1), r, settings), Error) << "directions not P x C";
  EXPECT_THROW(call(a, r.slice(1, 1), settings), Error) << "factor not k x C";
  EXPECT_THROW(call(a, torch::cat({r, r}, 0), settings), Error) << "factor with more rows than channels";
  EXPECT_THROW(call(a.to(torch::kFloat64), r, settings), Error) << "directions of another dtype";
  RasterizeSettings with_bg = settings;
  with_bg.background = torch::zeros({C});
  EXPECT_THROW(call(a, r, with_bg), Error) << "a background";
  // the plain-array rasterizer: no backward of cosines
  SplatInputs<float> in;
  in.cosines.count = 1;
  SplatForwardState<float> state;
  SplatGradients<float> grads;
  EXPECT_THROW(rasterize_backward_cpu<float>(in, state, nullptr, nullptr, nullptr, grads), std::invalid_argument);
}

}  // namespace
}  // namespace cls
