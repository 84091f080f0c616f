#pragma once
// A small but complete run directory in today's layout, made in milliseconds without any training:
// run.json, label previews and legend, training curves, render.json with photos and renders, eval.json
// with per-view GT/prediction images, and both methods' query.json with relevance maps. Real PNGs
// (cv::imwrite), so a browser decodes every image. Used by test_report and by the browser test's
// generator (tests/report/sample/).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/atomic_file.h"

namespace cls::test {

namespace sample {

namespace fs = std::filesystem;
using nlohmann::json;

// A gradient with a few blocks: many colours, different per seed.
inline void write_png(const fs::path& path, int seed, int width = 64, int height = 48) {
  cv::Mat img(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      img.at<cv::Vec3b>(y, x) = cv::Vec3b((x * 4 + seed * 40) & 255, (y * 5 + seed * 17) & 255, (x + y + seed * 90) & 255);
  cv::rectangle(img, {8 + seed % 16, 10, 20, 14}, cv::Scalar(40, 40, 200), cv::FILLED);
  cv::rectangle(img, {36, 20 + seed % 10, 18, 18}, cv::Scalar(30, 160, 60), cv::FILLED);
  fs::create_directories(path.parent_path());
  if (!cv::imwrite(path.string(), img)) throw std::runtime_error("cannot write " + path.string());
}

inline void write_json(const fs::path& path, const json& j) { write_text_atomic(path, j.dump(2) + "\n"); }

inline void write_rows(const fs::path& path, const std::vector<json>& rows) {
  std::string text;
  for (const json& r : rows) text += r.dump() + "\n";
  write_text_atomic(path, text);
}

// The views of the sample; one name with a space and '#', which a page must URL-encode.
inline const std::vector<std::string>& views() {
  static const std::vector<std::string> v = {"view_000", "view_001", "view 002 #b"};
  return v;
}

inline json scores_2d(double base) {
  return {{"gt_coverage", 0.9},
          {"coverage", 0.8},
          {"miou", base},
          {"wiou", base + 0.1},
          {"accuracy", base + 0.2},
          {"per_class",
           {{"wall", {{"iou", base}, {"precision", base + 0.1}, {"recall", base + 0.2}}},
            {"roof", {{"iou", base + 0.05}, {"precision", base}, {"recall", base}}}}}};
}

inline json scores_3d(double base) {
  return {{"coverage", 0.7}, {"mean_distance", 0.05}, {"miou", base}, {"wiou", base + 0.1},
          {"best_labelling", {{"miou", 0.9}}}};
}

}  // namespace sample

// Writes the sample run into `dir` (which should be empty or absent). `models`: "clip", "clip-tiny" or
// "synthetic"; the last two carry run.json's "warning".
inline void write_sample_run(const std::filesystem::path& dir, const std::string& models = "synthetic") {
  using namespace sample;
  const std::vector<std::string> methods = {"citylangsplat", "langsplat"};
  json run = {{"scene", "/data/scenes/sample"},
              {"city_model", "/data/scenes/sample/city.gml"},
              {"models", models},
              {"provider", {{"provider", models}, {"seed", 1}}},
              {"settings", {{"resolution", 1}, {"alpha", 0.5}, {"regions", "class"}, {"rgb-iterations", 50}}},
              {"align_check", {{"fraction_within", 0.97}, {"median", 0.02}, {"threshold", 0.5}}},
              {"labels", {{"status", "done"}, {"seconds", 1.5}, {"dir", (dir / "labels").string()}, {"mean_coverage", 0.8}}},
              {"features", {{"status", "reused"}, {"seconds", 0.1}, {"computed_views", 0}}},
              {"autoencoder", {{"status", "done"}, {"seconds", 12.0}, {"holdout_cosine", 0.97}}},
              {"train-rgb", {{"status", "done"}, {"seconds", 754.0}, {"test_psnr", 24.1}, {"gaussians", 5400}}},
              {"evaluate", {{"status", "done"}, {"seconds", 3.2}}}};
  if (models == "synthetic") run["warning"] = "mechanics: synthetic features, not CLIP";
  if (models == "clip-tiny") run["warning"] = "mechanics: tiny random models, scores meaningless";
  // "stages" as run_pipeline writes it: a stage run per method is "<stage>/<method>" (docs/pipeline.md).
  json stages = {"labels", "features", "autoencoder", "train-rgb"};
  for (const std::string& m : methods) {
    run["train-language"][m] = {{"status", "done"}, {"seconds", 60.0}, {"dir", (dir / "language" / m).string()}};
    stages.push_back("train-language/" + m);
  }
  for (const std::string& m : methods) {
    run["query"][m] = {{"status", "done"}, {"seconds", 2.0}};
    stages.push_back("query/" + m);
  }
  stages.push_back("evaluate");
  run["stages"] = stages;
  write_json(dir / "run.json", run);

  write_json(dir / "labels" / "legend.json",
             json::array({{{"id", 0}, {"name", "wall"}, {"level", 2}, {"color", {200, 200, 120}}},
                          {{"id", 1}, {"name", "roof"}, {"level", 2}, {"color", {180, 40, 40}}},
                          {{"id", 2}, {"name", "window"}, {"level", 1}, {"color", {40, 120, 220}}}}));
  for (size_t v = 0; v < views().size(); ++v) write_png(dir / "labels" / views()[v] / "preview.png", int(v));

  std::vector<json> rgb;
  for (int it = 1; it <= 50; ++it) {
    json r = {{"iteration", it},       {"loss", 0.3 * std::exp(-it / 15.0) + 0.02}, {"l1", 0.25 * std::exp(-it / 15.0)},
              {"psnr", 12 + 0.2 * it}, {"gaussians", 1000 + 90 * it},               {"sh_degree", it / 20},
              {"seconds", 0.5 * it}};
    if (it % 10 == 0) r["test_psnr"] = 11 + 0.18 * it, r["test_ssim"] = 0.5 + 0.005 * it;
    rgb.push_back(r);
  }
  write_rows(dir / "rgb" / "metrics.jsonl", rgb);
  for (const std::string& m : methods) {
    std::vector<json> rows;
    for (int level = 1; level <= 3; ++level)
      for (int it = 1; it <= 10; ++it)
        rows.push_back({{"level", level}, {"iteration", it}, {"loss", 0.5 / (it + level)}, {"l_sam", 0.1},
                        {"l_sam_gml", 0.1}, {"seconds", 0.1 * (it + 10 * level)}});
    write_rows(dir / "language" / m / "metrics.jsonl", rows);
  }

  json render_views = json::array();
  for (size_t v = 0; v < 2; ++v) {
    const std::string stem = views()[v];
    const fs::path vd = fs::path("views") / stem;
    write_png(dir / "render" / vd / "rgb.png", int(v) + 3);
    write_png(dir / "render" / vd / "photo.png", int(v) + 4);
    render_views.push_back({{"name", stem + ".png"},
                            {"split", v == 0 ? "test" : "train"},
                            {"psnr", 24.5 - double(v)},
                            {"ssim", 0.81},
                            {"files", {{"rgb", (vd / "rgb.png").string()}, {"photo", (vd / "photo.png").string()}}}});
  }
  write_json(dir / "render" / "render.json", {{"views", render_views}, {"mean_psnr", 24.5}, {"mean_ssim", 0.81}});

  json results;
  for (size_t k = 0; k < methods.size(); ++k)
    results[methods[k]] = {{"classes", {"wall", "roof"}},
                           {"2d", scores_2d(0.5 + 0.1 * double(k))},
                           {"2d_covered", scores_2d(0.6 + 0.1 * double(k))},
                           {"3d", scores_3d(0.4 - 0.1 * double(k))},
                           {"3d_visible", scores_3d(0.45 - 0.1 * double(k))}};
  results["city-model-labels"] = {{"classes", {"wall", "roof"}}, {"reference", true}, {"2d", scores_2d(0.8)}};
  write_json(dir / "eval" / "eval.json",
             {{"methods", {"citylangsplat", "langsplat", "city-model-labels"}}, {"results", results}});
  for (const auto& [m, _] : results.items())
    for (size_t v = 0; v < views().size(); ++v) {
      write_png(dir / "eval" / m / "views" / (views()[v] + "_gt.png"), 7);
      write_png(dir / "eval" / m / "views" / (views()[v] + "_pred.png"), int(v) + 8);
    }

  for (const std::string& m : methods) {
    json queries = json::array();
    for (const char* text : {"wall", "roof"}) {
      const std::string stem = views()[0];
      json maps = json::array();
      for (const char* kind : {"_cosine.png", "_relevancy.png"}) {
        const std::string rel = std::string("maps/") + text + "/" + stem + kind;
        write_png(dir / "query" / m / rel, int(maps.size()) + 11);
        maps.push_back(rel);
      }
      queries.push_back({{"text", text}, {"slug", text}, {"level", 2}, {"scores", {{"max", 0.61}}}, {"maps", maps}});
    }
    write_png(dir / "query" / m / "maps" / "legend_turbo.png", 20, 256, 16);
    write_json(dir / "query" / m / "query.json", {{"queries", queries}, {"maps", {{"legend", "maps/legend_turbo.png"}}}});
  }
}

}  // namespace cls::test
