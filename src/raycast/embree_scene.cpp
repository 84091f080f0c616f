#include "raycast/embree_scene.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

const char* error_name(RTCError e) {
  switch (e) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

}  // namespace

void validate_triangle_mesh(const std::vector<Vec3f>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles,
                            const char* who) {
  for (const auto& v : vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw Error(cat(who, ": non-finite vertex coordinate"));
  for (const auto& t : triangles)
    for (uint32_t v : t)
      if (v >= vertices.size())
        throw Error(cat(who, ": triangle vertex index ", v, " out of range (", vertices.size(), " vertices)"));
}

RTCDevice new_embree_device() {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) throw Error(cat("Embree: cannot create a device (", error_name(rtcGetDeviceError(nullptr)), ")"));
  return device;
}

void check_embree(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) throw Error(cat("Embree: ", what, " failed (", error_name(e), ")"));
}

RTCScene build_triangle_scene(RTCDevice device, const std::vector<Vec3f>& vertices,
                              const std::vector<std::array<uint32_t, 3>>& triangles,
                              const std::vector<uint32_t>* subset) {
  RTCScene scene = rtcNewScene(device);
  // High quality (spatial splits) pays off for the long thin triangles of facades.
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  const size_t count = subset ? subset->size() : triangles.size();
  if (count > 0) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), vertices.size()));
    auto* ib = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              3 * sizeof(uint32_t), count));
    if (!vb || !ib) {
      rtcReleaseGeometry(g);
      rtcReleaseScene(scene);
      check_embree(device, "allocating geometry buffers");
      throw Error("Embree: allocating geometry buffers failed");
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
      vb[3 * i] = vertices[i].x;
      vb[3 * i + 1] = vertices[i].y;
      vb[3 * i + 2] = vertices[i].z;
    }
    for (size_t i = 0; i < count; ++i) {
      const auto& t = triangles[subset ? (*subset)[i] : i];
      std::copy(t.begin(), t.end(), ib + 3 * i);
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(scene);
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) {
    rtcReleaseScene(scene);
    throw Error(cat("Embree: building the BVH failed (", error_name(e), ")"));
  }
  return scene;
}

}  // namespace cls
