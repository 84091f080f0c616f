#pragma once
// SSIM (Wang et al. 2004) as 3DGS's loss_utils.ssim computes it: an 11x11 Gaussian window
// (sigma 1.5, centred on the middle tap, normalised to sum 1) applied per channel as a
// convolution with zero padding, C1 = 0.01^2, C2 = 0.03^2, the SSIM map averaged over all
// pixels and channels. Built from LibTorch ops, so it is differentiable.
#include <ATen/core/Tensor.h>

namespace cls {

// The 1-D window: w[i] = exp(-(i - 5)^2 / (2 sigma^2)) / sum, i = 0..10.
at::Tensor ssim_window_1d(at::ScalarType dtype);

// Mean SSIM of two H x W x C images (channel-last, the rasterizer's layout) of the same shape and
// dtype; values are expected in [0, 1] (the constants assume a dynamic range of 1). With b not
// requiring a gradient, kernels compute it and its gradient: ssim_cpu.h's on the CPU (float, double),
// ssim_cuda.h's for float32 CUDA tensors in a CUDA build; otherwise ssim_ops.
at::Tensor ssim(const at::Tensor& a, const at::Tensor& b);

// The same from LibTorch ops (a separable grouped convolution of the five moment maps): any device,
// both images differentiable; the reference the kernels are tested against.
at::Tensor ssim_ops(const at::Tensor& a, const at::Tensor& b);

// D-SSIM term of the 3DGS loss: 1 - ssim(a, b).
at::Tensor dssim_loss(const at::Tensor& a, const at::Tensor& b);

// PSNR in dB for a peak of 1 (3DGS's image_utils.psnr): 20 log10(1 / sqrt(MSE)), the MSE over all
// pixels and channels of two same-shaped images, floored at 1e-20 so that identical images give 200 dB.
double psnr(const at::Tensor& a, const at::Tensor& b);

}  // namespace cls
