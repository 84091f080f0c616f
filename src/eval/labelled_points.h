#pragma once
// A labelled point cloud (the evaluation's 3D ground truth): positions and one integer class per point,
// as the synthetic scenes write gt/points.ply (src/synth/gt_point_cloud.h) and as ZAHA provides.
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace cls {

struct LabelledPoints {
  std::vector<Vec3d> positions;
  std::vector<int32_t> labels;  // taxonomy class id; -1 (or any negative) = unlabelled
  size_t size() const { return positions.size(); }
};

// Reads the vertex element of a PLY file (core/ply.h: ascii or binary_little_endian; any scalar types;
// elements after the vertices are skipped). Needs x, y, z (finite) and the integer property
// `class_property` (default "class"). cls::Error naming the file on malformed or truncated input,
// NaN or infinite coordinates, or missing properties.
LabelledPoints read_labelled_points(const std::string& path, const std::string& class_property = "class");

// Binary little-endian PLY with float x y z and int `class`, written atomically (tests and tools).
void write_labelled_points(const std::string& path, const LabelledPoints& points);

}  // namespace cls
