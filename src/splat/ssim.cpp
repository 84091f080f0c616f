#include "splat/ssim.h"

#include <torch/torch.h>

#include <algorithm>
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
  // The window is separable and the padding zero, so a 1 x 11 pass then an 11 x 1 pass equal the
  // 11 x 11 convolution (22 instead of 121 taps). The five local moments go through one grouped
  // convolution: [x, y, x^2, y^2, xy], each channel filtered on its own.
  const at::Tensor x = a.permute({2, 0, 1}).unsqueeze(0);
  const at::Tensor y = b.permute({2, 0, 1}).unsqueeze(0);
  const at::Tensor maps = torch::cat({x, y, x * x, y * y, x * y}, 1);
  const int64_t groups = 5 * channels;
  const at::Tensor horizontal = w1.view({1, 1, 1, kWindow}).expand({groups, 1, 1, kWindow}).contiguous();
  const at::Tensor vertical = w1.view({1, 1, kWindow, 1}).expand({groups, 1, kWindow, 1}).contiguous();
  const int64_t r = kWindow / 2;
  const std::vector<int64_t> stride{1, 1}, dilation{1, 1}, pad_h{0, r}, pad_v{r, 0};
  const at::Tensor filtered = torch::conv2d(torch::conv2d(maps, horizontal, at::Tensor(), stride, pad_h, dilation, groups),
                                            vertical, at::Tensor(), stride, pad_v, dilation, groups);
  const std::vector<at::Tensor> m = filtered.split(channels, 1);
  const at::Tensor &mu_x = m[0], &mu_y = m[1];
  const at::Tensor mu_x2 = mu_x * mu_x, mu_y2 = mu_y * mu_y, mu_xy = mu_x * mu_y;
  const at::Tensor sigma_x2 = m[2] - mu_x2;
  const at::Tensor sigma_y2 = m[3] - mu_y2;
  const at::Tensor sigma_xy = m[4] - mu_xy;
  constexpr double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  const at::Tensor map = ((2 * mu_xy + C1) * (2 * sigma_xy + C2)) / ((mu_x2 + mu_y2 + C1) * (sigma_x2 + sigma_y2 + C2));
  return map.mean();
}

at::Tensor dssim_loss(const at::Tensor& a, const at::Tensor& b) { return 1 - ssim(a, b); }

double psnr(const at::Tensor& a, const at::Tensor& b) {
  if (a.sizes() != b.sizes())
    throw Error("psnr: images of different shapes " + c10::str(a.sizes()) + " and " + c10::str(b.sizes()));
  const double mse = (a - b).pow(2).mean().item<double>();
  return 20 * std::log10(1.0 / std::sqrt(std::max(mse, 1e-20)));
}

}  // namespace cls
