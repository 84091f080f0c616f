#pragma once
// SSIM on CUDA (ssim_cuda.cu): the passes of the CPU kernels (ssim_cpu.h), one thread per pixel and
// channel. The forward blurs the five moment maps along rows, then along columns, where each pixel gets
// its SSIM and the three moment derivatives (ssim_pixel.h); the backward blurs those back the same way.
// Replaces LibTorch's grouped convolutions and elementwise ops for float32 CUDA images (about 2.6 ms of a
// photometric iteration at 1600x1000 on an H100, 0.42 ms with these; docs/benchmarks.md, "GPU, second
// round"). No CUDA headers here; device pointers;
// images H x W x C, channel-last, contiguous; `taps`: the kSsimWindow window taps (host memory,
// ssim_window_taps); `stream` is a cudaStream_t. Both return the first cudaError_t met (0 = success).
namespace cls {

// map: C x H x W SSIM values (their mean is the SSIM); dm: C x 3 x H x W moment derivatives, or null;
// work: 5 x C x H x W floats.
int ssim_forward_cuda(const float* taps, const float* a, const float* b, int H, int W, int C, float* map, float* dm,
                      float* work, void* stream);

// grad_a = scale[0] / (H W C) (blur(dm_0) + 2 a blur(dm_1) + b blur(dm_2)), the window being symmetric;
// scale: one device float (the incoming gradient); work: 3 x C x H x W floats.
int ssim_backward_cuda(const float* taps, const float* a, const float* b, const float* dm, int H, int W, int C,
                       const float* scale, float* grad_a, float* work, void* stream);

}  // namespace cls
