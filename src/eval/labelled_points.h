#pragma once
// A labelled point cloud (the evaluation's 3D ground truth): positions and one integer class per point,
// as the synthetic scenes write gt/points.ply (src/synth/gt_point_cloud.h), or a user's LAS cloud (ZAHA,
// TUM-FACADE, MLS campaigns) whose classification or extra-bytes field a class map turns into ours.
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "eval/class_map.h"

namespace cls {

struct LabelledPoints {
  std::vector<Vec3d> positions;
  std::vector<int32_t> labels;  // taxonomy class id; -1 (or any negative) = unlabelled
  size_t size() const { return positions.size(); }
};

// The label field a cloud is read with when none is named: "class" in a PLY, "classification" in a LAS.
std::string default_label_field(const std::string& path);

// Reads a labelled cloud: a PLY's vertex element (core/ply.h: ascii or binary_little_endian; any scalar
// types; elements after the vertices are skipped) with x, y, z and the property `field`, or a LAS file
// (scene/las.h, by its .las extension) with `field` "classification" or an extra-bytes field ("" = the
// format's default_label_field). Without `map` the values are taxonomy class ids (a LAS cloud needs a
// map: its codes are not ours); with it they are mapped (class_map.h). cls::Error naming the file on
// malformed or truncated input, NaN or infinite coordinates, a missing field, or an unmapped value.
LabelledPoints read_labelled_points(const std::string& path, const std::string& field = "",
                                    const ClassMap* map = nullptr);

// Binary little-endian PLY with float x y z and int `class`, written atomically (tests and tools).
void write_labelled_points(const std::string& path, const LabelledPoints& points);

}  // namespace cls
