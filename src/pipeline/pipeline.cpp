#include "pipeline/pipeline.h"

#include <nlohmann/json.hpp>

#include "citymodel/scene_city_model.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/hash.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "eval/evaluation.h"
#include "features/feature_stage.h"
#include "language/autoencoder_stage.h"
#include "language/language_model.h"
#include "language/language_training.h"
#include "pipeline/city_alignment.h"
#include "pipeline/feature_source.h"
#include "pipeline/fingerprints.h"
#include "pipeline/run_record.h"
#include "query/query_job.h"
#include "raycast/alignment.h"
#include "raycast/label_export.h"
#include "render/render_job.h"
#include "report/report.h"
#include "splat/train_rgb.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

StageReport done(nlohmann::json fields) { return {"done", 0, std::move(fields)}; }
StageReport interrupted() { return {"interrupted", 0, nlohmann::json::object()}; }

// The methods trained on identical inputs: CityLangSplat, (unless disabled) LangSplat's objective on the
// shared autoencoder, and (when asked) LangSplat as published.
std::vector<std::pair<std::string, fs::path>> language_methods(const PipelineConfig& c) {
  std::vector<std::pair<std::string, fs::path>> m = {{"citylangsplat", c.out_dir / "language" / "citylangsplat"}};
  if (c.baseline) m.push_back({"langsplat", c.out_dir / "language" / "langsplat"});
  if (c.baseline_original) m.push_back({"langsplat-original", c.out_dir / "language" / "langsplat-original"});
  return m;
}

}  // namespace

int exit_code(PipelineOutcome outcome) {
  switch (outcome) {
    case PipelineOutcome::Finished: return kExitOk;
    case PipelineOutcome::Interrupted: return kInterruptedExit;
    case PipelineOutcome::MissingWeights: return kExitMissingWeights;
  }
  return kExitInternal;
}

PipelineResult run_pipeline(const PipelineConfig& c) {
  c.validate();
  const fs::path out = c.out_dir;

  // Inputs: everything is read and validated before anything is written.
  SceneOptions scene_options;
  scene_options.resolution_factor = c.resolution;
  const Scene scene = load_scene(c.scene_dir.string(), scene_options);
  if (scene.views.empty()) fail(c.scene_dir.string(), "the scene has no views");
  SceneCityModel city = load_scene_city_model(c.city, c.city_transform, c.city_options, "run");
  const fs::path labels_dir = out / "labels";
  label_map_dirs(scene, labels_dir);
  const FeatureSource source = resolve_feature_source(c, city.taxonomy);
  log_info(cat("run: ", scene.views.size(), " views (", scene.source, "), ", scene.points.size(), " sparse points; ",
               city.mesh.format, " ", city.mesh.version, " LoD", city.mesh.lod, ", ", city.mesh.num_triangles(),
               " triangles"));
  if (!source.note.empty()) log_warn("run: " + source.note);
  if (!source.warning.empty()) log_warn("run: " + source.warning);
  install_interrupt_handlers();

  nlohmann::json header = {{"scene", fs::absolute(c.scene_dir).string()},
                           {"city_model", c.city},
                           {"models", models_choice_name(source.models)},
                           {"settings", c.to_json()}};
  if (source.provider) header["provider"] = source.provider->spec();
  if (!source.warning.empty()) header["warning"] = source.warning;
  if (!source.note.empty()) header["note"] = source.note;
  // The settings as they ran: the schedule's counts, not the "0 = default" of the config.
  header["settings"]["rgb_iterations"] = source.rgb_iterations;
  header["settings"]["language_iterations"] = source.language_iterations;
  header["settings"]["autoencoder_epochs"] = source.autoencoder_epochs;
  RunRecord record(out / "run.json", header);
  PipelineResult result;
  result.run_json = record.file();
  // Every run ends with its report, also one that stopped early: it shows what was done.
  auto finish = [&] {
    record.set("report", (out / "report" / "index.html").string());
    record.save();
    result.report = write_report(out);
    log_info("run: report: " + result.report.string());
    return result;
  };
  // Stages that do not poll the signal flag themselves finish their step; the run stops after them.
  auto stopped_by_signal = [&](const char* after_stage) {
    if (!interrupt_requested()) return false;
    record.set("interrupted_after", after_stage);
    record.save();
    log_warn(cat("run: interrupted after ", after_stage, "; run the same command again to continue"));
    result.outcome = PipelineOutcome::Interrupted;
    return true;
  };
  auto stopped_in = [&](const std::string& stage, const StageReport& r) {
    record.add(stage, r);
    if (!r.interrupted()) return false;
    log_warn("run: interrupted during " + stage + "; run the same command again to resume");
    result.outcome = PipelineOutcome::Interrupted;
    return true;
  };

  // Alignment refinement, then the check on the transform the label maps use (cheap; a warning, not a
  // failure, so a user sees it before training).
  const CityAlignment alignment = align_city_model(scene, city, c.align, c.align_distance, out);
  record.set("align", alignment.record);
  PipelineConfig labelled = c;  // the label maps' inputs: the refined transform where one is used
  if (alignment.applied) labelled.city_transform = alignment.transform.string();
  if (!scene.points.empty()) {
    const AlignmentStats s = check_alignment(scene, city, c.align_distance);
    log_info(cat("run: align-check: ", 100 * s.fraction_within, "% of sparse points within ", c.align_distance,
                 " m of the city model (median ", s.median, " m)"));
    if (s.fraction_within < kMisalignedFraction)
      log_warn("run: the city model and the scene look misaligned; check the city transform");
    record.set("align_check", {{"fraction_within", s.fraction_within}, {"median", s.median},
                               {"threshold", c.align_distance}});
  }

  // Label maps (3.1).
  const std::string labels_fp = labels_fingerprint(labelled, scene);
  record.add("labels", run_stage({"labels", labels_dir / "stage.json", {labels_dir / "objects.json", labels_dir / "legend.json"}, labels_fp,
                                  {{"dir", labels_dir.string()}}, [&] {
                                    const LabelExportSummary s = export_label_maps(scene, city, labels_dir);
                                    log_info(cat("run: labels: wrote ", s.views, " views to ", labels_dir.string(),
                                                 " (mean coverage ", 100 * s.mean_coverage, "%)"));
                                    return done({{"dir", labels_dir.string()}, {"mean_coverage", s.mean_coverage}});
                                  }}));

  // Features (3.1-3.2). Real weights may be absent: stop here and say how to get them.
  if (!source.provider) {
    record.add("features", {"stopped: no model weights", 0, {{"reason", source.missing_weights}}});
    result.outcome = PipelineOutcome::MissingWeights;
    result.message = source.missing_weights;
    return finish();
  }
  const std::string images_fp = images_fingerprint(scene);
  const fs::path features_dir = out / "features";
  // The stage's own per-view stamps (features/feature_stage.h) remain its resume within the stage.
  const std::string features_inputs_fp = hex64(fnv1a64(
      cat(labels_fp, "|", images_fp, "|", source.provider->spec().dump(), "|", c.alpha, "|", c.regions)));
  const StageReport features = run_stage(
      {"features", features_dir / "stage.json", {features_dir / "features.json"}, features_inputs_fp,
       {{"dir", features_dir.string()}, {"computed_views", 0}}, [&] {
         FeatureStageOptions o;
         o.labels_dir = labels_dir;
         o.out_dir = features_dir;
         o.alpha = c.alpha;
         o.region_mode = c.regions == "instance" ? RegionMode::Instance : RegionMode::Class;
         const int computed = run_feature_stage(scene, *source.provider, city.taxonomy, o);
         if (interrupt_requested()) return interrupted();
         log_info(cat("run: features: ", computed, " views computed, ", scene.views.size() - computed, " reused (",
                      features_dir.string(), ")"));
         return done({{"dir", features_dir.string()}, {"computed_views", computed}});
       }});
  if (stopped_in("features", features)) return finish();
  const std::string features_fp = features_fingerprint(features_dir);

  if (c.stop_after_features) {
    log_info("run: stopped after the features (--stop-after features)");
    return finish();
  }

  // The shared autoencoder (3.2), trained on the SAM features only; or the one shared by all tiles. The
  // published LangSplat baseline trains its own, with LangSplat's sizes and settings.
  const auto autoencoder_stage = [&](const std::string& name, const fs::path& file, AutoencoderConfig config,
                                     AutoencoderTrainOptions train, const std::string& variant) {
    record.add(name, run_stage({name, out / (file.stem().string() + ".stage.json"), {file},
                                hex64(fnv1a64(cat(features_fp, "|", source.autoencoder_epochs, variant))),
                                {{"file", file.string()}}, [&] {
                                  AutoencoderStageOptions o;
                                  o.features_dirs = {features_dir};
                                  o.out = file;
                                  o.config = config;
                                  o.train = train;
                                  o.train.epochs = source.autoencoder_epochs;
                                  const AutoencoderReport r = run_autoencoder_stage(o);
                                  log_info(cat("run: ", name, ": ", r.train_samples, " SAM features, held-out cosine ",
                                               r.holdout_cosine));
                                  return done({{"file", file.string()}, {"holdout_cosine", r.holdout_cosine}});
                                }}));
  };
  const fs::path ae_path = c.autoencoder.empty() ? out / "autoencoder.safetensors" : fs::path(c.autoencoder);
  if (!c.autoencoder.empty())
    record.add("autoencoder", {"shared", 0, {{"file", ae_path.string()}}});
  else
    autoencoder_stage("autoencoder", ae_path, AutoencoderConfig{}, AutoencoderTrainOptions{}, "");
  const fs::path original_ae_path = out / "autoencoder-langsplat.safetensors";
  if (c.baseline_original && !interrupt_requested())
    autoencoder_stage("autoencoder-langsplat", original_ae_path, langsplat_autoencoder_config(),
                      langsplat_autoencoder_training(), "|langsplat-original");
  if (stopped_by_signal("autoencoder")) return finish();

  // The photometric model (or an imported 3DGS PLY).
  fs::path geometry;
  if (!c.rgb_model.empty()) {
    geometry = c.rgb_model;
    record.add("train-rgb", {"imported", 0, {{"ply", geometry.string()}}});
  } else {
    const fs::path rgb_dir = out / "rgb";
    geometry = rgb_dir / "point_cloud.ply";
    const std::string fp = hex64(fnv1a64(cat(images_fp, "|", source.rgb_iterations)));
    const StageReport r = run_stage({"train-rgb", rgb_dir / "stage.json", {geometry}, fp, {{"ply", geometry.string()}}, [&] {
      RgbTrainOptions o;
      o.out_dir = rgb_dir.string();
      o.iterations = source.rgb_iterations;
      o.densify_until = std::min(o.densify_until, source.rgb_iterations / 2);
      o.resume = resume_training(rgb_dir / "started.json", rgb_dir / "checkpoints" / "checkpoint.safetensors", fp);
      const RgbTrainReport t = train_rgb(scene, o);
      if (t.interrupted) return interrupted();
      log_info(cat("run: train-rgb: ", t.iterations, " iterations, ", t.gaussians, " Gaussians, test PSNR ", t.test_psnr,
                   " dB over ", t.test_views, " views"));
      return done({{"ply", geometry.string()}, {"test_psnr", t.test_psnr}, {"test_ssim", t.test_ssim},
                   {"gaussians", t.gaussians}, {"iterations", t.iterations}});
    }});
    if (stopped_in("train-rgb", r)) return finish();
  }

  // Pictures of the photometric model: the held-out views beside their photos (PSNR, SSIM) and depth.
  const fs::path render_dir = out / "render";
  const std::string geometry_fp = file_fnv1a64_hex(geometry);
  const StageReport rendered = run_stage(
      {"render", render_dir / "stage.json", {render_dir / "render.json"},
       hex64(fnv1a64(cat(geometry_fp, "|", images_fp, "|", c.resolution))), {{"dir", render_dir.string()}}, [&] {
         RenderOptions o;
         // The PLY itself: the folder's highest point_cloud/iteration_N may be left from an earlier schedule.
         o.model = geometry.string();
         o.scene_dir = c.scene_dir.string();
         o.out_dir = render_dir.string();
         o.what = {"rgb", "depth"};
         o.resolution = c.resolution;
         const nlohmann::json r = render_views(o);
         log_info(cat("run: render: ", r["views"].size(), " held-out views, mean PSNR ", r.value("mean_psnr", 0.0),
                      " dB (", render_dir.string(), ")"));
         return done({{"dir", render_dir.string()}, {"mean_psnr", r.value("mean_psnr", 0.0)},
                      {"mean_ssim", r.value("mean_ssim", 0.0)}});
       }});
  record.add("render", rendered);
  if (stopped_by_signal("render")) return finish();

  // Language fields (3.3): CityLangSplat, and LangSplat's objective on identical inputs.
  const auto methods = language_methods(c);
  for (const auto& [method, dir] : methods) {
    const bool original = method == "langsplat-original";
    LanguageTrainOptions o;
    o.geometry_ply = geometry.string();
    o.features_dir = features_dir.string();
    o.autoencoder_path = (original ? original_ae_path : ae_path).string();
    o.out_dir = dir.string();
    o.iterations = source.language_iterations;
    o.lambda_sam = c.lambda_sam;
    o.lambda_citygml = c.lambda_citygml;
    o.baseline = method != "citylangsplat";
    o.normalize_latents = original;  // LangSplat's renderer splats each Gaussian's normalised feature
    o.test_every = RgbTrainOptions{}.test_every;  // train-rgb's held-out views stay unseen: evaluate scores 2D on them
    // The baseline's objective has no lambdas (LangSplat's L1 on every pixel): changing them keeps it.
    const std::string weights = o.baseline ? "langsplat" : cat(o.lambda_sam, "|", o.lambda_citygml);
    const std::string fp =
        hex64(fnv1a64(cat(geometry_fp, "|", file_fnv1a64_hex(o.autoencoder_path), "|", features_fp, "|", o.iterations,
                          "|", weights, "|held-out ", o.test_every, o.normalize_latents ? "|normalised" : "")));
    const StageReport r = run_stage({"train-language (" + method + ")", dir / "stage.json", {dir / "model.json", dir / "city_objects.json"}, fp,
                                     {{"dir", dir.string()}}, [&, method = method, dir = dir] {
                                       LanguageTrainOptions t = o;
                                       t.resume = resume_training(dir / "started.json", dir / "checkpoints", fp);
                                       const LanguageTrainReport lr = train_language(scene, t);
                                       if (lr.interrupted) return interrupted();
                                       log_info(cat("run: train-language (", method, "): ", t.iterations,
                                                    " iterations per level in ", lr.seconds, " s"));
                                       return done({{"dir", dir.string()}});
                                     }});
    if (stopped_in("train-language/" + method, r)) return finish();
  }
  std::string latents_fp;
  for (const auto& [method, dir] : methods) latents_fp += method + ":" + file_fnv1a64_hex(dir / "latents.safetensors") + ";";

  // Queries for the taxonomy's classes (scores and selections per Gaussian, maps of the first view).
  std::vector<std::string> class_names;
  std::string class_list;
  for (const SemanticClass& k : city.taxonomy.classes) {
    class_names.push_back(k.name);
    class_list += k.name + "\n";
  }
  for (const auto& [method, dir] : methods) {
    const fs::path qdir = out / "query" / method;
    record.add("query/" + method,
               run_stage({"query (" + method + ")", qdir / "stage.json", {qdir / "query.json"},
                          hex64(fnv1a64(cat(latents_fp, "|", method, "|", class_list))),
                          {{"dir", qdir.string()}}, [&, dir = dir] {
                            QueryOptions q;
                            q.model_dir = dir.string();
                            q.texts = class_names;
                            q.out_dir = qdir.string();
                            q.scene_dir = c.scene_dir.string();
                            q.views = {scene.views.front().name};
                            run_query(q);
                            return done({{"dir", qdir.string()}});
                          }}));
  }
  log_info("run: query: scores and selections for " + std::to_string(class_names.size()) + " classes in " +
           (out / "query").string());
  if (stopped_by_signal("query")) return finish();

  // Evaluation (section 4) when the scene has a labelled point cloud.
  const fs::path gt = c.scene_dir / "gt" / "points.ply";
  const fs::path eval_dir = out / "eval";
  if (!fs::exists(gt)) {
    record.add("evaluate", {"skipped: no " + gt.string(), 0, nlohmann::json::object()});
  } else {
    const nlohmann::json files = {{"tables", (eval_dir / "eval.md").string()}, {"json", (eval_dir / "eval.json").string()}};
    record.add("evaluate", run_stage({"evaluate", eval_dir / "stage.json", {eval_dir / "eval.md", eval_dir / "eval.json"},
                                      hex64(fnv1a64(cat(file_fnv1a64_hex(gt), "|", latents_fp, "|", kEvaluationTables))),
                                      files, [&] {
                                        EvaluationOptions e;
                                        e.gt_points = gt.string();
                                        e.labels_dir = labels_dir.string();
                                        e.test_every = RgbTrainOptions{}.test_every;
                                        std::vector<std::pair<std::string, nlohmann::json>> results;
                                        for (const auto& [method, dir] : methods) {
                                          e.out_dir = (eval_dir / method).string();
                                          const LanguageModel model = load_language_model(dir.string());
                                          results.emplace_back(method, evaluate_model(scene, model, *source.provider,
                                                                                      city.taxonomy, e));
                                        }
                                        e.out_dir = (eval_dir / kLabelMapsMethod).string();
                                        results.emplace_back(kLabelMapsMethod, evaluate_label_maps(scene, city.taxonomy, e));
                                        const std::string md =
                                            write_evaluation(eval_dir, results, c.scene_dir.string(), gt.string(),
                                                             source.warning);
                                        std::fprintf(stdout, "%s", md.c_str());
                                        return done(files);
                                      }}));
  }
  if (stopped_by_signal("evaluate")) return finish();
  log_info("run: done. Results: " + record.file().string());
  return finish();
}

}  // namespace cls
