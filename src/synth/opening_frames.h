#pragma once
// The outline and plane of each window and door of the city model, so their materials can draw
// a frame along the border, mullions and panels in the opening's own 2D coordinates.
#include <array>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "synth/synth_geometry.h"

namespace cls::synth {

struct OpeningFrame {
  Vec3f axis_u{1, 0, 0}, axis_v{0, 0, 1};  // in-plane axes: horizontal, and up the opening
  float u_min = 0, u_max = 0, v_min = 0, v_max = 0;  // extent along the axes (world units)
  std::vector<std::array<Vec3f, 2>> border;  // outline segments (edges used by one triangle)
  float distance_to_border(Vec3f p) const;
};

struct OpeningFrames {
  std::vector<OpeningFrame> frames;
  std::vector<int32_t> frame_of_triangle;  // per geometry triangle; -1 where not a window or door
};

// One frame per opening entity (level-1 entity of the face; its source polygon where it has none)
// over the Glass and Door triangles of the city part of `g`.
OpeningFrames build_opening_frames(const SynthGeometry& g, const SemanticMesh& mesh);

}  // namespace cls::synth
