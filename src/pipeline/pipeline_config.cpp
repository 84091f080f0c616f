#include "pipeline/pipeline_config.h"

#include <algorithm>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/run_layout.h"
#include "pipeline/pipeline.h"

namespace cls {
namespace fs = std::filesystem;

const std::vector<std::string> kBaselines = {"langsplat-original", "langsplat"};

ProviderChoice PipelineConfig::auto_features() {
  ProviderChoice c;
  c.models = kAutoModels;
  return c;
}

void PipelineConfig::validate() const {
  if (resolution != 1 && resolution != 2 && resolution != 4 && resolution != 8)
    throw UsageError("run: --resolution must be 1, 2, 4 or 8");
  if (max_side < 0) throw UsageError("run: --max-side must be 0 (off) or a number of pixels");
  if (feature_height < 0) throw UsageError("run: --feature-height must be 0 (off) or a number of pixels");
  if (rgb_iterations < 0 || language_iterations < 0 || autoencoder_epochs < 0)
    throw UsageError("run: iteration and epoch counts must not be negative (0: the feature provider's schedule)");
  if (!(alpha >= 0 && alpha <= 1)) throw UsageError("run: --alpha must be in [0, 1]");
  if (features.models == "image-segments" && resolution != 1)
    throw UsageError("run: --models image-segments reads the full-resolution ground truth: use -r 1");
  if (!(align_distance >= 0)) throw UsageError("run: --align-distance must be >= 0");
  // What the codecs check for the command line and files, for a configuration made in code.
  if (align != "off" && align != "refine" && align != "auto") throw UsageError("run: --align must be off, refine or auto");
  if (georef != "off" && georef != "gps" && georef != "frame" && georef != "auto")
    throw UsageError("run: --georef must be off, frame, gps or auto");
  if (regions != "class" && regions != "instance") throw UsageError("run: --regions must be class or instance");
  const std::vector<std::string> steps = pipeline_step_names();
  const auto step = std::find(steps.begin(), steps.end(), stop_after);
  if (stop_after != "none" && step == steps.end())
    throw UsageError("run: --stop-after must be a step (" + one_of(steps) + ") or none, not '" + stop_after + "'");
  if (city.empty())
    throw UsageError("run: no city model: give --city, or a scene.json / --config with \"city_model\"");
  if (!rgb_model.empty() && !fs::exists(rgb_model)) fail(rgb_model, "--rgb-model: file not found");
  const bool original = std::find(baselines.begin(), baselines.end(), "langsplat-original") != baselines.end();
  if (field != "dense" && field != "sparse") throw UsageError("run: --field must be dense or sparse");
  if (field == "sparse" && original)
    throw UsageError("run: --field sparse has no decoder, so LangSplat as published (its own 3-d autoencoder, the "
                     "default baseline langsplat-original) cannot train in it: give --baseline langsplat (LangSplat's "
                     "objective in the sparse field) or none");
  if (field == "sparse" && (codebook_size < 1 || top_k < 1 || top_k > codebook_size))
    throw UsageError("run: --top-k must lie in [1, --codebook-size]");
  if (!autoencoder.empty() && original)
    throw UsageError("run: the baseline langsplat-original (the default) trains its own autoencoder: with --autoencoder "
                     "give --baseline langsplat or none");
  // The autoencoder is read from its step on (tiles stop after the features, before it exists).
  const bool needs_autoencoder = step == steps.end() || step >= std::find(steps.begin(), steps.end(), "autoencoder");
  if (!autoencoder.empty() && needs_autoencoder && !fs::exists(autoencoder))
    fail(autoencoder, "--autoencoder: file not found");
}

namespace {

// --baseline: a comma-separated list of kBaselines ("none" adds nothing), kept in kBaselines' order
// and once each, so that the stages and the evaluation's columns do not depend on how it was written.
Codec<std::vector<std::string>> baselines_codec() {
  Codec<std::vector<std::string>> c = default_codec<std::vector<std::string>>();
  const auto check = [](const std::vector<std::string>& names) {
    for (const std::string& n : names)
      if (n != "none" && std::find(kBaselines.begin(), kBaselines.end(), n) == kBaselines.end())
        throw std::invalid_argument("takes " + one_of(kBaselines) + " (comma-separated) or none, not '" + n + "'");
    std::vector<std::string> known;
    for (const std::string& b : kBaselines)
      if (std::find(names.begin(), names.end(), b) != names.end()) known.push_back(b);
    return known;
  };
  c.text = [text = c.text](const std::vector<std::string>& v) { return v.empty() ? std::string("none") : text(v); };
  c.parse = [check, parse = c.parse](const std::string& s) { return check(parse(s)); };
  c.from_json = [check, from = c.from_json](const nlohmann::json& j) { return check(from(j)); };
  return c;
}

std::string schedule_help(int Schedule::*count) {
  std::string s;
  for (const FeatureProviderInfo& p : feature_providers())
    s += (s.empty() ? "" : ", ") + p.name + " " + std::to_string(p.schedule.*count);
  return "0: the feature provider's (" + s + ")";
}

OptionList<PipelineConfig> make_pipeline_options() {
  using C = PipelineConfig;
  using R = OptionRole;
  OptionList<C> o;
  o.add("scene", &C::scene_dir, "scene directory (COLMAP, OPF or Pix4D, images under SCENE_DIR/images)", R::Location)
      .positional("SCENE_DIR").per_scene()
      .add("out", &C::out_dir, "output directory", R::Location).default_text("SCENE_DIR/citylangsplat").per_scene()
      .add("city", &C::city, "city model: CityGML, CityJSON or CityJSONSeq (overrides the config)", R::Location)
      .per_scene()
      .add("city-transform", &C::city_transform, "city transform JSON (overrides the config; identity if none)",
           R::Location)
      .per_scene()
      .add("lod", [](C& c) -> int& { return c.city_options.lod; }, "level of detail: 1, 2, 3 or highest (overrides the config)",
           R::Setting, lod_codec())
      .per_scene()
      .add("taxonomy", [](C& c) -> std::string& { return c.city_options.taxonomy_path; },
           "taxonomy JSON (overrides the config; the built-in one if none)", R::Location)
      .per_scene()
      .add("resolution", &C::resolution, "divide the image size by 1, 2, 4 or 8").short_name("r")
      .add("max-side", &C::max_side,
           "with -r 1, photos whose longer side exceeds this many pixels are loaded at it (3DGS loads photos wider "
           "than 1600 px at 1600); 0 keeps them whole")
      .add("feature-height", &C::feature_height,
           "with -r 1, the label maps, features, language fields, queries and evaluation use the photos at most this "
           "tall (LangSplat extracts its features at 1080 px); 0 uses train-rgb's size")
      .add("align-distance", &C::align_distance, "alignment check: distance threshold in city-model metres")
      .add("georef", &C::georef,
           "find the city transform before aligning (as `georef`): from the frame a Pix4D/OPF project names (frame), "
           "from the photos' EXIF GPS (gps), off, or auto (when no city transform is given: frame if the project "
           "names one, else gps if at least 3 photos carry a GPS position with an altitude)",
           R::Setting, choice_codec({"off", "frame", "gps", "auto"}))
      .add("crs", &C::crs, "with --georef: the city model's CRS (EPSG:N; default: its srsName / referenceSystem)",
           R::Setting)
      .per_scene()
      .add("align", &C::align,
           "refine the city transform from the sparse points before raycasting (as `align`): refine, off, or auto "
           "(refine, and use it when it moves the model by more than 5 cm)",
           R::Setting, choice_codec({"off", "refine", "auto"}))
      .include(provider_options(), &C::features, {"models", "clip", "sam"})
      .add("alpha", &C::alpha, "text-guidance weight of the CityGML features, in [0, 1]")
      .add("regions", &C::regions, "CityGML regions: class (one per class and view) or instance", R::Setting,
           choice_codec({"class", "instance"}))
      .add("rgb-model", &C::rgb_model, "import this 3DGS PLY instead of training the photometric model", R::Location)
      .per_scene()
      .add("rgb-iterations", &C::rgb_iterations, "photometric iterations; " + schedule_help(&Schedule::rgb_iterations))
      .add("language-iterations", &C::language_iterations,
           "language iterations per level; " + schedule_help(&Schedule::language_iterations))
      .add("autoencoder-epochs", &C::autoencoder_epochs,
           "autoencoder epochs; " + schedule_help(&Schedule::autoencoder_epochs))
      .add("lambda-sam", &C::lambda_sam, "weight of the SAM term in covered pixels")
      .add("lambda-citygml", &C::lambda_citygml, "weight of the CityGML term")
      .add("field", &C::field,
           "the language field of every method: dense (a latent per Gaussian, decoded by the autoencoder) or sparse "
           "(top-K weights over a codebook of CLIP-space bases, no decoder; docs/language.md)",
           R::Setting, choice_codec({"dense", "sparse"}))
      .add("codebook-size", &C::codebook_size, "sparse field: bases per level")
      .add("top-k", &C::top_k, "sparse field: weights per Gaussian and level")
      .add("baseline", &C::baselines,
           "baselines beside CityLangSplat, comma-separated: langsplat-original (the paper's baseline: LangSplat "
           "as published, its 3-d autoencoder and settings, normalised splatting), langsplat (an ablation: "
           "LangSplat's objective on CityLangSplat's 128-d autoencoder and splatting), or none",
           R::Setting, baselines_codec())
      .add("autoencoder", &C::autoencoder,
           "use this autoencoder (e.g. the one shared by all tiles, docs/scale.md) instead of training one",
           R::Location)
      .per_scene()
      .add("stop-after", &C::stop_after,
           "stop after this step (" + one_of(pipeline_step_names()) + "), or none",
           R::Control, [] {
             std::vector<std::string> names = pipeline_step_names();
             names.insert(names.begin(), "none");
             return choice_codec(names);
           }())
      .per_scene();
  return o;
}

}  // namespace

const OptionList<PipelineConfig>& pipeline_options() {
  static const OptionList<PipelineConfig> list = make_pipeline_options();
  return list;
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

namespace cls {

bool is_scene_config_option(const OptionList<PipelineConfig>::Binding& b) {
  return b.name == "city" || b.name == "city-transform" || b.name == "lod" || b.name == "taxonomy";
}

void apply_scene_config(const Args& args, const fs::path& config_file, PipelineConfig& config) {
  const fs::path file = config_file.empty() ? SceneFiles{config.scene_dir}.config() : config_file;
  if (!config_file.empty() && !fs::exists(file)) fail(file.string(), "config file not found");
  if (!fs::exists(file)) return;
  read_scene_config(file, config);
  pipeline_options().apply(args, config, is_scene_config_option);  // the command line over the file
}

}  // namespace cls
