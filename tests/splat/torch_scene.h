#pragma once
// A random scene of the rasterizer tests (splat_scene.h) as LibTorch tensors with its settings, and random
// weights of its image, alpha and depth for the losses whose gradients the tests check.
#include <torch/torch.h>

#include "splat/rasterize.h"
#include "splat_scene.h"

namespace cls {

struct TorchScene {
  RasterizeSettings settings;
  torch::Tensor means, scales, quats, opacities, values, w_image, w_alpha, w_depth;
  bool sh = true;
};

inline TorchScene torch_scene(bool use_sh, int channels, unsigned seed, torch::Dtype dtype, int gaussians = 10, int width = 36,
                              int height = 34) {
  const auto s = test::random_scene(gaussians, width, height, channels, use_sh, seed, 0.7);
  TorchScene t;
  t.sh = use_sh;
  t.settings.camera = PinholeCamera{s.cam.fx, s.cam.fy, s.cam.cx, s.cam.cy, s.cam.width, s.cam.height};
  t.settings.pose.R = s.cam.R;
  t.settings.pose.t = s.cam.t;
  auto tensor = [&](const std::vector<double>& v, std::vector<int64_t> shape) {
    return torch::tensor(v, torch::kFloat64).reshape(shape).to(dtype);
  };
  const int64_t n = s.n;
  t.means = tensor(s.means, {n, 3});
  t.scales = tensor(s.scales, {n, 3});
  t.quats = tensor(s.quats, {n, 4});
  t.opacities = tensor(s.opacities, {n});
  t.values = use_sh ? tensor(s.sh, {n, 16, 3}) : tensor(s.features, {n, channels});
  t.settings.background = tensor(s.background, {int64_t(s.background.size())});
  torch::manual_seed(seed);
  t.w_image = torch::randn({s.cam.height, s.cam.width, s.channels}, torch::kFloat64).to(dtype);
  t.w_alpha = torch::randn({s.cam.height, s.cam.width}, torch::kFloat64).to(dtype);
  t.w_depth = 0.2 * torch::randn({s.cam.height, s.cam.width}, torch::kFloat64).to(dtype);
  return t;
}

}  // namespace cls
