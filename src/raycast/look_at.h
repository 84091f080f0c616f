#pragma once
// Camera placement helpers for raycast tests, benchmarks and synthetic views.
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

}  // namespace cls
