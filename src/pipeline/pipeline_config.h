#pragma once
// Everything one `run` depends on, as plain data (COLMAP's Options pattern): the CLI fills it from its
// options and the scene's scene.json; the pipeline reads no other setting.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "citymodel/scene_city_model.h"

namespace cls {

// Where the language features come from. Auto: real CLIP/SAM where both weight files are found,
// otherwise the synthetic provider (said on the terminal, in run.json and in the report). ImageSegments:
// the robustness benchmark's provider (image segments, features from SCENE/gt/labels; docs/features.md).
enum class ModelsChoice { Auto, Real, Tiny, Synthetic, ImageSegments };

ModelsChoice parse_models_choice(const std::string& name);  // cls::UsageError for an unknown name
const char* models_choice_name(ModelsChoice choice);

struct PipelineConfig {
  std::filesystem::path scene_dir;
  std::filesystem::path out_dir;           // default SCENE_DIR/citylangsplat
  // The city model: scene.json's "city_model", "city_transform", "taxonomy", "lod" unless overridden.
  std::string city, city_transform;
  CityModelOptions city_options;
  int resolution = 1;                      // 3DGS-style image downscaling: 1, 2, 4 or 8
  double align_distance = 0.5;             // alignment check threshold (city-model metres)
  std::string align = "auto";              // refine the city transform: off, refine or auto (city_alignment.h)
  ModelsChoice models = ModelsChoice::Auto;
  std::string clip_weights, sam_weights;   // empty: searched (`citylangsplat models list`)
  double alpha = 0.5;                      // text-guidance weight of the CityGML features
  std::string regions = "class";           // "class" or "instance"
  std::string rgb_model;                   // a 3DGS PLY to import instead of training
  // 0: the feature source's defaults (FeatureSource below).
  int rgb_iterations = 0, language_iterations = 0, autoencoder_epochs = 0;
  double lambda_sam = 1.0, lambda_citygml = 0.5;
  bool baseline = true;                    // also train the LangSplat baseline
  // Also LangSplat as published (its 3-d autoencoder and training settings, normalised splatting), on the
  // same features: the paper's "original implementation with its default configuration".
  bool baseline_original = false;
  // Tiles (docs/scale.md): a shared autoencoder trained on the features of every tile replaces this
  // scene's own, and a run may stop after the features, which the shared autoencoder needs first.
  std::string autoencoder;                 // "" = train one on this scene's SAM features
  bool stop_after_features = false;

  // Checks ranges and names (cls::UsageError saying which option is wrong).
  void validate() const;
  // run.json's "settings": every field, flat.
  nlohmann::json to_json() const;
};

// Reads the city-model keys of a scene config (scene.json as `synth` writes it, or --config FILE) into
// `config`; paths are relative to the file. cls::Error naming the file for malformed JSON or fields.
void read_scene_config(const std::filesystem::path& file, PipelineConfig& config);

}  // namespace cls
