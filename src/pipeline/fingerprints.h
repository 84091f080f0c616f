#pragma once
// Fingerprints of what stages read (core/hash.h FNV-1a over the bytes): a stage is redone exactly when
// one of its inputs changed.
#include <filesystem>
#include <string>

#include "citymodel/taxonomy.h"
#include "scene/scene.h"

namespace cls {

// Every view's name, intrinsics and pose at the loaded resolution.
std::string views_fingerprint(const Scene& scene);
// Every field of every class (names, levels, source types, prompts, colours): the built-in taxonomy has no
// file, and a new release may change it.
std::string taxonomy_fingerprint(const Taxonomy& taxonomy);

// The views and their images' bytes (what the photometric model and the features see).
std::string images_fingerprint(const Scene& scene);

// A file's bytes; "" for no file (an empty path).
std::string file_fingerprint(const std::filesystem::path& file);

// The features stage's result: features.json plus every view's `_gml.json`, which holds the view's
// stamp (label-map and image hashes, provider, alpha, regions).
std::string features_fingerprint(const std::filesystem::path& features_dir);

}  // namespace cls
