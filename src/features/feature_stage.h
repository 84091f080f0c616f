#pragma once
// The features stage (`citylangsplat features`): for every view, the SAM branch and the CityGML
// branch (view_features.h), cached per image: a view whose files are complete and whose stamp
// matches is skipped, so a killed run resumes where it stopped. OUT/features.json records the
// provider spec, alpha, region mode, taxonomy and the list of views.
#include <filesystem>
#include <string>

#include "citymodel/taxonomy.h"
#include "core/option_list.h"
#include "features/feature_provider.h"
#include "scene/scene.h"

namespace cls {

enum class RegionMode { Class, Instance };  // paper: one region per class and view / one per object

struct FeatureStageOptions {
  std::filesystem::path labels_dir;  // the label maps (raycast / run OUT/labels)
  std::filesystem::path out_dir;
  double alpha = 0.5;                // text-guidance weight (paper eq. f^{gml+txt})
  RegionMode region_mode = RegionMode::Class;
  bool overwrite = false;            // recompute cached views
  int min_region_pixels = 16;        // CityGML regions with fewer pixels are skipped (-1 in the seg map)
};

// The options of the stage (`features`; run's fingerprint of the stage takes their settings).
const OptionList<FeatureStageOptions>& feature_stage_options();

// Returns the number of views computed (0 when every view was cached). Stops early, leaving
// features.json unwritten, when interrupt_requested() (core/interrupt.h) turns true between views.
int run_feature_stage(const Scene& scene, FeatureProvider& provider, const Taxonomy& taxonomy,
                      const FeatureStageOptions& options);

}  // namespace cls
