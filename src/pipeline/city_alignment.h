#pragma once
// `run --align`: refine the city transform from the scene's sparse points before the label maps
// (docs/alignment.md). The refined transform is written to the run's align transform
// (RunLayout::align_transform) and used from then on.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "citymodel/scene_city_model.h"
#include "scene/scene.h"

namespace cls {

// auto applies the refinement only when it moves some vertex of the model by more than this (metres of
// the city model): a transform that is right to a few centimetres keeps its label maps byte for byte;
// and only when it brings more sparse points within the finest ICP gate (onto the surfaces), loses at
// most 1% of them from within the check's distance, and the points constrain the whole motion.
constexpr double kAlignApplyMetres = 0.05;

struct CityAlignment {
  bool applied = false;
  std::filesystem::path transform;  // the refined transform's file when applied
  nlohmann::json record;            // run.json's "align"
};

// "off", "refine" (always apply; a failed refinement or a scene without points is an error) or "auto"
// (see kAlignApplyMetres; a failed refinement is a warning). Updates `city` when applied.
CityAlignment align_city_model(const Scene& scene, SceneCityModel& city, const std::string& mode, double threshold,
                               const std::filesystem::path& refined_transform);

}  // namespace cls
