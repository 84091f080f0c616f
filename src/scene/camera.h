#pragma once
// Cameras and poses as the rest of the pipeline sees them.
//
// Conventions (COLMAP's, which 3DGS and gsplat follow):
// - A pose maps world to camera: x_cam = R * X_world + t. The camera looks down +z, x right, y down.
// - Pixel (i, j) covers [i, i+1) x [j, j+1) in image coordinates; its centre is (i + 0.5, j + 0.5).
//   The principal point (cx, cy) is in the same coordinates, so an ideal centred camera has
//   cx = width / 2, cy = height / 2.
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace cls {

// The camera models the scene reader accepts, with COLMAP's numeric model ids.
enum class CameraModel : int {
  SimplePinhole = 0,  // f, cx, cy
  Pinhole = 1,        // fx, fy, cx, cy
  SimpleRadial = 2,   // f, cx, cy, k
  Radial = 3,         // f, cx, cy, k1, k2
  OpenCV = 4,         // fx, fy, cx, cy, k1, k2, p1, p2
};

// A camera as stored in a COLMAP model (possibly distorted).
struct Camera {
  uint32_t id = 0;
  CameraModel model = CameraModel::Pinhole;
  int width = 0, height = 0;
  std::vector<double> params;
};

// The undistorted pinhole camera every later stage uses.
struct PinholeCamera {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  int width = 0, height = 0;
};

// World-to-camera rigid transform.
struct Pose {
  Mat3d R = Mat3d::identity();
  Vec3d t{};
  Vec3d center() const { return -(transpose(R) * t); }  // camera centre in world coordinates
};

}  // namespace cls
