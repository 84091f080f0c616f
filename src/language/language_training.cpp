// Language training (paper 3.3) on a frozen photometric model; see language_training.h.
//
// Choices beyond the paper, as LangSplat's train.py makes them unless said otherwise:
//  - latents start at zero (LangSplat's language_feature init; the sparse field's logits start lifted from
//    the targets, sparse_lifting.h), one N x L tensor per level, trained one level after the other
//    (LangSplat trains one model per feature level);
//  - Adam (eps 1e-15 as 3DGS/LangSplat), constant lr;
//  - views in a random order without replacement per epoch (LangSplat pops random cameras from a
//    stack). The order of epoch e at level l is a pure function of (seed, l, e), so the "RNG state"
//    of a resume is the (level, iteration) pair itself and a resumed run repeats the exact order;
//  - the rendered background is zero;
//  - M_t (the coverage) is taken from the CityGML seg maps: a pixel is covered when any level has a
//    region there (docs/conventions.md: coverage is 255 where any level has a label, and the
//    features stage writes -1 wherever M = 0).
// Only the per-segment latents (the encoder applied once per view) and the seg maps are kept in
// memory; the loss runs straight from the seg maps (language_loss_from_seg; the sparse field's cosine:
// sparse_cosine_loss), on the CPU or a GPU.
#include "language/language_training.h"

#include <ATen/ATen.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "core/metrics_log.h"
#include "core/progress.h"
#include "core/run_layout.h"
#include "features/view_features.h"
#include "language/language_loss.h"
#include "language/language_model.h"
#include "language/provenance.h"
#include "language/sparse_field.h"
#include "language/sparse_lifting.h"
#include "language/sparse_loss.h"
#include "scene/view_selection.h"
#include "splat/compute_device.h"
#include "splat/adam.h"
#include "splat/checkpoint.h"
#include "splat/ply_gaussians.h"
#include "splat/rasterize.h"
#include "splat/view_blend_caches.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

constexpr int kLevels = 3;

// What training needs of one view: the camera, the seg maps and the encoded segment latents. Held for
// every training view at once, so compact: the seg maps are int16 when their ids fit (they index the
// view's segments and regions, a few hundred), the coverage one byte a pixel. 200 photos at 1440x1080
// took 9.6 GB as int32 maps with a float coverage (docs/benchmarks.md), 13 of 32 bytes a pixel now.
struct ViewTargets {
  size_t view = 0;  // index into scene.views
  std::string stem;
  int height = 0, width = 0;
  at::Tensor seg;          // 6 x H x W, int16 or int32 (CPU): SAM's levels s, m, l, then CityGML's 1, 2, 3
  at::Tensor sam_latents;  // N x L (device)
  at::Tensor gml_latents;  // R x L (device)
  at::Tensor coverage;     // H x W uint8 0/1 (device)

  // The int32 H x W maps the loss reads at a level (1..3).
  at::Tensor sam_map(int level) const { return seg[level - 1].to(at::kInt); }
  at::Tensor gml_map(int level) const { return seg[2 + level].to(at::kInt); }
};

// SAM's maps 1..3 (its default level 0 is no level's target) and CityGML's three, as int16 when every id fits.
at::Tensor compact_seg_maps(std::vector<int32_t>& sam_seg, std::vector<int32_t>& gml_seg, int height, int width) {
  const at::Tensor maps = at::cat({at::from_blob(sam_seg.data(), {4, height, width}, at::kInt).slice(0, 1, 4),
                                   at::from_blob(gml_seg.data(), {3, height, width}, at::kInt)}, 0);
  const bool fits = maps.min().item<int32_t>() >= INT16_MIN && maps.max().item<int32_t>() <= INT16_MAX;
  return fits ? maps.to(at::kShort) : maps;
}

// The targets in the space the field is trained in: the autoencoder's latents (dense), or the features
// themselves (sparse: no autoencoder). `dim`: the features' size, for an empty table.
at::Tensor target_rows(const Autoencoder* ae, const at::Tensor& features, int64_t dim, at::Device device) {
  if (!features.defined() || features.size(0) == 0)
    return at::zeros({0, ae ? int64_t(ae->config().latent_dim()) : dim}, at::kFloat).to(device);
  if (!ae) return features.to(at::kFloat).contiguous().to(device);
  return ae->encode(features.to(at::kFloat)).detach().to(at::kCPU).contiguous().to(device);
}

// The features' size for the sparse field (no autoencoder to say it): the provider's recorded "dim", else
// the first view's SAM table.
int64_t provider_dim(const nlohmann::json& provider, const std::string& features_dir) {
  if (provider.is_object() && provider.contains("dim") && provider["dim"].is_number_integer()) return provider["dim"].get<int64_t>();
  for (const auto& entry : fs::directory_iterator(features_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 6 && name.compare(name.size() - 6, 6, "_f.npy") == 0) {
      const std::string stem = name.substr(0, name.size() - 6);
      if (!view_features_complete(features_dir, stem)) continue;
      const ViewFeatures f = read_view_features(features_dir, stem);
      if (f.sam_features.defined() && f.sam_features.dim() == 2) return f.sam_features.size(1);
    }
  }
  fail(features_dir, "no view's features say their size (run `citylangsplat features`)");
}

bool held_out_all(const Scene& scene, int test_every) { return split_views(scene, test_every).train.empty(); }

// ae: null for the sparse field; `dim`: the features' size.
std::vector<ViewTargets> load_targets(const Scene& scene, const LanguageTrainOptions& o, const Autoencoder* ae,
                                      int64_t dim, at::Device device) {
  std::vector<ViewTargets> views;
  std::set<const SceneView*> held_out;
  for (const SceneView* v : split_views(scene, o.test_every).test) held_out.insert(v);
  Progress progress("language targets", scene.views.size(), "views");
  for (size_t i = 0; i < scene.views.size(); ++i) {
    const SceneView& sv = scene.views[i];
    const std::string stem = fs::path(sv.name).stem().string();
    progress.advance();
    if (held_out.count(&sv)) continue;
    if (!view_features_complete(o.features_dir, stem)) {
      log_warn(cat("language training: no features for view ", sv.name, " in ", o.features_dir, "; skipped"));
      continue;
    }
    ViewFeatures f = read_view_features(o.features_dir, stem);
    const std::string what = (fs::path(o.features_dir) / (stem + "_s.npy")).string();
    f.validate(what);
    if (f.height != sv.camera.height || f.width != sv.camera.width)
      fail(what, cat("features are ", f.width, " x ", f.height, " but the scene loads view ", sv.name, " at ",
                     sv.camera.width, " x ", sv.camera.height, " (match --resolution to the features stage)"));
    const std::string taker = ae ? "the autoencoder takes " : "the provider gives ";
    if (f.sam_features.defined() && f.sam_features.size(0) > 0 && f.sam_features.size(1) != dim)
      fail(what, cat("SAM features have ", f.sam_features.size(1), " channels, ", taker, dim));
    if (f.gml_features.defined() && f.gml_features.size(0) > 0 && f.gml_features.size(1) != dim)
      fail(what, cat("CityGML features have ", f.gml_features.size(1), " channels, ", taker, dim));
    ViewTargets t;
    t.view = i;
    t.stem = stem;
    t.height = f.height;
    t.width = f.width;
    t.sam_latents = target_rows(ae, f.sam_features, dim, device);
    t.gml_latents = target_rows(ae, f.gml_features, dim, device);
    const size_t hw = size_t(t.height) * t.width;
    at::Tensor m = at::zeros({t.height, t.width}, at::kByte);
    uint8_t* mp = m.data_ptr<uint8_t>();
    for (int l = 0; l < kLevels; ++l)
      for (size_t p = 0; p < hw; ++p)
        if (f.gml_seg[l * hw + p] >= 0) mp[p] = 1;
    t.coverage = m.to(device);
    t.seg = compact_seg_maps(f.sam_seg, f.gml_seg, t.height, t.width);
    views.push_back(std::move(t));
  }
  progress.finish();
  if (views.empty() && !held_out_all(scene, o.test_every))
    fail(o.features_dir, "no view of the scene has complete features (run `citylangsplat features`)");
  if (views.empty())
    throw UsageError(cat("language training: holding out every ", o.test_every, "-th view leaves none of the scene's ",
                         scene.views.size(), " views to train on (train-language --test-every 0 trains on all)"));
  return views;
}

// Fisher-Yates with the raw engine (std::shuffle's distribution is implementation-defined).
std::vector<int> epoch_order(uint64_t seed, int level, int64_t epoch, int n) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + uint64_t(level) * 0x100000001B3ull + uint64_t(epoch));
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  for (int i = n - 1; i > 0; --i) std::swap(order[i], order[rng() % uint64_t(i + 1)]);
  return order;
}

std::string adam_name(int level) { return "latents_l" + std::to_string(level); }
std::string codebook_name(int level) { return "codebook_l" + std::to_string(level); }

// The sparse field's first codebook of a level: k-means (LangSplatV2's start) over the targets the level is
// trained towards, the SAM segments and CityGML regions its seg maps name in every training view.
at::Tensor initial_codebook(const std::vector<ViewTargets>& views, int size, uint64_t seed, int level) {
  std::vector<at::Tensor> rows;
  for (const ViewTargets& v : views)
    for (const auto& [map, table] : {std::pair{v.sam_map(level), v.sam_latents}, std::pair{v.gml_map(level), v.gml_latents}}) {
      const at::Tensor ids = std::get<0>(at::_unique(map.reshape({-1})));
      const at::Tensor used = ids.masked_select(ids >= 0).to(at::kLong);
      if (used.numel() > 0) rows.push_back(table.cpu().index_select(0, used));
    }
  if (rows.empty()) throw Error(cat("language training: no target features at level ", level, " to start the sparse field's codebook from"));
  return kmeans_codebook(at::cat(rows, 0), size, seed * 0x9E3779B97F4A7C15ull + uint64_t(level));
}

// A training view's camera and pose as the rasterizer takes them (zero background).
RasterizeSettings view_settings(const SceneView& view) {
  RasterizeSettings settings;
  settings.camera = view.camera;
  settings.pose = view.pose;
  return settings;
}

// What a Gaussian splats of its latent: the latent, or LangSplat's latent / (|latent| + 1e-9).
at::Tensor splatted(const at::Tensor& latents, const LanguageTrainOptions& o) {
  return o.normalize_latents ? latents / (latents.norm(2, {1}, true) + 1e-9) : latents;
}

// Everything that must agree between a checkpoint and the run that resumes it.
nlohmann::json run_config(const LanguageTrainOptions& o, int64_t n, int latent, size_t views) {
  // The baseline's objective has no lambdas: record the weights it uses, so that --lambda-* do not
  // keep its checkpoint from resuming.
  nlohmann::json c = {{"seed", o.seed},
          {"baseline", o.baseline},
          {"normalize_latents", o.normalize_latents},
          {"lambda_sam", o.baseline ? 1.0 : o.lambda_sam},
          {"lambda_citygml", o.baseline ? 0.0 : o.lambda_citygml},
          {"lr", o.lr},
          {"gaussians", n},
          {"latent_dim", latent},
          {"views", views},
          {"iterations", o.iterations}};
  if (o.field == "sparse") {
    c["field"] = o.field, c["codebook_size"] = o.codebook_size, c["top_k"] = o.top_k, c["codebook_lr"] = o.codebook_lr, c["logit_lr"] = o.logit_lr,
    c["sparse_warmup"] = o.sparse_warmup;
    // Only when lifting: a checkpoint from before the lifted start resumes with --lift-temperature 0.
    if (o.lift_temperature > 0) c["lift_temperature"] = o.lift_temperature;
    // Likewise: a checkpoint from before the cosine distance resumes with --sparse-distance l1.
    if (o.sparse_distance != "l1") c["sparse_distance"] = o.sparse_distance;
  }
  return c;
}

struct TrainState {
  int level = 1;          // 1..3
  int64_t iteration = 0;  // iterations done at `level`
  int64_t total = 0;      // iterations done over all levels
  double ema_loss = 0;
  std::array<double, 3> final_loss{0, 0, 0};
  std::array<at::Tensor, 3> latents;    // finished levels and the current one (sparse: the N x L logits)
  std::array<at::Tensor, 3> codebooks;  // sparse: L x D per level
};

void save_checkpoint(const std::string& path, const TrainState& s, const Adam& adam, const nlohmann::json& config) {
  Checkpoint c;
  for (int l = 0; l < kLevels; ++l)
    for (const auto& [name, t] : {std::pair{"latents", &s.latents[l]}, std::pair{"codebook", &s.codebooks[l]}})
      if (t->defined()) c.tensors[std::string(name) + ".level" + std::to_string(l + 1)] = t->detach().cpu().contiguous();
  for (const auto& [name, t] : adam.state_tensors()) c.tensors[name] = t.detach().cpu().contiguous();
  c.info = {{"kind", "language"},
            {"level", s.level},
            {"iteration", s.iteration},
            {"total", s.total},
            {"ema_loss", s.ema_loss},
            {"final_loss", s.final_loss},
            {"adam", adam.state_scalars()},
            {"config", config}};
  fs::create_directories(fs::path(path).parent_path());
  write_checkpoint(path, c);
}


// The city objects of the label maps the features were made from, one per Gaussian (provenance.h).
// Label maps without object maps (hand-made, or from before them) give a model without provenance.
void attach_city_objects(LanguageModel& model, const Scene& scene, const fs::path& labels_dir) {
  if (labels_dir.empty() || !fs::exists(labels_dir / "objects.json")) {
    log_info("language training: no objects.json beside the label maps" +
             (labels_dir.empty() ? std::string() : " (" + labels_dir.string() + ")") +
             ": the model records no city object per Gaussian (`query --objects` and the viewer's object list need "
             "label maps from this version's `raycast`)");
    return;
  }
  const ProvenanceSettings settings;
  const GaussianProvenance provenance = assign_provenance(model.gaussians, scene, labels_dir, settings);
  attach_provenance(model.gaussians, provenance);
  model.objects = read_city_objects(labels_dir / "objects.json");
  model.info["provenance"] = provenance.summary(settings);
  log_info(cat("language training: ", provenance.assigned, " of ", model.gaussians.size(),
               " Gaussians lie on a city object (majority over ", provenance.views, " views)"));
}

}  // namespace

const OptionList<LanguageTrainOptions>& language_train_options() {
  using O = LanguageTrainOptions;
  using R = OptionRole;
  static const OptionList<O> list = [] {
    OptionList<O> o;
    o.add("model", &O::geometry_ply,
          "photometric model: train-rgb's point_cloud.ply or any 3DGS PLY (geometry stays frozen)", R::Location)
        .required()
        .add("features", &O::features_dir, "features stage output directory (per-view *_s.npy / *_f.npy / *_gml_*.npy)",
             R::Location)
        .required()
        .add("autoencoder", &O::autoencoder_path,
             "the shared autoencoder (`autoencoder` output, .safetensors); the dense field's, the sparse field takes none",
             R::Location)
        .add("out", &O::out_dir, "output model directory (model.json, point_cloud.ply, latents, autoencoder, checkpoints/)",
             R::Location)
        .required()
        .add("iterations", &O::iterations, "iterations per level")
        .add("lr", &O::lr, "Adam learning rate of the dense field's latents (LangSplat's)")
        .add("lambda-sam", &O::lambda_sam, "weight of the SAM term inside CityGML coverage")
        .add("lambda-citygml", &O::lambda_citygml, "weight of the CityGML term inside coverage")
        .add("normalize-latents", &O::normalize_latents,
             "LangSplat's splatting: each Gaussian's latent divided by its norm before it is splatted (default: raw "
             "latents; docs/language.md measures both)")
        .add("field", &O::field,
             "dense (a latent per Gaussian and level, decoded by the autoencoder) or sparse (top-K weights over a "
             "codebook of CLIP-space bases per level, no decoder; docs/language.md)")
        .add("codebook-size", &O::codebook_size, "sparse field: bases per level (L)")
        .add("top-k", &O::top_k, "sparse field: weights per Gaussian and level (K)")
        .add("sparse-warmup", &O::sparse_warmup,
             "sparse field: share of each level's iterations that splat the softmax over all bases before the top K")
        .add("lift-temperature", &O::lift_temperature,
             "sparse field: the first logits are each basis's mean cosine with the targets a Gaussian is blended "
             "into, divided by this, plus a seeded 0.01 jitter (0: the jitter alone)")
        .add("sparse-distance", &O::sparse_distance,
             "sparse field: the distance in the paper's loss, in CLIP space: cosine (1 - cos, LangSplatV2's; taken in "
             "the L-d weight space through the codebook's Gram matrix) or l1 (the paper's, on the D-d features)")
        .add("logit-lr", &O::logit_lr, "sparse field: Adam learning rate of the weights' logits")
        .add("codebook-lr", &O::codebook_lr, "sparse field: Adam learning rate of the codebook")
        .add("checkpoint-every", &O::checkpoint_every, "iterations between checkpoints (0 = only on interrupt)",
             R::Control)
        .add("resume", &O::resume, "continue from OUT/checkpoints/language.safetensors if present", R::Control)
        .add("seed", &O::seed, "seed of the view order")
        .add("test-every", &O::test_every,
             "leave every this-th view (sorted by name) out of training, as train-rgb: the views `evaluate` scores in "
             "2D (0 = train on all)")
        .add("device", &O::device, "auto, cpu or cuda", R::Control)
        .add("blend-cache-mb", &O::blend_cache_mb,
             "CPU: memory (MiB) for the frozen Gaussians' blend weights per view, recorded on a view's first iteration "
             "and read on its later ones instead of blending (the same results, within float rounding; views beyond it "
             "blend every iteration; 0: all do; at most a quarter of the machine's memory)",
             R::Control);
    return o;
  }();
  return list;
}

LanguageTrainReport train_language(const Scene& scene, const LanguageTrainOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.iterations < 1) throw UsageError("--iterations must be at least 1");
  if (o.lr <= 0) throw UsageError("--lr must be positive");
  if (!(o.sparse_warmup >= 0 && o.sparse_warmup <= 1)) throw UsageError("--sparse-warmup must lie in [0, 1]");
  if (o.blend_cache_mb < 0) throw UsageError("--blend-cache-mb must be 0 or more");
  if (!(o.logit_lr > 0)) throw UsageError("--logit-lr must be positive");
  if (!(o.lift_temperature >= 0)) throw UsageError("--lift-temperature must be 0 (off) or positive");
  if (o.sparse_distance != "l1" && o.sparse_distance != "cosine")
    throw UsageError("--sparse-distance must be l1 or cosine, got '" + o.sparse_distance + "'");
  if (o.codebook_lr < 0) throw UsageError("--codebook-lr must not be negative (0: the codebook stays as initialised)");
  const at::Device device = compute_device(o.device);
  install_interrupt_handlers();

  // Frozen geometry: activated parameters without gradients.
  const GaussianModel geometry = read_gaussians_ply(o.geometry_ply);
  geometry.validate(o.geometry_ply);
  const int64_t n = geometry.size();
  if (n == 0) fail(o.geometry_ply, "has no Gaussians");
  const at::Tensor means = geometry.means.detach().to(device, at::kFloat).contiguous();
  const at::Tensor scales = geometry.scales().detach().to(device, at::kFloat).contiguous();
  const at::Tensor quats = geometry.quats.detach().to(device, at::kFloat).contiguous();
  const at::Tensor opacities = geometry.opacities().detach().to(device, at::kFloat).contiguous();

  const bool sparse = o.field == "sparse";
  if (o.field != "dense" && !sparse) throw UsageError("--field must be dense or sparse, got '" + o.field + "'");
  if (sparse && (o.codebook_size < 1 || o.top_k < 1 || o.top_k > o.codebook_size))
    throw UsageError(cat("--top-k must lie in [1, --codebook-size] and --codebook-size be positive, got ", o.top_k, " and ",
                         o.codebook_size));
  if (sparse && o.normalize_latents)
    throw UsageError("--normalize-latents is LangSplat's splatting of dense latents; the sparse field splats softmax weights");
  if (!sparse && o.autoencoder_path.empty()) throw UsageError("--autoencoder is needed for the dense field");
  std::optional<Autoencoder> autoencoder;
  if (!sparse) autoencoder = Autoencoder::load(o.autoencoder_path);
  const int latent = sparse ? o.codebook_size : autoencoder->config().latent_dim();

  nlohmann::json provider = nullptr, taxonomy = nullptr;
  fs::path labels_dir;  // for the city-object provenance
  const fs::path features_json = fs::path(o.features_dir) / "features.json";
  if (fs::exists(features_json)) {
    try {
      const nlohmann::json fj = nlohmann::json::parse(read_text_file(features_json));
      if (fj.contains("provider")) provider = fj["provider"];
      else if (fj.contains("spec")) provider = fj["spec"];
      if (fj.contains("taxonomy")) taxonomy = fj["taxonomy"];  // the class legend, for query / evaluate
      if (fj.contains("labels_dir")) labels_dir = fj["labels_dir"].get<std::string>();
    } catch (const nlohmann::json::exception& e) {
      fail(features_json.string(), std::string("not valid JSON: ") + e.what());
    }
  } else {
    log_warn(cat("language training: ", features_json.string(), " missing; the provider is not recorded"));
  }

  const std::vector<ViewTargets> views =
      load_targets(scene, o, autoencoder ? &*autoencoder : nullptr, sparse ? provider_dim(provider, o.features_dir)
                                                                             : autoencoder->config().input_dim, device);
  const int nviews = int(views.size());
  const nlohmann::json config = run_config(o, n, latent, views.size());
  const std::string checkpoint_path = (RunLayout::checkpoints(o.out_dir) / "language.safetensors").string();

  TrainState s;
  Adam adam(0.9, 0.999, 1e-15);
  bool restored = false;
  Checkpoint resume_from;
  if (o.resume && fs::exists(checkpoint_path)) {
    resume_from = read_checkpoint(checkpoint_path);
    const nlohmann::json& info = resume_from.info;
    if (info.value("kind", "") != "language") fail(checkpoint_path, "not a language-training checkpoint");
    if (info.value("config", nlohmann::json()) != config)
      fail(checkpoint_path, "was written with other settings or inputs: " + info.value("config", nlohmann::json()).dump() +
                                " vs now " + config.dump() + " (start without --resume, or restore those settings)");
    s.level = info.at("level").get<int>();
    s.iteration = info.at("iteration").get<int64_t>();
    s.total = info.at("total").get<int64_t>();
    s.ema_loss = info.at("ema_loss").get<double>();
    s.final_loss = info.at("final_loss").get<std::array<double, 3>>();
    for (int l = 0; l < kLevels; ++l) {
      const auto it = resume_from.tensors.find("latents.level" + std::to_string(l + 1));
      if (it == resume_from.tensors.end()) continue;
      if (it->second.dim() != 2 || it->second.size(0) != n || it->second.size(1) != latent)
        fail(checkpoint_path, "tensor 'latents.level" + std::to_string(l + 1) + "' has the wrong shape");
      s.latents[l] = it->second.to(device, at::kFloat).clone();
      if (!sparse) continue;
      const auto book = resume_from.tensors.find("codebook.level" + std::to_string(l + 1));
      if (book == resume_from.tensors.end() || book->second.dim() != 2 || book->second.size(0) != latent)
        fail(checkpoint_path, "no codebook of " + std::to_string(latent) + " bases for level " + std::to_string(l + 1));
      s.codebooks[l] = book->second.to(device, at::kFloat).clone();
    }
    if (s.level < 1 || s.level > kLevels || !s.latents[s.level - 1].defined())
      fail(checkpoint_path, "inconsistent level / latents");
    restored = true;
    log_info(cat("language training: resuming at level ", s.level, ", iteration ", s.iteration));
  } else if (o.resume) {
    log_info(cat("language training: no checkpoint at ", checkpoint_path, "; starting from scratch"));
  }

  // The curves: a row every metrics_every iterations of a level and at its last. A resume drops the rows
  // a killed run wrote after its checkpoint and continues the clock of the last row kept.
  const fs::path metrics_path = fs::path(o.out_dir) / "metrics.jsonl";
  auto up_to_checkpoint = [&](const nlohmann::json& row) {
    const int level = row.value("level", 0);
    return level < s.level || (level == s.level && row.value("iteration", int64_t(0)) <= s.iteration);
  };
  MetricsLog metrics = restored ? MetricsLog::resume(metrics_path, up_to_checkpoint) : MetricsLog::start(metrics_path);
  const int64_t metrics_every = metrics_interval(o.iterations);
  const double earlier_seconds = metrics.last().is_object() ? metrics.last().value("seconds", 0.0) : 0.0;

  LanguageTrainReport report;
  const LanguageLossWeights weights{o.lambda_sam, o.lambda_citygml, o.baseline};
  // The geometry is frozen: on the CPU each view's blend weights are recorded once and read by every level,
  // within --blend-cache-mb and at most a quarter of the machine's memory (a default that fits a workstation
  // must not push a small machine into swap).
  const size_t physical = size_t(std::max(0L, sysconf(_SC_PHYS_PAGES))) * size_t(std::max(0L, sysconf(_SC_PAGE_SIZE)));
  const size_t blend_budget = std::min(size_t(o.blend_cache_mb) << 20, physical > 0 ? physical / 4 : SIZE_MAX);
  ViewBlendCaches blend_caches(nviews, device.is_cpu() ? blend_budget : 0);
  for (int level = s.level; level <= kLevels; ++level) {
    if (level != s.level) {  // a new level
      s.level = level;
      s.iteration = 0;
      s.ema_loss = 0;
    }
    at::Tensor& latents = s.latents[level - 1];
    at::Tensor& codebook = s.codebooks[level - 1];
    if (!latents.defined() && sparse) {
      // A seeded jitter near zero, then (unless --lift-temperature 0) what the targets say of each Gaussian
      // (sparse_lifting.h). The jitter decides the K bases of a Gaussian no pixel sees (all-equal logits would
      // give every such Gaussian the same K).
      std::mt19937_64 rng(o.seed * 0x100000001B3ull + uint64_t(level));
      latents = normal_noise(n, latent, 0.01f, rng).to(device);
      codebook = initial_codebook(views, o.codebook_size, o.seed, level).to(device);
      if (o.lift_temperature > 0) {
        auto view = [&](int64_t i) {
          const ViewTargets& v = views[size_t(i)];
          return LiftingView{view_settings(scene.views[v.view]), {v.sam_map(level), v.sam_latents},
                             {v.gml_map(level), v.gml_latents}, v.coverage};
        };
        latents += lifted_logits(means, scales, quats, opacities, nviews, view, codebook, weights, o.lift_temperature);
      }
    }
    if (!latents.defined()) latents = at::zeros({n, int64_t(latent)}, at::TensorOptions(device).dtype(at::kFloat));
    latents = latents.detach().requires_grad_(true);
    adam = Adam(0.9, 0.999, 1e-15);
    adam.add(adam_name(level), latents, sparse ? o.logit_lr : o.lr);
    if (sparse) {
      codebook = codebook.detach().requires_grad_(true);
      adam.add(codebook_name(level), codebook, o.codebook_lr);
    }
    if (restored) {
      std::map<std::string, at::Tensor> tensors;
      for (const auto& [name, t] : resume_from.tensors)
        if (name.rfind("adam.", 0) == 0) tensors[name] = t.to(device);
      std::map<std::string, double> scalars = resume_from.info.at("adam").get<std::map<std::string, double>>();
      adam.restore(tensors, scalars, checkpoint_path);
      restored = false;
    }

    Progress progress(cat("language level ", level), uint64_t(std::max<int64_t>(0, o.iterations - s.iteration)), "it");
    const int64_t log_every = std::max<int64_t>(1, o.iterations / 20);
    std::vector<int> order;
    int64_t order_epoch = -1;
    while (s.iteration < o.iterations) {
      const int64_t epoch = s.iteration / nviews;
      if (epoch != order_epoch) order = epoch_order(o.seed, level, epoch, nviews), order_epoch = epoch;
      const int view_index = order[s.iteration % nviews];
      const ViewTargets& v = views[view_index];
      RasterizeSettings settings = view_settings(scene.views[v.view]);
      settings.blend_cache = blend_caches.settings_for(view_index);
      const SegMapTarget sam_target{v.sam_map(level), v.sam_latents}, gml_target{v.gml_map(level), v.gml_latents};
      LanguageLoss loss;
      if (sparse) {  // the rendered weights times the codebook: the features the targets are compared with
        const at::Tensor& logits = adam.group(adam_name(level)).param;
        const at::Tensor& book = adam.group(codebook_name(level)).param;
        const bool cosine = o.sparse_distance == "cosine";
        // The first iterations splat the softmax over all bases, so that every logit learns which bases fit
        // before the top K are kept (from random logits a Gaussian's K would hold the right basis by chance).
        at::Tensor map;
        if (s.iteration < int64_t(o.sparse_warmup * o.iterations)) {
          map = rasterize_features(means, scales, quats, opacities, at::softmax(logits, 1), at::Tensor(), settings).image;
        } else {
          const SparseWeights w = top_k_softmax(logits, o.top_k);
          if (cosine && settings.blend_cache && blend_cache_bytes(*settings.blend_cache) > 0)  // the view's weights:
            loss = sparse_cosine_loss_recorded(means, scales, quats, opacities, w.weights, w.indices, settings, book,
                                               sam_target, gml_target, v.coverage, weights);  // map and loss at once
          else
            map = rasterize_sparse_features(means, scales, quats, opacities, w.weights, w.indices, latent,
                                            at::Tensor(), settings).image;
        }
        if (map.defined())
          loss = cosine ? sparse_cosine_loss(map, book, sam_target, gml_target, v.coverage, weights)
                        : language_loss_from_seg(at::matmul(map, book), sam_target, gml_target, v.coverage, weights);
      } else {
        const at::Tensor rendered = rasterize_features(means, scales, quats, opacities,
                                                       splatted(adam.group(adam_name(level)).param, o), at::Tensor(),
                                                       settings).image;
        loss = language_loss_from_seg(rendered, sam_target, gml_target, v.coverage, weights);
      }
      loss.total.backward();
      adam.step();
      adam.zero_grad();
      blend_caches.recorded(view_index);

      const double value = loss.total.item<double>();
      s.ema_loss = s.iteration == 0 ? value : 0.4 * value + 0.6 * s.ema_loss;  // 3DGS's ema_loss_for_log
      ++s.iteration;
      ++s.total;
      ++report.iterations;
      if (s.iteration % 10 == 0 || s.iteration == o.iterations) {
        char detail[64];
        std::snprintf(detail, sizeof detail, "loss %.4g", s.ema_loss);
        progress.set_detail(detail);
      }
      progress.advance();
      if (s.iteration % metrics_every == 0 || s.iteration == o.iterations) {
        nlohmann::json row = {{"level", level}, {"iteration", s.iteration}, {"loss", value},
                              {"l_sam", loss.sam.item<double>()}, {"l_sam_gml", loss.sam_gml.item<double>()}};
        if (!o.baseline) row["l_citygml"] = loss.citygml.item<double>();  // the baseline has no CityGML term
        row["seconds"] = earlier_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        metrics.append(row);
      }
      if (s.iteration % log_every == 0 || s.iteration == o.iterations)
        log_verbose(cat("language level ", level, " iteration ", s.iteration, "/", o.iterations, " loss ", s.ema_loss,
                        " (SAM ", loss.sam.item<double>(), ", SAM-GML ", loss.sam_gml.item<double>(), ", CityGML ",
                        loss.citygml.item<double>(), ")"));
      latents = adam.group(adam_name(level)).param;
      if (sparse) codebook = adam.group(codebook_name(level)).param;

      const bool stop = interrupt_requested() || (o.stop_after > 0 && s.total >= o.stop_after);
      if (stop || (o.checkpoint_every > 0 && s.total % o.checkpoint_every == 0))
        save_checkpoint(checkpoint_path, s, adam, config);
      if (stop) {
        progress.finish();
        report.interrupted = true;
        report.final_loss[level - 1] = s.ema_loss;
        report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        log_info(cat("language training stopped at level ", level, ", iteration ", s.iteration,
                     "; checkpoint written to ", checkpoint_path));
        return report;
      }
    }
    progress.finish();
    if (device.is_cpu())
      log_verbose(cat("blend weights kept for ", blend_caches.kept_views(), " of ", nviews, " views, ",
                      (blend_caches.bytes() + (1 << 19)) >> 20, " MiB of ", blend_budget >> 20,
                      " (--blend-cache-mb ", o.blend_cache_mb, ", at most a quarter of the memory)"));
    s.final_loss[level - 1] = s.ema_loss;
    latents = latents.detach();
    if (sparse) codebook = codebook.detach();
    log_info(cat("language level ", level, ": ", o.iterations, " iterations, loss ", s.ema_loss));
  }
  for (int l = 0; l < kLevels; ++l) report.final_loss[l] = s.final_loss[l];

  nlohmann::json info = {{"method", o.baseline ? "langsplat" : "citylangsplat"},
                         {"iterations", o.iterations},
                         {"lr", o.lr},
                         {"lambda_sam", o.baseline ? 1.0 : o.lambda_sam},
                         {"lambda_citygml", o.baseline ? 0.0 : o.lambda_citygml},
                         {"features", fs::absolute(o.features_dir).string()},
                         {"provider", provider},
                         {"taxonomy", taxonomy},
                         {"geometry_source", fs::absolute(o.geometry_ply).string()},
                         {"autoencoder_source", sparse ? nlohmann::json(nullptr) : nlohmann::json(fs::absolute(o.autoencoder_path).string())},
                         {"views", nviews},
                         {"seed", o.seed},
                         {"test_every", o.test_every},
                         {"normalize_latents", o.normalize_latents},
                         {"final_loss", s.final_loss}};
  if (sparse)
    info["logit_lr"] = o.logit_lr, info["codebook_lr"] = o.codebook_lr, info["sparse_warmup"] = o.sparse_warmup,
    info["lift_temperature"] = o.lift_temperature, info["sparse_distance"] = o.sparse_distance;
  GaussianModel frozen = geometry;
  LanguageModel model{std::move(frozen), {}, std::move(autoencoder), std::move(info), {}, {}};
  for (int l = 0; l < kLevels; ++l)
    if (sparse) {
      const SparseWeights w = top_k_softmax(s.latents[l].detach(), o.top_k);
      model.sparse[l] = {w.indices.cpu(), w.weights.cpu(), s.codebooks[l].detach().cpu().contiguous()};
    } else {
      model.latents[l] = splatted(s.latents[l].detach(), o).cpu().contiguous();
    }
  attach_city_objects(model, scene, labels_dir);
  save_language_model(o.out_dir, model);
  // A final checkpoint at the end, so a `--resume` of a finished run only rewrites the model.
  save_checkpoint(checkpoint_path, s, adam, config);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace cls
