// The features stage on a tiny synthetic scene: caching, resuming, the CLI, and one run of the
// real CLIP/SAM code path with tiny random models.
#include <ATen/ATen.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_runner.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "features/feature_stage.h"
#include "features/image_segment_provider.h"
#include "features/synthetic_provider.h"
#include "features/view_features.h"

namespace cls {
namespace {
namespace fs = std::filesystem;
using test::run_cli;

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

// One tiny synthetic scene (3 views of 96 x 72) and its label maps, shared by the tests and
// removed at exit.
struct SceneDir {
  fs::path path;
  ~SceneDir() { fs::remove_all(path); }
};

const fs::path& scene_dir() {
  static const SceneDir dir{[] {
    const fs::path d = fs::temp_directory_path() / ("cls_features_scene_" + std::to_string(::getpid()));
    fs::remove_all(d);
    auto r = run_cli("-q synth --city " + kFzk + " --out " + d.string() +
                     " --views 3 --width 96 --height 72 --gt-density 20 --seed 3");
    EXPECT_EQ(r.status, 0) << r.err;
    r = run_cli("-q raycast --scene " + d.string() + " --city " + (d / "city/fzk_haus_lod3_v2.gml").string() +
                " --city-transform " + (d / "city/transform.json").string() + " --out " + (d / "labels").string());
    EXPECT_EQ(r.status, 0) << r.err;
    return d;
  }()};
  return dir.path;
}

struct StageFixture : ::testing::Test {
  void SetUp() override {
    set_log_level(LogLevel::Quiet);
    scene = load_scene(scene_dir().string());
    out = scene_dir().string() + "_out_" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(out);
    options.labels_dir = scene_dir() / "labels";
    options.out_dir = out;
  }
  void TearDown() override { fs::remove_all(out); }
  std::string stem(size_t k) const { return fs::path(scene.views[k].name).stem().string(); }

  Scene scene;
  fs::path out;
  FeatureStageOptions options;
  Taxonomy taxonomy = Taxonomy::builtin();
};

TEST_F(StageFixture, WritesEveryViewAndResumesFromTheCache) {
  SyntheticFeatureProvider provider(SyntheticProviderParams{}, taxonomy);
  ASSERT_EQ(scene.views.size(), 3u);
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 3);
  ASSERT_TRUE(fs::exists(out / "features.json"));
  const auto record = nlohmann::json::parse(read_text_file(out / "features.json"));
  EXPECT_EQ(record["views"].size(), 3u);
  EXPECT_EQ(record["alpha"], 0.5);
  EXPECT_EQ(record["provider"]["provider"], "synthetic");

  // The CityGML branch: seg ids agree with the label maps and the regions' classes.
  const ViewFeatures f = read_view_features(out, stem(0));
  EXPECT_EQ(f.width, 96);
  EXPECT_EQ(f.height, 72);
  EXPECT_EQ(f.sam_features.size(1), 512);
  ASSERT_GT(f.regions.size(), 2u);
  const cv::Mat l2 = cv::imread((options.labels_dir / stem(0) / "level2.png").string(), cv::IMREAD_UNCHANGED);
  int checked = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x)
      if (const int32_t id = f.gml_at(2, y, x); id >= 0) {
        EXPECT_EQ(f.regions[id].class_id + 1, l2.at<uint16_t>(y, x));
        EXPECT_EQ(f.regions[id].level, 2);
        ++checked;
      }
  EXPECT_GT(checked, 0);
  // Fused rows are unit vectors close to their class (synthetic: gml and text both near u_c).
  const auto u_wall = provider.class_vector(taxonomy.find("wall"));
  for (size_t r = 0; r < f.regions.size(); ++r) {
    EXPECT_NEAR(f.gml_features[r].norm().item<double>(), 1.0, 1e-5);
    if (f.regions[r].class_name == "wall")
      EXPECT_GT((f.gml_features[r] * at::tensor(u_wall)).sum().item<double>(), 0.9);
  }

  // Second run: nothing to do.
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 0);
  // One view's json removed: exactly that view is recomputed; the others' files stay untouched.
  const auto t0 = fs::last_write_time(out / (stem(0) + "_f.npy"));
  const auto t2 = fs::last_write_time(out / (stem(2) + "_f.npy"));
  fs::remove(out / (stem(1) + "_gml.json"));
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 1);
  EXPECT_TRUE(view_features_complete(out, stem(1)));
  EXPECT_EQ(fs::last_write_time(out / (stem(0) + "_f.npy")), t0);
  EXPECT_EQ(fs::last_write_time(out / (stem(2) + "_f.npy")), t2);
  // A different alpha or region mode invalidates every view; --overwrite recomputes everything.
  options.alpha = 0.3;
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 3);
  options.region_mode = RegionMode::Instance;
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 3);
  const ViewFeatures g = read_view_features(out, stem(0));
  EXPECT_GE(g.regions.size(), f.regions.size());
  for (const auto& r : g.regions) EXPECT_GE(r.instance, 0);
  options.overwrite = true;
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 3);
}

TEST_F(StageFixture, ChangedLabelMapsInvalidateTheirView) {
  SyntheticFeatureProvider provider(SyntheticProviderParams{}, taxonomy);
  const fs::path labels = out.string() + "_labels";
  fs::remove_all(labels);
  fs::copy(options.labels_dir, labels, fs::copy_options::recursive);
  options.labels_dir = labels;
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 3);
  cv::Mat c = cv::imread((labels / stem(2) / "coverage.png").string(), cv::IMREAD_UNCHANGED);
  c.setTo(0);
  cv::imwrite((labels / stem(2) / "coverage.png").string(), c);
  EXPECT_EQ(run_feature_stage(scene, provider, taxonomy, options), 1);
  // No coverage: no CityGML regions.
  EXPECT_TRUE(read_view_features(out, stem(2)).regions.empty());
  fs::remove(labels / stem(0) / "level1.png");
  EXPECT_THROW(run_feature_stage(scene, provider, taxonomy, options), Error);
  fs::remove_all(labels);
}

// The image-segment provider's SAM branch comes from the images and the ground truth only: blanking every
// label map and coverage mask leaves it byte for byte the same (and removes the CityGML regions).
TEST_F(StageFixture, ImageSegmentsSamBranchNeverReadsTheLabelMaps) {
  ImageSegmentParams params;
  params.gt_labels = (scene_dir() / "gt" / "labels").string();
  ImageSegmentProvider provider(params, taxonomy);
  ASSERT_EQ(run_feature_stage(scene, provider, taxonomy, options), 3);
  const fs::path labels = out.string() + "_blank_labels", blank_out = out.string() + "_blank";
  fs::remove_all(labels);
  fs::remove_all(blank_out);
  fs::copy(options.labels_dir, labels, fs::copy_options::recursive);
  for (size_t k = 0; k < scene.views.size(); ++k)
    for (const char* file : {"level1.png", "level2.png", "level3.png", "coverage.png"}) {
      cv::Mat m = cv::imread((labels / stem(k) / file).string(), cv::IMREAD_UNCHANGED);
      m.setTo(0);
      cv::imwrite((labels / stem(k) / file).string(), m);
    }
  FeatureStageOptions blank = options;
  blank.labels_dir = labels;
  blank.out_dir = blank_out;
  ASSERT_EQ(run_feature_stage(scene, provider, taxonomy, blank), 3);
  for (size_t k = 0; k < scene.views.size(); ++k) {
    const ViewFeatures a = read_view_features(out, stem(k)), b = read_view_features(blank_out, stem(k));
    EXPECT_EQ(a.sam_seg, b.sam_seg) << stem(k);
    EXPECT_TRUE(at::equal(a.sam_features, b.sam_features)) << stem(k);
    EXPECT_FALSE(a.regions.empty());
    EXPECT_TRUE(b.regions.empty());
  }
  fs::remove_all(labels);
  fs::remove_all(blank_out);
}

TEST(FeaturesCli, ErrorsAreClear) {
  const fs::path out = fs::temp_directory_path() / ("cls_features_cli_" + std::to_string(::getpid()));
  auto r = run_cli("features --scene " + scene_dir().string() + " --labels " + (scene_dir() / "no_labels").string() +
                   " --out " + out.string() + " --models synthetic");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no_labels"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("citylangsplat raycast"), std::string::npos) << r.err;
  r = run_cli("features --scene " + scene_dir().string() + " --labels " + (scene_dir() / "labels").string() +
              " --out " + out.string() + " --models magic");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("magic"), std::string::npos) << r.err;
  r = run_cli("features --scene " + scene_dir().string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--labels"), std::string::npos) << r.err;
  r = run_cli("features --scene " + scene_dir().string() + " --labels " + (scene_dir() / "labels").string() +
              " --out " + out.string() + " --models synthetic --regions blobs");
  EXPECT_EQ(r.status, 2);
  // Real weights absent: the message says how to get them.
  r = run_cli("features --scene " + scene_dir().string() + " --labels " + (scene_dir() / "labels").string() +
              " --out " + out.string() + " --models clip --models-dir " + (out / "no_models").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("citylangsplat models download openclip-vit-b-16-laion2b"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("citylangsplat models download sam-vit-h"), std::string::npos) << r.err;
  // A working run, then a second that reuses every view.
  r = run_cli("features --scene " + scene_dir().string() + " --labels " + (scene_dir() / "labels").string() +
              " --out " + out.string() + " --models synthetic --regions instance");
  EXPECT_EQ(r.status, 0) << r.err;
  r = run_cli("features --scene " + scene_dir().string() + " --labels " + (scene_dir() / "labels").string() +
              " --out " + out.string() + " --models synthetic --regions instance");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("computed 0 of 3 views"), std::string::npos) << r.err;
  fs::remove_all(out);
}

// The real code path (AMG, masks_update, seg maps, CLIP crops and text) with tiny random models.
TEST(ClipTinyProvider, RunsTheRealCodePath) {
  const Taxonomy taxonomy = Taxonomy::builtin();
  const auto provider = make_feature_provider({{"provider", "clip-tiny"}, {"seed", 1}}, taxonomy);
  EXPECT_EQ(provider->name(), "clip-tiny");
  EXPECT_NE(provider->spec().dump().find("meaningless"), std::string::npos);
  const int d = provider->dim();
  EXPECT_EQ(d, 512);  // the real models' width, so later stages see the usual shapes
  FeatureView v;
  v.name = "tiny.png";
  v.rgb = cv::Mat(40, 56, CV_8UC3);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 56; ++x) v.rgb.at<cv::Vec3b>(y, x) = x < 28 ? cv::Vec3b(200, 40, 40) : cv::Vec3b(30, 60, 220);
  const SamSegments s = provider->sam_segments(v);
  ASSERT_EQ(s.seg.size(), 4u * 40 * 56);
  ASSERT_EQ(s.features.dim(), 2);
  EXPECT_EQ(s.features.size(1), d);
  EXPECT_GT(s.features.size(0), 0) << "the relaxed AMG should find masks even with a random SAM";
  for (const int32_t id : s.seg) ASSERT_TRUE(id >= -1 && id < s.features.size(0));
  if (s.features.size(0) > 0)
    EXPECT_TRUE(at::allclose(s.features.norm(2, 1), at::ones({s.features.size(0)}), 1e-4, 1e-4));

  RegionMask r;
  r.mask = cv::Mat::zeros(40, 56, CV_8UC1);
  r.mask(cv::Rect(0, 0, 28, 40)).setTo(255);
  const at::Tensor g = provider->region_features(v, {r, r});
  ASSERT_EQ(g.size(0), 2);
  EXPECT_NEAR(g[0].norm().item<double>(), 1.0, 1e-4);
  EXPECT_TRUE(at::allclose(g[0], g[1]));
  const at::Tensor t = provider->text_features({"a window on a building facade", "a roof of a building"});
  ASSERT_EQ(t.size(0), 2);
  EXPECT_EQ(t.size(1), d);
  EXPECT_NEAR(t[1].norm().item<double>(), 1.0, 1e-4);
  EXPECT_FALSE(at::allclose(t[0], t[1]));
}

}  // namespace
}  // namespace cls
