#pragma once
// Embree plumbing shared by the raycaster and the closest-point query (internal to src/raycast).
#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace cls {

// cls::Error naming `who` for out-of-range triangle indices or non-finite vertices.
void validate_triangle_mesh(const std::vector<Vec3f>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles,
                            const char* who);

// A new device; cls::Error if Embree cannot create one (e.g. unsupported CPU).
RTCDevice new_embree_device();

// cls::Error if the device has a pending error ("Embree: <what> failed (<error>)").
void check_embree(RTCDevice device, const char* what);

// A committed scene of one triangle geometry: all `triangles`, or only those listed in `subset`.
RTCScene build_triangle_scene(RTCDevice device, const std::vector<Vec3f>& vertices,
                              const std::vector<std::array<uint32_t, 3>>& triangles,
                              const std::vector<uint32_t>* subset = nullptr);

}  // namespace cls
