#include "export/splat_gltf.h"

#include <torch/torch.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "core/error.h"
#include "core/log.h"
#include "export/finite_values.h"
#include "export/spz.h"
#include "splat/sh.h"

namespace cls {
namespace {
using nlohmann::json;

// Feature IDs are FLOAT attributes: glTF has no 32-bit integer vertex attribute, a 16-bit one would
// need a padded stride (vertex attributes align to 4 bytes), and a float holds every integer to 2^24.
constexpr int64_t kMaxFeatureIds = int64_t(1) << 24;
constexpr const char* kLevelLabels[3] = {"level1_opening", "level2_surface", "level3_building"};

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// A STRING column of a property table: the UTF-8 bytes and the count + 1 UINT32 offsets.
json string_column(GltfBuilder& gltf, const std::vector<std::string>& values) {
  std::string bytes;
  std::vector<uint32_t> offsets{0};
  for (const std::string& v : values) {
    bytes += v;
    offsets.push_back(static_cast<uint32_t>(bytes.size()));
  }
  if (bytes.size() > UINT32_MAX) throw Error("export: the city objects' ids exceed 4 GB");
  // A buffer view holds at least one byte: a column of empty strings keeps one unused.
  const int values_view = gltf.add_view(bytes.empty() ? "" : bytes.data(), std::max<size_t>(bytes.size(), 1));
  const int offsets_view = gltf.add_view(offsets.data(), offsets.size() * sizeof(uint32_t));
  return {{"values", values_view}, {"stringOffsets", offsets_view}, {"stringOffsetType", "UINT32"}};
}

json string_property(const std::string& description) {
  return {{"type", "STRING"}, {"description", description}};
}

// The city objects' table, its class and the three feature ID sets on the primitive.
void add_semantics(GltfBuilder& gltf, const SplatSemantics& semantics, int64_t n, json& primitive, json& metadata) {
  const CityObjects& objects = *semantics.objects;
  if (static_cast<int64_t>(semantics.object_of.size()) != n)
    throw std::logic_error("export: semantics of another length than the model");
  const int64_t rows = static_cast<int64_t>(objects.objects.size());
  if (rows + 1 >= kMaxFeatureIds) throw Error(cat("export: ", rows, " city objects: feature IDs hold at most ", kMaxFeatureIds - 2));

  std::vector<std::string> ids, classes, buildings, parts;
  std::vector<uint8_t> levels;
  for (int32_t k = 0; k < static_cast<int32_t>(rows); ++k) {
    ids.push_back(objects.objects[k].id);
    classes.push_back(objects.class_name(k));
    levels.push_back(static_cast<uint8_t>(objects.objects[k].level));
    const int32_t building = objects.at_level(k, 3), part = objects.part_of(k);
    buildings.push_back(building >= 0 ? objects.objects[building].id : "");
    parts.push_back(part >= 0 ? objects.objects[part].id : "");
  }
  metadata["schema"]["classes"]["cityObject"] = {
      {"name", "City object"},
      {"description", "An object of the city model (" + objects.source + "): an opening, a boundary surface, a building or part"},
      {"properties",
       {{"id", string_property("gml:id or CityJSON id")},
        {"class", string_property("the taxonomy's class")},
        {"level", {{"type", "SCALAR"}, {"componentType", "UINT8"},
                   {"description", "1 opening, 2 surface or installation, 3 building or building part"}}},
        {"building", string_property("the id of the Building it belongs to")},
        {"part", string_property("the id of the BuildingPart it lies in, empty outside one")}}}};
  json table{{"name", "city objects"}, {"class", "cityObject"}, {"count", rows}, {"properties", json::object()}};
  table["properties"]["id"] = string_column(gltf, ids);
  table["properties"]["class"] = string_column(gltf, classes);
  table["properties"]["level"] = {{"values", gltf.add_view(levels.data(), levels.size())}};
  table["properties"]["building"] = string_column(gltf, buildings);
  table["properties"]["part"] = string_column(gltf, parts);
  metadata["propertyTables"] = json::array({table});

  // The null ID is one past the table's last row.
  json feature_ids = json::array();
  for (int level = 1; level <= 3; ++level) {
    std::vector<float> id(n);
    std::set<int32_t> distinct;
    for (int64_t i = 0; i < n; ++i) {
      const int32_t o = semantics.object_of[i];
      if (o >= rows) throw std::logic_error(cat("export: Gaussian ", i, " names city object ", o, " of ", rows));
      const int32_t answer = o < 0 ? -1 : objects.at_level(o, level);
      id[i] = answer < 0 ? static_cast<float>(rows) : static_cast<float>(answer);
      if (answer >= 0) distinct.insert(answer);
    }
    const std::string attribute = "_FEATURE_ID_" + std::to_string(level - 1);
    primitive["attributes"][attribute] = gltf.add_accessor(id.data(), n, "SCALAR", kGltfFloat);
    feature_ids.push_back({{"featureCount", distinct.size()},
                           {"attribute", level - 1},
                           {"propertyTable", 0},
                           {"nullFeatureId", rows},
                           {"label", kLevelLabels[level - 1]}});
  }
  primitive["extensions"]["EXT_mesh_features"] = {{"featureIds", feature_ids}};
  gltf.use_extension("EXT_mesh_features");
}

void add_scores(GltfBuilder& gltf, const std::vector<SplatScores>& scores, int64_t n, json& primitive, json& metadata) {
  json properties = json::object(), attributes = json::object();
  for (size_t k = 0; k < scores.size(); ++k) {
    const SplatScores& s = scores[k];
    if (static_cast<int64_t>(s.values.size()) != n) throw std::logic_error("export: scores of another length than the model");
    check_finite(s.values, "scores of '" + s.text + "'");
    const std::string attribute = "_SCORE_" + std::to_string(k);
    primitive["attributes"][attribute] = gltf.add_accessor(s.values.data(), n, "SCALAR", kGltfFloat);
    properties[s.id] = {{"name", s.text},
                        {"description", cat("cosine of the splat's language feature on level ", s.level,
                                            " with the text's (query/relevance.h)")},
                        {"type", "SCALAR"},
                        {"componentType", "FLOAT32"}};
    attributes[s.id] = {{"attribute", attribute}};
  }
  metadata["schema"]["classes"]["queryScores"] = {
      {"name", "Query scores"}, {"description", "per splat, the score of each text query"}, {"properties", properties}};
  metadata["propertyAttributes"] = json::array({{{"class", "queryScores"}, {"properties", attributes}}});
  primitive["extensions"]["EXT_structural_metadata"] = {{"propertyAttributes", json::array({0})}};
}

}  // namespace

std::string sh_attribute_name(int k) {
  int degree = 0;
  while (sh_coeff_count(degree) <= k) ++degree;
  const int first = degree == 0 ? 0 : sh_coeff_count(degree - 1);
  return cat("KHR_gaussian_splatting:SH_DEGREE_", degree, "_COEF_", k - first);
}

GltfBuilder splat_gltf(const GaussianModel& g, const SplatSemantics* semantics, const std::vector<SplatScores>& scores,
                       const SplatGltfOptions& options) {
  at::NoGradGuard no_grad;
  const int64_t n = g.size();
  if (n == 0) throw Error("export: the model has no Gaussians");
  GltfBuilder gltf;
  gltf.json()["asset"]["generator"] = "citylangsplat " CLS_VERSION;
  if (!options.extras.empty()) gltf.json()["asset"]["extras"] = options.extras;
  json primitive{{"mode", 0}, {"attributes", json::object()}};
  json& attributes = primitive["attributes"];

  const std::vector<float> means = finite_floats(g.means, "positions");
  std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
  for (int64_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], double(means[3 * i + a]));
      hi[a] = std::max(hi[a], double(means[3 * i + a]));
    }
  // Unit quaternions reordered from (w, x, y, z) to glTF's (x, y, z, w).
  const std::vector<float> wxyz = finite_floats(torch::nn::functional::normalize(
      g.quats.to(torch::kFloat64), torch::nn::functional::NormalizeFuncOptions().dim(1)), "rotations");
  std::vector<float> xyzw(4 * n);
  for (int64_t i = 0; i < n; ++i)
    for (int c = 0; c < 4; ++c) xyzw[4 * i + c] = wxyz[4 * i + (c + 1) % 4];
  const std::vector<float> scales = finite_floats(g.scales(), "scales");
  const std::vector<float> opacity = finite_floats(g.opacities(), "opacities");
  const int64_t coeffs = sh_coeff_count(g.sh_degree());
  const std::vector<float> sh = finite_floats(g.sh(), "spherical harmonics");  // N x coeffs x 3
  // The fallback colour: the DC colour, clamped, decoded from sRGB to glTF's linear COLOR_0; alpha the opacity.
  std::vector<uint8_t> rgba(4 * n);
  for (int64_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double srgb = std::clamp(kShC0 * sh[i * coeffs * 3 + c] + 0.5, 0.0, 1.0);
      rgba[4 * i + c] = static_cast<uint8_t>(std::lround(255 * srgb_to_linear(srgb)));
    }
    rgba[4 * i + 3] = static_cast<uint8_t>(std::lround(255 * std::clamp(double(opacity[i]), 0.0, 1.0)));
  }

  // With SPZ the payload holds position, colour, alpha, scale, rotation and SH of degree >= 1, and the
  // accessors that stand for them have no buffer view; OPACITY and the DC term are the payload's (as the
  // extension's example and CesiumJS read it).
  const bool spz = options.compression == SplatCompression::Spz;
  const auto data = [spz](const void* p) { return spz ? nullptr : p; };
  attributes["POSITION"] = gltf.add_accessor(data(means.data()), n, "VEC3", kGltfFloat, false, lo, hi);
  attributes["COLOR_0"] = gltf.add_accessor(data(rgba.data()), n, "VEC4", kGltfUnsignedByte, true);
  attributes["KHR_gaussian_splatting:ROTATION"] = gltf.add_accessor(data(xyzw.data()), n, "VEC4", kGltfFloat);
  attributes["KHR_gaussian_splatting:SCALE"] = gltf.add_accessor(data(scales.data()), n, "VEC3", kGltfFloat);
  if (!spz) attributes["KHR_gaussian_splatting:OPACITY"] = gltf.add_accessor(opacity.data(), n, "SCALAR", kGltfFloat);
  std::vector<float> column(3 * n);
  for (int64_t k = spz ? 1 : 0; k < coeffs; ++k) {
    for (int64_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) column[3 * i + c] = sh[(i * coeffs + k) * 3 + c];
    attributes[sh_attribute_name(static_cast<int>(k))] = gltf.add_accessor(data(column.data()), n, "VEC3", kGltfFloat);
  }

  json& splatting = primitive["extensions"]["KHR_gaussian_splatting"];
  splatting = {{"kernel", "ellipse"},
               {"colorSpace", "srgb_rec709_display"},
               {"projection", "perspective"},
               {"sortingMethod", "cameraDistance"}};
  gltf.use_extension("KHR_gaussian_splatting", spz);
  if (spz) {
    const std::string payload = spz_v2(g, options.spz_axes);
    splatting["extensions"]["KHR_gaussian_splatting_compression_spz_2"] = {
        {"bufferView", gltf.add_view(payload.data(), payload.size())}};
    gltf.use_extension("KHR_gaussian_splatting_compression_spz_2", true);
  }

  json metadata = json::object();
  if (semantics && semantics->objects) add_semantics(gltf, *semantics, n, primitive, metadata);
  if (!scores.empty()) add_scores(gltf, scores, n, primitive, metadata);
  if (!metadata.empty()) {
    metadata["schema"]["id"] = "citylangsplat";
    metadata["schema"]["name"] = "CityLangSplat";
    gltf.json()["extensions"]["EXT_structural_metadata"] = metadata;
    gltf.use_extension("EXT_structural_metadata");
  }

  gltf.json()["meshes"] = json::array({{{"primitives", json::array({primitive})}}});
  json node{{"mesh", 0}, {"name", "gaussians"}};
  if (options.node_matrix) node["matrix"] = *options.node_matrix;
  gltf.json()["nodes"] = json::array({node});
  gltf.json()["scenes"] = json::array({{{"nodes", json::array({0})}}});
  gltf.json()["scene"] = 0;
  return gltf;
}

}  // namespace cls
