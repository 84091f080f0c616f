#include "splat/ssim.h"

#include <torch/torch.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "splat/ssim_cpu.h"

#ifdef CLS_WITH_CUDA
#include <c10/cuda/CUDAGuard.h>
#include <c10/cuda/CUDAStream.h>

#include "splat/cuda_check.h"
#include "splat/ssim_cuda.h"
#endif

namespace cls {

at::Tensor ssim_window_1d(at::ScalarType dtype) {
  const std::array<double, kSsimWindow> taps = ssim_window_taps();
  return torch::tensor(std::vector<double>(taps.begin(), taps.end()), torch::kFloat64).to(dtype);
}

namespace {

constexpr int kWindow = kSsimWindow;

void check_images(const at::Tensor& a, const at::Tensor& b) {
  if (a.dim() != 3 || a.sizes() != b.sizes())
    throw Error("ssim: expected two H x W x C images of the same shape, got " + c10::str(a.sizes()) + " and " +
                c10::str(b.sizes()));
}

#ifdef CLS_WITH_CUDA
// The window's taps in float, computed once (every training iteration asks twice).
const float* float_taps() {
  static const std::array<float, kSsimWindow> taps = [] {
    const std::array<double, kSsimWindow> t = ssim_window_taps();
    std::array<float, kSsimWindow> f{};
    for (int i = 0; i < kSsimWindow; ++i) f[i] = static_cast<float>(t[i]);
    return f;
  }();
  return taps.data();
}
#endif

// The kernels' forward (ssim_cpu.h, or ssim_cuda.h for CUDA tensors) of contiguous images; dm
// (C x 3 x H x W) receives the moment derivatives when defined. A 0-d tensor on a's device.
at::Tensor kernel_ssim_forward(const at::Tensor& a, const at::Tensor& b, const at::Tensor& dm) {
  const int H = int(a.size(0)), W = int(a.size(1)), C = int(a.size(2));
  if (a.is_cuda()) {
#ifdef CLS_WITH_CUDA
    const c10::cuda::CUDAGuard guard(a.device());  // the stream of the images' GPU
    at::Tensor map = torch::empty({C, H, W}, a.options()), work = torch::empty({5, C, H, W}, a.options());
    check_cuda(ssim_forward_cuda(float_taps(), a.data_ptr<float>(), b.data_ptr<float>(), H, W, C,
                                 map.data_ptr<float>(), dm.defined() ? dm.data_ptr<float>() : nullptr,
                                 work.data_ptr<float>(), c10::cuda::getCurrentCUDAStream().stream()),
               "ssim: forward");
    return map.mean();
#endif
  }
  const double value =
      a.scalar_type() == torch::kDouble
          ? ssim_forward_cpu(a.data_ptr<double>(), b.data_ptr<double>(), H, W, C, dm.defined() ? dm.data_ptr<double>() : nullptr)
          : ssim_forward_cpu(a.data_ptr<float>(), b.data_ptr<float>(), H, W, C, dm.defined() ? dm.data_ptr<float>() : nullptr);
  return torch::scalar_tensor(value, a.options());
}

// The kernels as an autograd function of the first image (the second is the target).
struct SsimKernels : torch::autograd::Function<SsimKernels> {
  static at::Tensor forward(torch::autograd::AutogradContext* ctx, const at::Tensor& a_in, const at::Tensor& b_in) {
    const at::Tensor a = a_in.contiguous(), b = b_in.contiguous();
    const at::Tensor dm = torch::empty({a.size(2), 3, a.size(0), a.size(1)}, a.options());
    ctx->save_for_backward({a, b, dm});
    return kernel_ssim_forward(a, b, dm);
  }
  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad_out) {
    // The gradient is computed by the kernel, not by differentiable ops: no second derivative.
    if (at::GradMode::is_enabled())
      throw Error("ssim: the SSIM kernels give no second derivative (create_graph); use ssim_ops for that");
    const torch::autograd::variable_list saved = ctx->get_saved_variables();
    const at::Tensor &a = saved[0], &b = saved[1], &dm = saved[2];
    const int H = int(a.size(0)), W = int(a.size(1)), C = int(a.size(2));
    at::Tensor grad = torch::empty_like(a);
    if (a.is_cuda()) {
#ifdef CLS_WITH_CUDA
      const c10::cuda::CUDAGuard guard(a.device());
      // the incoming gradient stays on the device: no wait for it
      const at::Tensor scale = grad_out[0].to(a.options()).contiguous();
      at::Tensor work = torch::empty({3, C, H, W}, a.options());
      check_cuda(ssim_backward_cuda(float_taps(), a.data_ptr<float>(), b.data_ptr<float>(), dm.data_ptr<float>(),
                                    H, W, C, scale.data_ptr<float>(), grad.data_ptr<float>(), work.data_ptr<float>(),
                                    c10::cuda::getCurrentCUDAStream().stream()),
                 "ssim: backward");
#endif
    } else if (a.scalar_type() == torch::kDouble) {
      ssim_backward_cpu(a.data_ptr<double>(), b.data_ptr<double>(), dm.data_ptr<double>(), H, W, C,
                        grad_out[0].item<double>(), grad.data_ptr<double>());
    } else {
      ssim_backward_cpu(a.data_ptr<float>(), b.data_ptr<float>(), dm.data_ptr<float>(), H, W, C,
                        grad_out[0].item<float>(), grad.data_ptr<float>());
    }
    return {grad, at::Tensor()};
  }
};

// ssim_ops after its shape check.
at::Tensor ssim_from_ops(const at::Tensor& a, const at::Tensor& b) {
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
  constexpr double C1 = kSsimC1, C2 = kSsimC2;
  const at::Tensor map = ((2 * mu_xy + C1) * (2 * sigma_xy + C2)) / ((mu_x2 + mu_y2 + C1) * (sigma_x2 + sigma_y2 + C2));
  return map.mean();
}

}  // namespace

at::Tensor ssim(const at::Tensor& a, const at::Tensor& b) {
  check_images(a, b);
  const bool cpu = a.device().is_cpu() && b.device().is_cpu() &&
                   (a.scalar_type() == torch::kFloat || a.scalar_type() == torch::kDouble);
#ifdef CLS_WITH_CUDA
  const bool cuda = a.is_cuda() && b.device() == a.device() && a.scalar_type() == torch::kFloat;
#else
  const bool cuda = false;
#endif
  const bool kernels = (cpu || cuda) && a.numel() > 0 && !b.requires_grad() && b.scalar_type() == a.scalar_type();
  if (!kernels) return ssim_from_ops(a, b);
  if (a.requires_grad() && at::GradMode::is_enabled()) return SsimKernels::apply(a, b);
  return kernel_ssim_forward(a.contiguous(), b.contiguous(), at::Tensor());
}

at::Tensor ssim_ops(const at::Tensor& a, const at::Tensor& b) {
  check_images(a, b);
  return ssim_from_ops(a, b);
}

at::Tensor dssim_loss(const at::Tensor& a, const at::Tensor& b) { return 1 - ssim(a, b); }

double psnr(const at::Tensor& a, const at::Tensor& b) {
  if (a.sizes() != b.sizes())
    throw Error("psnr: images of different shapes " + c10::str(a.sizes()) + " and " + c10::str(b.sizes()));
  const double mse = (a - b).pow(2).mean().item<double>();
  return 20 * std::log10(1.0 / std::sqrt(std::max(mse, 1e-20)));
}

}  // namespace cls
