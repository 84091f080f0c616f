// Finite-difference checks (double precision, central differences) of the hand-derived backward
// passes: SH colour, projection (quaternion, covariance, EWA, mean2d, depth) and the full rasterizer
// (blending included). Scenes keep away from the clamps, where the functions are smooth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "splat/blend_pixel.h"
#include "splat/sh.h"
#include "splat_scene.h"

namespace cls {
namespace {

constexpr double kH = 1e-6;

// Relative error with a floor, so components that are ~0 are compared absolutely.
double rel_err(double a, double b, double floor = 1e-3) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), floor});
}

double central_diff(double& x, const std::function<double()>& f) {
  const double x0 = x;
  x = x0 + kH;
  const double fp = f();
  x = x0 - kH;
  const double fm = f();
  x = x0;
  return (fp - fm) / (2 * kH);
}

TEST(SplatGradients, ShColour) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int degree = 0; degree <= 3; ++degree) {
    std::vector<double> coeffs(3 * 16);
    for (int k = 0; k < 16; ++k)
      for (int c = 0; c < 3; ++c) coeffs[3 * k + c] = k == 0 ? 1.5 + 0.2 * U(rng) : 0.1 * U(rng);
    Vec3d v{U(rng), U(rng), 2 + U(rng)};
    const double w[3] = {0.3, -1.1, 0.7};
    auto loss = [&]() {
      double rgb[3];
      bool cl[3];
      sh_to_rgb(degree, coeffs.data(), v, rgb, cl);
      EXPECT_FALSE(cl[0] || cl[1] || cl[2]);
      return w[0] * rgb[0] + w[1] * rgb[1] + w[2] * rgb[2];
    };
    std::vector<double> dcoeffs(3 * 16, 0.0);
    const bool cl[3] = {false, false, false};
    const Vec3d dv = sh_to_rgb_backward(degree, coeffs.data(), v, cl, w, dcoeffs.data());
    for (int k = 0; k < 3 * sh_coeff_count(degree); ++k)
      EXPECT_LT(rel_err(dcoeffs[k], central_diff(coeffs[k], loss)), 1e-4) << "degree " << degree << " coeff " << k;
    for (int k = 0; k < 3; ++k)
      EXPECT_LT(rel_err(dv[k], central_diff(v[k], loss)), 1e-4) << "degree " << degree << " dir " << k;
  }
}

// Hand-computed value: degree 1 along +z adds C1 * c_2 to the DC term.
TEST(SplatGradients, ShKnownValue) {
  double coeffs[12] = {1, 2, 3, 0, 0, 0, 0.5, -0.5, 1, 0, 0, 0};
  double rgb[3];
  bool cl[3];
  sh_to_rgb(1, coeffs, Vec3d{0, 0, 5}, rgb, cl);
  const double C0 = 0.28209479177387814, C1 = 0.4886025119029199;
  EXPECT_NEAR(rgb[0], 0.5 + C0 * 1 + C1 * 0.5, 1e-15);
  EXPECT_NEAR(rgb[1], 0.5 + C0 * 2 - C1 * 0.5, 1e-15);
  EXPECT_NEAR(rgb[2], 0.5 + C0 * 3 + C1 * 1, 1e-15);
  coeffs[0] = -3;  // clamps at 0
  sh_to_rgb(1, coeffs, Vec3d{0, 0, 5}, rgb, cl);
  EXPECT_EQ(rgb[0], 0.0);
  EXPECT_TRUE(cl[0]);
}

// Projection of one Gaussian: loss = w . (mean2d, conic, depth) as a function of mean, scale, quat.
void check_projection(const SplatCamera<double>& cam, Vec3d mean, double size, const char* what) {
  double scale[3] = {0.5 * size, 1.1 * size, 0.8 * size};
  double quat[4] = {0.8, 0.3, -0.4, 0.25};
  const double w[6] = {0.7, -0.4, 30.0, -50.0, 20.0, 0.9};
  auto loss = [&]() {
    const auto p = project_gaussian(cam, mean, covariance_3d(scale, quat));
    EXPECT_TRUE(p.visible);
    return w[0] * p.mean2d[0] + w[1] * p.mean2d[1] + w[2] * p.conic[0] + w[3] * p.conic[1] + w[4] * p.conic[2] +
           w[5] * p.depth;
  };
  Mat3d dSigma;
  const Vec3d dmean = project_gaussian_backward(cam, mean, covariance_3d(scale, quat), w, w + 2, w[5], dSigma);
  double dscale[3] = {}, dquat[4] = {};
  covariance_3d_backward(scale, quat, dSigma, dscale, dquat);
  for (int k = 0; k < 3; ++k) EXPECT_LT(rel_err(dmean[k], central_diff(mean[k], loss)), 1e-4) << what << " mean " << k;
  for (int k = 0; k < 3; ++k) EXPECT_LT(rel_err(dscale[k], central_diff(scale[k], loss)), 1e-4) << what << " scale " << k;
  for (int k = 0; k < 4; ++k) EXPECT_LT(rel_err(dquat[k], central_diff(quat[k], loss)), 1e-4) << what << " quat " << k;
}

TEST(SplatGradients, Projection) {
  const auto s = test::random_scene(1, 64, 48, 3, true, 1);
  ASSERT_GT(2.4 / 3.0, 1.3 * (s.cam.width - s.cam.cx) / s.cam.fx);
  check_projection(s.cam, transpose(s.cam.R) * (Vec3d{0.3, -0.2, 3.0} - s.cam.t), 0.1, "inside");
  // beyond 1.3x the field of view in x and y: the Jacobian uses the clamped point
  check_projection(s.cam, transpose(s.cam.R) * (Vec3d{2.4, -2.0, 3.0} - s.cam.t), 1.0, "clamped");
}

TEST(SplatGradients, QuaternionScaleInvariance) {
  // R(q) normalises q, so dL/dq is orthogonal to q.
  double q[4] = {0.8, 0.3, -0.4, 0.25}, dq[4];
  Mat3d dR;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) dR.m[i][j] = 0.1 * (i + 1) - 0.2 * j;
  quat_to_rotation_backward(q, dR, dq);
  EXPECT_NEAR(q[0] * dq[0] + q[1] * dq[1] + q[2] * dq[2] + q[3] * dq[3], 0.0, 1e-14);
}

// Full rasterizer in double: loss = <Wi, image> + <Wa, alpha> + <Wd, depth>.
struct FullCheck {
  test::RandomScene s;
  test::SceneArrays<double> a;
  std::vector<double> wi, wa, wd;
  FullCheck(bool use_sh, int channels, unsigned seed) {
    s = test::random_scene(12, 40, 36, channels, use_sh, seed, 0.7);
    a = test::scene_arrays<double>(s);
    std::mt19937 rng(seed + 100);
    std::uniform_real_distribution<double> U(-1, 1);
    const size_t n_pix = 40 * 36;
    for (size_t i = 0; i < n_pix * s.channels; ++i) wi.push_back(U(rng));
    for (size_t i = 0; i < n_pix; ++i) wa.push_back(U(rng)), wd.push_back(0.2 * U(rng));
  }
  double loss() const {
    const size_t n_pix = 40 * 36;
    std::vector<double> image(n_pix * s.channels), alpha(n_pix), depth(n_pix);
    SplatForwardState<double> st;
    rasterize_forward_cpu(s.cam, a.inputs(s), image.data(), alpha.data(), depth.data(), st);
    double L = 0;
    for (size_t i = 0; i < image.size(); ++i) L += wi[i] * image[i];
    for (size_t i = 0; i < n_pix; ++i) L += wa[i] * alpha[i] + wd[i] * depth[i];
    return L;
  }
  void run(const char* what) {
    const size_t n_pix = 40 * 36;
    std::vector<double> image(n_pix * s.channels), alpha(n_pix), depth(n_pix);
    SplatForwardState<double> st;
    rasterize_forward_cpu(s.cam, a.inputs(s), image.data(), alpha.data(), depth.data(), st);
    int contributing = 0;
    for (size_t i = 0; i < n_pix; ++i) contributing += st.n_contrib[i] > 1;
    EXPECT_GT(contributing, 100) << "scene too sparse to test blending";
    std::vector<double> gm(a.means.size()), gs(a.scales.size()), gq(a.quats.size()), go(a.opacities.size()),
        gsh(a.sh.size()), gf(a.features.size()), g2(2 * s.n), g2abs(2 * s.n);
    SplatGradients<double> g;
    g.means = gm.data(), g.scales = gs.data(), g.quats = gq.data(), g.opacities = go.data();
    g.sh = gsh.empty() ? nullptr : gsh.data();
    g.features = gf.empty() ? nullptr : gf.data();
    g.mean2d = g2.data(), g.mean2d_abs = g2abs.data();
    rasterize_backward_cpu(a.inputs(s), st, wi.data(), wa.data(), wd.data(), g);
    auto L = [&] { return loss(); };
    auto check = [&](std::vector<double>& x, const std::vector<double>& gx, const char* name) {
      for (size_t k = 0; k < x.size(); ++k) EXPECT_LT(rel_err(gx[k], central_diff(x[k], L)), 1e-4) << what << " " << name << "[" << k << "]";
    };
    check(a.means, gm, "means");
    check(a.scales, gs, "scales");
    check(a.quats, gq, "quats");
    check(a.opacities, go, "opacities");
    if (!a.sh.empty()) check(a.sh, gsh, "sh");
    if (!a.features.empty()) check(a.features, gf, "features");
    // Screen-space mean gradient: mean2d = (fx x/z + cx, ...) so dL/dcx = sum_i dL/dmean2d_x,i.
    double sx = 0, sy = 0;
    for (int i = 0; i < s.n; ++i) {
      sx += g2[2 * i], sy += g2[2 * i + 1];
      EXPECT_GE(g2abs[2 * i], std::abs(g2[2 * i]) - 1e-12);
      EXPECT_GE(g2abs[2 * i + 1], std::abs(g2[2 * i + 1]) - 1e-12);
    }
    EXPECT_LT(rel_err(sx, central_diff(s.cam.cx, L)), 1e-4) << what << " mean2d x";
    EXPECT_LT(rel_err(sy, central_diff(s.cam.cy, L)), 1e-4) << what << " mean2d y";
  }
};

TEST(SplatGradients, RasterizerRgbFromSh) { FullCheck(true, 3, 5).run("sh"); }
TEST(SplatGradients, RasterizerFeatures) {
  FullCheck(false, 5, 6).run("features5");
  FullCheck(false, 1, 7).run("features1");
  // 147 = 128 + 16 + 3: the many-channel paths' blocks of eight registers, of one register, and single
  // channels (every build's register holds 4, 8 or 16 floats)
  FullCheck(false, 147, 9).run("features147");
}

}  // namespace
}  // namespace cls

namespace cls {
namespace {

// Pixels that nothing was blended into (n_contrib 0) give no gradient, whatever their dL/d(image, alpha,
// depth) hold, also when they share a 4x4 sub-tile (the CPU's vector lanes) with covered pixels: NaN
// there leaves every gradient as with zeros.
TEST(SplatGradients, UncoveredPixelsReachNoGradient) {
  for (const int channels : {3, 20}) {
    const auto s = test::random_scene(6, 40, 36, channels, /*use_sh=*/false, 31, 0.7);
    const auto a = test::scene_arrays<float>(s);
    const size_t n_pix = static_cast<size_t>(s.cam.width) * s.cam.height;
    std::vector<float> image(n_pix * channels), alpha(n_pix), depth(n_pix);
    SplatForwardState<float> st;
    rasterize_forward_cpu(test::cast_camera<float>(s.cam), a.inputs(s), image.data(), alpha.data(), depth.data(), st);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> U(-1, 1);
    std::vector<float> di(n_pix * channels), da(n_pix), dd(n_pix);
    for (float& v : di) v = U(rng);
    for (size_t i = 0; i < n_pix; ++i) da[i] = U(rng), dd[i] = U(rng);
    auto grads = [&](float uncovered) {
      std::vector<float> i2 = di, a2 = da, d2 = dd;
      for (size_t p = 0; p < n_pix; ++p) {
        if (st.n_contrib[p] != 0) continue;
        a2[p] = d2[p] = uncovered;
        for (int c = 0; c < channels; ++c) i2[p * channels + c] = uncovered;
      }
      std::vector<float> gm(a.means.size()), gs(a.scales.size()), gq(a.quats.size()), go(a.opacities.size()),
          gf(a.features.size());
      SplatGradients<float> g;
      g.means = gm.data(), g.scales = gs.data(), g.quats = gq.data(), g.opacities = go.data(), g.features = gf.data();
      rasterize_backward_cpu(a.inputs(s), st, i2.data(), a2.data(), d2.data(), g);
      std::vector<float> all;
      for (const auto* v : {&gm, &gs, &gq, &go, &gf}) all.insert(all.end(), v->begin(), v->end());
      return all;
    };
    // the case must exist: an uncovered pixel in the same 4x4 block as a covered one
    int mixed = 0;
    for (int y = 0; y < s.cam.height; y += 4)
      for (int x = 0; x < s.cam.width; x += 4) {
        int covered = 0, total = 0;
        for (int dy = 0; dy < 4 && y + dy < s.cam.height; ++dy)
          for (int dx = 0; dx < 4 && x + dx < s.cam.width; ++dx, ++total)
            covered += st.n_contrib[static_cast<size_t>(y + dy) * s.cam.width + x + dx] != 0;
        mixed += covered > 0 && covered < total;
      }
    ASSERT_GT(mixed, 0) << "no sub-tile mixes covered and uncovered pixels";
    const std::vector<float> with_zero = grads(0.0f), with_nan = grads(std::nanf(""));
    // equal up to the order in which threads add tiles' sums (rasterize_cpu.h)
    for (size_t k = 0; k < with_zero.size(); ++k) {
      ASSERT_TRUE(std::isfinite(with_nan[k])) << "channels " << channels << " gradient " << k;
      ASSERT_NEAR(with_zero[k], with_nan[k], 1e-5 * (1 + std::abs(with_zero[k]))) << "channels " << channels << " gradient " << k;
    }
  }
}

}  // namespace
}  // namespace cls
