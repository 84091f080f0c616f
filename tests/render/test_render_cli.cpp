// `citylangsplat render` end to end on a tiny synthetic scene: a short train-rgb, its 3DGS layout, the
// per-view pictures, an orbit MP4, a language model's features and relevance, and bad inputs.
#include <gtest/gtest.h>
#include <torch/torch.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "cli_runner.h"
#include "core/atomic_file.h"
#include "language/language_model.h"
#include "scene/scene.h"
#include "scene/view_selection.h"
#include "splat/ply_gaussians.h"

namespace cls {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using test::run_cli;

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

// A synthetic scene of 9 views (test split: sorted views 0 and 8), its label maps and a 30-iteration
// photometric model, shared by the tests of this file.
struct Fixture {
  fs::path root, scene, labels, model;
  Fixture() {
    root = fs::temp_directory_path() / ("cls_render_test_" + std::to_string(::getpid()));
    fs::remove_all(root);
    scene = root / "scene";
    labels = root / "labels";
    model = root / "rgb";
    auto r = run_cli("-q synth --city " + kFzk + " --out " + scene.string() +
                     " --views 9 --width 64 --height 48 --gt-density 20 --seed 3");
    EXPECT_EQ(r.status, 0) << r.err;
    r = run_cli("-q raycast --scene " + scene.string() + " --city " + kFzk + " --city-transform " +
                (scene / "city" / "transform.json").string() + " --out " + labels.string());
    EXPECT_EQ(r.status, 0) << r.err;
    r = run_cli("-q train-rgb --scene " + scene.string() + " --out " + model.string() + " --iterations 30");
    EXPECT_EQ(r.status, 0) << r.err;
  }
  ~Fixture() { fs::remove_all(root); }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

json read_json(const fs::path& p) { return json::parse(read_text_file(p)); }

// 3DGS's llffhold: of n views sorted by name, those at indices 0, 8, 16, ... are held out.
int held_out_views(const fs::path& scene) { return (int(cls::load_scene(scene.string()).views.size()) + 7) / 8; }

int mp4_frames(const fs::path& p, cv::Size* size) {
  cv::VideoCapture cap(p.string(), cv::CAP_FFMPEG);
  if (!cap.isOpened()) return -1;
  int n = 0;
  for (cv::Mat f; cap.read(f); ++n) *size = f.size();
  return n;
}

TEST(RenderCli, TrainRgbWritesThe3dgsLayout) {
  const Fixture& f = fixture();
  const json summary = read_json(f.model / "summary.json");
  const fs::path ply = f.model / "point_cloud" / ("iteration_" + std::to_string(summary["iterations"].get<int>())) /
                       "point_cloud.ply";
  ASSERT_TRUE(fs::exists(ply));
  EXPECT_TRUE(fs::equivalent(ply, f.model / "point_cloud.ply"));
  const Scene scene = load_scene(f.scene.string());
  const ViewSplit split = split_views(scene, 8);
  const json cams = read_json(f.model / "cameras.json");
  ASSERT_EQ(cams.size(), scene.views.size());
  size_t k = 0;
  for (const auto* list : {&split.test, &split.train})
    for (const SceneView* v : *list) {
      const json& c = cams[k++];
      const Vec3d centre = v->pose.center();
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(c["position"][i].get<double>(), centre[i], 1e-9);
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(c["rotation"][i][j].get<double>(), v->pose.R.m[j][i], 1e-6);
      }
      EXPECT_EQ(c["img_name"], fs::path(v->name).stem().string());
    }
}

TEST(RenderCli, ViewsPicturesAndAnOrbitVideo) {
  const Fixture& f = fixture();
  const fs::path out = f.root / "render_all";
  const int frames = 10;
  const auto r = run_cli("render " + f.model.string() + " --scene " + f.scene.string() + " --out " + out.string() +
                         " --views all --labels " + f.labels.string() + " --path orbit --frames " +
                         std::to_string(frames) + " --fps 5");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = read_json(out / "render.json");
  EXPECT_EQ(j["what"], json({"rgb", "depth", "labels"}));
  const Scene scene = load_scene(f.scene.string());
  ASSERT_EQ(j["views"].size(), scene.views.size());
  int test_views = 0;
  for (const json& v : j["views"]) {
    test_views += v["split"] == "test";
    EXPECT_GT(v["psnr"].get<double>(), 5) << v.dump();
    EXPECT_GT(v["ssim"].get<double>(), 0) << v.dump();
    for (const char* key : {"rgb", "photo", "compare", "depth", "labels", "labels_level2", "labels_level3", "labels_gt"}) {
      ASSERT_TRUE(v["files"].contains(key)) << key;
      const cv::Mat img = cv::imread((out / v["files"][key].get<std::string>()).string());
      ASSERT_FALSE(img.empty()) << key;
      EXPECT_EQ(img.rows, v["height"].get<int>()) << key;
      EXPECT_EQ(img.cols, std::string(key) == "compare" ? 2 * v["width"].get<int>() + 4 : v["width"].get<int>()) << key;
    }
  }
  EXPECT_EQ(test_views, held_out_views(fixture().scene));
  EXPECT_GT(j["mean_psnr"].get<double>(), 5);

  EXPECT_EQ(j["path"]["frames"], frames);
  cv::Size size;
  EXPECT_EQ(mp4_frames(out / j["path"]["files"]["rgb_mp4"].get<std::string>(), &size), frames);
  EXPECT_EQ(size, cv::Size(j["path"]["width"].get<int>(), j["path"]["height"].get<int>()));
  const fs::path frame_dir = out / j["path"]["files"]["rgb_frames"].get<std::string>();
  EXPECT_EQ(std::distance(fs::directory_iterator(frame_dir), fs::directory_iterator()), frames);
  EXPECT_TRUE(fs::exists(frame_dir / "frame_0000.png"));
}

TEST(RenderCli, PsnrOfARenderAgainstItselfIsTheQuantisationLimit) {
  // A scene whose photos are the model's own 8-bit renders: the only error left is rounding to 8 bits,
  // |e| <= 0.5 / 255, so PSNR >= 20 log10(255 / 0.5) = 54.2 dB (uniform rounding: about 58.9 dB).
  const Fixture& f = fixture();
  const fs::path first = f.root / "render_self1", copy = f.root / "scene_self", second = f.root / "render_self2";
  ASSERT_EQ(run_cli("-q render " + f.model.string() + " --scene " + f.scene.string() + " --out " + first.string() +
                    " --views test --what rgb").status, 0);
  fs::copy(f.scene, copy, fs::copy_options::recursive);
  const json j1 = read_json(first / "render.json");
  for (const json& v : j1["views"])
    fs::copy_file(first / v["files"]["rgb"].get<std::string>(), copy / "images" / v["name"].get<std::string>(),
                  fs::copy_options::overwrite_existing);
  const auto r = run_cli("-q render " + f.model.string() + " --scene " + copy.string() + " --out " + second.string() +
                         " --views test --what rgb");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j2 = read_json(second / "render.json");
  ASSERT_EQ(int(j2["views"].size()), held_out_views(f.scene));
  for (const json& v : j2["views"]) {
    EXPECT_GE(v["psnr"].get<double>(), 54.15) << v["name"];
    EXPECT_GT(v["ssim"].get<double>(), 0.999) << v["name"];
  }
}

TEST(RenderCli, LanguageModelFeaturesRelevanceAndOverlayVideo) {
  const Fixture& f = fixture();
  // A language model on the trained geometry: random latents, a small random autoencoder and the
  // synthetic feature provider (what the query tests use).
  const fs::path lm = f.root / "language";
  const int latent = 6, dim = 16;
  torch::manual_seed(2);
  LanguageModel m{read_gaussians_ply((f.model / "point_cloud.ply").string()), {},
                  Autoencoder(AutoencoderConfig{dim, {12, latent}, {12, dim}}, 7), {}};
  for (int l = 0; l < 3; ++l) m.latents[l] = torch::randn({m.gaussians.size(), latent});
  m.info = {{"method", "citylangsplat"},
            {"provider", {{"provider", "synthetic"}, {"seed", 3}, {"dim", dim}}},
            {"scene", f.scene.string()}};
  save_language_model(lm.string(), m);

  const fs::path out = f.root / "render_language";
  const int frames = 4;
  const auto r = run_cli("-q render " + lm.string() + " --out " + out.string() +
                         " --what 'rgb,features,relevance:a window on a building facade' --path interpolate --frames " +
                         std::to_string(frames));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = read_json(out / "render.json");
  ASSERT_EQ(j["queries"].size(), 1u);
  const std::string slug = j["queries"][0]["slug"];
  EXPECT_EQ(slug, "a_window_on_a_building_facade");
  for (const json& v : j["views"]) {
    for (const std::string& key : std::vector<std::string>{"rgb", "features_level1", "features_level2", "features_level3", "relevance_" + slug}) {
      ASSERT_TRUE(v["files"].contains(key)) << key;
      EXPECT_FALSE(cv::imread((out / v["files"][key].get<std::string>()).string()).empty()) << key;
    }
    EXPECT_FALSE(v["files"].contains("depth"));
    EXPECT_TRUE(fs::exists(out / "views" / view_stem(v["name"]) / ("relevance_" + slug + ".npy")));
  }
  cv::Size size;
  EXPECT_EQ(mp4_frames(out / j["path"]["files"]["rgb_mp4"].get<std::string>(), &size), frames);
  EXPECT_EQ(mp4_frames(out / j["path"]["files"]["relevance_" + slug + "_mp4"].get<std::string>(), &size), frames);
}

TEST(RenderCli, BadInputsNameWhatIsWrong) {
  const Fixture& f = fixture();
  const fs::path out = f.root / "render_bad";
  auto r = run_cli("render " + (f.root / "no_such_model").string() + " --scene " + f.scene.string() + " --out " +
                   out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find((f.root / "no_such_model").string()), std::string::npos) << r.err;

  r = run_cli("render " + f.model.string() + " --scene " + f.scene.string() + " --out " + out.string() +
              " --views 0001.png,nope.png");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no view named 'nope.png'"), std::string::npos) << r.err;

  r = run_cli("render " + f.model.string() + " --scene " + f.scene.string() + " --out " + out.string() +
              " --what rgb,features");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("need a language model"), std::string::npos) << r.err;

  r = run_cli("render " + f.model.string() + " --scene " + f.scene.string() + " --out " + out.string() +
              " --path spiral");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("spiral"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "render.json"));

  r = run_cli("render --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--frames"), std::string::npos);
}

}  // namespace
}  // namespace cls
