#pragma once
// Small random Gaussian scenes for the rasterizer tests (double storage; tests cast as needed).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "splat/rasterize_cpu.h"

namespace cls::test {

// Runs the CPU rasterizer with one instruction-set build of its tile kernels until the end of the scope
// (named in test failures), then goes back to the best one.
class ScopedCpuKernels {
 public:
  explicit ScopedCpuKernels(CpuKernels k) : trace_(__FILE__, __LINE__, cpu_kernels_name(k)) { set_cpu_kernels(k); }
  ~ScopedCpuKernels() { set_cpu_kernels(best_cpu_kernels()); }
  ScopedCpuKernels(const ScopedCpuKernels&) = delete;
  ScopedCpuKernels& operator=(const ScopedCpuKernels&) = delete;

 private:
  ::testing::ScopedTrace trace_;
};

struct RandomScene {
  SplatCamera<double> cam;
  int n = 0, sh_degree = 3, channels = 3;
  std::vector<double> means, scales, quats, opacities, sh, features, background;

  template <class T>
  static std::vector<T> as(const std::vector<double>& v) {
    return std::vector<T>(v.begin(), v.end());
  }
};

// A camera looking down +z after a small rotation, an image with partial edge tiles, and n Gaussians
// in front of it with moderate sizes and opacities (away from the 0.99 clamp).
inline RandomScene random_scene(int n, int width, int height, int channels, bool use_sh, unsigned seed,
                                double max_opacity = 0.8) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  RandomScene s;
  s.n = n;
  s.channels = use_sh ? 3 : channels;
  s.sh_degree = use_sh ? 3 : -1;
  s.cam.width = width, s.cam.height = height;
  s.cam.fx = 0.9 * width, s.cam.fy = 0.95 * width;
  s.cam.cx = 0.5 * width + 1.3, s.cam.cy = 0.5 * height - 0.7;
  s.cam.R = quat_to_rotation(1.0, 0.05, -0.03, 0.02);
  s.cam.t = {0.1, -0.2, 0.3};
  const Vec3d centre = s.cam.center();
  const Mat3d Rt = transpose(s.cam.R);
  for (int i = 0; i < n; ++i) {
    const double z = 2.0 + 4.0 * U(rng);
    const Vec3d pc{(U(rng) - 0.5) * 1.1 * z * width / s.cam.fx, (U(rng) - 0.5) * 1.1 * z * height / s.cam.fy, z};
    const Vec3d pw = Rt * (pc - s.cam.t);
    (void)centre;
    s.means.insert(s.means.end(), {pw.x, pw.y, pw.z});
    for (int k = 0; k < 3; ++k) s.scales.push_back(z / s.cam.fx * (1.0 + 5.0 * U(rng)));
    double q[4], qn = 0;
    for (double& v : q) v = U(rng) - 0.5, qn += v * v;
    for (double v : q) s.quats.push_back(v / std::sqrt(qn) * (0.5 + U(rng)));
    s.opacities.push_back(0.1 + (max_opacity - 0.1) * U(rng));
  }
  if (use_sh) {
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 16; ++k)
        for (int c = 0; c < 3; ++c) s.sh.push_back(k == 0 ? 0.5 + U(rng) : 0.15 * (U(rng) - 0.5));
  } else {
    for (int i = 0; i < n * channels; ++i) s.features.push_back(U(rng) * 2 - 0.5);
  }
  for (int c = 0; c < s.channels; ++c) s.background.push_back(0.1 + 0.3 * U(rng));
  return s;
}

template <class T>
struct SceneArrays {
  std::vector<T> means, scales, quats, opacities, sh, features, background;
  SplatInputs<T> inputs(const RandomScene& s, bool with_background = true) const {
    SplatInputs<T> in;
    in.n = s.n;
    in.means = means.data(), in.scales = scales.data(), in.quats = quats.data(), in.opacities = opacities.data();
    if (!sh.empty()) in.sh = sh.data(), in.sh_degree = s.sh_degree;
    if (!features.empty()) in.features = features.data();
    in.channels = s.channels;
    in.background = with_background ? background.data() : nullptr;
    return in;
  }
};

template <class T>
SceneArrays<T> scene_arrays(const RandomScene& s) {
  SceneArrays<T> a;
  a.means = RandomScene::as<T>(s.means), a.scales = RandomScene::as<T>(s.scales);
  a.quats = RandomScene::as<T>(s.quats), a.opacities = RandomScene::as<T>(s.opacities);
  a.sh = RandomScene::as<T>(s.sh), a.features = RandomScene::as<T>(s.features);
  a.background = RandomScene::as<T>(s.background);
  return a;
}

template <class T, class U>
SplatCamera<T> cast_camera(const SplatCamera<U>& c) {
  SplatCamera<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.R.m[i][j] = T(c.R.m[i][j]);
  r.t = {T(c.t.x), T(c.t.y), T(c.t.z)};
  r.fx = T(c.fx), r.fy = T(c.fy), r.cx = T(c.cx), r.cy = T(c.cy);
  r.width = c.width, r.height = c.height;
  return r;
}

}  // namespace cls::test
