#pragma once
// Per-pixel ray generation, shared by the CPU raycaster and the CUDA kernel (pixel_rays.cu).
#include "core/host_device.h"
#include "core/math.h"

namespace cls {

// Camera-frame direction (z = 1) of the ray through the centre of pixel (i, j) of a pinhole
// camera: ((i + 0.5 - cx) / fx, (j + 0.5 - cy) / fy, 1). Its z component is 1, so a hit's ray
// parameter t along this unnormalised direction is directly the z-depth.
template <class T>
CLS_HD Vec3<T> pixel_ray_camera(T fx, T fy, T cx, T cy, int i, int j) {
  return {(T(i) + T(0.5) - cx) / fx, (T(j) + T(0.5) - cy) / fy, T(1)};
}

// The same ray in world coordinates for a world-to-camera pose (R, t): direction R^T d.
// The origin is the camera centre -R^T t.
template <class T>
CLS_HD Vec3<T> camera_to_world_dir(const Mat3<T>& R, Vec3<T> d) {
  return transpose(R) * d;
}

}  // namespace cls
