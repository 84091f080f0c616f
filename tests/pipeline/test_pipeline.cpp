// run_pipeline in this process on tiny synthetic FZK-Haus scenes: what a run records, which stages a
// second run reuses, which a changed input redoes, how an interrupted run resumes, and what it refuses.
// The CLI's own smoke test is test_run_cli.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <ATen/ATen.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/run_layout.h"
#include "language/language_model.h"
#include "models/temp_dir.h"
#include "pipeline/pipeline.h"
#include "query/query_job.h"
#include "synth/city_error.h"
#include "synth/synth_job.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";
// An official LoD2 tile as published: multi-part buildings as Building -> BuildingPart (CityGML 1.0).
const std::string kNrwTile = CLS_TEST_DATA "/citygml/nrw/LoD2_32_329_5730_1_NW.gml";

fs::path work_path(const std::string& name) {
  static const test::TempDir root("cls_pipeline_");
  return root.path / name;
}

// A synthetic scene of `views` views of 120x90 (seed 3), optionally with a city transform off the truth;
// of another city model, a district with the views shared out over its buildings.
fs::path make_scene(const std::string& name, int views, const std::string& city_error = "",
                    const std::string& city = kFzk) {
  synth::SynthJob job;
  job.city_path = city;
  job.settings.per_building = city != kFzk;
  job.out_dir = work_path(name).string();
  job.settings.views = views;
  job.settings.width = 120;
  job.settings.height = 90;
  job.settings.gt_density = 20;
  job.settings.seed = 3;
  if (!city_error.empty()) job.city_error = synth::parse_city_error(city_error);
  synth::run_synth_job(job);
  return job.out_dir;
}

// The four-view scene most tests share (each test copies what it changes).
const fs::path& shared_scene() {
  static const fs::path dir = make_scene("scene", 4);
  return dir;
}

fs::path copy_scene(const std::string& name) {
  const fs::path to = work_path(name);
  fs::remove_all(to);
  fs::copy(shared_scene(), to, fs::copy_options::recursive);
  return to;
}

// No weights anywhere the model registry looks.
void hide_model_weights() {
  const fs::path none = work_path("no_models");
  fs::create_directories(none);
  ::setenv("HOME", none.c_str(), 1);
  ::setenv("XDG_CACHE_HOME", none.c_str(), 1);
  ::unsetenv("CITYLANGSPLAT_MODELS");
}

// The configuration `run SCENE --models M --out OUT` gives, with scene.json read as run reads it.
PipelineConfig config_of(const fs::path& scene, const fs::path& out, const std::string& models) {
  PipelineConfig c;
  c.scene_dir = scene;
  c.out_dir = out;
  c.features.models = models;
  read_scene_config(SceneFiles{scene}.config(), c);
  return c;
}

// A short synthetic schedule: every stage runs, in seconds.
PipelineConfig quick(const fs::path& scene, const fs::path& out) {
  PipelineConfig c = config_of(scene, out, "synthetic");
  c.rgb_iterations = 5;
  c.language_iterations = 2;
  c.autoencoder_epochs = 3;
  c.baselines = {"langsplat"};  // the baseline on the shared autoencoder: no second autoencoder to train
  return c;
}

nlohmann::json record_of(const fs::path& out) { return nlohmann::json::parse(read_text_file(RunLayout(out).run_json())); }

// A stage's status in run.json ("train-language/langsplat" is record["train-language"]["langsplat"]).
std::string status(const nlohmann::json& record, const std::string& stage) {
  const size_t slash = stage.find('/');
  const nlohmann::json& entry =
      slash == std::string::npos ? record.at(stage) : record.at(stage.substr(0, slash)).at(stage.substr(slash + 1));
  return entry.at("status").get<std::string>();
}

const std::vector<std::string> kAllStages = {"labels",        "features",       "autoencoder",
                                             "train-rgb",     "render",         "train-language/citylangsplat",
                                             "train-language/langsplat",        "query/citylangsplat",
                                             "query/langsplat", "evaluate"};

// The synthetic GT carries the level-1 class wherever the city model is visible: the share of those
// pixels where the run's level-1 label map agrees (clutter only removes GT labels; GT 0 is not compared).
double label_agreement(const fs::path& scene, const fs::path& out, int views) {
  size_t compared = 0, agree = 0;
  for (int k = 0; k < views; ++k) {
    char stem[8];
    std::snprintf(stem, sizeof stem, "%04d", k);
    const cv::Mat gt = cv::imread((SceneFiles{scene}.gt_labels() / (std::string(stem) + ".png")).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat l1 = cv::imread((RunLayout(out).labels() / stem / "level1.png").string(), cv::IMREAD_UNCHANGED);
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

// The gml:ids of the elements `<tag ` of a file, read from its text.
std::set<std::string> ids_of(const std::string& file, const std::string& tag) {
  const std::string text = read_text_file(file);
  std::set<std::string> ids;
  for (size_t at = text.find(tag + " "); at != std::string::npos; at = text.find(tag + " ", at + 1)) {
    const size_t id = text.find("gml:id=\"", at);
    if (id == std::string::npos || id > text.find('>', at)) continue;
    ids.insert(text.substr(id + 8, text.find('"', id + 8) - id - 8));
  }
  return ids;
}

}  // namespace

// An official LoD2 tile whose buildings have BuildingParts runs through every stage (it once stopped
// after the language training: "a parent must lie on a coarser level"), and its answers name whole
// Buildings at level 3 and list a part's surfaces with their Building and part.
TEST(Pipeline, APublishedTileWithBuildingPartsRunsToTheEndAndAnswersWithItsBuildings) {
  hide_model_weights();
  const std::set<std::string> buildings = ids_of(kNrwTile, "<bldg:Building"), parts = ids_of(kNrwTile, "<bldg:BuildingPart");
  ASSERT_FALSE(parts.empty());
  const fs::path scene = make_scene("nrw", static_cast<int>(buildings.size()), "", kNrwTile);  // a view per building
  const fs::path out = work_path("nrw_out");
  const PipelineResult r = run_pipeline(quick(scene, out));
  ASSERT_EQ(r.outcome, PipelineOutcome::Finished) << r.message;
  QueryOptions q;
  q.model_dir = RunLayout(out).language("citylangsplat").string();
  q.texts = {"roof"};
  q.maps = false;
  q.objects = true;
  q.scene_dir = scene.string();
  size_t rows_in_parts = 0;
  for (const std::string level : {"3", "2"}) {
    q.level = level;
    q.out_dir = (out / ("objects_" + level)).string();
    run_query(q);
    const nlohmann::json rows =
        nlohmann::json::parse(read_text_file(fs::path(q.out_dir) / "objects_roof.json")).at("objects");
    ASSERT_FALSE(rows.empty()) << level;
    for (const nlohmann::json& row : rows) {
      EXPECT_EQ(buildings.count(row["building"].get<std::string>()), 1u) << row.dump();
      if (level == "3") {
        EXPECT_EQ(buildings.count(row["id"].get<std::string>()), 1u) << row.dump();
        EXPECT_EQ(row["part"], "") << row.dump();  // the whole building answers, in no part
      }
      const std::string part = row["part"].get<std::string>();
      EXPECT_TRUE(part.empty() || parts.count(part)) << row.dump();
      rows_in_parts += !part.empty();
    }
  }
  EXPECT_GT(rows_in_parts, 0u) << "no surface of a BuildingPart answered";
}

// --models clip without weights: the label maps are made (and agree with the synthetic ground truth),
// then the run stops before the features, says how to get the weights and still writes its report.
TEST(Pipeline, MissingWeightsStopBeforeTheFeaturesAfterCorrectLabelMaps) {
  hide_model_weights();
  const fs::path out = work_path("missing_weights");
  const PipelineResult r = run_pipeline(config_of(shared_scene(), out, "clip"));
  EXPECT_EQ(r.outcome, PipelineOutcome::MissingWeights);
  EXPECT_EQ(exit_code(r.outcome), 4);
  EXPECT_NE(r.message.find("models download"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("--models clip-tiny"), std::string::npos) << r.message;
  const nlohmann::json record = record_of(out);
  EXPECT_EQ(status(record, "labels"), "done");
  EXPECT_EQ(status(record, "features"), "stopped: no model weights");
  EXPECT_FALSE(fs::exists(RunLayout(out).features()));
  EXPECT_TRUE(fs::exists(r.report)) << "a run that stopped early has its report too";
  EXPECT_GE(label_agreement(shared_scene(), out, 4), 0.999);
  // Weight files named with --models auto are a request for the real models: a wrong path fails the
  // same way instead of falling back to synthetic features.
  PipelineConfig named = config_of(shared_scene(), out, "auto");
  named.features.clip = "/nonexistent/clip.bin";
  const PipelineResult n = run_pipeline(named);
  EXPECT_EQ(n.outcome, PipelineOutcome::MissingWeights);
  EXPECT_NE(n.message.find("/nonexistent/clip.bin"), std::string::npos) << n.message;
}

// --align auto on a scene whose city transform is 1 m, 2 deg and 1% off: the refinement is applied before
// the label maps, which then agree with the ground truth as with the exact transform; with --align off
// they do not, and the label maps are redone.
TEST(Pipeline, AlignAutoRefinesAMisplacedCityModelBeforeTheLabelMaps) {
  hide_model_weights();
  const fs::path scene = make_scene("misaligned", 8, "t=1,r=2,s=0.01");
  const fs::path out = work_path("misaligned_out");
  PipelineConfig c = config_of(scene, out, "clip");
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::MissingWeights);
  const nlohmann::json align = record_of(out)["align"];
  EXPECT_EQ(align["mode"], "auto");
  EXPECT_TRUE(align["applied"].get<bool>()) << align.dump();
  EXPECT_GT(align["change"]["max_displacement"].get<double>(), 1.0);
  EXPECT_TRUE(fs::exists(RunLayout(out).align_transform()));
  EXPECT_GE(label_agreement(scene, out, 8), 0.99);

  c.align = "off";
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::MissingWeights);
  EXPECT_EQ(status(record_of(out), "labels"), "done");  // another transform: redone
  EXPECT_FALSE(record_of(out)["align"]["applied"].get<bool>());
  EXPECT_FALSE(fs::exists(RunLayout(out).align_transform()));
  EXPECT_LT(label_agreement(scene, out, 8), 0.9);
}

// Stage reuse follows the inputs: a second run reuses every stage; a changed image redoes the features
// and everything trained on them but not the label maps; a changed city transform redoes the label maps
// and what depends on them but not the photometric model, which never sees the city model; a lambda
// retrains CityLangSplat only.
TEST(Pipeline, ASecondRunReusesEveryStageAndChangedInputsRedoExactlyTheirDependants) {
  hide_model_weights();
  const fs::path scene = copy_scene("reuse");
  const fs::path out = scene / "out";
  const PipelineConfig c = quick(scene, out);
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::Finished);
  nlohmann::json record = record_of(out);
  for (const std::string& stage : kAllStages) EXPECT_EQ(status(record, stage), "done") << stage;
  EXPECT_EQ(record["models"], "synthetic");
  EXPECT_NE(record["warning"].get<std::string>().find("synthetic features, not CLIP"), std::string::npos);
  EXPECT_EQ(record["settings"]["models"], "synthetic");
  EXPECT_EQ(record["settings"]["rgb_iterations"], 5);
  // The stages in the order they ran, each with its time.
  std::vector<std::string> order;
  for (const auto& s : record["stages"]) order.push_back(s.get<std::string>());
  std::vector<std::string> expected = {"georef", "align"};
  expected.insert(expected.end(), kAllStages.begin(), kAllStages.end());
  EXPECT_EQ(order, expected);
  EXPECT_EQ(status(record, "georef"), "skipped: a city transform is given") << "synth's scene.json names one";

  const auto stamp_time = fs::last_write_time(RunLayout::stamp_in(RunLayout(out).labels()));
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::Finished);
  record = record_of(out);
  for (const std::string& stage : kAllStages) EXPECT_EQ(status(record, stage), "reused") << stage;
  EXPECT_EQ(fs::last_write_time(RunLayout::stamp_in(RunLayout(out).labels())), stamp_time);

  // One pixel of one image, at the centre where the building is (a pixel no Gaussian reaches may leave
  // every trained latent unchanged).
  const fs::path image = scene / "images" / "0001.png";
  cv::Mat pixels = cv::imread(image.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(pixels.empty());
  cv::Vec3b& centre = pixels.at<cv::Vec3b>(pixels.rows / 2, pixels.cols / 2);
  centre = cv::Vec3b(centre[0] ^ 0x40, 1, 2);
  ASSERT_TRUE(cv::imwrite(image.string(), pixels));
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::Finished);
  record = record_of(out);
  EXPECT_EQ(status(record, "labels"), "reused");
  EXPECT_EQ(status(record, "features"), "done");
  EXPECT_EQ(record["features"]["computed_views"], 1);
  for (const char* stage : {"autoencoder", "train-rgb", "render", "train-language/citylangsplat", "evaluate"})
    EXPECT_EQ(status(record, stage), "done") << stage;

  // The city transform's bytes (same meaning): the label maps again, not the photometric model.
  const fs::path transform = scene / "city" / "transform.json";
  write_text_atomic(transform, read_text_file(transform) + " ");
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::Finished);
  record = record_of(out);
  EXPECT_EQ(status(record, "labels"), "done");
  EXPECT_EQ(status(record, "train-rgb"), "reused");
  EXPECT_EQ(status(record, "render"), "reused");  // pictures of the photometric model only

  // Another CityGML weight retrains CityLangSplat only: the baseline's objective has no lambdas.
  PipelineConfig lambda = c;
  lambda.lambda_citygml = 0.25;
  ASSERT_EQ(run_pipeline(lambda).outcome, PipelineOutcome::Finished);
  record = record_of(out);
  EXPECT_EQ(status(record, "train-language/citylangsplat"), "done");
  EXPECT_EQ(status(record, "train-language/langsplat"), "reused");

  // The published LangSplat beside them: its own 3-d autoencoder and field; the others are reused.
  lambda.baselines = {"langsplat", "langsplat-original"};
  ASSERT_EQ(run_pipeline(lambda).outcome, PipelineOutcome::Finished);
  record = record_of(out);
  EXPECT_EQ(status(record, "train-language/citylangsplat"), "reused");
  EXPECT_EQ(status(record, "train-language/langsplat"), "reused");
  EXPECT_EQ(status(record, "autoencoder"), "reused");
  EXPECT_EQ(status(record, "autoencoder-langsplat"), "done");
  EXPECT_EQ(status(record, "train-language/langsplat-original"), "done");
  const nlohmann::json original =
      nlohmann::json::parse(read_text_file(LanguageModelFiles{RunLayout(out).language("langsplat-original")}.model_json()));
  EXPECT_EQ(original["normalize_latents"], true);
  EXPECT_EQ(original["method"], "langsplat");
  const nlohmann::json eval = nlohmann::json::parse(read_text_file(RunLayout(out).eval() / "eval.json"));
  EXPECT_TRUE(eval["results"].contains("langsplat-original")) << eval.dump();
}

// An interrupt during a training stage ends the run after its checkpoint; the same run then resumes
// that checkpoint (run.json says so) and ends where an uninterrupted run ends, reusing every stage before
// it. A checkpoint of other inputs is never resumed.
TEST(Pipeline, AnInterruptedRunResumesItsCheckpointAndEndsAsAnUninterruptedOne) {
  hide_model_weights();
  const fs::path scene = copy_scene("resume");
  PipelineConfig c = quick(scene, scene / "whole");
  c.language_iterations = 6;
  c.baselines = {};
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::Finished);
  const LanguageModel whole = load_language_model(RunLayout(c.out_dir).language("citylangsplat").string());

  c.out_dir = scene / "interrupted";
  const auto interrupt_at = [](const std::string& at) {
    return [at](const std::string& stage) {
      if (stage == at) request_interrupt();
    };
  };
  const PipelineResult stopped = run_pipeline(c, interrupt_at("train-language/citylangsplat"));
  reset_interrupt();
  EXPECT_EQ(stopped.outcome, PipelineOutcome::Interrupted);
  EXPECT_EQ(exit_code(stopped.outcome), 130);
  nlohmann::json record = record_of(c.out_dir);
  EXPECT_EQ(status(record, "train-language/citylangsplat"), "interrupted");
  EXPECT_FALSE(record.contains("query"));
  const fs::path checkpoints = RunLayout::checkpoints(RunLayout(c.out_dir).language("citylangsplat"));
  EXPECT_TRUE(fs::exists(checkpoints)) << checkpoints;

  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::Finished);
  record = record_of(c.out_dir);
  for (const char* stage : {"labels", "features", "autoencoder", "train-rgb", "render"})
    EXPECT_EQ(status(record, stage), "reused") << stage;
  EXPECT_EQ(status(record, "train-language/citylangsplat"), "done");
  EXPECT_TRUE(record["train-language"]["citylangsplat"]["resumed"].get<bool>());
  const LanguageModel resumed = load_language_model(RunLayout(c.out_dir).language("citylangsplat").string());
  for (int l = 0; l < 3; ++l) EXPECT_TRUE(at::equal(whole.latents[l], resumed.latents[l])) << "level " << l + 1;

  // Interrupted again, then run with another lambda: that checkpoint belongs to other inputs.
  fs::remove_all(RunLayout(c.out_dir).language("citylangsplat"));
  ASSERT_EQ(run_pipeline(c, interrupt_at("train-language/citylangsplat")).outcome, PipelineOutcome::Interrupted);
  reset_interrupt();
  c.lambda_citygml = 0.25;
  ASSERT_EQ(run_pipeline(c).outcome, PipelineOutcome::Finished);
  EXPECT_FALSE(record_of(c.out_dir)["train-language"]["citylangsplat"]["resumed"].get<bool>());
}

// A signal during a stage that does not poll it (the autoencoders) ends the run after that stage, also
// between two stages of one step: LangSplat's own autoencoder does not start.
TEST(Pipeline, ASignalBetweenTwoStagesOfAStepStopsTheRunThere) {
  hide_model_weights();
  PipelineConfig c = quick(shared_scene(), work_path("signal_between"));
  c.baselines = {"langsplat-original"};
  const PipelineResult r = run_pipeline(c, [](const std::string& stage) {
    if (stage == "autoencoder") request_interrupt();
  });
  reset_interrupt();
  EXPECT_EQ(r.outcome, PipelineOutcome::Interrupted);
  const nlohmann::json record = record_of(c.out_dir);
  EXPECT_EQ(status(record, "autoencoder"), "done");
  EXPECT_FALSE(record.contains("autoencoder-langsplat"));
  EXPECT_EQ(record["interrupted_after"], "autoencoder");
}

// --stop-after ends the run after that step (tiles stop after the features), with its report.
TEST(Pipeline, StopAfterEndsTheRunAfterThatStep) {
  hide_model_weights();
  PipelineConfig c = quick(shared_scene(), work_path("stop_after"));
  c.stop_after = "features";
  const PipelineResult r = run_pipeline(c);
  EXPECT_EQ(r.outcome, PipelineOutcome::Finished);
  const nlohmann::json record = record_of(c.out_dir);
  EXPECT_EQ(status(record, "features"), "done");
  EXPECT_FALSE(record.contains("autoencoder"));
  EXPECT_TRUE(fs::exists(r.report));
}

// Photos taller than --feature-height: train-rgb and its renders keep the training size, the label maps,
// features, language fields and evaluation use the photos at that height (as LangSplat's 1080P), every
// stage to the end; without it, one size for all.
TEST(Pipeline, LanguageStagesUseThePhotosAtTheFeatureHeight) {
  const cv::Mat photo = cv::imread((shared_scene() / "images" / "0000.png").string());
  ASSERT_FALSE(photo.empty());
  PipelineConfig c = quick(shared_scene(), work_path("feature_height"));
  c.feature_height = photo.rows * 2 / 3;
  const int width = static_cast<int>(photo.cols / (double(photo.rows) / c.feature_height));
  const PipelineResult r = run_pipeline(c);
  EXPECT_EQ(r.outcome, PipelineOutcome::Finished);
  const nlohmann::json record = record_of(c.out_dir);
  for (const std::string& stage : kAllStages) EXPECT_EQ(status(record, stage), "done") << stage;
  const cv::Mat level1 = cv::imread((RunLayout(c.out_dir).labels() / "0000" / "level1.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(level1.rows, c.feature_height);
  EXPECT_EQ(level1.cols, width);
  size_t renders = 0;
  for (const auto& e : fs::recursive_directory_iterator(RunLayout(c.out_dir).render()))
    if (e.path().filename() == "rgb.png") {
      const cv::Mat rgb = cv::imread(e.path().string());
      EXPECT_EQ(rgb.size(), photo.size()) << e.path();
      ++renders;
    }
  EXPECT_GT(renders, 0u);

  c.feature_height = 0;
  run_pipeline(c);
  EXPECT_EQ(status(record_of(c.out_dir), "labels"), "done") << "the label maps are redone at the other size";
  EXPECT_EQ(cv::imread((RunLayout(c.out_dir).labels() / "0000" / "level1.png").string(), cv::IMREAD_UNCHANGED).size(),
            photo.size());
}

// Bad inputs fail with the file named before anything is written.
TEST(Pipeline, BadInputsFailWithTheFileNamedAndWriteNothing) {
  const fs::path out = work_path("bad");
  PipelineConfig c = quick(shared_scene(), out);
  c.city = "/nonexistent/model.gml";
  try {
    run_pipeline(c);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/model.gml"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));

  c = quick(shared_scene(), out);
  c.city.clear();
  EXPECT_THROW(run_pipeline(c), UsageError);  // no city model anywhere
  c = quick(shared_scene(), out);
  c.resolution = 3;
  EXPECT_THROW(run_pipeline(c), UsageError);
  EXPECT_FALSE(fs::exists(out));
}
