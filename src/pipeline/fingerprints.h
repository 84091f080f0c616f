#pragma once
// Fingerprints of what each stage depends on (core/hash.h FNV-1a over the bytes and settings): a
// stage is redone exactly when one of its inputs changed.
#include <filesystem>
#include <string>

#include "pipeline/pipeline_config.h"
#include "scene/scene.h"

namespace cls {

// The label maps: the city model, transform and taxonomy bytes, the LoD, and every view's name,
// intrinsics and pose at the loaded resolution.
std::string labels_fingerprint(const PipelineConfig& config, const Scene& scene);

// The views and their images' bytes (what the photometric model and the features see).
std::string images_fingerprint(const Scene& scene);

// The features stage's result: features.json plus every view's `_gml.json`, which holds the view's
// stamp (label-map and image hashes, provider, alpha, regions).
std::string features_fingerprint(const std::filesystem::path& features_dir);

}  // namespace cls
