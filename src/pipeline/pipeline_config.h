#pragma once
// Everything one `run` depends on, as plain data (COLMAP's Options pattern), and its options declared
// once (pipeline_options()): the CLI, run.json's "settings" and run-tiles' carried settings all come
// from that list. The pipeline reads no other setting.
#include <filesystem>
#include <string>
#include <vector>

#include "citymodel/city_model.h"
#include "core/option_list.h"
#include "features/provider_registry.h"

namespace cls {

struct PipelineConfig {
  std::filesystem::path scene_dir;
  std::filesystem::path out_dir;           // empty: SCENE_DIR/citylangsplat (RunLayout::of_scene)
  // The city model: scene.json's "city_model", "city_transform", "taxonomy", "lod" unless overridden.
  std::string city, city_transform;
  CityModelOptions city_options;
  int resolution = 1;                      // 3DGS-style image downscaling: 1, 2, 4 or 8
  int max_side = 1600;                     // with -r 1: photos with a longer side load at this (0 = whole)
  int feature_height = 1080;               // with -r 1: the language stages' photos at most this tall (0 = as train-rgb's)
  double align_distance = 0.5;             // alignment check threshold (city-model metres)
  std::string georef = "auto";             // the city transform from a project's frame or the photos' GPS: off, frame, gps or auto (stage_georef.cpp)
  std::string crs;                         // the city model's CRS for --georef ("" = its srsName / referenceSystem)
  std::string align = "auto";              // refine the city transform: off, refine or auto (city_alignment.h)
  ProviderChoice features = auto_features();  // --models (auto: real weights where found), --clip, --sam
  double alpha = 0.5;                      // text-guidance weight of the CityGML features
  std::string regions = "class";           // "class" or "instance"
  std::string rgb_model;                   // a 3DGS PLY to import instead of training
  // 0: the feature provider's schedule (provider_registry.h).
  int rgb_iterations = 0, language_iterations = 0, autoencoder_epochs = 0;
  double lambda_sam = 1.0, lambda_citygml = 0.5;
  // The language field of every method (language_training.h): dense, or sparse with its codebook size and K.
  std::string field = "dense";
  int codebook_size = 64, top_k = 4;
  // Trained beside CityLangSplat on identical inputs (kBaselines): LangSplat's objective on the shared
  // autoencoder, and LangSplat as published (its 3-d autoencoder and training settings, normalised
  // splatting: the paper's "original implementation with its default configuration").
  std::vector<std::string> baselines = {"langsplat-original"};  // the paper's baseline
  // Tiles (docs/scale.md): a shared autoencoder trained on the features of every tile replaces this
  // scene's own, and a run may stop after the features, which the shared autoencoder needs first.
  std::string autoencoder;                 // "" = train one on this scene's SAM features
  std::string stop_after = "none";         // a step of pipeline_step_names(), or none

  static ProviderChoice auto_features();

  // Checks what the options' codecs cannot: ranges and combinations (cls::UsageError saying which
  // option is wrong), and that named input files exist (cls::Error naming the file).
  void validate() const;
};

// The baselines `run` knows, in the order of the tables ("langsplat-original", "langsplat").
extern const std::vector<std::string> kBaselines;

// Every option of `run`, declared once. per_scene() marks those each scene of a tiled job has its own
// (run-tiles carries the others to every tile).
const OptionList<PipelineConfig>& pipeline_options();

// Reads the city-model keys of a scene config (scene.json as `synth` writes it, or --config FILE) into
// `config`; paths are relative to the file. cls::Error naming the file for malformed JSON or fields.
void read_scene_config(const std::filesystem::path& file, PipelineConfig& config);

// The options a scene config can set (city, city-transform, lod, taxonomy).
bool is_scene_config_option(const OptionList<PipelineConfig>::Binding& binding);

// The configuration as `run` and `tile` take it: the options the command line gave (already applied to
// `config`, whose scene_dir is set), over the scene config `config_file`, or SCENE_DIR/scene.json where
// it exists. cls::Error naming a --config file that does not exist.
void apply_scene_config(const Args& args, const std::filesystem::path& config_file, PipelineConfig& config);

}  // namespace cls
