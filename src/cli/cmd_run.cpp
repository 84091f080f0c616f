// citylangsplat run: every stage of the pipeline on one scene directory, reusing finished stages.
//
// Stages in this version: scene + city model input, alignment check, label maps (paper 3.1).
// The feature, training, query and evaluation stages come with later work; `run` stops before them
// with a message saying so, after everything it can do has been done.
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
#include "raycast/label_export.h"
#include "scene/scene.h"

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

// Identifies everything the label maps depend on: the city model, transform and taxonomy bytes,
// the LoD, and every view's name, intrinsics and pose at the loaded resolution.
std::string labels_fingerprint(const RunInputs& in, const Scene& scene) {
  uint64_t h = fnv1a64(read_text_file(in.city));
  if (!in.transform.empty()) h = fnv1a64(read_text_file(in.transform), h);
  if (!in.model.taxonomy_path.empty()) h = fnv1a64(read_text_file(in.model.taxonomy_path), h);
  h = fnv1a64(std::to_string(in.model.lod), h);
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

}  // namespace

int cmd_run(int argc, char** argv) {
  Args args("run",
            "Run every stage on a scene directory (COLMAP or Pix4D, images under SCENE/images), reusing "
            "stages whose inputs have not changed. The city model comes from --config FILE or "
            "SCENE/scene.json (keys city_model, city_transform, taxonomy, lod; paths relative to the file), "
            "or from the options below, which override the file. This version runs the alignment check "
            "and the label maps (OUT/labels); the feature, training, query and evaluation stages are not "
            "available yet and the run stops before them, saying so.");
  args.positional("SCENE_DIR", "scene directory")
      .option("config", "", "JSON config (default: SCENE_DIR/scene.json when it exists)")
      .option("out", "", "output directory (default: SCENE_DIR/citylangsplat)")
      .option("city", "", "city model (overrides the config)")
      .option("city-transform", "", "city transform JSON (overrides the config)")
      .option("lod", "", "1, 2, 3 or highest (overrides the config; default highest)")
      .option("taxonomy", "", "taxonomy JSON (overrides the config; default built-in)")
      .option("resolution", "1", "divide the image size by 1, 2, 4 or 8", "r")
      .option("align-distance", "0.5", "alignment check: distance threshold in city-model metres");
  if (!args.parse(argc, argv)) return 0;
  const fs::path scene_dir = args.get("SCENE_DIR");
  const fs::path out = args.has("out") ? fs::path(args.get("out")) : scene_dir / "citylangsplat";
  const int factor = args.get_int("resolution");
  if (factor != 1 && factor != 2 && factor != 4 && factor != 8)
    throw UsageError("run: --resolution must be 1, 2, 4 or 8");
  const double align_distance = args.get_double("align-distance");
  const RunInputs inputs = resolve_inputs(args, scene_dir);

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

  nlohmann::json record = {{"scene", fs::absolute(scene_dir).string()}, {"city_model", inputs.city}};

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
  const std::string fingerprint = labels_fingerprint(inputs, scene);
  const fs::path stamp = labels_dir / "stage.json";
  if (stage_is_current(stamp, fingerprint) && fs::exists(labels_dir / "legend.json")) {
    log_info("run: labels: up to date in " + labels_dir.string() + " (reused)");
    record["labels"] = {{"status", "reused"}, {"dir", labels_dir.string()}};
  } else {
    const LabelExportSummary summary = export_label_maps(scene, city, labels_dir);
    write_text_atomic(stamp, nlohmann::json({{"fingerprint", fingerprint}, {"views", summary.views}}).dump(2) + "\n");
    log_info(cat("run: labels: wrote ", summary.views, " views to ", labels_dir.string(), " (mean coverage ",
                 100 * summary.mean_coverage, "%)"));
    record["labels"] = {{"status", "done"}, {"dir", labels_dir.string()}, {"mean_coverage", summary.mean_coverage}};
  }

  const char* not_yet = "not available in this version";
  for (const char* stage : {"features", "autoencoder", "train-rgb", "train-language", "query", "evaluate"})
    record[stage] = {{"status", not_yet}};
  write_text_atomic(out / "run.json", record.dump(2) + "\n");
  log_info("run: stopped after the label maps: the stages features (CLIP + SAM), autoencoder, train-rgb, "
           "train-language, query and evaluate are " + std::string(not_yet) + ". Results so far: " +
           (out / "run.json").string());
  return 0;
}

}  // namespace cls
