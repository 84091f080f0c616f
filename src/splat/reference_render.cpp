#include "splat/reference_render.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "splat/sh.h"

namespace cls {
namespace {

struct RefGaussian {
  bool visible = false;
  double u = 0, v = 0, depth = 0;
  double inv[2][2]{};  // inverse 2D covariance
  int rect_min[2]{}, rect_max[2]{};
  std::vector<double> value;
};

Mat3d diag(double a, double b, double c) {
  Mat3d D;
  D.m[0][0] = a, D.m[1][1] = b, D.m[2][2] = c;
  return D;
}

RefGaussian project(const SplatCamera<double>& cam, const SplatInputs<double>& in, int i) {
  RefGaussian g;
  const double* m = in.means + 3 * i;
  const Vec3d mean{m[0], m[1], m[2]};
  const double* q = in.quats + 4 * i;
  const double* s = in.scales + 3 * i;
  const Mat3d R = quat_to_rotation(q[0], q[1], q[2], q[3]);
  const Mat3d Sigma = R * diag(s[0] * s[0], s[1] * s[1], s[2] * s[2]) * transpose(R);
  const Vec3d t = cam.R * mean + cam.t;
  if (t.z <= 0.2) return g;
  // Jacobian of (fx x/z, fy y/z) at the point clamped to 1.3x the frustum
  const double xr = std::clamp(t.x / t.z, -1.3 * cam.cx / cam.fx, 1.3 * (cam.width - cam.cx) / cam.fx);
  const double yr = std::clamp(t.y / t.z, -1.3 * cam.cy / cam.fy, 1.3 * (cam.height - cam.cy) / cam.fy);
  Mat3d J;  // third row zero
  J.m[0][0] = cam.fx / t.z, J.m[0][2] = -cam.fx * xr / t.z;
  J.m[1][1] = cam.fy / t.z, J.m[1][2] = -cam.fy * yr / t.z;
  const Mat3d cov = J * cam.R * Sigma * transpose(cam.R) * transpose(J);
  const double a = cov.m[0][0] + 0.3, b = cov.m[0][1], c = cov.m[1][1] + 0.3;
  const double det = a * c - b * b;
  if (!(det > 0)) return g;
  g.inv[0][0] = c / det, g.inv[0][1] = g.inv[1][0] = -b / det, g.inv[1][1] = a / det;
  const double mid = 0.5 * (a + c);
  const double l1 = mid + std::sqrt(std::max(0.1, mid * mid - det));
  const int radius = int(std::ceil(3 * std::sqrt(l1)));
  g.u = cam.fx * t.x / t.z + cam.cx;
  g.v = cam.fy * t.y / t.z + cam.cy;
  g.depth = t.z;
  tile_rect(g.u, g.v, radius, cam.tiles_x(), cam.tiles_y(), g.rect_min, g.rect_max);
  if ((g.rect_max[0] - g.rect_min[0]) * (g.rect_max[1] - g.rect_min[1]) == 0) return g;
  g.visible = true;
  if (in.use_sh()) {
    g.value.resize(3);
    bool clamped[3];
    sh_to_rgb(in.sh_degree, in.sh + 3 * sh_coeff_count(in.sh_degree) * i, mean - cam.center(), g.value.data(), clamped);
  } else {
    g.value.assign(in.features + static_cast<size_t>(i) * in.channels, in.features + static_cast<size_t>(i + 1) * in.channels);
  }
  return g;
}

}  // namespace

ReferenceImage reference_render(const SplatCamera<double>& cam, const SplatInputs<double>& in) {
  const int C = in.use_sh() ? 3 : in.channels;
  std::vector<RefGaussian> gs(in.n);
  for (int i = 0; i < in.n; ++i) gs[i] = project(cam, in, i);
  std::vector<int> order(in.n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return gs[a].depth < gs[b].depth || (gs[a].depth == gs[b].depth && a < b);
  });
  ReferenceImage out;
  out.width = cam.width, out.height = cam.height, out.channels = C;
  out.image.assign(static_cast<size_t>(cam.width) * cam.height * C, 0.0);
  out.alpha.assign(static_cast<size_t>(cam.width) * cam.height, 0.0);
  out.depth.assign(static_cast<size_t>(cam.width) * cam.height, 0.0);
  for (int y = 0; y < cam.height; ++y) {
    for (int x = 0; x < cam.width; ++x) {
      const int tile_x = x / 16, tile_y = y / 16;
      const double px = x + 0.5, py = y + 0.5;  // pixel centre
      double transmittance = 1.0, depth = 0.0;
      std::vector<double> colour(C, 0.0);
      for (int i : order) {
        const RefGaussian& g = gs[i];
        if (!g.visible) continue;
        if (tile_x < g.rect_min[0] || tile_x >= g.rect_max[0] || tile_y < g.rect_min[1] || tile_y >= g.rect_max[1])
          continue;  // the rasterizer only blends a Gaussian into the tiles of its 3-sigma rectangle
        const double dx = g.u - px, dy = g.v - py;
        const double power = -0.5 * (g.inv[0][0] * dx * dx + 2 * g.inv[0][1] * dx * dy + g.inv[1][1] * dy * dy);
        if (power > 0) continue;
        const double alpha = std::min(0.99, in.opacities[i] * std::exp(power));
        if (alpha < 1.0 / 255.0) continue;
        if (transmittance * (1 - alpha) < 1e-4) break;
        for (int c = 0; c < C; ++c) colour[c] += g.value[c] * alpha * transmittance;
        depth += g.depth * alpha * transmittance;
        transmittance *= 1 - alpha;
      }
      const size_t pix = static_cast<size_t>(y) * cam.width + x;
      for (int c = 0; c < C; ++c)
        out.image[pix * C + c] = colour[c] + (in.background ? transmittance * in.background[c] : 0.0);
      out.alpha[pix] = 1 - transmittance;
      out.depth[pix] = depth;
    }
  }
  return out;
}

}  // namespace cls
