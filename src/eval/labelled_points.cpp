#include "eval/labelled_points.h"

#include <climits>
#include <cstring>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/ply.h"

namespace cls {

LabelledPoints read_labelled_points(const std::string& path, const std::string& class_property) {
  const PlyVertices v = read_ply_vertices(path);
  const PlyProperty &x = v.require("x"), &y = v.require("y"), &z = v.require("z"), &c = v.require(class_property);
  LabelledPoints out;
  out.positions.resize(v.count);
  out.labels.resize(v.count);
  for (uint64_t i = 0; i < v.count; ++i) {
    out.positions[i] = {v.finite_value(i, x), v.finite_value(i, y), v.finite_value(i, z)};
    const double label = v.finite_value(i, c);
    if (label < INT32_MIN || label > INT32_MAX)
      fail(path, "vertex " + std::to_string(i) + " has " + class_property + " = " + std::to_string(label) +
                     ": not a class id");
    out.labels[i] = static_cast<int32_t>(label);
  }
  return out;
}

void write_labelled_points(const std::string& path, const LabelledPoints& points) {
  if (points.labels.size() != points.positions.size()) fail(path, "labelled points: positions and labels differ in size");
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(points.size()) +
                             "\nproperty float x\nproperty float y\nproperty float z\nproperty int class\nend_header\n";
  constexpr size_t kRecord = 16;
  std::string body(points.size() * kRecord, '\0');
  for (size_t i = 0; i < points.size(); ++i) {
    const float xyz[3] = {float(points.positions[i].x), float(points.positions[i].y), float(points.positions[i].z)};
    std::memcpy(body.data() + i * kRecord, xyz, 12);
    std::memcpy(body.data() + i * kRecord + 12, &points.labels[i], 4);
  }
  write_text_atomic(path, header + body);
}

}  // namespace cls
