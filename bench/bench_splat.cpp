// Rasterizer speed: forward and forward+backward ms per iteration for a fixed random scene
// (default 200k Gaussians, 800x600) with RGB from SH degree 3 and with 128 feature channels.
// --device cpu calls the CPU kernels directly; --device cuda goes through the autograd functions
// (rasterize.h) on CUDA tensors, synchronising after each pass, and adds a photometric training step
// (forward, L1 + 0.2 D-SSIM against a target image, backward: 3DGS's loss).
// Usage: bench_splat [--threads N] [--device cpu|cuda] [--gaussians N] [--width W] [--height H] [--iters N]
// Figures go to docs/benchmarks.md.
#include <omp.h>
#include <torch/cuda.h>
#include <torch/torch.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "bench_timer.h"
#include "core/args.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "splat/compute_device.h"
#include "splat/rasterize.h"
#include "splat/rasterize_cpu.h"
#include "splat/ssim.h"

namespace cls {
namespace {

using bench::Clock;
// Process CPU time: on a shared machine, CPU ms / threads estimates the idle-core wall time.
double cpu_ms() { return 1e3 * bench::cpu_seconds(); }

struct Scene {
  SplatCamera<float> cam;
  int n = 0;
  std::vector<float> means, scales, quats, opacities, sh, features;
};

// Gaussians spread over the view frustum between z = 3 and 15, screen sigmas log-uniform in
// [0.5, 8] px (the range a trained 3DGS scene has), opacities in [0.1, 0.9], SH degree 3.
Scene make_scene(int n, int width, int height, int channels) {
  Scene s;
  s.n = n;
  s.cam.width = width, s.cam.height = height;
  s.cam.fx = s.cam.fy = 0.8f * width;
  s.cam.cx = 0.5f * width, s.cam.cy = 0.5f * height;
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> U(0, 1);
  for (int i = 0; i < n; ++i) {
    const float z = 3 + 12 * U(rng);
    s.means.insert(s.means.end(), {(U(rng) - 0.5f) * z * width / s.cam.fx, (U(rng) - 0.5f) * z * height / s.cam.fy, z});
    for (int k = 0; k < 3; ++k) s.scales.push_back(z / s.cam.fx * 0.5f * std::pow(16.0f, U(rng)));
    float q[4], qn = 0;
    for (float& v : q) v = U(rng) - 0.5f, qn += v * v;
    for (float v : q) s.quats.push_back(v / std::sqrt(qn));
    s.opacities.push_back(0.1f + 0.8f * U(rng));
  }
  s.sh.resize(static_cast<size_t>(n) * 48);
  for (auto& v : s.sh) v = 0.2f * (U(rng) - 0.5f);
  for (int i = 0; i < n; ++i) s.sh[48 * i] += 1;
  s.features.resize(static_cast<size_t>(n) * channels);
  for (auto& v : s.features) v = U(rng);
  return s;
}

struct Timing {
  double forward_ms = 0, backward_ms = 0, cpu_ms = 0;
  double instances = 0;
  double max_image_diff = -1;  // CUDA: max |image - the CPU kernels' image| of the last iteration
};

// The CPU kernels' view of the scene: SH degree 3 or `channels` features.
SplatInputs<float> inputs_of(const Scene& s, bool use_sh, int channels) {
  SplatInputs<float> in;
  in.n = s.n;
  in.means = s.means.data(), in.scales = s.scales.data(), in.quats = s.quats.data(), in.opacities = s.opacities.data();
  if (use_sh) in.sh = s.sh.data(), in.sh_degree = 3;
  else in.features = s.features.data(), in.channels = channels;
  return in;
}

Timing run(const Scene& s, bool use_sh, int channels, int iters) {
  const SplatInputs<float> in = inputs_of(s, use_sh, channels);
  const int C = use_sh ? 3 : channels;
  const size_t n_pix = static_cast<size_t>(s.cam.width) * s.cam.height;
  std::vector<float> image(n_pix * C), alpha(n_pix), depth(n_pix), dimage(n_pix * C, 1e-3f);
  std::vector<float> gm(s.means.size()), gs(s.scales.size()), gq(s.quats.size()), go(s.opacities.size()),
      gsh(use_sh ? s.sh.size() : 0), gf(use_sh ? 0 : s.features.size()), g2(2 * s.n), g2a(2 * s.n);
  SplatForwardState<float> st;
  Timing t;
  for (int it = -1; it < iters; ++it) {  // iteration -1 warms up
    const double c0 = cpu_ms();
    const auto t0 = Clock::now();
    rasterize_forward_cpu(s.cam, in, image.data(), alpha.data(), depth.data(), st);
    const auto t1 = Clock::now();
    SplatGradients<float> g;
    g.means = gm.data(), g.scales = gs.data(), g.quats = gq.data(), g.opacities = go.data();
    g.sh = use_sh ? gsh.data() : nullptr;
    g.features = use_sh ? nullptr : gf.data();
    g.mean2d = g2.data(), g.mean2d_abs = g2a.data();
    rasterize_backward_cpu<float>(in, st, dimage.data(), nullptr, nullptr, g);
    const auto t2 = Clock::now();
    const double c2 = cpu_ms();
    if (it >= 0) {
      t.cpu_ms += (c2 - c0) / iters;
      t.forward_ms += std::chrono::duration<double, std::milli>(t1 - t0).count() / iters;
      t.backward_ms += std::chrono::duration<double, std::milli>(t2 - t1).count() / iters;
    }
  }
  t.instances = static_cast<double>(st.ids.size());
  return t;
}

// The same scene and passes through the autograd functions on `device`. `photometric`: the loss is
// 0.8 L1 + 0.2 D-SSIM against a target image (RGB only); else sum(1e-3 * image), the CPU run's dL/dimage.
Timing run_autograd(const Scene& s, bool use_sh, int channels, int iters, const at::Device& device, bool photometric) {
  const int64_t n = s.n;
  auto tensor = [&](const std::vector<float>& v, std::vector<int64_t> shape) {
    return torch::from_blob(const_cast<float*>(v.data()), shape, torch::kFloat32).to(device).requires_grad_(true);
  };
  const at::Tensor means = tensor(s.means, {n, 3}), scales = tensor(s.scales, {n, 3}), quats = tensor(s.quats, {n, 4}),
                   opacities = tensor(s.opacities, {n});
  const at::Tensor values = use_sh ? tensor(s.sh, {n, 16, 3}) : tensor(s.features, {n, channels});
  const at::Tensor means2d = torch::zeros({n, 2}, means.options()).requires_grad_(true);
  RasterizeSettings settings;
  settings.camera = PinholeCamera{s.cam.fx, s.cam.fy, s.cam.cx, s.cam.cy, s.cam.width, s.cam.height};
  const at::Tensor target = torch::rand({s.cam.height, s.cam.width, 3}, means.options().requires_grad(false));
  const auto sync = [&] {
    if (device.is_cuda()) torch::cuda::synchronize();
  };
  Timing t;
  for (int it = -1; it < iters; ++it) {  // iteration -1 warms up
    const auto t0 = Clock::now();
    const RasterizeOutput out = use_sh ? rasterize_sh(means, scales, quats, opacities, values, 3, means2d, settings)
                                       : rasterize_features(means, scales, quats, opacities, values, means2d, settings);
    const at::Tensor loss = photometric ? 0.8 * (out.image - target).abs().mean() + 0.2 * dssim_loss(out.image, target)
                                        : (out.image * 1e-3).sum();
    sync();
    const auto t1 = Clock::now();
    loss.backward();
    sync();
    const auto t2 = Clock::now();
    for (const at::Tensor& p : {means, scales, quats, opacities, values, means2d}) p.mutable_grad().zero_();
    if (it >= 0) {
      t.forward_ms += std::chrono::duration<double, std::milli>(t1 - t0).count() / iters;
      t.backward_ms += std::chrono::duration<double, std::milli>(t2 - t1).count() / iters;
    }
    // at this scale too, the same image as the CPU kernels (the photometric run's image is the RGB run's)
    if (it == iters - 1 && device.is_cuda() && !photometric) {
      const SplatInputs<float> in = inputs_of(s, use_sh, channels);
      const int64_t C = use_sh ? 3 : channels, n_pix = int64_t(s.cam.width) * s.cam.height;
      std::vector<float> image(static_cast<size_t>(n_pix * C)), alpha(static_cast<size_t>(n_pix)),
          depth(static_cast<size_t>(n_pix));
      SplatForwardState<float> st;
      rasterize_forward_cpu(s.cam, in, image.data(), alpha.data(), depth.data(), st);
      const at::Tensor cpu = torch::from_blob(image.data(), {s.cam.height, s.cam.width, C});
      t.max_image_diff = (out.image.detach().cpu() - cpu).abs().max().item<double>();
    }
  }
  return t;
}

int bench_main(int argc, char** argv) {
  Args args("bench_splat", "Gaussian rasterizer forward/backward time (CPU kernels or CUDA)", "");
  int threads = 2, gaussians = 200000, width = 800, height = 600, channels = 128, iters = 5;
  std::string device_name = "cpu";
  args.bind("threads", threads, "OpenMP threads")
      .bind("gaussians", gaussians, "number of Gaussians")
      .bind("width", width, "image width")
      .bind("height", height, "image height")
      .bind("channels", channels, "feature channels of the second run")
      .bind("iters", iters, "timed iterations per configuration (after one warm-up)")
      .bind("device", device_name, "cpu (the kernels directly) or cuda (autograd functions; needs a CUDA build)");
  if (!args.parse(argc, argv)) return 0;
  const at::Device device = compute_device(device_name);
  omp_set_num_threads(threads);
  const Scene s = make_scene(gaussians, width, height, channels);
  std::printf("scene: %d Gaussians, %dx%d, %s, %d threads\n", s.n, s.cam.width, s.cam.height, device.str().c_str(),
              threads);
  if (device.is_cuda()) {
    const Timing t = run_autograd(s, true, 3, iters, device, true);
    std::printf("%-14s forward+loss %8.2f ms  backward %8.2f ms  iteration %8.2f ms\n", "RGB L1+D-SSIM", t.forward_ms,
                t.backward_ms, t.forward_ms + t.backward_ms);
  }
  for (int pass = 0; pass < 2; ++pass) {
    const bool use_sh = pass == 0;
    const std::string what = use_sh ? "RGB (SH deg 3)" : std::to_string(channels) + " channels";
    if (device.is_cuda()) {
      const Timing t = run_autograd(s, use_sh, channels, iters, device, false);
      std::printf("%-14s forward %8.2f ms  backward %8.2f ms  forward+backward %8.2f ms  max |image - CPU| %.2e\n",
                  what.c_str(), t.forward_ms, t.backward_ms, t.forward_ms + t.backward_ms, t.max_image_diff);
      continue;
    }
    const Timing t = run(s, use_sh, channels, iters);
    std::printf("%-14s forward %8.2f ms  backward %8.2f ms  forward+backward %8.2f ms  CPU %8.1f ms  "
                "(%.0f tile instances)\n",
                what.c_str(), t.forward_ms, t.backward_ms, t.forward_ms + t.backward_ms, t.cpu_ms, t.instances);
  }
  return 0;
}

}  // namespace
}  // namespace cls

int main(int argc, char** argv) {
  cls::reuse_freed_memory();  // as the CLI does
  try {
    return cls::bench_main(argc, argv);
  } catch (const cls::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
