#pragma once
// A random feature scene of the rasterizer tests (tests/splat/splat_scene.h) as a GaussianModel with
// one latent row per Gaussian, and its camera and pose.
#include <torch/torch.h>

#include "scene/camera.h"
#include "splat/gaussians.h"
#include "splat/splat_scene.h"

namespace cls::test {

struct LatentScene {
  RandomScene s;
  GaussianModel g;
  at::Tensor latents;  // N x L float32
  PinholeCamera camera;
  Pose pose;
};

inline LatentScene latent_scene(int n, int w, int h, int L, unsigned seed) {
  LatentScene t;
  t.s = random_scene(n, w, h, L, /*use_sh=*/false, seed, 0.95);
  t.g = make_gaussians(n, 0);
  auto tensor = [](const std::vector<double>& v, std::vector<int64_t> shape) {
    return torch::tensor(v, torch::kFloat64).reshape(shape);
  };
  t.g.means = tensor(t.s.means, {n, 3}).to(torch::kFloat32);
  t.g.log_scales = tensor(t.s.scales, {n, 3}).log().to(torch::kFloat32);
  t.g.quats = tensor(t.s.quats, {n, 4}).to(torch::kFloat32);
  t.g.opacity_logits = tensor(t.s.opacities, {n, 1}).logit().to(torch::kFloat32);
  t.latents = tensor(t.s.features, {n, L}).to(torch::kFloat32);
  t.camera = PinholeCamera{t.s.cam.fx, t.s.cam.fy, t.s.cam.cx, t.s.cam.cy, w, h};
  t.pose.R = t.s.cam.R;
  t.pose.t = t.s.cam.t;
  return t;
}

}  // namespace cls::test
