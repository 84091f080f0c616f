#pragma once
// Embree 3 raycasting of a triangle mesh: one ray per pixel centre (pixel_ray.h convention).
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "scene/camera.h"

namespace cls {

constexpr uint32_t kNoHit = std::numeric_limits<uint32_t>::max();

struct RayHit {
  float depth = 0;       // z-depth in the camera frame (for cast_view) or ray parameter t (for cast)
  uint32_t prim = kNoHit;
  float u = 0, v = 0;    // barycentrics of the hit in triangle prim (p = (1-u-v) v0 + u v1 + v v2)
};

struct Ray {
  Vec3f origin;
  Vec3f dir;  // need not be unit length; t is in units of |dir|
  float tnear = 0, tfar = std::numeric_limits<float>::infinity();
};

// Triangles in float (already in the frame the rays are in). `priority` (optional, one per
// triangle): where two triangles are hit at the same depth (within a relative 1e-4 of the depth
// plus 1e-5 absolute), the one with higher priority wins — openings over their walls.
class Raycaster {
 public:
  Raycaster(const std::vector<Vec3f>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles,
            const std::vector<uint8_t>& priority = {});
  ~Raycaster();
  Raycaster(const Raycaster&) = delete;
  Raycaster& operator=(const Raycaster&) = delete;

  // One ray per pixel centre of `camera` at `pose`; out has width*height entries, row-major.
  // Multithreaded (OpenMP) over image tiles.
  void cast_view(const PinholeCamera& camera, const Pose& pose, std::vector<RayHit>& out) const;
  // Arbitrary rays (multithreaded).
  void cast(const std::vector<Ray>& rays, std::vector<RayHit>& out) const;

  size_t num_triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cls
