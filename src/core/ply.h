#pragma once
// The vertex element of a PLY file (Stanford polygon format: a text header, then the elements in
// order), shared by every reader of a user's PLY: Gaussian splats, labelled ground-truth points and
// photogrammetric point clouds. ascii and binary_little_endian; scalar vertex properties of any PLY
// type; elements after the vertices (faces, ...) are ignored, elements before them must be empty.
// The header is checked against the file before anything is allocated: a count of 10^11 vertices
// is a damaged header, not a reason to run out of memory.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cls {

struct PlyProperty {
  std::string name, type;  // type as the header spells it ("float", "uchar", "float32", ...)
  int size = 0;            // bytes
  bool is_int = false;
  size_t offset = 0;       // within a vertex row
};

struct PlyVertices {
  std::string file;                      // errors name it
  std::vector<std::string> comments;     // the header's comment lines, without "comment "
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
  size_t stride = 0;                     // bytes per row
  std::string rows;                      // count x stride, little-endian (ascii files are converted)

  const PlyProperty* find(const std::string& name) const;  // nullptr if absent
  const PlyProperty& require(const std::string& name) const;  // cls::Error naming the file if absent
  double value(uint64_t row, const PlyProperty& p) const;
  // value(), or a cls::Error naming the file, the vertex and the property when it is NaN or infinite.
  double finite_value(uint64_t row, const PlyProperty& p) const;
  // Number of properties prefix0, prefix1, ... present without a gap.
  int count_indexed(const std::string& prefix) const;
};

// Parses a whole PLY file held in memory; `file` names it in every error.
PlyVertices parse_ply_vertices(std::string_view bytes, const std::string& file);
PlyVertices read_ply_vertices(const std::string& path);

}  // namespace cls
