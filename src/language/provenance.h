#pragma once
// Which city object each Gaussian belongs to (issue 12): the finest object of the raycast label maps
// (object.npy) at the Gaussian's centre, by majority over the views where the centre lies on the
// city model's first hit. What the viewer and `query --objects` answer with.
//
// Visible in a view means: the centre projects inside the image, in front of the camera, and its
// camera depth z agrees with the label map's depth d of that pixel within
// max(relative_depth_tolerance * d, scale_tolerance * the Gaussian's largest scale). A Gaussian of a
// tree in front of a facade, of terrain the city model lacks, or one hidden behind a wall gets no vote
// from that view. A vote can be "none" (the hit triangle has no object); none wins only with strictly
// more votes than every object. Ties between objects go to the lower object index.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "scene/scene.h"
#include "splat/gaussians.h"

namespace cls {

struct ProvenanceSettings {
  double relative_depth_tolerance = 0.02;
  double scale_tolerance = 3.0;
};

struct GaussianProvenance {
  std::vector<int32_t> object;  // per Gaussian: index into the label maps' objects.json, -1 none
  std::vector<float> support;   // the winner's share of the Gaussian's votes (0 without votes)
  int64_t assigned = 0;         // Gaussians with an object
  size_t views = 0;
  nlohmann::json summary(const ProvenanceSettings& settings) const;  // counts and the rule, for model.json
};

// Reads every view's object.npy and depth.pfm under `labels_dir` (raycast layout, label_map_dirs);
// cls::Error naming the file when one is missing or has another size than the scene's view.
GaussianProvenance assign_provenance(const GaussianModel& gaussians, const Scene& scene,
                                     const std::filesystem::path& labels_dir, const ProvenanceSettings& settings = {});

// The PLY extras of a model with provenance.
constexpr const char* kObjectProperty = "city_object";                  // int32
constexpr const char* kObjectSupportProperty = "city_object_support";  // float32

// Sets (replaces) both extras on `gaussians`.
void attach_provenance(GaussianModel& gaussians, const GaussianProvenance& provenance);

}  // namespace cls
