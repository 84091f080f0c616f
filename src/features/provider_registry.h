#pragma once
// Every feature provider by name, the one vocabulary of the model choice (`run --models`,
// `features --models`, run-tiles, model.json's "provider"): what each is, what every output made with it
// must say of itself, the schedule `run` gives it, how a user's options become its spec, and how a spec
// becomes the provider. A new provider is one entry here (docs/development.md, "A feature provider").
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "citymodel/taxonomy.h"
#include "core/option_list.h"
#include "features/feature_provider.h"

namespace cls {

// What a user chooses, as options (provider_options()): a provider's name, or "auto", and the settings
// its spec is made of.
struct ProviderChoice {
  std::string models = "clip";  // a name of feature_providers(), or kAutoModels
  uint64_t seed = 1;            // synthetic, image-segments, clip-tiny
  std::string device = "auto";  // clip, clip-tiny: auto (CUDA where available), cpu or cuda
  std::string clip, sam;        // clip: weight files (empty: searched, `citylangsplat models list`)
  std::string clip_model = "openclip-vit-b-16-laion2b", sam_model = "sam-vit-h";  // clip: which known models
  std::string models_dir;       // clip: searched first for weights
  std::string gt;               // image-segments: GT label images (empty: SCENE/gt/labels)
};

// "auto": real CLIP/SAM where both weight files are found, synthetic features otherwise (said wherever
// results are shown); weight files named explicitly make it "clip".
constexpr const char* kAutoModels = "auto";

// The iteration counts `run` gives a provider's features unless told otherwise.
struct Schedule {
  int rgb_iterations = 0, language_iterations = 0, autoencoder_epochs = 0;
};

struct FeatureProviderInfo {
  std::string name;
  std::string summary;  // one line of --help
  std::string warning;  // what every output made with it says of itself ("" for real CLIP)
  Schedule schedule;
  std::function<nlohmann::json(const ProviderChoice&, const std::string& scene_dir)> spec;
  std::function<std::unique_ptr<FeatureProvider>(const nlohmann::json& spec, const Taxonomy&)> create;
};

const std::vector<FeatureProviderInfo>& feature_providers();
// cls::UsageError "<what>: unknown feature provider 'x' (available: ...)".
const FeatureProviderInfo& feature_provider_info(const std::string& name, const std::string& what);
// "auto, clip, clip-tiny, synthetic or image-segments" and each one's summary, for --help.
std::string models_help();
// The codec of --models: a provider's name or auto.
Codec<std::string> models_codec();

// The options of the choice, declared once (`features` takes them all, `run` models, clip and sam).
const OptionList<ProviderChoice>& provider_options();

// The provider a choice makes, "auto" resolved. With real weights missing: no provider, and `missing`
// says what is missing and how to get it; `note` says when auto fell back to synthetic features.
struct ResolvedProvider {
  std::string name;  // never "auto"
  std::unique_ptr<FeatureProvider> provider;
  std::string missing, note;
};
ResolvedProvider resolve_provider(const ProviderChoice& choice, const std::string& scene_dir, const Taxonomy& taxonomy);

}  // namespace cls
