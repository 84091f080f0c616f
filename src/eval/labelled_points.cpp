#include "eval/labelled_points.h"

#include <climits>
#include <cstring>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/ply.h"
#include "scene/las.h"

namespace cls {

std::string default_label_field(const std::string& path) { return is_las_path(path) ? "classification" : "class"; }

LabelledPoints read_labelled_points(const std::string& path, const std::string& field_arg, const ClassMap* map) {
  const std::string field = field_arg.empty() ? default_label_field(path) : field_arg;
  LabelledPoints out;
  std::vector<double> values;
  if (is_las_path(path)) {
    if (!map)
      fail(path, "a LAS ground truth needs a class map (--class-map FILE) from its " + field +
                     " values to the taxonomy's classes (data/class-maps/ has ZAHA's)");
    LasPoints las = read_las(path, 1, field == "classification" ? "" : field);
    out.positions = std::move(las.xyz);
    values = field == "classification" ? std::vector<double>(las.classification.begin(), las.classification.end())
                                       : std::move(las.field);
  } else {
    const PlyVertices v = read_ply_vertices(path);
    const PlyProperty &x = v.require("x"), &y = v.require("y"), &z = v.require("z"), &c = v.require(field);
    out.positions.resize(v.count);
    values.resize(v.count);
    for (uint64_t i = 0; i < v.count; ++i) {
      out.positions[i] = {v.finite_value(i, x), v.finite_value(i, y), v.finite_value(i, z)};
      values[i] = v.finite_value(i, c);
    }
  }
  if (map) {
    out.labels = map_labels(*map, values, path, field);
    return out;
  }
  out.labels.resize(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    if (values[i] < INT32_MIN || values[i] > INT32_MAX)
      fail(path, "vertex " + std::to_string(i) + " has " + field + " = " + std::to_string(values[i]) + ": not a class id");
    out.labels[i] = static_cast<int32_t>(values[i]);
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
