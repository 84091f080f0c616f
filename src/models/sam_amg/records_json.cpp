#include "models/sam_amg/records_json.h"

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"

namespace cls::amg {

namespace {
template <class T, size_t N>
std::array<T, N> fixed_array(const nlohmann::json& j, const std::string& where, const char* key) {
  if (!j.is_array() || j.size() != N) fail(where, cat("'", key, "' must be an array of ", N, " numbers"));
  std::array<T, N> a{};
  for (size_t i = 0; i < N; ++i) a[i] = j[i].get<T>();
  return a;
}
}  // namespace

MaskRecord record_from_json(const nlohmann::json& j, const std::string& where) {
  try {
    MaskRecord r;
    const auto& seg = j.at("segmentation");
    const auto size = fixed_array<int, 2>(seg.at("size"), where, "segmentation.size");
    r.segmentation.height = size[0];
    r.segmentation.width = size[1];
    r.segmentation.counts = seg.at("counts").get<std::vector<uint32_t>>();
    r.area = j.at("area").get<int64_t>();
    r.bbox = fixed_array<int64_t, 4>(j.at("bbox"), where, "bbox");
    r.predicted_iou = j.at("predicted_iou").get<float>();
    const auto& pc = j.at("point_coords");
    if (!pc.is_array() || pc.size() != 1) fail(where, "'point_coords' must hold one point");
    r.point = fixed_array<double, 2>(pc[0], where, "point_coords");
    r.stability_score = j.at("stability_score").get<float>();
    r.crop_box = fixed_array<int64_t, 4>(j.at("crop_box"), where, "crop_box");
    return r;
  } catch (const nlohmann::json::exception& e) {
    fail(where, cat("bad mask record: ", e.what()));
  }
}

nlohmann::json record_to_json(const MaskRecord& r) {
  nlohmann::json j;
  j["segmentation"] = {{"size", {r.segmentation.height, r.segmentation.width}},
                       {"counts", r.segmentation.counts}};
  j["area"] = r.area;
  j["bbox"] = r.bbox;
  j["predicted_iou"] = static_cast<double>(r.predicted_iou);
  j["point_coords"] = nlohmann::json::array({r.point});
  j["stability_score"] = static_cast<double>(r.stability_score);
  j["crop_box"] = r.crop_box;
  return j;
}

MaskLevels levels_from_json(const nlohmann::json& levels, const std::string& where) {
  MaskLevels out;
  for (int l = 0; l < kNumLevels; ++l) {
    if (!levels.contains(level_name(l))) fail(where, cat("missing level '", level_name(l), "'"));
    for (const auto& rec : levels.at(level_name(l))) out[l].push_back(record_from_json(rec, where));
  }
  return out;
}

nlohmann::json levels_to_json(const MaskLevels& levels) {
  nlohmann::json j = nlohmann::json::object();
  for (int l = 0; l < kNumLevels; ++l) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : levels[l]) list.push_back(record_to_json(r));
    j[level_name(l)] = std::move(list);
  }
  return j;
}

AmgParams params_from_json(const nlohmann::json& j, const std::string& where) {
  try {
    AmgParams p;
    p.points_per_side = j.at("points_per_side");
    p.points_per_batch = j.at("points_per_batch");
    p.pred_iou_thresh = j.at("pred_iou_thresh");
    p.stability_score_thresh = j.at("stability_score_thresh");
    p.stability_score_offset = j.at("stability_score_offset");
    p.box_nms_thresh = j.at("box_nms_thresh");
    p.crop_n_layers = j.at("crop_n_layers");
    p.crop_nms_thresh = j.at("crop_nms_thresh");
    p.crop_overlap_ratio = j.at("crop_overlap_ratio");
    p.crop_n_points_downscale_factor = j.at("crop_n_points_downscale_factor");
    p.min_mask_region_area = j.at("min_mask_region_area");
    p.mask_threshold = j.at("mask_threshold").get<float>();
    return p;
  } catch (const nlohmann::json::exception& e) {
    fail(where, cat("bad AMG params: ", e.what()));
  }
}

MaskLevels read_levels_file(const std::string& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    fail(path, cat("not valid JSON: ", e.what()));
  }
  if (!j.contains("levels")) fail(path, "no 'levels' object");
  return levels_from_json(j.at("levels"), path);
}

}  // namespace cls::amg
