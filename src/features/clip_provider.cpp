#include "features/clip_provider.h"

#include <torch/torch.h>

#include <cmath>
#include <set>

#include "core/error.h"
#include "core/log.h"
#include "models/clip/clip_loader.h"
#include "models/clip/clip_model.h"
#include "models/clip/region_encoder.h"
#include "models/clip/tokenizer.h"
#include "models/model_registry.h"
#include "models/sam/sam_model.h"
#include "models/sam/sam_predictor.h"
#include "models/sam_amg/automatic_mask_generator.h"
#include "models/sam_amg/langsplat_post.h"
#include "models/sam_amg/mask_rle.h"
#include "models/sam_amg/sam_amg_model.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

struct ClipProviderSetup {
  nlohmann::json spec;                 // what spec() returns
  std::string name;                    // "clip" | "clip-tiny"
  amg::AmgParams amg;
  amg::MaskNmsParams nms;              // masks_update
  int batch_size = 32;
};

class ClipFeatureProvider : public FeatureProvider {
 public:
  ClipFeatureProvider(ClipProviderSetup setup, clip::ClipModel clip, sam::Sam sam)
      : setup_(std::move(setup)), clip_(std::move(clip)), predictor_(std::move(sam)) {}

  std::string name() const override { return setup_.name; }
  nlohmann::json spec() const override { return setup_.spec; }
  int dim() const override { return clip_.config().arch.embed_dim; }

  SamSegments sam_segments(const FeatureView& view) override {
    const cv::Mat rgb = contiguous_rgb(view);
    amg::SamPredictorAmgModel model(predictor_);
    torch::NoGradGuard no_grad;
    const amg::MaskLevels raw = amg::generate_masks(model, rgb.data, rgb.rows, rgb.cols, setup_.amg);
    const amg::MasksUpdateResult kept = amg::masks_update(raw, setup_.nms);
    const amg::SegMap seg = amg::build_seg_map(kept.levels, rgb.rows, rgb.cols);
    // Features in the seg map's order: [default | s | m | l], each level's masks in list order.
    std::vector<at::Tensor> parts;
    for (int level = 0; level < amg::kNumLevels; ++level) {
      std::vector<cv::Mat> masks;
      for (const amg::MaskRecord& r : kept.levels[level]) masks.push_back(to_mat(amg::rle_to_mask(r.segmentation)));
      if (!masks.empty()) parts.push_back(clip::encode_regions(clip_, rgb, masks, setup_.batch_size));
    }
    SamSegments out;
    out.seg = seg.values;
    out.features = parts.empty() ? at::zeros({0, dim()}, at::kFloat) : at::cat(parts, 0).to(at::kFloat).contiguous();
    return out;
  }

  at::Tensor region_features(const FeatureView& view, const std::vector<RegionMask>& regions) override {
    if (regions.empty()) return at::zeros({0, dim()}, at::kFloat);
    const cv::Mat rgb = contiguous_rgb(view);
    std::vector<cv::Mat> masks;
    for (const RegionMask& r : regions) masks.push_back(r.mask);
    torch::NoGradGuard no_grad;
    return clip::encode_regions(clip_, rgb, masks, setup_.batch_size).to(at::kFloat).contiguous();
  }

  at::Tensor text_features(const std::vector<std::string>& texts) override {
    if (texts.empty()) return at::zeros({0, dim()}, at::kFloat);
    const int context = clip_.config().arch.context_length;
    const std::vector<int64_t> ids = tokenizer_.tokenize(texts, context);
    const at::Tensor tokens = at::tensor(ids, at::kLong).reshape({static_cast<int64_t>(texts.size()), context});
    torch::NoGradGuard no_grad;
    return clip::l2_normalize(clip_.encode_text(tokens.to(clip_.options().device))).to(at::kCPU, at::kFloat).contiguous();
  }

 private:
  static cv::Mat contiguous_rgb(const FeatureView& view) {
    if (view.rgb.type() != CV_8UC3 || view.rgb.empty()) throw Error(view.name + ": the image must be 8-bit RGB");
    return view.rgb.isContinuous() ? view.rgb : view.rgb.clone();
  }
  static cv::Mat to_mat(const amg::BinaryMask& m) {
    cv::Mat out(m.height, m.width, CV_8UC1);
    std::copy(m.pixels.begin(), m.pixels.end(), out.data);
    return out;
  }

  ClipProviderSetup setup_;
  clip::ClipModel clip_;
  sam::SamPredictor predictor_;
  clip::Tokenizer tokenizer_;
};

// "cpu", "cuda" or "auto" (CUDA when this LibTorch build and the machine have it).
c10::Device parse_device(const nlohmann::json& spec, std::string* name) {
  *name = spec.value("device", std::string("auto"));
  if (*name == "auto") *name = torch::cuda::is_available() ? "cuda" : "cpu";
  if (*name == "cpu") return c10::Device(c10::kCPU);
  if (*name == "cuda") {
    if (!torch::cuda::is_available()) throw Error("clip provider: device cuda requested but CUDA is not available");
    return c10::Device(c10::kCUDA);
  }
  throw Error("clip provider spec: device must be auto, cpu or cuda, not '" + *name + "'");
}

// ---- clip-tiny: random models built in code -------------------------------------------------

ClipArch tiny_clip_arch() {
  ClipArch a;
  a.name = "custom";
  a.embed_dim = 512;  // the real models' feature size, so later stages see the usual shapes
  a.image_resolution = 32;
  a.vision_layers = 1;
  a.vision_width = 64;
  a.vision_patch_size = 16;
  a.context_length = clip::kContextLength;
  a.vocab_size = 49408;  // the tokenizer's ids
  a.transformer_width = 64;
  a.transformer_layers = 1;
  return a;
}

sam::SamConfig tiny_sam_config() {
  sam::SamConfig c;
  c.name = "custom";
  c.encoder_embed_dim = 32;
  c.encoder_depth = 1;
  c.encoder_num_heads = 1;
  c.global_attn_indexes = {0};
  c.prompt_embed_dim = 32;
  c.mask_in_chans = 4;
  c.decoder_depth = 1;
  c.decoder_num_heads = 1;
  c.decoder_mlp_dim = 64;
  c.iou_head_hidden_dim = 32;
  return c;
}

std::unique_ptr<FeatureProvider> make_tiny(const nlohmann::json& spec) {
  for (const auto& [k, v] : spec.items()) {
    (void)v;
    if (k != "provider" && k != "seed" && k != "note" && k != "device") throw Error("clip-tiny provider spec: unknown key '" + k + "'");
  }
  const uint64_t seed = spec.value("seed", uint64_t(1));
  std::string device_name;
  const c10::Device device = parse_device(spec, &device_name);
  torch::manual_seed(seed);
  // CLIP: every tensor of the architecture drawn at random; LayerNorm scales near 1.
  const clip::ClipConfig config = clip::clip_config(tiny_clip_arch(), clip::Activation::Gelu);
  std::map<std::string, at::Tensor> state;
  for (const ExpectedTensor& t : clip_expected_tensors(config.arch)) {
    at::Tensor v = torch::randn(t.shape) * 0.05;
    const bool ln = t.name.find("ln_") != std::string::npos;
    if (ln && t.name.size() > 7 && t.name.compare(t.name.size() - 7, 7, ".weight") == 0) v = v + 1.0;
    if (t.name == "logit_scale") v = torch::full(t.shape, std::log(1 / 0.07));
    state[t.name] = v;
  }
  clip::ClipOptions clip_options;
  clip_options.device = device;
  clip::ClipModel clip(config, state, clip_options, "clip-tiny random weights");
  // SAM: LibTorch's default initialisation under the seed (drawn on the CPU, then moved).
  sam::Sam sam(tiny_sam_config());
  sam->eval();
  sam->to(device);

  ClipProviderSetup setup;
  setup.name = "clip-tiny";
  // A 4 x 4 point grid on the whole image, no quality filters: random models still yield masks.
  setup.amg.points_per_side = 4;
  setup.amg.points_per_batch = 16;
  setup.amg.pred_iou_thresh = 0.0;
  setup.amg.stability_score_thresh = 0.0;
  setup.amg.crop_n_layers = 0;
  setup.amg.min_mask_region_area = 0;
  setup.nms.score_thr = 0.0;
  setup.spec = {{"provider", "clip-tiny"},
                {"seed", seed},
                {"device", device_name},
                {"note", "tiny random models: results meaningless (a smoke test of the CLIP/SAM code path)"}};
  return std::make_unique<ClipFeatureProvider>(std::move(setup), std::move(clip), std::move(sam));
}

// ---- clip: real weights --------------------------------------------------------------------

std::string find_weights(const nlohmann::json& spec, const char* path_key, const char* name_key, const char* def_name,
                         const std::string& family, const KnownModel** known) {
  const std::string name = spec.value(name_key, std::string(def_name));
  *known = find_known_model(name);
  if (!*known || (*known)->family != family)
    throw UsageError(std::string("clip provider: '") + name + "' is not a known " + family +
                     " model (see `citylangsplat models list`)");
  if (spec.contains(path_key)) {
    const std::string p = spec.at(path_key).get<std::string>();
    if (!fs::is_regular_file(p)) fail(p, "weight file not found");
    return p;
  }
  const auto dirs = model_search_dirs(spec.value("models_dir", std::string()));
  if (const auto p = find_model_file(**known, dirs)) return p->string();
  std::string where;
  for (const auto& d : dirs) where += "\n  " + d.string();
  throw Error(std::string("clip provider: the ") + (*known)->description + " weights (" + (*known)->file_name +
              ") were not found in:" + where + "\nget them with `citylangsplat models download " + (*known)->name +
              "` (or put the file into one of these directories, or pass its path with --" + path_key + ")");
}

std::unique_ptr<FeatureProvider> make_real(const nlohmann::json& spec) {
  static const std::set<std::string> known_keys = {"provider",  "clip",       "sam",    "clip_model",
                                                   "sam_model", "clip_activation", "models_dir", "points_per_side",
                                                   "batch_size", "device", "note"};
  for (const auto& [k, v] : spec.items()) {
    (void)v;
    if (!known_keys.count(k)) throw Error("clip provider spec: unknown key '" + k + "'");
  }
  const KnownModel *clip_known = nullptr, *sam_known = nullptr;
  // Both looked up before either is loaded, so one message names everything missing first.
  std::string clip_path, sam_path, missing;
  try {
    clip_path = find_weights(spec, "clip", "clip_model", "openclip-vit-b-16-laion2b", "clip", &clip_known);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    missing = e.what();
  }
  try {
    sam_path = find_weights(spec, "sam", "sam_model", "sam-vit-h", "sam", &sam_known);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    missing += (missing.empty() ? "" : "\n") + std::string(e.what());
  }
  if (!missing.empty()) throw Error(missing);

  // OpenAI's CLIP uses QuickGELU, OpenCLIP's laion models exact GELU (not stored in the weights).
  const std::string act_name =
      spec.value("clip_activation", clip_known->name.rfind("openai", 0) == 0 ? std::string("quick_gelu") : "gelu");
  const clip::Activation act = clip::parse_activation(act_name);

  std::string device_name;
  const c10::Device device = parse_device(spec, &device_name);
  ClipProviderSetup setup;
  setup.name = "clip";
  setup.amg.points_per_side = spec.value("points_per_side", setup.amg.points_per_side);
  setup.batch_size = spec.value("batch_size", setup.batch_size);
  setup.spec = {{"provider", "clip"},
                {"clip", fs::absolute(clip_path).string()},
                {"clip_model", clip_known->name},
                {"clip_activation", act_name},
                {"sam", fs::absolute(sam_path).string()},
                {"sam_model", sam_known->name},
                {"points_per_side", setup.amg.points_per_side},
                {"batch_size", setup.batch_size},
                {"device", device_name}};
  log_info("features: loading CLIP " + clip_path + " and SAM " + sam_path);
  clip::ClipOptions clip_options;
  clip_options.device = device;
  clip::ClipModel clip =
      clip::load_clip_model(clip_path, act, clip::clip_config(clip_arch(clip_known->arch), act), clip_options);
  sam::Sam sam = sam::load_sam(sam_path, sam::sam_config_by_name(sam_known->arch));
  sam->to(device);
  return std::make_unique<ClipFeatureProvider>(std::move(setup), std::move(clip), std::move(sam));
}

}  // namespace

std::unique_ptr<FeatureProvider> make_clip_provider(const nlohmann::json& spec, const Taxonomy& /*taxonomy*/) {
  try {
    const std::string name = spec.at("provider").get<std::string>();
    if (name == "clip-tiny") return make_tiny(spec);
    if (name == "clip") return make_real(spec);
  } catch (const nlohmann::json::exception& e) {
    throw Error(std::string("clip provider spec: ") + e.what());
  }
  throw UsageError("make_clip_provider: provider must be clip or clip-tiny");
}

}  // namespace cls
