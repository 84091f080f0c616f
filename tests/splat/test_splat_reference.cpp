// The fast CPU rasterizer (float32) against the double-precision reference renderer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "omp_threads.h"
#include "splat/reference_render.h"
#include "splat_scene.h"

namespace cls {
namespace {

struct Diff {
  double image = 0, alpha = 0, depth = 0;
  double coverage = 0;  // fraction of pixels with alpha > 0.05 (the scene must not be empty)
};

Diff compare_with_reference(const test::RandomScene& s) {
  const auto af = test::scene_arrays<float>(s);
  const auto ad = test::scene_arrays<double>(s);
  const size_t n_pix = static_cast<size_t>(s.cam.width) * s.cam.height;
  std::vector<float> image(n_pix * s.channels), alpha(n_pix), depth(n_pix);
  SplatForwardState<float> st;
  rasterize_forward_cpu(test::cast_camera<float>(s.cam), af.inputs(s), image.data(), alpha.data(), depth.data(), st);
  const ReferenceImage ref = reference_render(s.cam, ad.inputs(s));
  Diff d;
  for (size_t i = 0; i < image.size(); ++i) d.image = std::max(d.image, std::abs(image[i] - ref.image[i]));
  for (size_t i = 0; i < n_pix; ++i) {
    d.alpha = std::max(d.alpha, std::abs(alpha[i] - ref.alpha[i]));
    d.depth = std::max(d.depth, std::abs(depth[i] - ref.depth[i]) / std::max(1.0, ref.depth[i]));
    d.coverage += ref.alpha[i] > 0.05 ? 1.0 / n_pix : 0.0;
  }
  return d;
}

// Every instruction-set build of the tile kernels this CPU runs (rasterize_cpu.h) is held to the reference.
TEST(SplatReference, RgbFromShMatchesReference) {
  for (CpuKernels k : available_cpu_kernels()) {
    test::ScopedCpuKernels use(k);
    for (unsigned seed : {1u, 2u}) {
      const auto s = test::random_scene(300, 70, 45, 3, /*use_sh=*/true, seed, /*max_opacity=*/0.98);
      const Diff d = compare_with_reference(s);
      EXPECT_LT(d.image, 1e-5) << "seed " << seed;
      EXPECT_LT(d.alpha, 1e-5) << "seed " << seed;
      EXPECT_LT(d.depth, 1e-5) << "seed " << seed;
      EXPECT_GT(d.coverage, 0.5);
    }
  }
}

class SplatReferenceChannels : public ::testing::TestWithParam<int> {};

TEST_P(SplatReferenceChannels, FeaturesMatchReference) {
  const int C = GetParam();
  for (CpuKernels k : available_cpu_kernels()) {
    test::ScopedCpuKernels use(k);
    const auto s = test::random_scene(200, 53, 37, C, /*use_sh=*/false, 10 + C, 0.98);
    const Diff d = compare_with_reference(s);
    EXPECT_LT(d.image, 1e-5);
    EXPECT_LT(d.alpha, 1e-5);
    EXPECT_LT(d.depth, 1e-5);
    EXPECT_GT(d.coverage, 0.5);
  }
}

INSTANTIATE_TEST_SUITE_P(Channels, SplatReferenceChannels, ::testing::Values(1, 3, 16, 32, 128, 147));

// Pixel convention: a small round Gaussian whose mean projects exactly onto the centre of pixel
// (20, 11), i.e. image point (20.5, 11.5), is brightest there and symmetric around it.
TEST(SplatReference, PixelCentreConvention) {
  SplatCamera<float> cam;
  cam.width = 40, cam.height = 30, cam.fx = 50, cam.fy = 50, cam.cx = 17.25f, cam.cy = 14.5f;
  const float z = 4;
  const float mean[3] = {(20.5f - cam.cx) * z / cam.fx, (11.5f - cam.cy) * z / cam.fy, z};
  const float scale[3] = {0.08f, 0.08f, 0.08f}, quat[4] = {1, 0, 0, 0}, opacity[1] = {0.9f}, feat[1] = {1};
  SplatInputs<float> in;
  in.n = 1, in.means = mean, in.scales = scale, in.quats = quat, in.opacities = opacity;
  in.features = feat, in.channels = 1;
  std::vector<float> image(40 * 30), alpha(40 * 30), depth(40 * 30);
  SplatForwardState<float> st;
  rasterize_forward_cpu(cam, in, image.data(), alpha.data(), depth.data(), st);
  auto at = [&](int i, int j) { return image[j * 40 + i]; };
  EXPECT_NEAR(at(20, 11), 0.9f, 1e-6);  // exp(0) at the centre
  EXPECT_NEAR(at(19, 11), at(21, 11), 1e-6);
  EXPECT_NEAR(at(20, 10), at(20, 12), 1e-6);
  EXPECT_LT(at(19, 11), at(20, 11));
  EXPECT_NEAR(depth[11 * 40 + 20], 0.9f * z, 1e-5);
}

// Hand-computed blending at the centre of pixel (10, 10) where every Gaussian peaks (power = 0).
struct StackedGaussians {
  std::vector<float> means, scales, quats, opacities, values;
  float background = 1000;
  void add(float depth, float opacity, float value) {
    const float u = 10.5f, v = 10.5f, f = 40, c = 8;  // camera: f = 40, principal point (8, 8)
    for (float m : {(u - c) * depth / f, (v - c) * depth / f, depth}) means.push_back(m);
    for (int k = 0; k < 3; ++k) scales.push_back(0.05f * depth);
    for (float q : {1.f, 0.f, 0.f, 0.f}) quats.push_back(q);
    opacities.push_back(opacity);
    values.push_back(value);
  }
  // Returns (fast path, reference) values at pixel (10, 10).
  std::pair<float, double> render() const {
    SplatCamera<float> cam;
    cam.width = cam.height = 24, cam.fx = cam.fy = 40, cam.cx = cam.cy = 8;
    SplatInputs<float> in;
    in.n = static_cast<int>(opacities.size());
    in.means = means.data(), in.scales = scales.data(), in.quats = quats.data(), in.opacities = opacities.data();
    in.features = values.data(), in.channels = 1, in.background = &background;
    std::vector<float> image(24 * 24), alpha(24 * 24), depth(24 * 24);
    SplatForwardState<float> st;
    rasterize_forward_cpu(cam, in, image.data(), alpha.data(), depth.data(), st);
    auto d = [](const std::vector<float>& v) { return std::vector<double>(v.begin(), v.end()); };
    const auto md = d(means), sd = d(scales), qd = d(quats), od = d(opacities), vd = d(values);
    const double bg = background;
    SplatInputs<double> ind;
    ind.n = in.n, ind.means = md.data(), ind.scales = sd.data(), ind.quats = qd.data(), ind.opacities = od.data();
    ind.features = vd.data(), ind.channels = 1, ind.background = &bg;
    const ReferenceImage ref = reference_render(test::cast_camera<double>(cam), ind);
    return {image[10 * 24 + 10], ref.image[10 * 24 + 10]};
  }
};

TEST(SplatReference, AlphaIsClampedAt099) {
  StackedGaussians s;
  s.add(3, 1.0f, 1);
  const auto [fast, ref] = s.render();
  EXPECT_NEAR(fast, 0.99 * 1 + 0.01 * 1000, 1e-3);
  EXPECT_NEAR(ref, 0.99 * 1 + 0.01 * 1000, 1e-9);
}

TEST(SplatReference, BlendingStopsBeforeTransmittanceFallsBelow1e4) {
  // alpha 0.98 three times: T = 0.02, 4e-4, then 8e-6 < 1e-4, so the third is not blended and the
  // background is weighted by T = 4e-4.
  StackedGaussians s;
  s.add(2, 0.98f, 1);
  s.add(3, 0.98f, 10);
  s.add(4, 0.98f, 100);
  const double expected = 0.98 * 1 + 0.02 * 0.98 * 10 + 0.02 * 0.02 * 1000;
  const auto [fast, ref] = s.render();
  EXPECT_NEAR(fast, expected, 1e-4);
  EXPECT_NEAR(ref, expected, 1e-5);  // opacities are the float 0.98f
}

// The per-tile lists of the forward state against a brute-force binning: every visible Gaussian whose tile
// rectangle holds the tile, front to back, ties in depth by id. Half the Gaussians share the depth of another
// (a copy moved sideways), on 1 to 3 threads, on an image of 10 x 7 tiles (the tiles are blended in strips of
// rows, rasterize_cpu.cpp): the lists must not depend on the threads, nor the image (of the scene without
// the copies: in double their depths differ by rounding, so the reference may order them otherwise).
TEST(SplatTiles, ListsHoldEveryGaussianOfItsTileFrontToBack) {
  const auto plain = test::random_scene(300, 150, 110, 5, /*use_sh=*/false, 21, 0.98);
  auto s = plain;
  for (int i = 1; i < s.n; i += 2) {  // the same camera z as Gaussian i - 1: the camera moves along its rotated axes
    const Vec3d shift = transpose(s.cam.R) * Vec3d{0.05 * i / s.n, -0.03, 0.0};
    for (int k = 0; k < 3; ++k) s.means[3 * i + k] = s.means[3 * (i - 1) + k] + shift[k];
  }
  const auto af = test::scene_arrays<float>(s);
  for (int threads : {1, 2, 3}) {
    const test::ScopedOmpThreads use(threads);
    const size_t n_pix = static_cast<size_t>(s.cam.width) * s.cam.height;
    std::vector<float> image(n_pix * s.channels), alpha(n_pix), depth(n_pix);
    SplatForwardState<float> st;
    rasterize_forward_cpu(test::cast_camera<float>(s.cam), af.inputs(s), image.data(), alpha.data(), depth.data(), st);
    const int tiles_x = st.cam.tiles_x(), n_tiles = tiles_x * st.cam.tiles_y();
    ASSERT_EQ(static_cast<int>(st.tile_begin.size()), n_tiles);
    int ties = 0;
    for (int tile = 0; tile < n_tiles; ++tile) {
      std::vector<std::pair<float, int32_t>> expected;
      for (int i = 0; i < s.n; ++i) {
        const ProjectedGaussian<float>& p = st.proj[i];
        const int x = tile % tiles_x, y = tile / tiles_x;
        if (p.visible && p.rect_min[0] <= x && x < p.rect_max[0] && p.rect_min[1] <= y && y < p.rect_max[1])
          expected.emplace_back(p.depth, i);
      }
      std::sort(expected.begin(), expected.end());
      for (size_t k = 1; k < expected.size(); ++k) ties += expected[k].first == expected[k - 1].first;
      const std::vector<int32_t> got(st.ids.begin() + st.tile_begin[tile], st.ids.begin() + st.tile_end[tile]);
      std::vector<int32_t> want;
      for (const auto& e : expected) want.push_back(e.second);
      ASSERT_EQ(got, want) << "tile " << tile;
    }
    EXPECT_GT(ties, 50) << "the scene must have Gaussians of equal depth in one tile";
    const Diff d = compare_with_reference(plain);
    EXPECT_LT(d.image, 1e-5);
    EXPECT_LT(d.alpha, 1e-5);
    EXPECT_GT(d.coverage, 0.5);
  }
}

}  // namespace
}  // namespace cls
