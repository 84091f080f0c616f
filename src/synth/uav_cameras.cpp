#include "synth/uav_cameras.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "raycast/look_at.h"
#include "synth/random.h"

namespace cls::synth {

namespace {
constexpr double kPi = 3.14159265358979323846;
double radians(double deg) { return deg * kPi / 180.0; }
}  // namespace

PinholeCamera pinhole_from_fov(int width, int height, double hfov_deg) {
  PinholeCamera c;
  c.width = width;
  c.height = height;
  c.fx = c.fy = 0.5 * width / std::tan(0.5 * radians(hfov_deg));
  c.cx = 0.5 * width;
  c.cy = 0.5 * height;
  return c;
}

std::vector<SynthView> make_uav_views(const Box3d& city, const CameraRigOptions& options) {
  const PinholeCamera camera = pinhole_from_fov(options.width, options.height, options.hfov_deg);
  const double half_fov = std::min(std::atan(0.5 * options.width / camera.fx),
                                   std::atan(0.5 * options.height / camera.fy));
  const Vec3d size = city.size();
  const double radius = std::max(0.5 * norm(size), 1.0);
  // The bounding sphere spans a little more than the narrower field of view: the building (smaller
  // than its sphere) fills much of the frame while terrain and clutter stay visible around it.
  const double distance = 0.9 * radius / std::sin(half_fov);
  const Vec3d center{city.center().x, city.center().y, city.lo.z + 0.4 * size.z};

  const int rings = std::min(options.views, 3);
  Rng rng(options.seed, Stream::Cameras);
  const double azimuth0 = rng.uniform(0, 2 * kPi);
  std::vector<SynthView> views;
  for (int r = 0; r < rings; ++r) {
    const int first = options.views * r / rings, count = options.views * (r + 1) / rings - first;
    const double ring_pitch = rings == 1 ? 40.0 : 18.0 + 37.0 * r / (rings - 1);
    for (int k = 0; k < count; ++k) {
      const double step = 2 * kPi / count;
      const double azimuth = azimuth0 + step * (k + 0.5 * r / rings) + rng.uniform(-0.25, 0.25) * step;
      const double pitch = radians(std::clamp(ring_pitch + rng.uniform(-3, 3), kMinPitchDeg, kMaxPitchDeg));
      const double d = distance * rng.uniform(0.92, 1.08);
      const Vec3d target = center + Vec3d{rng.uniform(-0.08, 0.08) * radius, rng.uniform(-0.08, 0.08) * radius,
                                          rng.uniform(-0.05, 0.05) * radius};
      // The eye sits on the line of sight through `target` at the chosen pitch, so the pitch is exact.
      const Vec3d eye = target + d * Vec3d{std::cos(pitch) * std::cos(azimuth), std::cos(pitch) * std::sin(azimuth),
                                           std::sin(pitch)};
      char name[32];
      std::snprintf(name, sizeof name, "%04d.png", static_cast<int>(views.size()));
      views.push_back({name, camera, look_at(eye, target)});
    }
  }
  return views;
}

std::vector<SynthView> make_building_views(const std::vector<Box3d>& buildings, const CameraRigOptions& options) {
  const int n = static_cast<int>(buildings.size());
  std::vector<SynthView> views;
  for (int b = 0; b < n; ++b) {
    CameraRigOptions own = options;
    own.views = options.views / n + (b < options.views % n ? 1 : 0);
    own.seed = options.seed + 7919 * static_cast<uint64_t>(b);  // distinct azimuths and jitter per building
    if (own.views == 0) continue;
    for (SynthView& v : make_uav_views(buildings[b], own)) {
      char name[32];
      std::snprintf(name, sizeof name, "%04d.png", static_cast<int>(views.size()));
      v.name = name;
      views.push_back(std::move(v));
    }
  }
  return views;
}

}  // namespace cls::synth
