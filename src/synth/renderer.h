#pragma once
// Renders one synthetic view: a 2x2-supersampled shaded image with hard sun shadows, the
// ground-truth label image and the depth map (both at pixel centres, as the raycast stage casts).
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "citymodel/semantic_mesh.h"
#include "raycast/raycaster.h"
#include "synth/shading.h"
#include "synth/synth_geometry.h"
#include "synth/uav_cameras.h"

namespace cls::synth {

struct RenderedView {
  cv::Mat image;             // CV_8UC3, BGR (OpenCV's order)
  cv::Mat labels;            // CV_16UC1: 0 = not the city model, k = level-1 class k-1 of the taxonomy
  std::vector<float> depth;  // z-depth per pixel (row-major), +inf where the ray leaves the scene
};

class ViewRenderer {
 public:
  // Builds one Raycaster over all triangles of `g`; keeps references to the arguments.
  ViewRenderer(const SynthGeometry& g, const SemanticMesh& mesh, const SurfaceShader& shader);

  RenderedView render(const SynthView& view) const;
  const Raycaster& raycaster() const { return raycaster_; }

 private:
  const SynthGeometry& g_;
  const SurfaceShader& shader_;
  Raycaster raycaster_;
  std::vector<uint16_t> triangle_label_;  // per triangle: level-1 class + 1 for city faces, else 0
  std::vector<Vec3f> triangle_normal_;
};

// Point of triangle `tri` at barycentrics (u, v).
Vec3f surface_point(const SynthGeometry& g, uint32_t tri, float u, float v);

}  // namespace cls::synth
