// SSIM against a slow double-precision per-pixel reference (zero padding, as conv2d), SSIM(x, x) = 1,
// and its gradient against central finite differences; the CPU kernels against the LibTorch-op form.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>
#include <vector>

#include "splat/rasterize_cpu.h"
#include "splat/ssim.h"

namespace {

// Direct evaluation of 3DGS's ssim: window taps computed here independently of ssim_window_1d.
double reference_ssim(const at::Tensor& a_in, const at::Tensor& b_in) {
  const at::Tensor a = a_in.to(torch::kFloat64).contiguous(), b = b_in.to(torch::kFloat64).contiguous();
  const int H = int(a.size(0)), W = int(a.size(1)), C = int(a.size(2));
  auto A = a.accessor<double, 3>();
  auto B = b.accessor<double, 3>();
  double w[11], sum = 0;
  for (int i = 0; i < 11; ++i) sum += (w[i] = std::exp(-double((i - 5) * (i - 5)) / 4.5));
  for (double& v : w) v /= sum;
  double total = 0;
  for (int c = 0; c < C; ++c)
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        double mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
        for (int dy = -5; dy <= 5; ++dy)
          for (int dx = -5; dx <= 5; ++dx) {
            const int py = y + dy, px = x + dx;
            if (py < 0 || py >= H || px < 0 || px >= W) continue;  // zero padding
            const double k = w[dy + 5] * w[dx + 5], va = A[py][px][c], vb = B[py][px][c];
            mx += k * va;
            my += k * vb;
            xx += k * va * va;
            yy += k * vb * vb;
            xy += k * va * vb;
          }
        const double sx = xx - mx * mx, sy = yy - my * my, sxy = xy - mx * my;
        const double C1 = 1e-4, C2 = 9e-4;
        total += ((2 * mx * my + C1) * (2 * sxy + C2)) / ((mx * mx + my * my + C1) * (sx + sy + C2));
      }
  return total / (double(H) * W * C);
}

TEST(Ssim, WindowIsCentredAndNormalised) {
  const at::Tensor w = cls::ssim_window_1d(torch::kFloat64);
  ASSERT_EQ(w.size(0), 11);
  EXPECT_NEAR(w.sum().item<double>(), 1.0, 1e-15);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(w[i].item<double>(), w[10 - i].item<double>());
  EXPECT_EQ(w.argmax().item<int64_t>(), 5);
  EXPECT_NEAR(w[4].item<double>() / w[5].item<double>(), std::exp(-1.0 / 4.5), 1e-14);
}

TEST(Ssim, MatchesPerPixelReference) {
  torch::manual_seed(1);
  const at::Tensor a = torch::rand({23, 31, 3}, torch::kFloat64);
  const at::Tensor b = (a + 0.2 * torch::randn({23, 31, 3}, torch::kFloat64)).clamp(0, 1);
  const double want = reference_ssim(a, b);
  EXPECT_NEAR(cls::ssim(a, b).item<double>(), want, 1e-12);
  EXPECT_NEAR(cls::ssim(a.to(torch::kFloat), b.to(torch::kFloat)).item<double>(), want, 1e-5);
  EXPECT_LT(want, 0.9);  // the images differ: a meaningful comparison
}

TEST(Ssim, IdenticalImagesGiveOne) {
  torch::manual_seed(2);
  const at::Tensor a = torch::rand({16, 20, 3});
  EXPECT_NEAR(cls::ssim(a, a).item<float>(), 1.0f, 1e-6f);
  EXPECT_NEAR(cls::dssim_loss(a, a).item<float>(), 0.0f, 1e-6f);
  EXPECT_THROW(cls::ssim(a, a.slice(0, 1)), std::exception);
}

TEST(Ssim, GradientMatchesFiniteDifferences) {
  torch::manual_seed(3);
  const at::Tensor a = torch::rand({9, 12, 2}, torch::kFloat64).requires_grad_(true);
  const at::Tensor b = torch::rand({9, 12, 2}, torch::kFloat64);
  cls::dssim_loss(a, b).backward();
  const at::Tensor grad = a.grad();
  const double h = 1e-6;
  for (int k = 0; k < 20; ++k) {
    const int64_t idx = (k * 37) % a.numel();
    at::Tensor p = a.detach().clone(), m = a.detach().clone();
    p.view({-1})[idx] += h;
    m.view({-1})[idx] -= h;
    const double fd = (cls::dssim_loss(p, b).item<double>() - cls::dssim_loss(m, b).item<double>()) / (2 * h);
    const double g = grad.view({-1})[idx].item<double>();
    EXPECT_NEAR(g, fd, 1e-7 + 1e-5 * std::abs(fd)) << idx;
  }
}

// The CPU kernels work in bands of rows with a halo: images taller than several bands, odd sizes, in
// every instruction-set build, against the LibTorch-op form (value and gradient of the first image).
// Restores the kernels in use when a test that forces a build ends, also on a failed assertion.
struct RestoreCpuKernels {
  cls::CpuKernels initial = cls::cpu_kernels();
  ~RestoreCpuKernels() { cls::set_cpu_kernels(initial); }
};

TEST(Ssim, CpuKernelsEqualTheOpsAcrossBandsInEveryBuild) {
  torch::manual_seed(4);
  const RestoreCpuKernels restore;
  for (const cls::CpuKernels k : cls::available_cpu_kernels()) {
    cls::set_cpu_kernels(k);
    for (const auto dtype : {torch::kFloat64, torch::kFloat32}) {
      const bool dbl = dtype == torch::kFloat64;
      const at::Tensor a0 = torch::rand({101, 67, 3}, dtype);
      const at::Tensor b = (a0 + 0.3 * torch::randn_like(a0)).clamp(0, 1);
      const at::Tensor a = a0.clone().requires_grad_(true), a_ops = a0.clone().requires_grad_(true);
      const at::Tensor s = cls::ssim(a, b), s_ops = cls::ssim_ops(a_ops, b);
      ASSERT_NE(s.grad_fn()->name().find("SsimKernels"), std::string::npos) << s.grad_fn()->name();  // the kernels ran
      EXPECT_NEAR(s.item<double>(), s_ops.item<double>(), dbl ? 1e-13 : 2e-6) << cls::cpu_kernels_name(k);
      (3.0 * s).backward();
      (3.0 * s_ops).backward();
      const double scale = a_ops.grad().abs().max().item<double>();
      ASSERT_GT(scale, 0);
      EXPECT_LT((a.grad() - a_ops.grad()).abs().max().item<double>() / scale, dbl ? 1e-12 : 1e-5)
          << cls::cpu_kernels_name(k) << (dbl ? " double" : " float");
      // without a gradient: the same value
      EXPECT_EQ(cls::ssim(a0, b).item<double>(), s.item<double>());
    }
  }
}

// Narrower than the window, four channels, the first image a non-contiguous view.
TEST(Ssim, CpuKernelsTakeSmallNonContiguousImages) {
  torch::manual_seed(6);
  const at::Tensor planar = torch::rand({4, 7, 5}, torch::kFloat64);
  const at::Tensor b = torch::rand({7, 5, 4}, torch::kFloat64);
  const at::Tensor a = planar.permute({1, 2, 0}).requires_grad_(true);
  ASSERT_FALSE(a.is_contiguous());
  const at::Tensor a_ops = a.detach().clone().requires_grad_(true);
  const at::Tensor s = cls::ssim(a, b);
  ASSERT_NE(s.grad_fn()->name().find("SsimKernels"), std::string::npos);
  EXPECT_NEAR(s.item<double>(), reference_ssim(a.detach(), b), 1e-12);
  s.backward();
  cls::ssim_ops(a_ops, b).backward();
  EXPECT_LT((a.grad() - a_ops.grad()).abs().max().item<double>(), 1e-12);
  // no second derivative from the kernels: an error, not a silent zero
  const at::Tensor a2 = torch::rand({9, 8, 3}, torch::kFloat64).requires_grad_(true);
  const at::Tensor s2 = cls::ssim(a2, torch::rand({9, 8, 3}, torch::kFloat64));
  EXPECT_THROW(torch::autograd::grad({s2}, {a2}, {}, /*retain_graph=*/true, /*create_graph=*/true), std::exception);
}

// A differentiable target takes the LibTorch-op form: both images get their gradient.
TEST(Ssim, DifferentiableTargetGetsItsGradient) {
  torch::manual_seed(5);
  const at::Tensor a = torch::rand({12, 10, 3}, torch::kFloat64).requires_grad_(true);
  const at::Tensor b = torch::rand({12, 10, 3}, torch::kFloat64).requires_grad_(true);
  cls::ssim(a, b).backward();
  ASSERT_TRUE(b.grad().defined());
  EXPECT_GT(b.grad().abs().max().item<double>(), 0);
}

}  // namespace
