#pragma once
// Camera placement helpers for raycast tests, benchmarks and synthetic views.
#include <algorithm>
#include <cmath>

#include "scene/camera.h"

namespace cls {

// World-to-camera pose of a camera at `eye` looking at `target`, with `up` pointing up in the
// image (the camera's y axis points down, camera.h). `up` must not be parallel to the view.
inline Pose look_at(Vec3d eye, Vec3d target, Vec3d up = {0, 0, 1}) {
  const Vec3d z = normalized(target - eye);
  const Vec3d x = normalized(cross(z, up));
  const Vec3d y = cross(z, x);
  Pose p;
  for (int c = 0; c < 3; ++c) {
    p.R.m[0][c] = x[c];
    p.R.m[1][c] = y[c];
    p.R.m[2][c] = z[c];
  }
  p.t = -(p.R * eye);
  return p;
}

// A camera looking at the centre of the box [lo, hi] from the direction (azimuth, elevation) in
// radians (z up), at the distance where the box corners just fit the image (fill = 1), or where
// the box appears `fill` times larger (fill > 1 crops it and fills more of the frame).
inline Pose frame_box(Vec3d lo, Vec3d hi, const PinholeCamera& cam, double azimuth, double elevation,
                      double fill = 1.0) {
  const Vec3d centre = 0.5 * (lo + hi);
  const Vec3d dir{std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                  std::sin(elevation)};
  // Largest corner offset from the principal point, relative to the half image size.
  auto extent = [&](double distance) -> double {
    const Pose pose = look_at(centre + distance * dir, centre);
    double worst = 0;
    for (int k = 0; k < 8; ++k) {
      const Vec3d corner{(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
      const Vec3d x = pose.R * corner + pose.t;
      if (x.z <= 0) return INFINITY;
      worst = std::max({worst, std::abs(cam.fx * x.x / x.z) / (0.5 * cam.width),
                        std::abs(cam.fy * x.y / x.z) / (0.5 * cam.height)});
    }
    return worst;
  };
  double near = 0, far = 1e-3 + norm(hi - lo);
  while (extent(far) > fill) far *= 2;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (near + far);
    (extent(mid) > fill ? near : far) = mid;
  }
  return look_at(centre + far * dir, centre);
}

}  // namespace cls
