#pragma once
// SSIM and its gradient on the CPU in one pass over the image per direction (the training loss's D-SSIM;
// ssim.h's LibTorch-op form is the reference the tests compare against, and what other devices use).
// Plain arrays, no LibTorch, templated on the scalar type (float for speed, double for the gradient checks).
// Same definition as ssim.h: 11-tap Gaussian window (sigma 1.5), zero padding, C1 = 0.01^2, C2 = 0.03^2.
#include <array>

#include "splat/ssim_pixel.h"

namespace cls {

constexpr int kSsimWindow = 11;  // taps of the 1-D window

// The normalised 1-D window: w[i] = exp(-(i - 5)^2 / (2 sigma^2)) / sum, i = 0..10.
std::array<double, kSsimWindow> ssim_window_taps();

// Mean SSIM of a and b (H x W x C, channel-last, contiguous). When dmoments is not null it receives, per
// channel c and pixel p, the derivatives of SSIM(p) with respect to the local moments mu_a, E[a^2] and
// E[ab] that ssim_backward_cpu needs: C x 3 x H x W values.
template <class T>
double ssim_forward_cpu(const T* a, const T* b, int H, int W, int C, T* dmoments);

// grad_a = d(scale * mean SSIM)/da from ssim_forward_cpu's dmoments (H x W x C, overwritten):
// scale / (H W C) * (blur(d mu_a) + 2 a blur(d E[a^2]) + b blur(d E[ab])), the window being symmetric.
template <class T>
void ssim_backward_cpu(const T* a, const T* b, const T* dmoments, int H, int W, int C, T scale, T* grad_a);

}  // namespace cls
