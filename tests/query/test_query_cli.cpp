// `citylangsplat query` on a tiny hand-made language model (random latents and autoencoder, the
// synthetic feature provider) and a two-view COLMAP scene; results checked against independent
// computations of the scores.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <opencv2/imgcodecs.hpp>
#include <set>

#include "citymodel/taxonomy.h"
#include "cli_runner.h"
#include "core/atomic_file.h"
#include "core/npy.h"
#include "features/feature_provider.h"
#include "language/language_model.h"
#include "language/provenance.h"
#include "latent_scene.h"
#include "query/relevance.h"
#include "scene/colmap.h"
#include "scene/scene.h"
#include "splat/ply_gaussians.h"

namespace cls {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kN = 250, kLatent = 8, kDim = 16;
const char* const kWindow = "a window on a building facade";  // a taxonomy prompt
const char* const kRoof = "Red roof!";                         // any other text

struct Fixture {
  fs::path root, model_dir, scene_dir;
  json provider_spec{{"provider", "synthetic"}, {"seed", 3}, {"dim", kDim}};
  // The built-in taxonomy plus a class of our own, recorded in model.json as its legend: a query for
  // its prompt only hits that class's direction if `query` uses the recorded taxonomy.
  Taxonomy taxonomy = Taxonomy::builtin();
  std::vector<std::pair<std::string, std::pair<int, int>>> views;  // name, (width, height)

  Fixture() {
    root = fs::temp_directory_path() / ("cls_query_test_" + std::to_string(::getpid()));
    fs::remove_all(root);
    model_dir = root / "model";
    SemanticClass crossing;
    crossing.name = "crossing";
    crossing.prompts = {"zebra crossing"};
    taxonomy.classes.push_back(crossing);
    scene_dir = root / "scene";
    const test::LatentScene t = test::latent_scene(kN, 48, 36, kLatent, 21);
    torch::manual_seed(4);
    LanguageModel m{t.g, {}, Autoencoder(AutoencoderConfig{kDim, {12, kLatent}, {12, kDim}}, 7), {}};
    for (int l = 0; l < 3; ++l) m.latents[l] = torch::randn({kN, kLatent});
    m.info = {{"method", "citylangsplat"},
              {"provider", provider_spec},
              {"scene", scene_dir.string()},
              {"taxonomy", json::parse(taxonomy.legend_json())}};
    save_language_model(model_dir.string(), m);

    // Two pinhole views of different sizes looking at the Gaussians.
    ColmapModel cm;
    cm.cameras[1] = Camera{1, CameraModel::Pinhole, 48, 36, {t.camera.fx, t.camera.fy, t.camera.cx, t.camera.cy}};
    cm.cameras[2] = Camera{2, CameraModel::Pinhole, 40, 30,
                           {t.camera.fx * 40 / 48, t.camera.fy * 40 / 48, t.camera.cx * 40 / 48, t.camera.cy * 40 / 48}};
    for (uint32_t i = 1; i <= 2; ++i) {
      ColmapImage im;
      im.id = i;
      im.camera_id = i;
      im.qvec = rotation_to_qvec(t.pose.R);
      im.tvec = {t.pose.t.x + 0.1 * (i - 1), t.pose.t.y, t.pose.t.z};
      im.name = i == 1 ? "a/0001.png" : "0002.jpg";
      cm.images[i] = im;
    }
    fs::create_directories(scene_dir / "sparse" / "0");
    write_colmap_binary((scene_dir / "sparse" / "0").string(), cm);
    views = {{"a/0001.png", {48, 36}}, {"0002.jpg", {40, 30}}};
  }
  ~Fixture() { fs::remove_all(root); }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

// Independent scores: the provider's text feature, the model's encoder, then cos per Gaussian in double.
std::vector<double> independent_scores(const LanguageModel& m, const std::string& text, int level) {
  const auto provider = make_feature_provider(fixture().provider_spec, fixture().taxonomy);
  const at::Tensor q = m.autoencoder->encode(provider->text_features({text})).to(torch::kFloat64)[0];
  const at::Tensor g = m.latents[level - 1].to(torch::kFloat64);
  std::vector<double> s(kN);
  for (int i = 0; i < kN; ++i) {
    double dot = 0, nq = 0, ng = 0;
    for (int j = 0; j < kLatent; ++j) {
      const double a = q[j].item<double>(), b = g[i][j].item<double>();
      dot += a * b, nq += a * a, ng += b * b;
    }
    s[i] = dot / std::sqrt(nq * ng);
  }
  return s;
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(QueryCli, TopKScoresMapsAndJson) {
  Fixture& f = fixture();
  const fs::path out = f.root / "out_topk";
  const int k = 7;
  const auto r = test::run_cli("-q query " + q(f.model_dir) + " '" + kWindow + "' '" + kRoof +
                               "' 'zebra crossing' --top-k 7 --out " + q(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read_text_file(out / "query.json"));
  const LanguageModel m = load_language_model(f.model_dir.string());
  const GaussianModel scored = read_gaussians_ply((out / "scores.ply").string());
  ASSERT_EQ(scored.size(), kN);
  EXPECT_TRUE(torch::allclose(scored.means, m.gaussians.means));

  const std::vector<std::string> texts{kWindow, "Red roof!", "zebra crossing"},
      slugs{"a_window_on_a_building_facade", "red_roof", "zebra_crossing"};
  ASSERT_EQ(j["queries"].size(), 3u);
  for (size_t t = 0; t < 3; ++t) {
    const json& qj = j["queries"][t];
    EXPECT_EQ(qj["slug"], slugs[t]);
    // "best": the level whose max score is highest.
    std::vector<double> max_of(3);
    for (int l = 1; l <= 3; ++l) {
      const auto s = independent_scores(m, texts[t], l);
      max_of[l - 1] = *std::max_element(s.begin(), s.end());
    }
    const int best = int(std::max_element(max_of.begin(), max_of.end()) - max_of.begin()) + 1;
    ASSERT_EQ(qj["level"], best);

    // Scores in the PLY equal the independent ones.
    const std::vector<double> s = independent_scores(m, texts[t], best);
    const GaussianExtra* e = scored.extra("score_" + slugs[t]);
    ASSERT_NE(e, nullptr);
    for (int i = 0; i < kN; ++i) ASSERT_NEAR(e->values[i].item<float>(), s[i], 1e-5) << i;

    // The selection: exactly the k Gaussians with the highest independent scores.
    std::vector<int> order(kN);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return s[a] > s[b]; });
    std::set<int> expected(order.begin(), order.begin() + k);
    const GaussianModel sel = read_gaussians_ply((out / ("selection_" + slugs[t] + ".ply")).string());
    ASSERT_EQ(sel.size(), k);
    EXPECT_EQ(qj["selection"]["count"], k);
    std::set<int> got;
    for (int r2 = 0; r2 < k; ++r2)
      for (int i = 0; i < kN; ++i)
        if (torch::equal(sel.means[r2], m.gaussians.means[i])) got.insert(i);
    EXPECT_EQ(got, expected);

    // Maps: one cosine and one relevancy map per view, PNG and .npy of the view's size.
    for (const auto& [name, size] : f.views) {
      std::string stem = fs::path(name).replace_extension().string();
      std::replace(stem.begin(), stem.end(), '/', '_');
      for (const char* kind : {"_cosine", "_relevancy"}) {
        const fs::path base = out / "maps" / slugs[t] / (stem + kind);
        const NpyArray a = read_npy(base.string() + ".npy");
        EXPECT_EQ(a.dtype, "<f4");
        EXPECT_EQ(a.shape, (std::vector<int64_t>{size.second, size.first})) << base;
        const cv::Mat png = cv::imread(base.string() + ".png", cv::IMREAD_COLOR);
        ASSERT_FALSE(png.empty()) << base;
        EXPECT_EQ(png.cols, size.first);
        EXPECT_EQ(png.rows, size.second);
        const std::vector<float> v = a.to_float();
        const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
        EXPECT_GE(*lo, std::string(kind) == "_cosine" ? -1.0001f : 0.0f);
        EXPECT_LE(*hi, 1.0001f);
        EXPECT_LT(*lo, *hi) << base << " is constant";
      }
    }
  }
  EXPECT_TRUE(fs::exists(out / "maps" / "legend_turbo.png"));
  EXPECT_EQ(j["views"].size(), 2u);
}

TEST(QueryCli, CosineMapEqualsDecodedFieldOfTheView) {
  // The job's chunked maps against cosine_maps of render_decoded of the loaded model.
  Fixture& f = fixture();
  const fs::path out = f.root / "out_level2";
  const auto r = test::run_cli("-q query " + q(f.model_dir) + " wall --level 2 --views 0002 --out " + q(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const LanguageModel m = load_language_model(f.model_dir.string());
  const Scene scene = load_scene(f.scene_dir.string(), SceneOptions{1, 0, false});
  const SceneView& view = scene.views[0].name == "0002.jpg" ? scene.views[0] : scene.views[1];
  const auto provider = make_feature_provider(f.provider_spec, f.taxonomy);
  const DecodedView d = render_decoded(m, 2, view);
  const at::Tensor expected = cosine_maps(d.features, provider->text_features({"wall"}))[0];
  const NpyArray a = read_npy(out / "maps" / "wall" / "0002_cosine.npy");
  const at::Tensor got = torch::tensor(a.to_float()).reshape({a.shape[0], a.shape[1]});
  EXPECT_LT((got - expected).abs().max().item<float>(), 1e-5);
  EXPECT_FALSE(fs::exists(out / "maps" / "wall" / "a_0001_cosine.npy"));  // only the named view
  EXPECT_EQ(json::parse(read_text_file(out / "query.json"))["queries"][0]["level"], 2);
}

// A sparse field (issue 36) through `query`: the scores are the cosines of each Gaussian's feature (weights
// times codebook, formed here in double) with the text's; the map is the cosine map of the decoded field.
TEST(QueryCli, SparseFieldScoresAndMapsAreThoseOfItsFeatures) {
  Fixture& f = fixture();
  const LanguageModel dense = load_language_model(f.model_dir.string());
  LanguageModel m{dense.gaussians, {}, std::nullopt, dense.info, {}, {}};
  torch::manual_seed(6);
  for (int l = 0; l < 3; ++l)
    m.sparse[l] = {torch::randint(0, 5, {kN, 3}, torch::kInt32), torch::softmax(torch::randn({kN, 3}), 1),
                   torch::randn({5, kDim})};
  const fs::path dir = f.root / "model_sparse", out = f.root / "out_sparse";
  save_language_model(dir.string(), m);
  const auto r = test::run_cli("-q query " + q(dir) + " wall --level 2 --views 0002 --out " + q(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto provider = make_feature_provider(f.provider_spec, f.taxonomy);
  const at::Tensor text = provider->text_features({"wall"}).to(torch::kFloat64)[0];
  const at::Tensor features = sparse_features(m.sparse[1]).to(torch::kFloat64);
  const at::Tensor expected = features.matmul(text) / (features.norm(2, {1}) * text.norm());
  const GaussianModel scored = read_gaussians_ply((out / "scores.ply").string());
  const GaussianExtra* score = scored.extra("score_wall");
  ASSERT_NE(score, nullptr);
  EXPECT_LT((score->values.to(torch::kFloat64).reshape({-1}) - expected).abs().max().item<double>(), 1e-5);
  const Scene scene = load_scene(f.scene_dir.string(), SceneOptions{1, 0, false});
  const SceneView& view = scene.views[0].name == "0002.jpg" ? scene.views[0] : scene.views[1];
  const at::Tensor map = cosine_maps(render_decoded(m, 2, view).features, provider->text_features({"wall"}))[0];
  const NpyArray a = read_npy(out / "maps" / "wall" / "0002_cosine.npy");
  const at::Tensor got = torch::tensor(a.to_float()).reshape({a.shape[0], a.shape[1]});
  EXPECT_LT((got - map).abs().max().item<float>(), 1e-5);
  EXPECT_GT(map.abs().max().item<float>(), 0.1f);
  EXPECT_FALSE(fs::exists(dir / "autoencoder.safetensors"));
}

TEST(QueryCli, ThresholdSelectsScoresAtOrAbove) {
  Fixture& f = fixture();
  const fs::path out = f.root / "out_threshold";
  const auto r = test::run_cli("-q query " + q(f.model_dir) + " wall --level 3 --threshold 0.3 --no-maps --out " + q(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const LanguageModel m = load_language_model(f.model_dir.string());
  const std::vector<double> s = independent_scores(m, "wall", 3);
  const int64_t expected = std::count_if(s.begin(), s.end(), [](double v) { return v >= 0.3; });
  ASSERT_GT(expected, 0);
  ASSERT_LT(expected, kN);
  EXPECT_EQ(read_gaussians_ply((out / "selection_wall.ply").string()).size(), expected);
  EXPECT_FALSE(fs::exists(out / "maps"));

  // Nothing reaches a threshold above 1: an empty selection is still a valid PLY.
  const fs::path none = f.root / "out_none";
  ASSERT_EQ(test::run_cli("-q query " + q(f.model_dir) + " wall --threshold 1.5 --no-maps --out " + q(none)).status, 0);
  EXPECT_EQ(read_gaussians_ply((none / "selection_wall.ply").string()).size(), 0);
  EXPECT_EQ(json::parse(read_text_file(none / "query.json"))["queries"][0]["selection"]["count"], 0);
}

TEST(QueryCli, Errors) {
  Fixture& f = fixture();
  const std::string model = q(f.model_dir);
  auto run = [&](const std::string& args) { return test::run_cli("query " + args + " --out " + q(f.root / "out_err")); };
  auto r = run(model + " ''");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("empty"), std::string::npos) << r.err;
  r = run(model + " wall --views 0002,nope");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'nope'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(f.root / "out_err" / "scores.ply"));  // views are checked before any work
  r = run(model + " wall --level 4");
  EXPECT_EQ(r.status, 2);
  r = run(model + " wall --top-k 3 --threshold 0.2");
  EXPECT_EQ(r.status, 2);
  r = run(model + " wall --device tpu");
  EXPECT_EQ(r.status, 2) << r.err;
  if (!at::hasCUDA()) {
    r = run(model + " wall --device cuda");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("no CUDA"), std::string::npos) << r.err;
  }
  r = run(q(f.root / "no_such_model") + " wall");
  EXPECT_EQ(r.status, 1);

  // A model directory missing a part names the file.
  const fs::path broken = f.root / "broken";
  fs::create_directories(broken);
  for (const char* file : {"model.json", "point_cloud.ply", "autoencoder.safetensors"})
    fs::copy_file(f.model_dir / file, broken / file, fs::copy_options::overwrite_existing);
  r = run(q(broken) + " wall");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("latents.safetensors"), std::string::npos) << r.err;

  // A model that records no scene: the maps need --scene.
  const fs::path noscene = f.root / "noscene";
  fs::create_directories(noscene);
  for (const char* file : {"point_cloud.ply", "latents.safetensors", "autoencoder.safetensors"})
    fs::copy_file(f.model_dir / file, noscene / file, fs::copy_options::overwrite_existing);
  json info = json::parse(read_text_file(f.model_dir / "model.json"));
  info.erase("scene");
  write_text_atomic(noscene / "model.json", info.dump());
  r = run(q(noscene) + " wall");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--scene"), std::string::npos) << r.err;
  EXPECT_EQ(run(q(noscene) + " wall --views 0002 --scene " + q(f.scene_dir)).status, 0);
}

}  // namespace
}  // namespace cls

namespace cls {
namespace {

TEST(QueryCli, ObjectsAnswerWithTheCityObjectsOfTheGaussians) {
  Fixture& f = fixture();
  // The fixture's model with a city-object table and each Gaussian on one of its objects.
  LanguageModel m = load_language_model(f.model_dir.string());
  m.objects.class_names = {"window", "wall", "building"};
  m.objects.objects = {{"bld", 3, 2, -1}, {"wall-1", 2, 1, 0}, {"win-1", 1, 0, 1}, {"win-2", 1, 0, 1}};
  GaussianProvenance p;
  for (int i = 0; i < kN; ++i) p.object.push_back(i % 5 - 1), p.support.push_back(1.0f);  // -1 .. 3
  attach_provenance(m.gaussians, p);
  const fs::path model_dir = f.root / "model_objects", out = f.root / "out_objects";
  save_language_model(model_dir.string(), m);

  const auto r = test::run_cli("-q query " + q(model_dir) + " '" + kWindow + "' --level 1 --objects --no-maps --out " + q(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const json ranking = json::parse(read_text_file(out / "objects_a_window_on_a_building_facade.json"));
  EXPECT_EQ(ranking["level"], 1);
  // At level 1 each object answers for the Gaussians whose finest object it is (the building too, for
  // those on no finer part); each row's mean is its Gaussians' mean score.
  const std::vector<double> s = independent_scores(m, kWindow, 1);
  ASSERT_EQ(ranking["objects"].size(), 4u);
  double previous = 2;
  for (const json& row : ranking["objects"]) {
    const int k = row["index"];
    double sum = 0;
    int count = 0;
    for (int i = 0; i < kN; ++i)
      if (i % 5 - 1 == k) sum += s[i], ++count;
    EXPECT_EQ(row["gaussians"], count);
    EXPECT_NEAR(row["mean_score"].get<double>(), sum / count, 1e-5);
    EXPECT_EQ(row["building"], "bld");
    EXPECT_LE(row["mean_score"].get<double>(), previous);
    previous = row["mean_score"];
  }
  EXPECT_NE(r.out.find("1. " + ranking["objects"][0]["class"].get<std::string>() + " " +
                       ranking["objects"][0]["id"].get<std::string>()),
            std::string::npos)
      << r.out;
  const std::string csv = read_text_file(out / "objects_a_window_on_a_building_facade.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  const json qj = json::parse(read_text_file(out / "query.json"));
  EXPECT_EQ(qj["queries"][0]["objects"]["ranked"], 4);

  // The PLY carries the provenance; a model without it cannot answer with objects.
  EXPECT_NE(load_language_model(model_dir.string()).gaussians.extra(kObjectProperty), nullptr);
  const auto none = test::run_cli("-q query " + q(f.model_dir) + " window --objects --no-maps --out " + q(f.root / "x"));
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.err.find("city_objects.json"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace cls
