#pragma once
// 3D Gaussians as a glTF 2.0 asset (issue 35): one point primitive with KHR_gaussian_splatting (Khronos,
// release candidate 2026: POSITION, KHR_gaussian_splatting:ROTATION (x, y, z, w), :SCALE (linear),
// :OPACITY (after the sigmoid), :SH_DEGREE_l_COEF_n (3DGS's real SH: the same basis, order and signs
// as splat/sh.h), the ellipse kernel in sRGB display colour as trained on photos), COLOR_0 as the
// extension's fallback for viewers without it, and what the run learned per splat:
// - EXT_mesh_features: three feature ID sets, _FEATURE_ID_0..2, the city object that answers for the
//   splat on level 1 (opening, or a surface without one), 2 (surface) and 3 (building), as
//   CityObjects::at_level does for the label maps; each indexes the property table below, null where
//   the splat has no object (provenance.h: trees, terrain, what the model lacks).
// - EXT_structural_metadata: the table of city objects (class `cityObject`: id = gml:id / CityJSON id,
//   class, level, building = its Building's id, part = its BuildingPart's id or ""), and the scores of
//   text queries as property attributes (class `queryScores`, one FLOAT32 attribute _SCORE_k each).
// The node's matrix places the splats (kept in the frame they were trained in) where the caller says.
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "citymodel/city_objects.h"
#include "export/gltf_builder.h"
#include "export/spz.h"
#include "splat/gaussians.h"

namespace cls {

// Per splat its finest city object (an index into `objects`, -1 none), as the language model keeps it.
struct SplatSemantics {
  const CityObjects* objects = nullptr;
  std::vector<int32_t> object_of;
};

// One text query's per-splat scores (query/text_queries.h).
struct SplatScores {
  std::string id;    // the property's id: letters, digits, '_' (score_<slug>)
  std::string text;
  int level = 0;
  std::vector<float> values;
};

// How the Gaussians are stored: plain accessors, or one SPZ payload (spz.h) as
// KHR_gaussian_splatting_compression_spz_2 (lossy: 8-bit colours, scales and rotations, SH of 5 and 4
// bits; about a tenth of the size; what CesiumJS renders in 3D Tiles).
enum class SplatCompression { None, Spz };

struct SplatGltfOptions {
  SplatCompression compression = SplatCompression::None;
  SpzAxes spz_axes = SpzAxes::Luf;                    // with Spz: the payload's axes (spz.h)
  std::optional<std::array<double, 16>> node_matrix;  // column-major, as glTF; none = identity
  nlohmann::json extras = nlohmann::json::object();   // the asset's extras (where the frame lies ...)
};

// The attribute semantic of SH coefficient `k` (k >= 0 in 3DGS's order: 0 the DC term, then degree 1's
// three ...): KHR_gaussian_splatting:SH_DEGREE_l_COEF_n.
std::string sh_attribute_name(int k);

// cls::Error when the model is empty or a Gaussian holds a value the extension cannot carry (not finite);
// std::logic_error for semantics or scores of another length than the model.
GltfBuilder splat_gltf(const GaussianModel& gaussians, const SplatSemantics* semantics,
                       const std::vector<SplatScores>& scores, const SplatGltfOptions& options);

}  // namespace cls
