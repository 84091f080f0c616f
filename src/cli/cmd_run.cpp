// citylangsplat run: every stage of the pipeline on one scene directory, reusing finished stages:
// inputs -> alignment check -> label maps (paper 3.1) -> features (3.1-3.2) -> shared autoencoder (3.2)
// -> photometric 3DGS -> language fields of CityLangSplat and the LangSplat baseline (3.3) -> queries
// for the taxonomy's classes -> evaluation against ground truth when the scene has it (section 4).
// Each stage writes a stamp (a fingerprint of everything it depends on) and is skipped when the stamp
// matches; the training stages resume from their checkpoints after an interruption.
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "citymodel/scene_city_model.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/log.h"
#include "raycast/alignment.h"
#include "core/interrupt.h"
#include "eval/evaluation.h"
#include "features/feature_provider.h"
#include "features/feature_stage.h"
#include "language/autoencoder_stage.h"
#include "language/language_model.h"
#include "language/language_training.h"
#include "query/query_job.h"
#include "raycast/label_export.h"
#include "scene/scene.h"
#include "splat/train_rgb.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

// Where the city model comes from: --config FILE, else SCENE/scene.json (as `synth` writes it),
// overridden by command-line options. Paths in a config file are relative to that file.
struct RunInputs {
  std::string city, transform;
  CityModelOptions model;
};

RunInputs resolve_inputs(const Args& args, const fs::path& scene_dir) {
  RunInputs in;
  fs::path config = args.has("config") ? fs::path(args.get("config")) : scene_dir / "scene.json";
  if (args.has("config") && !fs::exists(config)) fail(config.string(), "config file not found");
  if (fs::exists(config)) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(read_text_file(config));
    } catch (const nlohmann::json::exception& e) {
      fail(config.string(), std::string("malformed JSON: ") + e.what());
    }
    if (!j.is_object()) fail(config.string(), "expected a JSON object");
    const fs::path base = config.parent_path();
    auto path_field = [&](const char* key) -> std::string {
      if (!j.contains(key)) return "";
      if (!j[key].is_string()) fail(config.string(), std::string("\"") + key + "\" must be a string");
      const fs::path p = j[key].get<std::string>();
      return (p.is_absolute() ? p : base / p).string();
    };
    in.city = path_field("city_model");
    in.transform = path_field("city_transform");
    in.model.taxonomy_path = path_field("taxonomy");
    if (j.contains("lod")) {
      if (!j["lod"].is_number_integer()) fail(config.string(), "\"lod\" must be an integer (0 = highest)");
      in.model.lod = j["lod"].get<int>();
    }
  }
  if (args.has("city")) in.city = args.get("city");
  if (args.has("city-transform")) in.transform = args.get("city-transform");
  if (args.has("taxonomy")) in.model.taxonomy_path = args.get("taxonomy");
  if (args.has("lod")) in.model.lod = parse_lod_option(args.get("lod"));
  if (in.city.empty())
    throw UsageError("run: no city model: give --city, or a scene.json / --config with \"city_model\"");
  return in;
}

// Every view's name, intrinsics and pose at the loaded resolution.
uint64_t views_fingerprint(const Scene& scene, uint64_t h) {
  for (const SceneView& v : scene.views) {
    const PinholeCamera& c = v.camera;
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s|%.17g %.17g %.17g %.17g %d %d|", v.name.c_str(), c.fx, c.fy, c.cx, c.cy,
                  c.width, c.height);
    std::string s = buf;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) s += std::to_string(v.pose.R.m[i][j]) + " ";
      s += std::to_string(v.pose.t[i]) + ";";
    }
    h = fnv1a64(s, h);
  }
  return h;
}

// Identifies everything the label maps depend on: the city model, transform and taxonomy bytes,
// the LoD, and the views.
std::string labels_fingerprint(const RunInputs& in, const Scene& scene) {
  uint64_t h = fnv1a64(read_text_file(in.city));
  if (!in.transform.empty()) h = fnv1a64(read_text_file(in.transform), h);
  if (!in.model.taxonomy_path.empty()) h = fnv1a64(read_text_file(in.model.taxonomy_path), h);
  h = fnv1a64(std::to_string(in.model.lod), h);
  return hex64(views_fingerprint(scene, h));
}

// What the photometric model depends on: the views and their images' bytes (not the city model).
std::string images_fingerprint(const Scene& scene) {
  uint64_t h = views_fingerprint(scene, fnv1a64("images"));
  for (const SceneView& v : scene.views) h = fnv1a64(read_text_file(v.image_path), h);
  return hex64(h);
}

// The features stage's result: features.json plus every view's `_gml.json`, which holds the view's
// stamp (label-map and image hashes, provider, alpha, regions), so changed inputs change it.
std::string features_fingerprint_of(const fs::path& features_dir) {
  const fs::path index = features_dir / "features.json";
  const std::string text = read_text_file(index);
  uint64_t h = fnv1a64(text);
  const nlohmann::json index_json = nlohmann::json::parse(text);  // named: a temporary would dangle in the loop
  for (const auto& view : index_json.at("views"))
    h = fnv1a64(read_text_file(features_dir / (view.at("features").get<std::string>() + "_gml.json")), h);
  return hex64(h);
}

bool stage_is_current(const fs::path& stamp, const std::string& fingerprint) {
  if (!fs::exists(stamp)) return false;
  try {
    const auto j = nlohmann::json::parse(read_text_file(stamp));
    return j.value("fingerprint", "") == fingerprint;
  } catch (const std::exception&) {
    return false;  // an unreadable stamp only means the stage runs again
  }
}


void write_stamp(const fs::path& stamp, const std::string& fingerprint) {
  write_text_atomic(stamp, nlohmann::json({{"fingerprint", fingerprint}}).dump(2) + "\n");
}

// A training stage resumes its checkpoint only when the checkpoint belongs to a run of the same
// inputs: `started` records the fingerprint when training starts (a finished stage writes its stamp);
// a checkpoint of other inputs is deleted so that it can never be resumed later.
bool resume_training(const fs::path& started, const fs::path& checkpoint, const std::string& fingerprint) {
  const bool same = stage_is_current(started, fingerprint) && fs::exists(checkpoint);
  if (!same) fs::remove_all(checkpoint);
  write_stamp(started, fingerprint);
  return same;
}

// What `--models` selects: the feature provider and the iteration counts that go with it.
struct ModelsMode {
  std::string name;
  nlohmann::json spec;
  int rgb_iterations = 30000, language_iterations = 30000, autoencoder_epochs = 100;
  std::string warning;  // repeated in every output of a smoke run
};

ModelsMode models_mode(const Args& args) {
  ModelsMode m;
  m.name = args.get("models");
  if (m.name == "real") {
    m.spec = {{"provider", "clip"}};
    if (args.has("clip")) m.spec["clip"] = args.get("clip");
    if (args.has("sam")) m.spec["sam"] = args.get("sam");
  } else if (m.name == "tiny") {
    m.spec = {{"provider", "clip-tiny"}, {"seed", 1}};
    m.rgb_iterations = 100;
    m.language_iterations = 20;
    m.autoencoder_epochs = 5;
    m.warning = "--models tiny: tiny random CLIP/SAM models, a smoke test of the mechanics; every score is meaningless";
  } else if (m.name == "synthetic") {
    m.spec = {{"provider", "synthetic"}, {"seed", 1}};
    m.rgb_iterations = 3000;
    m.language_iterations = 1500;
    m.autoencoder_epochs = 40;
    m.warning = "--models synthetic: synthetic features (docs/features.md), a benchmark of the mechanics, not of CLIP";
  } else {
    throw UsageError("run: --models must be real, tiny or synthetic");
  }
  if (args.has("rgb-iterations")) m.rgb_iterations = args.get_int("rgb-iterations");
  if (args.has("language-iterations")) m.language_iterations = args.get_int("language-iterations");
  if (m.rgb_iterations < 1 || m.language_iterations < 1)
    throw UsageError("run: --rgb-iterations and --language-iterations must be >= 1");
  return m;
}

}  // namespace

int cmd_run(int argc, char** argv) {
  Args args("run",
            "Run every stage on a scene directory (COLMAP or Pix4D, images under SCENE/images), reusing "
            "stages whose inputs have not changed: label maps, features, autoencoder, photometric 3DGS, the "
            "language fields of CityLangSplat and of the LangSplat baseline, queries for the taxonomy's "
            "classes and, when SCENE/gt/points.ply exists, the evaluation. The city model comes from --config "
            "FILE or SCENE/scene.json (keys city_model, city_transform, taxonomy, lod; paths relative to the "
            "file), or from the options below, which override the file. --models real needs CLIP and SAM "
            "weights (`citylangsplat models list`); without them the run stops before the features and says "
            "how to get them.");
  args.positional("SCENE_DIR", "scene directory")
      .option("config", "", "JSON config (default: SCENE_DIR/scene.json when it exists)")
      .option("out", "", "output directory (default: SCENE_DIR/citylangsplat)")
      .option("city", "", "city model (overrides the config)")
      .option("city-transform", "", "city transform JSON (overrides the config)")
      .option("lod", "", "1, 2, 3 or highest (overrides the config; default highest)")
      .option("taxonomy", "", "taxonomy JSON (overrides the config; default built-in)")
      .option("resolution", "1", "divide the image size by 1, 2, 4 or 8", "r")
      .option("align-distance", "0.5", "alignment check: distance threshold in city-model metres")
      .option("models", "real",
              "real (CLIP + SAM weights), tiny (tiny random models: smoke test) or synthetic (synthetic "
              "features: mechanics benchmark)")
      .option("clip", "", "CLIP weights file (default: searched, see `models list`)")
      .option("sam", "", "SAM weights file (default: searched, see `models list`)")
      .option("alpha", "0.5", "text-guidance weight of the CityGML features")
      .option("regions", "class", "CityGML regions: class (one per class and view) or instance")
      .option("rgb-model", "", "import this 3DGS PLY instead of training the photometric model")
      .option("rgb-iterations", "", "photometric iterations (default: 30000; tiny 100; synthetic 3000)")
      .option("language-iterations", "",
              "language iterations per level (default: 30000; tiny 20; synthetic 1500)")
      .option("lambda-sam", "1.0", "weight of the SAM term in covered pixels")
      .option("lambda-citygml", "0.5", "weight of the CityGML term")
      .flag("no-baseline", "do not train the LangSplat baseline");
  if (!args.parse(argc, argv)) return 0;
  const fs::path scene_dir = args.get("SCENE_DIR");
  const fs::path out = args.has("out") ? fs::path(args.get("out")) : scene_dir / "citylangsplat";
  const int factor = args.get_int("resolution");
  if (factor != 1 && factor != 2 && factor != 4 && factor != 8)
    throw UsageError("run: --resolution must be 1, 2, 4 or 8");
  const double align_distance = args.get_double("align-distance");
  const RunInputs inputs = resolve_inputs(args, scene_dir);
  const ModelsMode mode = models_mode(args);
  const std::string region_name = args.get("regions");
  if (region_name != "class" && region_name != "instance") throw UsageError("run: --regions must be class or instance");
  if (args.has("rgb-model") && !fs::exists(args.get("rgb-model")))
    fail(args.get("rgb-model"), "--rgb-model: file not found");

  // Stage: inputs. Everything is read and validated before anything is written.
  SceneOptions scene_options;
  scene_options.resolution_factor = factor;
  const Scene scene = load_scene(scene_dir.string(), scene_options);
  if (scene.views.empty()) fail(scene_dir.string(), "the scene has no views");
  const SceneCityModel city = load_scene_city_model(inputs.city, inputs.transform, inputs.model, "run");
  const fs::path labels_dir = out / "labels";
  label_map_dirs(scene, labels_dir);
  log_info(cat("run: ", scene.views.size(), " views (", scene.source, "), ", scene.points.size(), " sparse points; ",
               city.mesh.format, " ", city.mesh.version, " LoD", city.mesh.lod, ", ", city.mesh.num_triangles(),
               " triangles"));
  if (!mode.warning.empty()) log_warn("run: " + mode.warning);
  install_interrupt_handlers();

  nlohmann::json record = {{"scene", fs::absolute(scene_dir).string()},
                           {"city_model", inputs.city},
                           {"models", mode.name},
                           {"provider", mode.spec}};
  if (!mode.warning.empty()) record["warning"] = mode.warning;
  const fs::path run_json = out / "run.json";
  auto save_record = [&] { write_text_atomic(run_json, record.dump(2) + "\n"); };
  // Stages that do not poll the signal flag themselves finish their step; the run stops after them.
  auto stopped_by_signal = [&](const char* after_stage) {
    if (!interrupt_requested()) return false;
    record["interrupted_after"] = after_stage;
    save_record();
    log_warn(cat("run: interrupted after ", after_stage, "; run the same command again to continue"));
    return true;
  };

  // Stage: alignment check (cheap; a warning, not a failure, so a user sees it before training).
  if (!scene.points.empty()) {
    const AlignmentStats s = check_alignment(scene, city, align_distance);
    log_info(cat("run: align-check: ", 100 * s.fraction_within, "% of sparse points within ", align_distance,
                 " m of the city model (median ", s.median, " m)"));
    if (s.fraction_within < kMisalignedFraction)
      log_warn("run: the city model and the scene look misaligned; check the city transform");
    record["align_check"] = {{"fraction_within", s.fraction_within}, {"median", s.median}, {"threshold", align_distance}};
  }

  // Stage: label maps.
  const std::string scene_fingerprint = labels_fingerprint(inputs, scene);
  const fs::path stamp = labels_dir / "stage.json";
  if (stage_is_current(stamp, scene_fingerprint) && fs::exists(labels_dir / "legend.json")) {
    log_info("run: labels: up to date in " + labels_dir.string() + " (reused)");
    record["labels"] = {{"status", "reused"}, {"dir", labels_dir.string()}};
  } else {
    const LabelExportSummary summary = export_label_maps(scene, city, labels_dir);
    write_stamp(stamp, scene_fingerprint);
    log_info(cat("run: labels: wrote ", summary.views, " views to ", labels_dir.string(), " (mean coverage ",
                 100 * summary.mean_coverage, "%)"));
    record["labels"] = {{"status", "done"}, {"dir", labels_dir.string()}, {"mean_coverage", summary.mean_coverage}};
  }
  save_record();

  // Stage: features (paper 3.1-3.2). Real weights may be absent: stop here and say how to get them.
  std::unique_ptr<FeatureProvider> provider;
  try {
    provider = make_feature_provider(mode.spec, city.taxonomy);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    if (mode.name != "real") throw;
    record["features"] = {{"status", "stopped: no model weights"}, {"reason", e.what()}};
    save_record();
    log_warn(std::string("run: stopped before the features: ") + e.what());
    log_warn("run: get the weights with `citylangsplat models download ...` (see `citylangsplat models list`), or "
             "run the mechanics without them: --models synthetic (synthetic features) or --models tiny "
             "(tiny random models). Results so far: " + run_json.string());
    return 0;
  }
  const fs::path features_dir = out / "features";
  {
    FeatureStageOptions o;
    o.labels_dir = labels_dir;
    o.out_dir = features_dir;
    o.alpha = args.get_double("alpha");
    o.region_mode = region_name == "instance" ? RegionMode::Instance : RegionMode::Class;
    const int computed = run_feature_stage(scene, *provider, city.taxonomy, o);
    if (interrupt_requested()) {
      record["features"] = {{"status", "interrupted"}};
      save_record();
      return kInterruptedExit;
    }
    log_info(cat("run: features: ", computed, " views computed, ", scene.views.size() - computed, " reused (",
                 features_dir.string(), ")"));
    record["features"] = {{"status", computed ? "done" : "reused"}, {"dir", features_dir.string()},
                          {"computed_views", computed}};
    save_record();
  }
  const std::string features_fingerprint = features_fingerprint_of(features_dir);

  // Stage: the shared autoencoder (3.2), trained on the SAM features only.
  const fs::path ae_path = out / "autoencoder.safetensors";
  {
    const std::string fp = hex64(fnv1a64(cat(features_fingerprint, "|", mode.autoencoder_epochs)));
    const fs::path ae_stamp = out / "autoencoder.stage.json";
    if (stage_is_current(ae_stamp, fp) && fs::exists(ae_path)) {
      log_info("run: autoencoder: up to date (reused)");
      record["autoencoder"] = {{"status", "reused"}, {"file", ae_path.string()}};
    } else {
      AutoencoderStageOptions o;
      o.features_dir = features_dir;
      o.out = ae_path;
      o.train.epochs = mode.autoencoder_epochs;
      const AutoencoderReport r = run_autoencoder_stage(o);
      write_stamp(ae_stamp, fp);
      log_info(cat("run: autoencoder: ", r.train_samples, " SAM features, held-out cosine ", r.holdout_cosine));
      record["autoencoder"] = {{"status", "done"}, {"file", ae_path.string()}, {"holdout_cosine", r.holdout_cosine}};
    }
    save_record();
  }

  if (stopped_by_signal("autoencoder")) return kInterruptedExit;

  // Stage: the photometric model (or an imported 3DGS PLY).
  fs::path geometry;
  if (args.has("rgb-model")) {
    geometry = args.get("rgb-model");
    record["train-rgb"] = {{"status", "imported"}, {"ply", geometry.string()}};
  } else {
    const fs::path rgb_dir = out / "rgb";
    geometry = rgb_dir / "point_cloud.ply";
    const std::string fp = hex64(fnv1a64(cat(images_fingerprint(scene), "|", mode.rgb_iterations)));
    const fs::path rgb_stamp = rgb_dir / "stage.json";
    if (stage_is_current(rgb_stamp, fp) && fs::exists(geometry)) {
      log_info("run: train-rgb: up to date (reused)");
      record["train-rgb"] = {{"status", "reused"}, {"ply", geometry.string()}};
    } else {
      RgbTrainOptions o;
      o.out_dir = rgb_dir.string();
      o.iterations = mode.rgb_iterations;
      o.densify_until = std::min(o.densify_until, mode.rgb_iterations / 2);
      o.resume = resume_training(rgb_dir / "started.json", rgb_dir / "checkpoints" / "checkpoint.safetensors", fp);
      const RgbTrainReport r = train_rgb(scene, o);
      if (r.interrupted) {
        record["train-rgb"] = {{"status", "interrupted"}};
        save_record();
        log_warn("run: interrupted during train-rgb; run the same command again to resume");
        return kInterruptedExit;
      }
      write_stamp(rgb_stamp, fp);
      log_info(cat("run: train-rgb: ", r.iterations, " iterations, ", r.gaussians, " Gaussians, test PSNR ",
                   r.test_psnr, " dB over ", r.test_views, " views"));
      record["train-rgb"] = {{"status", "done"}, {"ply", geometry.string()}, {"test_psnr", r.test_psnr},
                             {"test_ssim", r.test_ssim}, {"gaussians", r.gaussians}};
    }
    save_record();
  }

  // Stage: language fields (3.3): CityLangSplat, and LangSplat's objective on identical inputs.
  std::vector<std::pair<std::string, fs::path>> methods = {{"citylangsplat", out / "language" / "citylangsplat"}};
  if (!args.flag_set("no-baseline")) methods.push_back({"langsplat", out / "language" / "langsplat"});
  const std::string geometry_fp = file_fnv1a64_hex(geometry);
  const std::string ae_fp = file_fnv1a64_hex(ae_path);
  nlohmann::json language_record = nlohmann::json::object();
  for (const auto& [method, dir] : methods) {
    LanguageTrainOptions o;
    o.geometry_ply = geometry.string();
    o.features_dir = features_dir.string();
    o.autoencoder_path = ae_path.string();
    o.out_dir = dir.string();
    o.iterations = mode.language_iterations;
    o.lambda_sam = args.get_double("lambda-sam");
    o.lambda_citygml = args.get_double("lambda-citygml");
    o.baseline = method == "langsplat";
    // The baseline's objective has no lambdas (LangSplat's L1 on every pixel): changing them keeps it.
    const std::string weights = o.baseline ? "langsplat" : cat(o.lambda_sam, "|", o.lambda_citygml);
    const std::string fp =
        hex64(fnv1a64(cat(geometry_fp, "|", ae_fp, "|", features_fingerprint, "|", o.iterations, "|", weights)));
    const fs::path lstamp = dir / "stage.json";
    if (stage_is_current(lstamp, fp) && fs::exists(dir / "model.json")) {
      log_info("run: train-language (" + method + "): up to date (reused)");
      language_record[method] = {{"status", "reused"}, {"dir", dir.string()}};
      continue;
    }
    o.resume = resume_training(dir / "started.json", dir / "checkpoints", fp);
    const LanguageTrainReport r = train_language(scene, o);
    if (r.interrupted) {
      language_record[method] = {{"status", "interrupted"}};
      record["train-language"] = language_record;
      save_record();
      log_warn("run: interrupted during train-language; run the same command again to resume");
      return kInterruptedExit;
    }
    write_stamp(lstamp, fp);
    log_info(cat("run: train-language (", method, "): ", o.iterations, " iterations per level in ", r.seconds, " s"));
    language_record[method] = {{"status", "done"}, {"dir", dir.string()}};
  }
  record["train-language"] = language_record;
  save_record();
  std::string latents_fingerprint;
  for (const auto& [method, dir] : methods)
    latents_fingerprint += method + ":" + file_fnv1a64_hex(dir / "latents.safetensors") + ";";

  // Stage: queries for the taxonomy's classes (scores and selections per Gaussian, maps of the first
  // views).
  std::vector<std::string> class_names;
  for (const SemanticClass& c : city.taxonomy.classes) class_names.push_back(c.name);
  nlohmann::json query_record = nlohmann::json::object();
  for (const auto& [method, dir] : methods) {
    const fs::path qdir = out / "query" / method;
    const std::string fp = hex64(fnv1a64(cat(latents_fingerprint, "|", method, "|", class_names.size())));
    const fs::path qstamp = qdir / "stage.json";
    if (stage_is_current(qstamp, fp) && fs::exists(qdir / "query.json")) {
      query_record[method] = {{"status", "reused"}, {"dir", qdir.string()}};
      continue;
    }
    QueryOptions q;
    q.model_dir = dir.string();
    q.texts = class_names;
    q.out_dir = qdir.string();
    q.scene_dir = scene_dir.string();
    q.views = {scene.views.front().name};
    run_query(q);
    write_stamp(qstamp, fp);
    query_record[method] = {{"status", "done"}, {"dir", qdir.string()}};
  }
  record["query"] = query_record;
  log_info("run: query: scores and selections for " + std::to_string(class_names.size()) + " classes in " +
           (out / "query").string());
  save_record();

  if (stopped_by_signal("query")) return kInterruptedExit;

  // Stage: evaluation (section 4) when the scene has a labelled point cloud.
  const fs::path gt = scene_dir / "gt" / "points.ply";
  if (!fs::exists(gt)) {
    record["evaluate"] = {{"status", "skipped: no " + gt.string()}};
  } else if (const std::string fp =
                 hex64(fnv1a64(cat(file_fnv1a64_hex(gt), "|", latents_fingerprint, "|", kEvaluationTables)));
             stage_is_current(out / "eval" / "stage.json", fp) && fs::exists(out / "eval" / "eval.md")) {
    log_info("run: evaluate: up to date (reused): " + (out / "eval" / "eval.md").string());
    record["evaluate"] = {{"status", "reused"}, {"tables", (out / "eval" / "eval.md").string()}};
  } else {
    EvaluationOptions e;
    e.gt_points = gt.string();
    e.labels_dir = labels_dir.string();
    std::vector<std::pair<std::string, nlohmann::json>> results;
    for (const auto& [method, dir] : methods) {
      e.out_dir = (out / "eval" / method).string();
      const LanguageModel model = load_language_model(dir.string());
      results.emplace_back(method, evaluate_model(scene, model, *provider, city.taxonomy, e));
    }
    e.out_dir = (out / "eval" / kLabelMapsMethod).string();
    results.emplace_back(kLabelMapsMethod, evaluate_label_maps(scene, city.taxonomy, e));
    nlohmann::json all = nlohmann::json::object();
    for (const auto& [method, j] : results) all[method] = j;
    if (!mode.warning.empty()) all["warning"] = mode.warning;
    std::string md = evaluation_tables_markdown(results);
    if (!mode.warning.empty()) md = "> " + mode.warning + "\n\n" + md;
    write_text_atomic(out / "eval" / "eval.json", all.dump(2) + "\n");
    write_text_atomic(out / "eval" / "eval.md", md);
    write_stamp(out / "eval" / "stage.json", fp);
    record["evaluate"] = {{"status", "done"}, {"tables", (out / "eval" / "eval.md").string()}};
    std::fprintf(stdout, "%s", md.c_str());
  }
  save_record();
  if (stopped_by_signal("evaluate")) return kInterruptedExit;
  log_info("run: done. Results: " + run_json.string());
  return 0;
}

}  // namespace cls
