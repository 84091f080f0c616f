#pragma once
// The per-image feature files of the features stage (paper 3.1-3.2), in LangSplat's layout so its
// own tools read ours:
//   <stem>_s.npy      float32 ('<f4') 4 x H x W SAM seg maps [default, s, m, l] holding integer ids,
//                     -1 = no segment; values index the rows of <stem>_f.npy (LangSplat's offsets:
//                     level k's ids follow level k-1's). float32 because LangSplat's preprocess.py
//                     saves `seg_maps = torch.zeros(...)` (default dtype float32) and its loaders
//                     cast with .long(); ids are exact in float32 up to 2^24 (checked on write).
//   <stem>_f.npy      float32 N x D CLIP features of the SAM segments (L2-normalised)
// and the CityGML branch with the same layout:
//   <stem>_gml_s.npy  float32 3 x H x W integer region ids for levels 1, 2, 3 (subpart, part, whole),
//                     -1 where C^l is invalid or M = 0; values index the rows of <stem>_gml_f.npy
//   <stem>_gml_f.npy  float32 R x D fused features (1 - alpha) f_gml + alpha f_txt, L2-normalised
//   <stem>_gml.json   {"height", "width", "dim", "stamp", "regions": [per region: {"level", "class",
//                     "class_name", "instance" (-1 in class mode), "building", "pixels"}]}
// The reader also accepts int32/int64 seg maps (other tools' variants).
// Level l of the language field uses SAM seg map l (s, m, l) and CityGML map l - 1.
#include <ATen/core/Tensor.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cls {

struct CityRegion {
  int level = 1;          // 1, 2, 3
  int class_id = -1;      // taxonomy class id
  std::string class_name;
  int64_t instance = -1;  // instance mode: index of the connected component among the regions of the
                          // same level, class and building in this view; -1 in class mode
  int64_t building = -1;  // instance mode: building index (building.png - 1), -1 if none / class mode
  int64_t pixels = 0;
};

struct ViewFeatures {
  int height = 0, width = 0;
  std::vector<int32_t> sam_seg;  // 4 x H x W
  at::Tensor sam_features;       // N x D float32
  std::vector<int32_t> gml_seg;  // 3 x H x W
  at::Tensor gml_features;       // R x D float32
  std::vector<CityRegion> regions;  // R
  nlohmann::json stamp;             // what the features were made from (feature_stage: cache key)

  int32_t sam_at(int level, int y, int x) const { return sam_seg[(size_t(level) * height + y) * width + x]; }
  int32_t gml_at(int level, int y, int x) const {  // level 1..3
    return gml_seg[(size_t(level - 1) * height + y) * width + x];
  }
  // Shapes consistent, every id in range; cls::Error naming `what` otherwise.
  void validate(const std::string& what) const;
};

// Writes the five files atomically (json last, so its presence marks a complete view).
void write_view_features(const std::filesystem::path& dir, const std::string& stem, const ViewFeatures& f);
// cls::Error naming the file if one is missing, malformed, or inconsistent with the others.
ViewFeatures read_view_features(const std::filesystem::path& dir, const std::string& stem);
bool view_features_complete(const std::filesystem::path& dir, const std::string& stem);

}  // namespace cls
