// End-to-end tests of `citylangsplat run` on a tiny synthetic FZK-Haus scene.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_runner.h"
#include "core/atomic_file.h"

namespace fs = std::filesystem;
using cls::test::run_cli;

namespace {

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

// One tiny synthetic scene shared by the tests of this file (4 views of 120x90).
const fs::path& scene_dir() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("cls_run_scene_" + std::to_string(::getpid()));
    fs::remove_all(d);
    const auto r = run_cli("-q synth --city " + kFzk + " --out " + d.string() +
                           " --views 4 --width 120 --height 90 --gt-density 20 --seed 3");
    EXPECT_EQ(r.status, 0) << r.err;
    return d;
  }();
  return dir;
}

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(cls::read_text_file(p)); }

}  // namespace

TEST(RunCli, LabelMapsAgreeWithTheSyntheticGroundTruth) {
  const fs::path out = scene_dir().string() + "_out1";
  fs::remove_all(out);
  const auto r = run_cli("run " + scene_dir().string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("not available in this version"), std::string::npos) << r.err;
  const auto record = read_json(out / "run.json");
  EXPECT_EQ(record["labels"]["status"], "done");
  EXPECT_EQ(record["features"]["status"], "not available in this version");
  EXPECT_TRUE(fs::exists(out / "labels" / "legend.json"));
  // The synthetic ground truth (rendered with clutter by the generator) carries the level-1 class
  // wherever the city model is visible; the label map must agree there. Clutter only removes GT
  // labels, so pixels with GT 0 are not compared.
  size_t compared = 0, agree = 0;
  for (int k = 0; k < 4; ++k) {
    char stem[8];
    std::snprintf(stem, sizeof stem, "%04d", k);
    const cv::Mat gt = cv::imread((scene_dir() / "gt" / "labels" / (std::string(stem) + ".png")).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat l1 = cv::imread((out / "labels" / stem / "level1.png").string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(gt.empty());
    ASSERT_FALSE(l1.empty());
    ASSERT_EQ(gt.size(), l1.size());
    ASSERT_EQ(l1.type(), CV_16UC1);
    for (int y = 0; y < gt.rows; ++y)
      for (int x = 0; x < gt.cols; ++x) {
        const uint16_t g = gt.at<uint16_t>(y, x);
        if (g == 0) continue;
        ++compared;
        agree += l1.at<uint16_t>(y, x) == g;
      }
  }
  ASSERT_GT(compared, 1000u);
  EXPECT_GE(static_cast<double>(agree) / compared, 0.999) << agree << " of " << compared;
}

TEST(RunCli, SecondRunReusesLabelsAndAChangedTransformRedoesThem) {
  const fs::path out = scene_dir().string() + "_out2";
  fs::remove_all(out);
  ASSERT_EQ(run_cli("-q run " + scene_dir().string() + " --out " + out.string()).status, 0);
  const auto stamp_time = fs::last_write_time(out / "labels" / "stage.json");
  const auto again = run_cli("run " + scene_dir().string() + " --out " + out.string());
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(read_json(out / "run.json")["labels"]["status"], "reused");
  EXPECT_EQ(fs::last_write_time(out / "labels" / "stage.json"), stamp_time);

  // The stage is keyed on the transform's bytes: a copy keeps it current, any edit redoes it.
  const fs::path moved = out / "moved_transform.json";
  std::string text = cls::read_text_file(scene_dir() / "city" / "transform.json");
  cls::write_text_atomic(moved, text);
  const auto copied = run_cli("-q run " + scene_dir().string() + " --out " + out.string() + " --city-transform " +
                            moved.string());
  ASSERT_EQ(copied.status, 0) << copied.err;
  EXPECT_EQ(read_json(out / "run.json")["labels"]["status"], "reused");  // same bytes: still current
  cls::write_text_atomic(moved, text + " ");                              // same meaning, other bytes
  ASSERT_EQ(run_cli("-q run " + scene_dir().string() + " --out " + out.string() + " --city-transform " +
                    moved.string()).status, 0);
  EXPECT_EQ(read_json(out / "run.json")["labels"]["status"], "done");
}

TEST(RunCli, BadInputsFailWithTheFileNamedAndWriteNothing) {
  const fs::path out = scene_dir().string() + "_out3";
  fs::remove_all(out);
  const fs::path bad_config = scene_dir().string() + "_bad_config.json";
  cls::write_text_atomic(bad_config, "{\"city_model\": ");
  auto r = run_cli("run " + scene_dir().string() + " --out " + out.string() + " --config " + bad_config.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(bad_config.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  r = run_cli("run " + scene_dir().string() + " --out " + out.string() + " --city /nonexistent/model.gml");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/nonexistent/model.gml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  const fs::path empty = scene_dir().string() + "_empty";
  fs::create_directories(empty);
  r = run_cli("run " + empty.string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;  // no city model anywhere: a usage error
  EXPECT_FALSE(fs::exists(out));
}
