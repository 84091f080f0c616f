// libFuzzer target for the PLY readers a user's file reaches: the shared vertex reader (core/ply.h,
// under Gaussian splats, labelled ground-truth points and point clouds), asked for every value as
// those readers ask, and the semantic-mesh reader (citymodel/mesh_ply.h). The first byte picks one.
// Malformed input must end in a cls::Error; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "citymodel/mesh_ply.h"
#include "core/error.h"
#include "core/ply.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view input(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] % 2 == 0) {
      const cls::PlyVertices v = cls::parse_ply_vertices(input, "fuzz.ply");
      for (uint64_t row = 0; row < v.count; ++row)
        for (const cls::PlyProperty& p : v.properties) v.finite_value(row, p);
    } else {
      cls::parse_mesh_ply(input, "fuzz.ply");
    }
  } catch (const cls::Error&) {
    // expected for malformed input
  }
  return 0;
}
