#pragma once
// The model files CityLangSplat knows: where they come from, their size and sha256, and where a
// local copy is looked for (--models-dir, $CITYLANGSPLAT_MODELS, then the XDG cache directory
// $XDG_CACHE_HOME/citylangsplat/models, by default ~/.cache/citylangsplat/models).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cls {

struct KnownModel {
  std::string name;         // what `models download NAME` takes
  std::string family;       // "clip" | "sam"
  std::string arch;         // "ViT-B-16" | "vit_b" | "vit_l" | "vit_h"
  std::string file_name;    // the local file name
  std::vector<std::string> other_names;  // also accepted when looking for a local copy
  std::string url;          // the official source
  uint64_t size = 0;        // bytes; 0 = not known
  std::string sha256;       // lower-case hex; "" = not known
  std::string description;
};

const std::vector<KnownModel>& known_models();
// By name or alias (case-insensitive; "vit_h" / "sam_vit_h" find SAM ViT-H); nullptr if unknown.
const KnownModel* find_known_model(const std::string& name);

// The directories searched, in order: models_dir (if not empty), $CITYLANGSPLAT_MODELS (if set),
// the XDG cache directory.
std::vector<std::filesystem::path> model_search_dirs(const std::string& models_dir);
// Where downloads go: the first of model_search_dirs().
std::filesystem::path model_download_dir(const std::string& models_dir);
// The first existing local copy (file_name or one of other_names) in the search directories.
std::optional<std::filesystem::path> find_model_file(const KnownModel& m,
                                                     const std::vector<std::filesystem::path>& dirs);

}  // namespace cls
