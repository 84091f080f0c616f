// The CLI smoke test of `citylangsplat run` (run_pipeline itself is tested in process in
// test_pipeline.cpp): every stage with tiny random models on the bundled example, then a second run that
// reuses them; and what only the command line does (scene.json / --config, exit statuses).
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "eval/labelled_points.h"
#include "hand_las.h"
#include "core/atomic_file.h"
#include "core/exit_codes.h"
#include "core/run_layout.h"
#include "models/temp_dir.h"

namespace fs = std::filesystem;
using cls::test::run_cli;

namespace {

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

fs::path work_path(const std::string& name) {
  static const cls::test::TempDir root("cls_run_cli_");
  return root.path / name;
}

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(cls::read_text_file(p)); }

}  // namespace

// The command line over the scene config: a broken --config or city model fails with the file named and
// writes nothing; no city model anywhere is a usage error.
TEST(RunCli, BadInputsFailWithTheFileNamedAndWriteNothing) {
  const fs::path scene = work_path("scene");
  const auto made = run_cli("-q synth --city " + kFzk + " --out " + scene.string() +
                            " --views 4 --width 120 --height 90 --gt-density 20 --seed 3");
  ASSERT_EQ(made.status, 0) << made.err;
  const fs::path out = work_path("out");
  const fs::path bad_config = work_path("bad_config.json");
  cls::write_text_atomic(bad_config, "{\"city_model\": ");
  auto r = run_cli("run " + scene.string() + " --out " + out.string() + " --config " + bad_config.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(bad_config.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  r = run_cli("run " + scene.string() + " --out " + out.string() + " --config " + (scene / "missing.json").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;

  r = run_cli("run " + scene.string() + " --out " + out.string() + " --city /nonexistent/model.gml");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/nonexistent/model.gml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  r = run_cli("run " + scene.string() + " --out " + out.string() + " --models real");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("must be auto, clip, clip-tiny, synthetic or image-segments"), std::string::npos) << r.err;

  const fs::path empty = work_path("empty");
  fs::create_directories(empty);
  r = run_cli("run " + empty.string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;  // no city model anywhere: a usage error
  EXPECT_FALSE(fs::exists(out));
}

// The acceptance run of issue 6: every stage with tiny random models on the bundled example (made
// here by scripts/make_example.sh, as set-up makes it), then a second run that reuses every stage.
TEST(RunCli, TinyModelsRunEveryStageOnTheBundledExampleAndASecondRunReusesThem) {
  const fs::path base = fs::temp_directory_path() / ("cls_run_example_" + std::to_string(::getpid()));
  fs::remove_all(base);
  const std::string make = "CITYLANGSPLAT='" + std::string(CLS_BINARY) + "' bash '" CLS_TEST_DATA
                           "/../scripts/make_example.sh' '" + (base / "fzk-haus").string() + "' >/dev/null";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  const fs::path out = base / "out";
  const std::string cmd = "run " + (base / "fzk-haus").string() + " --models clip-tiny --out " + out.string();
  const auto first = run_cli(cmd);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.err.find("tiny random"), std::string::npos);
  const auto record = read_json(out / "run.json");
  for (const char* stage : {"labels", "features", "autoencoder", "autoencoder-langsplat", "train-rgb", "render", "evaluate"})
    EXPECT_EQ(record[stage]["status"], "done") << stage;
  // Beside CityLangSplat, the paper's baseline: LangSplat as published, with its own autoencoder.
  for (const char* method : {"citylangsplat", "langsplat-original"}) {
    EXPECT_EQ(record["train-language"][method]["status"], "done") << method;
    EXPECT_EQ(record["query"][method]["status"], "done") << method;
    EXPECT_TRUE(fs::exists(out / "language" / method / "latents.safetensors")) << method;
    EXPECT_TRUE(fs::exists(out / "query" / method / "scores.ply")) << method;
  }
  // Every output of a smoke run says so.
  EXPECT_NE(record["warning"].get<std::string>().find("meaningless"), std::string::npos);
  const std::string tables = cls::read_text_file(out / "eval" / "eval.md");
  EXPECT_NE(tables.find("meaningless"), std::string::npos);
  // The label maps' reference row and the scores on the covered GT.
  EXPECT_NE(tables.find("| city-model-labels |"), std::string::npos) << tables;
  EXPECT_NE(tables.find("Table 1b"), std::string::npos) << tables;
  EXPECT_NE(cls::read_text_file(out / "features" / "features.json").find("meaningless"), std::string::npos);
  // The run ends with its report, whose path it prints last; the page passes the real-browser check
  // (tests/report/browser_check.py: every image decoded, no console error, the tables and charts of a
  // complete report, the warning banner) where Chromium is installed, and says it skipped otherwise.
  const fs::path index = out / "report" / "index.html";
  EXPECT_NE(first.out.find("Report: " + index.string() + "\n"), std::string::npos) << first.out;
  const std::string browser = "/usr/bin/python3 '" CLS_TEST_DATA "/../tests/report/browser_check.py' '" +
                              index.string() + "' --screenshot '" + (base / "report.png").string() + "'";
  const int browser_status = WEXITSTATUS(std::system(browser.c_str()));
  if (browser_status != 77) EXPECT_EQ(browser_status, 0) << browser;
  // run.json lists the stages in the order they ran, each with its wall time.
  ASSERT_TRUE(record["stages"].is_array());
  EXPECT_EQ(record["stages"].front(), "georef");  // skipped: the bundled example names its city transform
  for (const auto& stage : record["stages"]) {
    const std::string name = stage.get<std::string>();
    const size_t slash = name.find('/');
    const auto& entry = slash == std::string::npos ? record[name] : record[name.substr(0, slash)][name.substr(slash + 1)];
    EXPECT_GE(entry["seconds"].get<double>(), 0.0) << name;
  }
  // One evaluation writer: `evaluate` on the run's own models and label maps writes the same bytes.
  const fs::path eval_again = base / "eval_again";
  const auto evaluated = run_cli("-q evaluate --scene " + (base / "fzk-haus").string() + " --model citylangsplat=" +
                                 (out / "language" / "citylangsplat").string() + " --model langsplat-original=" +
                                 (out / "language" / "langsplat-original").string() + " --labels " + (out / "labels").string() +
                                 " --out " + eval_again.string());
  ASSERT_EQ(evaluated.status, 0) << evaluated.err;
  EXPECT_EQ(cls::read_text_file(eval_again / "eval.json"), cls::read_text_file(out / "eval" / "eval.json"));
  EXPECT_TRUE(read_json(eval_again / "eval.json")["methods"].is_array());

  // The same GT as a user would bring it: a LAS cloud (format 6) in a projected CRS with its own class
  // codes, a class map to the taxonomy and the city transform into the scene: the same scores.
  {
    const cls::LabelledPoints ply = cls::read_labelled_points((base / "fzk-haus" / "gt" / "points.ply").string());
    const cls::Taxonomy taxonomy = cls::Taxonomy::builtin();
    const std::array<double, 3> crs{691000, 5335000, 500}, scale{0x1p-23, 0x1p-23, 0x1p-23};
    std::vector<cls::test::HandLasPoint> points(ply.size());
    nlohmann::json classes = {{"0", nullptr}};
    for (size_t k = 0; k < taxonomy.classes.size(); ++k) classes[std::to_string(k + 1)] = taxonomy.classes[k].name;
    for (size_t i = 0; i < ply.size(); ++i) {
      points[i].x = int32_t(std::llround(ply.positions[i].x / scale[0]));
      points[i].y = int32_t(std::llround(ply.positions[i].y / scale[1]));
      points[i].z = int32_t(std::llround(ply.positions[i].z / scale[2]));
      points[i].classification = uint8_t(ply.labels[i] + 1);
    }
    const fs::path las = base / "gt.las", map = base / "map.json", transform = base / "crs_to_scene.json";
    cls::write_text_atomic(las, cls::test::hand_las(6, points, scale, crs));
    cls::write_text_atomic(map, nlohmann::json{{"name", "codes + 1"}, {"classes", classes}}.dump());
    cls::write_text_atomic(transform, nlohmann::json{{"matrix", {{1, 0, 0, -crs[0]}, {0, 1, 0, -crs[1]}, {0, 0, 1, -crs[2]},
                                                                 {0, 0, 0, 1}}}}.dump());
    const auto from_las = run_cli("-q evaluate --scene " + (base / "fzk-haus").string() + " --model citylangsplat=" +
                                  (out / "language" / "citylangsplat").string() + " --labels " + (out / "labels").string() +
                                  " --gt " + las.string() + " --class-map " + map.string() + " --gt-transform " +
                                  transform.string() + " --no-images --out " + (base / "eval_las").string());
    ASSERT_EQ(from_las.status, 0) << from_las.err;
    nlohmann::json a = read_json(base / "eval_las" / "eval.json")["results"]["citylangsplat"];
    nlohmann::json b = read_json(out / "eval" / "eval.json")["results"]["citylangsplat"];
    EXPECT_EQ(a["class_map"], map.string());
    for (const char* key : {"gt_points", "class_map", "gt_transform"}) a.erase(key), b.erase(key);
    // Coordinates under 1 m are finer in the PLY's floats than 2^-23 m: the LAS moves them by up to
    // 6e-8 m, which only the mean match distance sees.
    for (const char* group : {"3d", "3d_visible"}) {
      EXPECT_NEAR(a[group]["mean_distance"].get<double>(), b[group]["mean_distance"].get<double>(), 1e-7) << group;
      a[group].erase("mean_distance"), b[group].erase("mean_distance");
    }
    EXPECT_EQ(a.dump(1), b.dump(1));
  }

  const auto second = run_cli(cmd);
  ASSERT_EQ(second.status, 0) << second.err;
  const auto again = read_json(out / "run.json");
  for (const char* stage : {"labels", "features", "autoencoder", "autoencoder-langsplat", "train-rgb", "render", "evaluate"})
    EXPECT_EQ(again[stage]["status"], "reused") << stage;
  for (const char* method : {"citylangsplat", "langsplat-original"}) {
    EXPECT_EQ(again["train-language"][method]["status"], "reused") << method;
    EXPECT_EQ(again["query"][method]["status"], "reused") << method;
  }
  fs::remove_all(base);
}

