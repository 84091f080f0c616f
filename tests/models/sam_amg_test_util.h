#pragma once
// Helpers shared by the AMG tests: fixture paths, mask comparison.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "models/sam_amg/binary_mask.h"
#include "models/sam_amg/mask_nms.h"

namespace amg_test {

inline std::string amg_fixture(const std::string& name) {
  return std::string(CLS_TEST_FIXTURES) + "/sam/amg/" + name;
}

// The mask_nms thresholds a <run>_post.json was made with (its "params_used", after any fallback).
inline cls::amg::MaskNmsParams post_params(const nlohmann::json& post) {
  cls::amg::MaskNmsParams p;
  p.iou_thr = post.at("params_used").at("iou_thr").get<double>();
  p.score_thr = post.at("params_used").at("score_thr").get<double>();
  p.inner_thr = post.at("params_used").at("inner_thr").get<double>();
  return p;
}

inline double mask_iou(const cls::amg::BinaryMask& a, const cls::amg::BinaryMask& b) {
  int64_t inter = 0, uni = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) inter += a.pixels[i] && b.pixels[i], uni += a.pixels[i] || b.pixels[i];
  return uni == 0 ? 1.0 : static_cast<double>(inter) / uni;
}

}  // namespace amg_test
