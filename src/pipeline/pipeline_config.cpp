#include "pipeline/pipeline_config.h"

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls {
namespace fs = std::filesystem;

ModelsChoice parse_models_choice(const std::string& name) {
  if (name == "auto") return ModelsChoice::Auto;
  if (name == "real") return ModelsChoice::Real;
  if (name == "tiny") return ModelsChoice::Tiny;
  if (name == "synthetic") return ModelsChoice::Synthetic;
  if (name == "image-segments") return ModelsChoice::ImageSegments;
  throw UsageError("run: --models must be auto, real, tiny, synthetic or image-segments, not '" + name + "'");
}

const char* models_choice_name(ModelsChoice choice) {
  switch (choice) {
    case ModelsChoice::Auto: return "auto";
    case ModelsChoice::Real: return "real";
    case ModelsChoice::Tiny: return "tiny";
    case ModelsChoice::Synthetic: return "synthetic";
    case ModelsChoice::ImageSegments: return "image-segments";
  }
  return "?";
}

void PipelineConfig::validate() const {
  if (resolution != 1 && resolution != 2 && resolution != 4 && resolution != 8)
    throw UsageError("run: --resolution must be 1, 2, 4 or 8");
  if (regions != "class" && regions != "instance") throw UsageError("run: --regions must be class or instance");
  if (rgb_iterations < 0 || language_iterations < 0 || autoencoder_epochs < 0)
    throw UsageError("run: iteration and epoch counts must not be negative (0: the feature source's default)");
  if (!(alpha >= 0 && alpha <= 1)) throw UsageError("run: --alpha must be in [0, 1]");
  if (models == ModelsChoice::ImageSegments && resolution != 1)
    throw UsageError("run: --models image-segments reads the full-resolution ground truth: use -r 1");
  if (!(align_distance >= 0)) throw UsageError("run: --align-distance must be >= 0");
  if (align != "off" && align != "refine" && align != "auto") throw UsageError("run: --align must be off, refine or auto");
  if (city.empty())
    throw UsageError("run: no city model: give --city, or a scene.json / --config with \"city_model\"");
  if (!rgb_model.empty() && !fs::exists(rgb_model)) fail(rgb_model, "--rgb-model: file not found");
  if (!autoencoder.empty() && baseline_original)
    throw UsageError("run: --baseline langsplat-original trains its own autoencoder: not with --autoencoder (tiles)");
  if (!autoencoder.empty() && !stop_after_features && !fs::exists(autoencoder))
    fail(autoencoder, "--autoencoder: file not found");
}

nlohmann::json PipelineConfig::to_json() const {
  return {{"scene", scene_dir.string()},
          {"out", out_dir.string()},
          {"city_model", city},
          {"city_transform", city_transform},
          {"taxonomy", city_options.taxonomy_path},
          {"lod", city_options.lod},
          {"resolution", resolution},
          {"align_distance", align_distance},
          {"align", align},
          {"models", models_choice_name(models)},
          {"clip", clip_weights},
          {"sam", sam_weights},
          {"alpha", alpha},
          {"regions", regions},
          {"rgb_model", rgb_model},
          {"rgb_iterations", rgb_iterations},
          {"language_iterations", language_iterations},
          {"autoencoder_epochs", autoencoder_epochs},
          {"lambda_sam", lambda_sam},
          {"lambda_citygml", lambda_citygml},
          {"baseline", baseline},
          {"baseline_original", baseline_original},
          {"autoencoder", autoencoder},
          {"stop_after_features", stop_after_features}};
}

void read_scene_config(const fs::path& file, PipelineConfig& config) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(file));
  } catch (const nlohmann::json::exception& e) {
    fail(file.string(), std::string("malformed JSON: ") + e.what());
  }
  if (!j.is_object()) fail(file.string(), "expected a JSON object");
  const fs::path base = file.parent_path();
  auto path_field = [&](const char* key, std::string& into) {
    if (!j.contains(key)) return;
    if (!j[key].is_string()) fail(file.string(), std::string("\"") + key + "\" must be a string");
    const fs::path p = j[key].get<std::string>();
    into = (p.is_absolute() ? p : base / p).string();
  };
  path_field("city_model", config.city);
  path_field("city_transform", config.city_transform);
  path_field("taxonomy", config.city_options.taxonomy_path);
  if (j.contains("lod")) {
    if (!j["lod"].is_number_integer()) fail(file.string(), "\"lod\" must be an integer (0 = highest)");
    config.city_options.lod = j["lod"].get<int>();
  }
}

}  // namespace cls
