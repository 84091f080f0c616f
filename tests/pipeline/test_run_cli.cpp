// End-to-end tests of `citylangsplat run` on a tiny synthetic FZK-Haus scene.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_runner.h"
#include "core/atomic_file.h"
#include "core/exit_codes.h"
#include "models/temp_dir.h"

namespace fs = std::filesystem;
using cls::test::run_cli;

namespace {

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

// The shared scene and what the tests make beside it, in one directory per process that goes with the
// process (ctest runs every test in a process of its own).
fs::path work_path(const std::string& name) {
  static const cls::test::TempDir root("cls_run_cli_");
  return root.path / name;
}

// One tiny synthetic scene shared by the tests of this file (4 views of 120x90).
const fs::path& scene_dir() {
  static const fs::path dir = [] {
    const fs::path d = work_path("scene");
    const auto r = run_cli("-q synth --city " + kFzk + " --out " + d.string() +
                           " --views 4 --width 120 --height 90 --gt-density 20 --seed 3");
    EXPECT_EQ(r.status, 0) << r.err;
    return d;
  }();
  return dir;
}

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(cls::read_text_file(p)); }

// No weights anywhere the model registry looks (for this test process and the commands it runs).
void hide_model_weights() {
  const fs::path no_models = work_path("no_models");
  fs::create_directories(no_models);
  ::setenv("HOME", no_models.c_str(), 1);
  ::setenv("XDG_CACHE_HOME", no_models.c_str(), 1);
  ::unsetenv("CITYLANGSPLAT_MODELS");
}

// The synthetic ground truth (rendered with clutter by the generator) carries the level-1 class wherever
// the city model is visible: the share of those pixels where the run's level-1 label map agrees. Clutter
// only removes GT labels, so pixels with GT 0 are not compared.
double label_agreement(const fs::path& scene, const fs::path& out, int views) {
  size_t compared = 0, agree = 0;
  for (int k = 0; k < views; ++k) {
    char stem[8];
    std::snprintf(stem, sizeof stem, "%04d", k);
    const cv::Mat gt = cv::imread((scene / "gt" / "labels" / (std::string(stem) + ".png")).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat l1 = cv::imread((out / "labels" / stem / "level1.png").string(), cv::IMREAD_UNCHANGED);
    EXPECT_FALSE(gt.empty() || l1.empty()) << stem;
    if (gt.empty() || l1.empty() || gt.size() != l1.size() || l1.type() != CV_16UC1) return 0;
    for (int y = 0; y < gt.rows; ++y)
      for (int x = 0; x < gt.cols; ++x) {
        const uint16_t g = gt.at<uint16_t>(y, x);
        if (g == 0) continue;
        ++compared;
        agree += l1.at<uint16_t>(y, x) == g;
      }
  }
  EXPECT_GT(compared, 1000u);
  return compared ? static_cast<double>(agree) / compared : 0;
}

}  // namespace

TEST(RunCli, LabelMapsAgreeWithTheSyntheticGroundTruth) {
  const fs::path out = work_path("out1");
  fs::remove_all(out);
  // --models real without weights: the run stops before the features with its own exit status,
  // saying how to get them.
  hide_model_weights();
  const auto r = run_cli("run " + scene_dir().string() + " --models real --out " + out.string());
  ASSERT_EQ(r.status, cls::kExitMissingWeights) << r.err;
  EXPECT_NE(r.err.find("stopped before the features"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("models download"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--models tiny"), std::string::npos) << r.err;
  const auto record = read_json(out / "run.json");
  EXPECT_EQ(record["labels"]["status"], "done");
  EXPECT_EQ(record["features"]["status"], "stopped: no model weights");
  EXPECT_FALSE(fs::exists(out / "features"));
  EXPECT_TRUE(fs::exists(out / "labels" / "legend.json"));
  EXPECT_TRUE(fs::exists(out / "report" / "index.html")) << "a run that stopped early has its report too";
  // Weight files named with the default --models auto are a request for the real models: a wrong path
  // fails the same way instead of falling back to synthetic features.
  const auto named = run_cli("run " + scene_dir().string() + " --clip /nonexistent/clip.bin --out " + out.string());
  EXPECT_EQ(named.status, cls::kExitMissingWeights) << named.err;
  EXPECT_NE(named.err.find("/nonexistent/clip.bin"), std::string::npos) << named.err;
  EXPECT_GE(label_agreement(scene_dir(), out, 4), 0.999);
}

// run --align auto on a scene whose city transform is 1 m, 2 deg and 1% off: the refinement is applied
// before the label maps, which then agree with the ground truth as with the exact transform; with
// --align off they do not.
TEST(RunCli, AlignAutoRefinesAMisplacedCityModelBeforeTheLabelMaps) {
  const fs::path scene = fs::temp_directory_path() / ("cls_run_misaligned_" + std::to_string(::getpid()));
  fs::remove_all(scene);
  const auto made = run_cli("-q synth --city " + kFzk + " --out " + scene.string() +
                            " --views 8 --width 120 --height 90 --gt-density 20 --seed 3 --city-error t=1,r=2,s=0.01");
  ASSERT_EQ(made.status, 0) << made.err;
  hide_model_weights();
  const fs::path out = scene.string() + "_out";
  auto r = run_cli("run " + scene.string() + " --models real --out " + out.string());
  ASSERT_EQ(r.status, cls::kExitMissingWeights) << r.err;
  const auto align = read_json(out / "run.json")["align"];
  EXPECT_EQ(align["mode"], "auto");
  EXPECT_TRUE(align["applied"].get<bool>()) << align.dump();
  EXPECT_GT(align["change"]["max_displacement"].get<double>(), 1.0);
  EXPECT_TRUE(fs::exists(out / "align" / "transform.json"));
  EXPECT_GE(label_agreement(scene, out, 8), 0.99);

  r = run_cli("-q run " + scene.string() + " --models real --align off --out " + out.string());
  ASSERT_EQ(r.status, cls::kExitMissingWeights) << r.err;
  EXPECT_EQ(read_json(out / "run.json")["labels"]["status"], "done");  // another transform: redone
  EXPECT_FALSE(read_json(out / "run.json")["align"]["applied"].get<bool>());
  EXPECT_LT(label_agreement(scene, out, 8), 0.9);
  fs::remove_all(scene);
  fs::remove_all(out);
}

TEST(RunCli, SecondRunReusesLabelsAndAChangedTransformRedoesThem) {
  const fs::path out = work_path("out2");
  fs::remove_all(out);
  // --align off: the transform given is the one the label maps use, whatever a refinement would find.
  const std::string run = "run " + scene_dir().string() + " --models real --align off --out " + out.string();
  hide_model_weights();
  ASSERT_EQ(run_cli("-q " + run).status, cls::kExitMissingWeights);
  const auto stamp_time = fs::last_write_time(out / "labels" / "stage.json");
  const auto again = run_cli(run);
  ASSERT_EQ(again.status, cls::kExitMissingWeights) << again.err;
  EXPECT_EQ(read_json(out / "run.json")["labels"]["status"], "reused");
  EXPECT_EQ(fs::last_write_time(out / "labels" / "stage.json"), stamp_time);

  // The stage is keyed on the transform's bytes: a copy keeps it current, any edit redoes it.
  const fs::path moved = out / "moved_transform.json";
  std::string text = cls::read_text_file(scene_dir() / "city" / "transform.json");
  cls::write_text_atomic(moved, text);
  const auto copied = run_cli("-q " + run + " --city-transform " + moved.string());
  ASSERT_EQ(copied.status, cls::kExitMissingWeights) << copied.err;
  EXPECT_EQ(read_json(out / "run.json")["labels"]["status"], "reused");  // same bytes: still current
  cls::write_text_atomic(moved, text + " ");                              // same meaning, other bytes
  ASSERT_EQ(run_cli("-q " + run + " --city-transform " + moved.string()).status, cls::kExitMissingWeights);
  EXPECT_EQ(read_json(out / "run.json")["labels"]["status"], "done");
}

TEST(RunCli, BadInputsFailWithTheFileNamedAndWriteNothing) {
  const fs::path out = work_path("out3");
  fs::remove_all(out);
  const fs::path bad_config = work_path("bad_config.json");
  cls::write_text_atomic(bad_config, "{\"city_model\": ");
  auto r = run_cli("run " + scene_dir().string() + " --out " + out.string() + " --config " + bad_config.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(bad_config.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  r = run_cli("run " + scene_dir().string() + " --out " + out.string() + " --city /nonexistent/model.gml");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/nonexistent/model.gml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

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
  const std::string cmd = "run " + (base / "fzk-haus").string() + " --models tiny --out " + out.string();
  const auto first = run_cli(cmd);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.err.find("tiny random"), std::string::npos);
  const auto record = read_json(out / "run.json");
  for (const char* stage : {"labels", "features", "autoencoder", "train-rgb", "render", "evaluate"})
    EXPECT_EQ(record[stage]["status"], "done") << stage;
  for (const char* method : {"citylangsplat", "langsplat"}) {
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
  EXPECT_EQ(record["stages"].front(), "labels");
  for (const auto& stage : record["stages"]) {
    const std::string name = stage.get<std::string>();
    const size_t slash = name.find('/');
    const auto& entry = slash == std::string::npos ? record[name] : record[name.substr(0, slash)][name.substr(slash + 1)];
    EXPECT_GE(entry["seconds"].get<double>(), 0.0) << name;
  }
  // One evaluation writer: `evaluate` on the run's own models and label maps writes the same bytes.
  const fs::path eval_again = base / "eval_again";
  const auto evaluated = run_cli("-q evaluate --scene " + (base / "fzk-haus").string() + " --model citylangsplat=" +
                                 (out / "language" / "citylangsplat").string() + " --model langsplat=" +
                                 (out / "language" / "langsplat").string() + " --labels " + (out / "labels").string() +
                                 " --out " + eval_again.string());
  ASSERT_EQ(evaluated.status, 0) << evaluated.err;
  EXPECT_EQ(cls::read_text_file(eval_again / "eval.json"), cls::read_text_file(out / "eval" / "eval.json"));
  EXPECT_TRUE(read_json(eval_again / "eval.json")["methods"].is_array());

  const auto second = run_cli(cmd);
  ASSERT_EQ(second.status, 0) << second.err;
  const auto again = read_json(out / "run.json");
  for (const char* stage : {"labels", "features", "autoencoder", "train-rgb", "render", "evaluate"})
    EXPECT_EQ(again[stage]["status"], "reused") << stage;
  for (const char* method : {"citylangsplat", "langsplat"}) {
    EXPECT_EQ(again["train-language"][method]["status"], "reused") << method;
    EXPECT_EQ(again["query"][method]["status"], "reused") << method;
  }
  fs::remove_all(base);
}

// Stage reuse follows the inputs: a changed image redoes the features and everything trained on
// them but not the label maps; a changed city transform redoes the label maps and the features but
// not the photometric model, which never sees the city model.
TEST(RunCli, ChangedInputsRedoExactlyTheStagesThatDependOnThem) {
  const fs::path scene = work_path("reuse");
  fs::remove_all(scene);
  fs::copy(scene_dir(), scene, fs::copy_options::recursive);
  const fs::path out = scene / "out";
  // The default --models auto without weights runs every stage with synthetic features and says so.
  hide_model_weights();
  const std::string cmd = "run " + scene.string() + " --rgb-iterations 5 --language-iterations 2 --out " + out.string();
  const auto first = run_cli(cmd);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.err.find("no CLIP/SAM weights found"), std::string::npos) << first.err;
  EXPECT_NE(first.err.find("synthetic features, not CLIP"), std::string::npos) << first.err;
  ASSERT_EQ(run_cli(cmd).status, 0);
  auto record = read_json(out / "run.json");
  EXPECT_EQ(record["models"], "synthetic");
  EXPECT_NE(record["warning"].get<std::string>().find("synthetic features, not CLIP"), std::string::npos);
  EXPECT_EQ(record["settings"]["models"], "auto");
  for (const char* stage : {"labels", "features", "autoencoder", "train-rgb", "evaluate"})
    EXPECT_EQ(record[stage]["status"], "reused") << stage;

  // One pixel of one image: at the centre, where the building is (a pixel no Gaussian reaches, as in a
  // corner of sky, may leave every trained latent unchanged).
  const fs::path image = scene / "images" / "0001.png";
  cv::Mat pixels = cv::imread(image.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(pixels.empty());
  cv::Vec3b& centre = pixels.at<cv::Vec3b>(pixels.rows / 2, pixels.cols / 2);
  centre = cv::Vec3b(centre[0] ^ 0x40, 1, 2);
  ASSERT_TRUE(cv::imwrite(image.string(), pixels));
  ASSERT_EQ(run_cli(cmd).status, 0);
  record = read_json(out / "run.json");
  EXPECT_EQ(record["labels"]["status"], "reused");
  EXPECT_EQ(record["features"]["status"], "done");
  EXPECT_EQ(record["features"]["computed_views"], 1);
  for (const char* stage : {"autoencoder", "train-rgb", "render", "evaluate"})
    EXPECT_EQ(record[stage]["status"], "done") << stage;
  EXPECT_EQ(record["train-language"]["citylangsplat"]["status"], "done");

  // The city transform's bytes (same meaning).
  const fs::path transform = scene / "city" / "transform.json";
  cls::write_text_atomic(transform, cls::read_text_file(transform) + " ");
  ASSERT_EQ(run_cli(cmd).status, 0);
  record = read_json(out / "run.json");
  EXPECT_EQ(record["labels"]["status"], "done");
  EXPECT_EQ(record["train-rgb"]["status"], "reused");
  EXPECT_EQ(record["render"]["status"], "reused");  // pictures of the photometric model only

  // Another CityGML weight retrains CityLangSplat only: the baseline's objective has no lambdas.
  ASSERT_EQ(run_cli(cmd + " --lambda-citygml 0.25").status, 0);
  record = read_json(out / "run.json");
  EXPECT_EQ(record["train-language"]["citylangsplat"]["status"], "done");
  EXPECT_EQ(record["train-language"]["langsplat"]["status"], "reused");

  // The published LangSplat beside them: its own 3-d autoencoder and field; the others are reused.
  ASSERT_EQ(run_cli(cmd + " --lambda-citygml 0.25 --baseline langsplat,langsplat-original").status, 0);
  record = read_json(out / "run.json");
  EXPECT_EQ(record["train-language"]["citylangsplat"]["status"], "reused");
  EXPECT_EQ(record["train-language"]["langsplat"]["status"], "reused");
  EXPECT_EQ(record["autoencoder"]["status"], "reused");
  EXPECT_EQ(record["autoencoder-langsplat"]["status"], "done");
  EXPECT_EQ(record["train-language"]["langsplat-original"]["status"], "done");
  const auto original = read_json(out / "language" / "langsplat-original" / "model.json");
  EXPECT_EQ(original["normalize_latents"], true);
  EXPECT_EQ(original["method"], "langsplat");
  const auto eval = read_json(out / "eval" / "eval.json");
  EXPECT_TRUE(eval["results"].contains("langsplat-original")) << eval.dump();
  EXPECT_NE(run_cli(cmd + " --baseline langsplat,other").status, 0);
  fs::remove_all(scene);
}
