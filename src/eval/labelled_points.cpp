#include "eval/labelled_points.h"

#include <cstring>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls {
namespace {

struct Property {
  std::string name, type;
  int size = 0;
  size_t offset = 0;
};

int type_size(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

// One binary little-endian scalar as double (the build targets are little-endian).
double read_binary(const char* p, const Property& prop) {
  const std::string& t = prop.type;
  if (t == "char" || t == "int8") { int8_t v; std::memcpy(&v, p, 1); return v; }
  if (t == "uchar" || t == "uint8") { uint8_t v; std::memcpy(&v, p, 1); return v; }
  if (t == "short" || t == "int16") { int16_t v; std::memcpy(&v, p, 2); return v; }
  if (t == "ushort" || t == "uint16") { uint16_t v; std::memcpy(&v, p, 2); return v; }
  if (t == "int" || t == "int32") { int32_t v; std::memcpy(&v, p, 4); return v; }
  if (t == "uint" || t == "uint32") { uint32_t v; std::memcpy(&v, p, 4); return v; }
  if (t == "float" || t == "float32") { float v; std::memcpy(&v, p, 4); return v; }
  double v; std::memcpy(&v, p, 8); return v;
}

}  // namespace

LabelledPoints read_labelled_points(const std::string& path, const std::string& class_property) {
  const std::string data = read_text_file(path);
  const size_t end = data.find("end_header");
  if (data.compare(0, 3, "ply") != 0 || end == std::string::npos) fail(path, "not a PLY file (no 'ply' magic or no end_header)");
  size_t body = data.find('\n', end);
  if (body == std::string::npos) fail(path, "PLY header does not end with a newline");
  ++body;

  std::istringstream header(data.substr(0, end));
  std::string line, format;
  std::vector<Property> props;
  size_t count = 0, record = 0;
  bool in_vertex = false, seen_vertex = false, element_before_vertex = false;
  while (std::getline(header, line)) {
    std::istringstream ls(line);
    std::string kw;
    ls >> kw;
    if (kw == "format") {
      ls >> format;
    } else if (kw == "element") {
      std::string name;
      ls >> name;
      in_vertex = name == "vertex";
      if (in_vertex) {
        if (!(ls >> count)) fail(path, "bad vertex element line: " + line);
        seen_vertex = true;
      } else if (!seen_vertex) {
        element_before_vertex = true;
      }
    } else if (kw == "property" && in_vertex) {
      Property p;
      ls >> p.type;
      if (p.type == "list") fail(path, "list property in the vertex element is not supported");
      ls >> p.name;
      p.size = type_size(p.type);
      if (p.size == 0 || p.name.empty()) fail(path, "unknown PLY property type in: " + line);
      p.offset = record;
      record += p.size;
      props.push_back(p);
    }
  }
  if (!seen_vertex) fail(path, "PLY has no vertex element");
  if (element_before_vertex) fail(path, "PLY elements before the vertex element are not supported");
  if (format != "ascii" && format != "binary_little_endian")
    fail(path, "PLY format '" + format + "' is not supported (ascii or binary_little_endian)");
  auto find = [&](const std::string& name) -> int {
    for (size_t i = 0; i < props.size(); ++i)
      if (props[i].name == name) return int(i);
    fail(path, "PLY has no vertex property '" + name + "'");
  };
  const int ix = find("x"), iy = find("y"), iz = find("z"), ic = find(class_property);

  LabelledPoints out;
  out.positions.resize(count);
  out.labels.resize(count);
  if (format == "binary_little_endian") {
    if (data.size() - body < count * record)
      fail(path, "PLY truncated: " + std::to_string(count) + " vertices of " + std::to_string(record) +
                     " bytes need " + std::to_string(count * record) + " bytes, found " + std::to_string(data.size() - body));
    for (size_t i = 0; i < count; ++i) {
      const char* r = data.data() + body + i * record;
      out.positions[i] = {read_binary(r + props[ix].offset, props[ix]), read_binary(r + props[iy].offset, props[iy]),
                          read_binary(r + props[iz].offset, props[iz])};
      out.labels[i] = int32_t(read_binary(r + props[ic].offset, props[ic]));
    }
  } else {
    std::istringstream in(data.substr(body));
    std::vector<double> values(props.size());
    for (size_t i = 0; i < count; ++i) {
      for (double& v : values)
        if (!(in >> v)) fail(path, "PLY truncated or malformed at vertex " + std::to_string(i));
      out.positions[i] = {values[ix], values[iy], values[iz]};
      out.labels[i] = int32_t(values[ic]);
    }
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
