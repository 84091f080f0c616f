#include "splat/ssim.h"

#include <torch/torch.h>

#include <cmath>

#include "core/error.h"

namespace cls {
namespace {
constexpr int kWindow = 11;
constexpr double kSigma = 1.5;
}  // namespace

at::Tensor ssim_window_1d(at::ScalarType dtype) {
  std::vector<double> w(kWindow);
  double sum = 0;
  for (int i = 0; i < kWindow; ++i) {
    const double x = i - kWindow / 2;
    w[i] = std::exp(-x * x / (2 * kSigma * kSigma));
    sum += w[i];
  }
  for (double& v : w) v /= sum;
  return torch::tensor(w, torch::kFloat64).to(dtype);
}

at::Tensor ssim(const at::Tensor& a, const at::Tensor& b) {
  if (a.dim() != 3 || a.sizes() != b.sizes())
    throw Error("ssim: expected two H x W x C images of the same shape, got " + c10::str(a.sizes()) + " and " +
                c10::str(b.sizes()));
  const int64_t channels = a.size(2);
  const at::Tensor w1 = ssim_window_1d(a.scalar_type()).to(a.device());
  // Separable window as one 2-D kernel (outer product), one copy per channel (grouped convolution).
  const at::Tensor window = torch::outer(w1, w1).expand({channels, 1, kWindow, kWindow}).contiguous();
  auto filter = [&](const at::Tensor& x) {
    return torch::conv2d(x, window, /*bias=*/{}, /*stride=*/1, /*padding=*/kWindow / 2, /*dilation=*/1, channels);
  };
  const at::Tensor x = a.permute({2, 0, 1}).unsqueeze(0);
  const at::Tensor y = b.permute({2, 0, 1}).unsqueeze(0);
  const at::Tensor mu_x = filter(x), mu_y = filter(y);
  const at::Tensor mu_x2 = mu_x * mu_x, mu_y2 = mu_y * mu_y, mu_xy = mu_x * mu_y;
  const at::Tensor sigma_x2 = filter(x * x) - mu_x2;
  const at::Tensor sigma_y2 = filter(y * y) - mu_y2;
  const at::Tensor sigma_xy = filter(x * y) - mu_xy;
  constexpr double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  const at::Tensor map = ((2 * mu_xy + C1) * (2 * sigma_xy + C2)) / ((mu_x2 + mu_y2 + C1) * (sigma_x2 + sigma_y2 + C2));
  return map.mean();
}

at::Tensor dssim_loss(const at::Tensor& a, const at::Tensor& b) { return 1 - ssim(a, b); }

}  // namespace cls
