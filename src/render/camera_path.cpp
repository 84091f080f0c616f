#include "render/camera_path.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/error.h"
#include "raycast/look_at.h"
#include "scene/colmap.h"

namespace cls {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The camera's up direction in world coordinates: -(R^T e_y), the negated second row of R.
Vec3d camera_up(const Pose& p) { return -p.R.row(1); }

Vec3d horizontal(Vec3d v, Vec3d up) { return v - dot(v, up) * up; }

// Uniform Catmull-Rom between p1 (t = 0) and p2 (t = 1).
Vec3d catmull_rom(Vec3d p0, Vec3d p1, Vec3d p2, Vec3d p3, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return 0.5 * ((2.0 * p1) + t * (p2 - p0) + t2 * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) +
                t3 * (3.0 * p1 - p0 - 3.0 * p2 + p3));
}

}  // namespace

OrbitCircle orbit_circle(const std::vector<Pose>& cameras, Vec3d target) {
  if (cameras.empty()) throw Error("orbit: no cameras to place the orbit by");
  Vec3d up{0, 0, 0}, mean_offset{0, 0, 0};
  for (const Pose& p : cameras) {
    up = up + camera_up(p);
    mean_offset = mean_offset + (p.center() - target);
  }
  if (norm(up) < 1e-12) throw Error("orbit: the cameras' up vectors cancel out; no up direction");
  up = normalized(up);
  OrbitCircle c;
  c.target = target;
  c.up = up;
  for (const Pose& p : cameras) {
    const Vec3d d = p.center() - target;
    c.height += dot(d, up);
    c.radius += norm(horizontal(d, up));
  }
  c.height /= double(cameras.size());
  c.radius /= double(cameras.size());
  if (c.radius < 1e-12) throw Error("orbit: every camera lies on the vertical axis through the target");
  Vec3d start = horizontal(cameras.front().center() - target, up);
  if (norm(start) < 1e-9 * c.radius) start = horizontal(mean_offset, up);
  if (norm(start) < 1e-9 * c.radius) throw Error("orbit: no horizontal start direction");
  c.start = normalized(start);
  c.centre = target + c.height * up;
  return c;
}

std::vector<Pose> orbit_path(const OrbitCircle& c, int frames) {
  if (frames < 1) throw Error("orbit: the number of frames must be positive, got " + std::to_string(frames));
  const Vec3d side = cross(c.up, c.start);  // start rotated by +90 degrees about up
  std::vector<Pose> poses;
  for (int k = 0; k < frames; ++k) {
    const double a = 2 * kPi * k / frames;
    const Vec3d eye = c.centre + c.radius * (std::cos(a) * c.start + std::sin(a) * side);
    poses.push_back(look_at(eye, c.target, c.up));
  }
  return poses;
}

Mat3d slerp(const Mat3d& a, const Mat3d& b, double t) {
  const std::array<double, 4> qa = rotation_to_qvec(a);
  std::array<double, 4> qb = rotation_to_qvec(b);
  double d = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3];
  if (d < 0) {  // q and -q are the same rotation: take the shorter arc
    for (double& v : qb) v = -v;
    d = -d;
  }
  double wa = 1 - t, wb = t;
  if (d < 1 - 1e-12) {  // otherwise (nearly) equal: the linear weights are exact enough
    const double theta = std::acos(std::min(d, 1.0));
    wa = std::sin((1 - t) * theta) / std::sin(theta);
    wb = std::sin(t * theta) / std::sin(theta);
  }
  return quat_to_rotation(wa * qa[0] + wb * qb[0], wa * qa[1] + wb * qb[1], wa * qa[2] + wb * qb[2],
                          wa * qa[3] + wb * qb[3]);
}

std::vector<Pose> interpolate_path(const std::vector<Pose>& keyframes, int frames) {
  const int K = int(keyframes.size());
  if (K < 2) throw Error("interpolate: needs at least 2 camera poses, the scene has " + std::to_string(K));
  if (frames < 2) throw Error("interpolate: needs at least 2 frames, got " + std::to_string(frames));
  auto centre = [&](int i) { return keyframes[size_t(std::clamp(i, 0, K - 1))].center(); };
  std::vector<Pose> poses;
  for (int k = 0; k < frames; ++k) {
    const double s = double(k) * (K - 1) / (frames - 1);
    const int i = std::min(int(s), K - 2);  // segment i..i+1; the last frame is t = 1 of the last segment
    const double t = s - i;
    Pose p;
    p.R = slerp(keyframes[size_t(i)].R, keyframes[size_t(i + 1)].R, t);
    const Vec3d c = catmull_rom(centre(i - 1), centre(i), centre(i + 1), centre(i + 2), t);
    p.t = -(p.R * c);
    poses.push_back(p);
  }
  return poses;
}

}  // namespace cls
