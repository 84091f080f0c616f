#include "citymodel/mesh_ply.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

// PLY binary_little_endian regardless of the host's byte order.
template <class T>
void put_le(std::string& out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (!host_is_little_endian()) std::reverse(bytes, bytes + sizeof(T));
  out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

// A header comment is one line: no line breaks from file names.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

// The property lines of both elements, as written and as the reader expects them.
const char* const kVertexProperties = "property float x\nproperty float y\nproperty float z\n";
const char* const kFaceProperties =
    "property list uchar int vertex_indices\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    "property int class_l1\nproperty int class_l2\nproperty int class_l3\nproperty int building\n";
constexpr size_t kFaceBytes = 1 + 3 * 4 + 3 + 4 * 4;

template <class T>
T get_le(const char* p) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if (!host_is_little_endian()) std::reverse(bytes, bytes + sizeof(T));
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

}  // namespace

void write_mesh_ply(const std::string& path, const SemanticMesh& mesh, const Taxonomy& taxonomy,
                    const CityTransform* transform) {
  // Building number of each level-3 entity that is a whole building.
  std::map<int32_t, int32_t> building_index;
  for (size_t b = 0; b < mesh.buildings.size(); ++b) building_index[mesh.buildings[b]] = static_cast<int32_t>(b);
  if (mesh.vertices.size() > static_cast<size_t>(INT32_MAX)) fail(path, "too many vertices for a PLY int index");

  char origin[160];
  std::snprintf(origin, sizeof origin, "%.17g %.17g %.17g", mesh.origin[0], mesh.origin[1], mesh.origin[2]);
  std::string header = "ply\nformat binary_little_endian 1.0\n";
  header += "comment citylangsplat " CLS_VERSION " semantic mesh\n";
  header += "comment source " + one_line(mesh.source_path) + "\n";
  header += "comment crs " + one_line(mesh.crs) + "\n";
  header += "comment origin " + std::string(origin) + "\n";
  header += transform ? "comment frame scene (city transform applied; source = inverse transform)\n"
                      : "comment frame local (source coordinate = vertex + origin)\n";
  header += "element vertex " + std::to_string(mesh.vertices.size()) + "\n" + kVertexProperties;
  header += "element face " + std::to_string(mesh.num_triangles()) + "\n" + kFaceProperties + "end_header\n";

  std::string body;
  body.reserve(mesh.vertices.size() * 12 + mesh.num_triangles() * 32);
  if (transform) {
    for (const Vec3f& v : scene_vertices(mesh, *transform)) {
      put_le(body, v.x);
      put_le(body, v.y);
      put_le(body, v.z);
    }
  } else {
    for (const auto& v : mesh.vertices)
      for (double x : v) put_le(body, static_cast<float>(x));
  }
  const std::array<unsigned char, 3> no_class_colour{128, 128, 128};
  for (size_t t = 0; t < mesh.num_triangles(); ++t) {
    put_le(body, static_cast<uint8_t>(3));
    for (uint32_t i : mesh.triangles[t]) put_le(body, static_cast<int32_t>(i));
    const auto& level_class = mesh.tri_level_class[t];
    const int c1 = level_class[0];
    const auto& colour =
        c1 >= 0 && c1 < static_cast<int>(taxonomy.classes.size()) ? taxonomy.classes[c1].color : no_class_colour;
    for (unsigned char c : colour) put_le(body, static_cast<uint8_t>(c));
    for (int32_t c : level_class) put_le(body, c);
    const auto b = building_index.find(mesh.tri_entity[t][2]);
    put_le(body, b == building_index.end() ? int32_t(-1) : b->second);
  }

  write_atomic(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    out.close();
    if (!out) fail(path, "write failed");
  });
  log_info(cat("wrote ", path, ": ", mesh.vertices.size(), " vertices, ", mesh.num_triangles(), " triangles"));
}

ColouredMesh read_mesh_ply(const std::string& path) { return parse_mesh_ply(read_text_file(path), path); }

ColouredMesh parse_mesh_ply(std::string_view bytes, const std::string& path) {
  const size_t end = bytes.find("end_header\n");
  if (bytes.rfind("ply\nformat binary_little_endian 1.0\n", 0) != 0 || end == std::string::npos)
    fail(path, "not a binary little-endian PLY");
  // The header without its comments must be exactly write_mesh_ply's, up to the counts.
  std::string header, line;
  size_t vertices = 0, faces = 0;
  std::istringstream in(std::string(bytes.substr(0, end)));
  while (std::getline(in, line)) {
    if (line.rfind("comment ", 0) == 0) continue;
    if (std::sscanf(line.c_str(), "element vertex %zu", &vertices) == 1) line = "element vertex N";
    else if (std::sscanf(line.c_str(), "element face %zu", &faces) == 1) line = "element face N";
    header += line + "\n";
  }
  const std::string expected = std::string("ply\nformat binary_little_endian 1.0\nelement vertex N\n") +
                               kVertexProperties + "element face N\n" + kFaceProperties;
  if (header != expected) fail(path, "not a semantic-mesh PLY of `citymodel export` / `raycast` (other properties)");
  const size_t body = end + std::strlen("end_header\n");
  const size_t data = bytes.size() - body;
  if (vertices > data / 12 || faces > (data - vertices * 12) / kFaceBytes || data != vertices * 12 + faces * kFaceBytes)
    fail(path, cat("truncated or oversized: ", data, " bytes of data for ", vertices, " vertices and ",
                   faces, " faces"));
  ColouredMesh mesh;
  const char* p = bytes.data() + body;
  mesh.vertices.resize(vertices);
  for (size_t i = 0; i < vertices; ++i, p += 12) {
    Vec3f& v = mesh.vertices[i];
    v = {get_le<float>(p), get_le<float>(p + 4), get_le<float>(p + 8)};
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      fail(path, cat("vertex ", i, " is not finite: the file must hold finite numbers only"));
  }
  mesh.triangles.resize(faces);
  mesh.colours.resize(faces);
  for (size_t f = 0; f < faces; ++f, p += kFaceBytes) {
    if (static_cast<uint8_t>(p[0]) != 3) fail(path, cat("face ", f, " is not a triangle"));
    for (int k = 0; k < 3; ++k) {
      const int32_t index = get_le<int32_t>(p + 1 + 4 * k);
      if (index < 0 || static_cast<size_t>(index) >= vertices)
        fail(path, cat("face ", f, " refers to vertex ", index, " of ", vertices));
      mesh.triangles[f][k] = index;
    }
    for (int k = 0; k < 3; ++k) mesh.colours[f][k] = static_cast<uint8_t>(p[13 + k]);
  }
  return mesh;
}

}  // namespace cls
