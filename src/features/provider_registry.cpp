#include "features/provider_registry.h"

#include <filesystem>

#include "core/error.h"
#include "core/run_layout.h"
#include "features/clip_provider.h"
#include "features/image_segment_provider.h"
#include "features/synthetic_provider.h"

namespace cls {
namespace {

constexpr const char* kWeightsHint =
    "get the weights with `citylangsplat models download openclip-vit-b-16-laion2b sam-vit-h` (see `citylangsplat "
    "models list`), or run the mechanics without them: --models synthetic (synthetic features) or --models clip-tiny "
    "(tiny random models)";

nlohmann::json seeded(const char* name, const ProviderChoice& c) { return {{"provider", name}, {"seed", c.seed}}; }

std::vector<FeatureProviderInfo> make_registry() {
  std::vector<FeatureProviderInfo> r;
  r.push_back({"clip", "SAM's automatic masks and CLIP features from the real weights (the method)", "",
               {30000, 30000, 100},
               [](const ProviderChoice& c, const std::string&) {
                 nlohmann::json spec = {{"provider", "clip"}, {"device", c.device},
                                        {"clip_model", c.clip_model}, {"sam_model", c.sam_model}};
                 if (!c.clip.empty()) spec["clip"] = c.clip;
                 if (!c.sam.empty()) spec["sam"] = c.sam;
                 if (!c.models_dir.empty()) spec["models_dir"] = c.models_dir;
                 return spec;
               },
               make_clip_provider});
  r.push_back({"clip-tiny", "tiny random CLIP and SAM models: a smoke test of the code path",
               "mechanics: tiny random CLIP/SAM models, a smoke test of the code path; every score is meaningless",
               {100, 20, 5},
               [](const ProviderChoice& c, const std::string&) {
                 nlohmann::json spec = seeded("clip-tiny", c);
                 spec["device"] = c.device;
                 return spec;
               },
               make_clip_provider});
  r.push_back({"synthetic", "deterministic stand-ins from the label maps: the mechanics benchmark",
               "mechanics: synthetic features, not CLIP (docs/features.md): a benchmark of the pipeline's mechanics, "
               "not a result of the method on real images",
               {1500, 300, 40},
               [](const ProviderChoice& c, const std::string&) { return seeded("synthetic", c); },
               [](const nlohmann::json& spec, const Taxonomy& taxonomy) -> std::unique_ptr<FeatureProvider> {
                 return std::make_unique<SyntheticFeatureProvider>(SyntheticFeatureProvider::params_from_spec(spec),
                                                                   taxonomy);
               }});
  r.push_back({"image-segments",
               "segments of the images, features from the ground truth under them (SCENE/gt/labels): the robustness "
               "benchmark",
               "robustness benchmark: segments of the images, features from the exact ground truth under them, not "
               "CLIP/SAM (docs/features.md)",
               {1500, 300, 40},
               [](const ProviderChoice& c, const std::string& scene_dir) {
                 nlohmann::json spec = seeded("image-segments", c);
                 // Absolute: the same scene named relatively or absolutely is the same provider (its stages reused).
                 const std::filesystem::path gt = c.gt.empty() ? SceneFiles{scene_dir}.gt_labels() : std::filesystem::path(c.gt);
                 spec["gt"] = std::filesystem::absolute(gt).lexically_normal().string();
                 return spec;
               },
               [](const nlohmann::json& spec, const Taxonomy& taxonomy) -> std::unique_ptr<FeatureProvider> {
                 return std::make_unique<ImageSegmentProvider>(ImageSegmentProvider::params_from_spec(spec), taxonomy);
               }});
  return r;
}

std::vector<std::string> choice_names() {
  std::vector<std::string> names = {kAutoModels};
  for (const FeatureProviderInfo& p : feature_providers()) names.push_back(p.name);
  return names;
}

}  // namespace

const std::vector<FeatureProviderInfo>& feature_providers() {
  static const std::vector<FeatureProviderInfo> registry = make_registry();
  return registry;
}

const FeatureProviderInfo& feature_provider_info(const std::string& name, const std::string& what) {
  std::vector<std::string> names;
  for (const FeatureProviderInfo& p : feature_providers()) {
    if (p.name == name) return p;
    names.push_back(p.name);
  }
  throw UsageError(what + ": unknown feature provider '" + name + "' (available: " + one_of(names) + ")");
}

std::string models_help() {
  std::string s = "which features: auto (clip where both weight files are found, else synthetic, said in every "
                  "output)";
  for (const FeatureProviderInfo& p : feature_providers()) s += ", " + p.name + " (" + p.summary + ")";
  return s;
}

Codec<std::string> models_codec() { return choice_codec(choice_names()); }

const OptionList<ProviderChoice>& provider_options() {
  static const OptionList<ProviderChoice> list = [] {
    OptionList<ProviderChoice> o;
    o.add("models", &ProviderChoice::models, models_help(), OptionRole::Setting, models_codec())
        .add("seed", &ProviderChoice::seed, "seed of the synthetic, image-segments and clip-tiny providers")
        .add("device", &ProviderChoice::device, "clip, clip-tiny: auto (CUDA where available), cpu or cuda",
             OptionRole::Control)
        .add("clip", &ProviderChoice::clip, "CLIP weights file (default: searched, see `models list`)",
             OptionRole::Location)
        .add("sam", &ProviderChoice::sam, "SAM weights file (default: searched, see `models list`)",
             OptionRole::Location)
        .add("clip-model", &ProviderChoice::clip_model, "which known CLIP model (see `models list`)")
        .add("sam-model", &ProviderChoice::sam_model, "which known SAM model (see `models list`)")
        .add("models-dir", &ProviderChoice::models_dir,
             "directory searched first for weights (then $CITYLANGSPLAT_MODELS, the XDG cache)", OptionRole::Location)
        .add("gt", &ProviderChoice::gt,
             "image-segments: ground-truth label images named as the views (default: SCENE/gt/labels)",
             OptionRole::Location);
    return o;
  }();
  return list;
}

ResolvedProvider resolve_provider(const ProviderChoice& choice, const std::string& scene_dir, const Taxonomy& taxonomy) {
  ResolvedProvider r;
  r.name = choice.models;
  // Weight files named on the command line are a request for the real models: a typo or a broken file
  // must fail, not turn quietly into a synthetic run.
  if (r.name == kAutoModels && (!choice.clip.empty() || !choice.sam.empty())) r.name = "clip";
  if (r.name == kAutoModels || r.name == "clip") {
    try {
      r.provider = feature_provider_info("clip", "models").create(
          feature_provider_info("clip", "models").spec(choice, scene_dir), taxonomy);
      r.name = "clip";
      return r;
    } catch (const UsageError&) {
      throw;
    } catch (const Error& e) {
      if (r.name == "clip") {
        r.missing = std::string(e.what()) + "; " + kWeightsHint;
        return r;
      }
      r.note = std::string("no CLIP/SAM weights found (") + e.what() +
               "): running every stage with synthetic features instead. For the method itself, " + kWeightsHint;
      r.name = "synthetic";
    }
  }
  const FeatureProviderInfo& info = feature_provider_info(r.name, "models");
  r.provider = info.create(info.spec(choice, scene_dir), taxonomy);
  return r;
}

}  // namespace cls
