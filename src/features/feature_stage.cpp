#include "features/feature_stage.h"

#include <ATen/ATen.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <chrono>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "core/progress.h"
#include "features/city_regions.h"
#include "features/view_features.h"
#include "raycast/label_export.h"
#include "raycast/label_map_io.h"
#include "scene/image_loader.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

const char* mode_name(RegionMode m) { return m == RegionMode::Class ? "class" : "instance"; }

struct ViewJob {
  const SceneView* view = nullptr;
  fs::path label_dir, out_dir;
  std::string stem;
  nlohmann::json stamp;
};

bool cached(const ViewJob& job) {
  if (!view_features_complete(job.out_dir, job.stem)) return false;
  try {
    const auto j = nlohmann::json::parse(read_text_file(job.out_dir / (job.stem + "_gml.json")));
    return j.value("stamp", nlohmann::json()) == job.stamp;
  } catch (const std::exception&) {
    return false;  // unreadable: recompute
  }
}

}  // namespace

const OptionList<FeatureStageOptions>& feature_stage_options() {
  using O = FeatureStageOptions;
  static const OptionList<O> list = [] {
    OptionList<O> o;
    o.add("labels", &O::labels_dir, "label map directory of `citylangsplat raycast`", OptionRole::Location).required()
        .add("out", &O::out_dir, "output directory", OptionRole::Location).required()
        .add("alpha", &O::alpha, "text-guidance weight alpha of the fusion, in [0, 1]")
        .add("regions", &O::region_mode,
             "CityGML regions: class (one per level and class, the paper) or instance (one per connected object "
             "within a building)",
             OptionRole::Setting, enum_codec<RegionMode>({{"class", RegionMode::Class}, {"instance", RegionMode::Instance}}))
        .add("min-region-pixels", &O::min_region_pixels, "skip CityGML regions smaller than this")
        .add("overwrite", &O::overwrite, "recompute every view, cached or not", OptionRole::Control);
    return o;
  }();
  return list;
}

int run_feature_stage(const Scene& scene, FeatureProvider& provider, const Taxonomy& taxonomy,
                      const FeatureStageOptions& options) {
  if (options.alpha < 0 || options.alpha > 1) throw UsageError("features: alpha must be in [0, 1]");
  if (!fs::is_directory(options.labels_dir))
    fail(options.labels_dir.string(), "label map directory not found (make it with `citylangsplat raycast`)");
  if (taxonomy.classes.empty()) throw Error("features: the taxonomy has no classes");

  // What every view's features depend on besides its own inputs.
  const nlohmann::json common = {{"provider", provider.spec()},
                                 {"alpha", options.alpha},
                                 {"region_mode", mode_name(options.region_mode)},
                                 {"min_region_pixels", options.min_region_pixels},
                                 {"taxonomy", fnv1a64_hex(taxonomy.legend_json())}};

  // Check every input and find the cached views before computing anything.
  const std::vector<fs::path> label_dirs = label_map_dirs(scene, options.labels_dir);
  const std::vector<fs::path> out_paths = label_map_dirs(scene, options.out_dir);
  std::vector<ViewJob> jobs;
  for (size_t k = 0; k < scene.views.size(); ++k) {
    ViewJob job;
    job.view = &scene.views[k];
    job.label_dir = label_dirs[k];
    job.out_dir = out_paths[k].parent_path();
    job.stem = out_paths[k].filename().string();
    nlohmann::json labels;
    for (const char* f : {"level1.png", "level2.png", "level3.png", "coverage.png"}) {
      const fs::path p = job.label_dir / f;
      if (!fs::is_regular_file(p))
        fail(p.string(), "missing: no label maps for view '" + job.view->name + "' (run `citylangsplat raycast`)");
      labels[f] = file_fnv1a64_hex(p);
    }
    if (options.region_mode == RegionMode::Instance) {
      const fs::path p = job.label_dir / "building.png";
      if (!fs::is_regular_file(p)) fail(p.string(), "missing: instance regions need the building map");
      labels["building.png"] = file_fnv1a64_hex(p);
    }
    job.stamp = common;
    job.stamp["labels"] = labels;
    job.stamp["image"] = {{"file", file_fnv1a64_hex(job.view->image_path)},
                          {"width", job.view->camera.width},
                          {"height", job.view->camera.height}};
    jobs.push_back(std::move(job));
  }
  fs::create_directories(options.out_dir);
  fs::remove(options.out_dir / "features.json");  // its presence marks a finished stage

  std::vector<const ViewJob*> todo;
  for (const ViewJob& job : jobs)
    if (options.overwrite || !cached(job)) todo.push_back(&job);
  log_info(cat("features: ", jobs.size(), " views, ", jobs.size() - todo.size(), " cached, provider ", provider.name(),
               ", alpha ", options.alpha, ", ", mode_name(options.region_mode), " regions"));

  // f^txt: the text feature of each class's prompt tau_c = prompts[0].
  at::Tensor class_text;
  if (!todo.empty()) {
    std::vector<std::string> prompts;
    for (const SemanticClass& c : taxonomy.classes) prompts.push_back(c.prompts.empty() ? c.name : c.prompts[0]);
    class_text = provider.text_features(prompts).to(at::kFloat).contiguous();
  }

  ImageLoader loader;
  Progress progress("features", todo.size(), "views");
  int computed = 0;
  for (const ViewJob* job : todo) {
    // A signal (when the caller installed core/interrupt.h's handlers) stops between views: the views
    // written so far stay cached, and features.json is not written, so the stage is not finished.
    if (interrupt_requested()) {
      log_warn(cat("features: interrupted after ", computed, " of ", todo.size(), " views; run again to resume"));
      return computed;
    }
    const SceneView& sv = *job->view;
    FeatureView view;
    view.name = sv.name;
    cv::cvtColor(loader.load(sv), view.rgb, cv::COLOR_BGR2RGB);
    const int h = view.rgb.rows, w = view.rgb.cols;
    for (int l = 0; l < 3; ++l)
      view.labels[l] = read_label_png(job->label_dir / ("level" + std::to_string(l + 1) + ".png"), CV_16UC1, h, w);
    view.coverage = read_label_png(job->label_dir / "coverage.png", CV_8UC1, h, w);
    cv::Mat building;
    if (options.region_mode == RegionMode::Instance) building = read_label_png(job->label_dir / "building.png", CV_16UC1, h, w);

    ViewFeatures f;
    f.height = h;
    f.width = w;
    f.stamp = job->stamp;
    SamSegments sam = provider.sam_segments(view);
    f.sam_seg = std::move(sam.seg);
    f.sam_features = sam.features;

    CityRegionSet regions = extract_city_regions(view.labels, view.coverage, building, options.region_mode, taxonomy,
                                                 options.min_region_pixels, job->label_dir.string());
    if (regions.masks.empty()) {
      f.gml_features = at::zeros({0, provider.dim()}, at::kFloat);
    } else {
      const at::Tensor gml = provider.region_features(view, regions.masks);
      std::vector<int64_t> cls_ids;
      for (const CityRegion& r : regions.regions) cls_ids.push_back(r.class_id);
      const at::Tensor txt = class_text.index_select(0, at::tensor(cls_ids, at::kLong));
      f.gml_features = fuse_features(gml, txt, options.alpha);
    }
    f.gml_seg = std::move(regions.seg);
    f.regions = std::move(regions.regions);
    write_view_features(job->out_dir, job->stem, f);
    log_verbose(cat(sv.name, ": ", f.sam_features.size(0), " SAM segments, ", f.regions.size(), " CityGML regions"));
    ++computed;
    progress.advance();
  }
  progress.finish();

  nlohmann::json views = nlohmann::json::array();
  for (const ViewJob& job : jobs)
    views.push_back({{"name", job.view->name},
                     {"features", fs::relative(job.out_dir / job.stem, options.out_dir).generic_string()}});
  nlohmann::json record = common;
  record["provider"] = provider.spec();
  record["taxonomy"] = nlohmann::json::parse(taxonomy.legend_json());
  record["dim"] = provider.dim();
  record["labels_dir"] = fs::absolute(options.labels_dir).string();
  record["layout"] = "LangSplat: <stem>_s.npy / _f.npy (SAM), <stem>_gml_s.npy / _gml_f.npy / _gml.json (CityGML)";
  record["views"] = views;
  write_text_atomic(options.out_dir / "features.json", record.dump(1) + "\n");
  return static_cast<int>(todo.size());
}

}  // namespace cls
