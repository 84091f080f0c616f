// evaluate_model end to end on a small synthetic scene with a hand-built language model: Gaussians on
// the GT points whose latents encode the synthetic provider's class vectors (what a perfectly trained
// field would hold). The correct field must score high, a field with two classes swapped low.
#include <gtest/gtest.h>
#include <unistd.h>

#include <ATen/ATen.h>
#include <ATen/CPUGeneratorImpl.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <set>

#include "cli_runner.h"
#include "error_of.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "eval/evaluation.h"
#include "eval/gt_projection.h"
#include "eval/labelled_points.h"
#include "features/synthetic_provider.h"
#include "language/language_model.h"
#include "raycast/label_export.h"
#include "scene/view_selection.h"
#include "raycast/label_map_io.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

constexpr int kDim = 64;

nlohmann::json provider_spec() { return {{"provider", "synthetic"}, {"dim", kDim}, {"seed", 3}}; }

struct Fixture {
  fs::path dir;
  Scene scene;
  Taxonomy taxonomy = Taxonomy::builtin();
  std::unique_ptr<FeatureProvider> provider;
  fs::path autoencoder;  // trained on noisy class vectors
  at::Tensor class_table;  // (1 + classes) x kDim: u_bg, u_0, u_1, ...
  LabelledPoints gt;
};

// Removes the fixture's directory at exit.
struct DirRemover {
  fs::path dir;
  ~DirRemover() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

Fixture& fixture() {
  static Fixture f = [] {
    Fixture x;
    x.dir = fs::temp_directory_path() / ("cls_eval_model_" + std::to_string(::getpid()));
    fs::remove_all(x.dir);
    const auto r = test::run_cli("-q synth --city " CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml --out " +
                                 (x.dir / "scene").string() + " --views 4 --width 160 --height 120 --gt-density 100 --seed 4");
    EXPECT_EQ(r.status, 0) << r.err;
    x.scene = load_scene((x.dir / "scene").string());
    x.gt = read_labelled_points((x.dir / "scene" / "gt" / "points.ply").string());
    x.provider = make_feature_provider(provider_spec(), x.taxonomy);
    // The autoencoder learns the class vectors (and background) with noise, as from SAM features.
    auto* synth = dynamic_cast<SyntheticFeatureProvider*>(x.provider.get());
    std::vector<at::Tensor> rows;
    for (int c = -1; c < int(x.taxonomy.classes.size()); ++c) {
      const std::vector<float> u = synth->class_vector(c);
      rows.push_back(at::from_blob(const_cast<float*>(u.data()), {1, kDim}, at::kFloat).clone().expand({80, kDim}));
    }
    at::Generator gen = at::detail::createCPUGenerator(11);
    at::Tensor samples = at::cat(rows, 0);
    samples = samples + 0.3 / std::sqrt(double(kDim)) * at::randn(samples.sizes(), gen);
    samples = samples / samples.norm(2, {1}, true);
    AutoencoderConfig config;
    config.input_dim = kDim;
    config.encoder_dims = {32, 16};
    config.decoder_dims = {32, kDim};
    Autoencoder ae(config, 2);
    AutoencoderTrainOptions o;
    o.epochs = 60;
    o.batch_size = 64;
    const AutoencoderReport rep = ae.train(samples, o);
    EXPECT_GT(rep.holdout_cosine, 0.9);
    x.autoencoder = x.dir / "ae.safetensors";
    ae.save(x.autoencoder.string());
    std::vector<at::Tensor> table;
    for (const at::Tensor& row : rows) table.push_back(row.slice(0, 0, 1));
    x.class_table = at::cat(table, 0);
    return x;
  }();
  static const DirRemover remover{f.dir};
  return f;
}

// Every second GT point becomes a Gaussian; level-1/2 latent = E(u of the point's class, with classes
// `swap_a` and `swap_b` exchanged), level 3 = E(u_building) on the model, E(u_bg) elsewhere.
LanguageModel make_model(int swap_a = -2, int swap_b = -2) {
  Fixture& f = fixture();
  std::vector<int64_t> keep;
  for (size_t i = 0; i < f.gt.size(); i += 2) keep.push_back(int64_t(i));
  const int64_t n = int64_t(keep.size());
  LanguageModel m{make_gaussians(n, 0), {}, Autoencoder::load(f.autoencoder.string()),
                  {{"method", "hand-built"}, {"provider", provider_spec()}}};
  const at::Tensor codes = m.autoencoder->encode(f.class_table);  // (1 + C) x 16
  std::vector<int64_t> row1(n), row3(n);
  const int building = f.taxonomy.find("building");
  float* means = m.gaussians.means.data_ptr<float>();
  for (int64_t i = 0; i < n; ++i) {
    const Vec3d p = f.gt.positions[size_t(keep[i])];
    means[3 * i] = float(p.x);
    means[3 * i + 1] = float(p.y);
    means[3 * i + 2] = float(p.z);
    int c = f.gt.labels[size_t(keep[i])];
    if (c == swap_a) c = swap_b;
    else if (c == swap_b) c = swap_a;
    row1[i] = c + 1;
    row3[i] = f.gt.labels[size_t(keep[i])] >= 0 ? building + 1 : 0;
  }
  m.gaussians.log_scales.fill_(std::log(0.08));
  m.gaussians.opacity_logits.fill_(4.0);
  const at::Tensor l1 = codes.index_select(0, at::tensor(row1, at::kLong)).contiguous();
  m.latents = {l1, l1.clone(), codes.index_select(0, at::tensor(row3, at::kLong)).contiguous()};
  return m;
}

EvaluationOptions options(const std::string& out = "") {
  EvaluationOptions o;
  o.gt_points = (fixture().dir / "scene" / "gt" / "points.ply").string();
  o.out_dir = out;
  return o;
}

}  // namespace

TEST(Evaluation, PrototypesAreNormalisedMeansOfThePromptFeatures) {
  Fixture& f = fixture();
  const int window = f.taxonomy.find("window");
  const std::vector<std::string>& prompts = f.taxonomy.classes[size_t(window)].prompts;
  ASSERT_GE(prompts.size(), 2u) << "the test needs a class with more than its fusion prompt";
  auto normalised_mean = [&](const std::vector<std::string>& texts) {
    const at::Tensor mean = f.provider->text_features(texts).mean(0);
    return mean / mean.norm();
  };
  // All prompts, and (the default) all but prompts[0], the class prompt the fusion used.
  const at::Tensor all = class_prototypes(*f.provider, f.taxonomy, {window}, "all");
  ASSERT_EQ(all.sizes(), (at::IntArrayRef{1, kDim}));
  EXPECT_TRUE(at::allclose(all[0], normalised_mean(prompts), 1e-5, 1e-6));
  const at::Tensor held_out = class_prototypes(*f.provider, f.taxonomy, {window});
  EXPECT_TRUE(at::allclose(held_out[0], normalised_mean({prompts.begin() + 1, prompts.end()}), 1e-5, 1e-6));
  EXPECT_FALSE(at::allclose(held_out[0], all[0], 1e-3, 1e-4));
  // A class with its fusion prompt only keeps it; an unknown rule is refused.
  SemanticClass lone;
  lone.name = "lone";
  lone.prompts = {"a lone prompt"};
  EXPECT_EQ(evaluation_phrases(lone, "held-out"), lone.prompts);
  EXPECT_EQ(evaluation_phrases(f.taxonomy.classes[size_t(window)], "held-out"),
            (std::vector<std::string>{prompts.begin() + 1, prompts.end()}));
  EXPECT_THROW(evaluation_phrases(lone, "first"), UsageError);
}

TEST(Evaluation, ACorrectFieldScoresHighAndWritesViews) {
  const fs::path out = fixture().dir / "out_correct";
  const nlohmann::json r = evaluate_model(fixture().scene, make_model(), *fixture().provider, fixture().taxonomy, options(out.string()));
  std::printf("correct field: 2D mIoU %.4f wIoU %.4f acc %.4f cov %.4f (GT cov %.4f); 3D mIoU %.4f cov %.4f dist %.4f\n",
              r["2d"]["miou"].get<double>(), r["2d"]["wiou"].get<double>(), r["2d"]["accuracy"].get<double>(),
              r["2d"]["coverage"].get<double>(), r["2d"]["gt_coverage"].get<double>(), r["3d"]["miou"].get<double>(),
              r["3d"]["coverage"].get<double>(), r["3d"]["mean_distance"].get<double>());
  // Measured: 2D mIoU 0.705 (ground, 29 GT pixels at a wall's foot, and small windows pull it down at
  // 160 x 120 with 8 cm Gaussians), wIoU 0.970, accuracy 0.984; 3D mIoU 0.964.
  EXPECT_GT(r["2d"]["miou"].get<double>(), 0.6);
  EXPECT_GT(r["2d"]["wiou"].get<double>(), 0.9);
  EXPECT_GT(r["2d"]["per_class"]["wall"]["iou"].get<double>(), 0.75);
  EXPECT_GT(r["2d"]["per_class"]["roof"]["iou"].get<double>(), 0.9);
  EXPECT_GT(r["2d"]["accuracy"].get<double>(), 0.9);
  EXPECT_GT(r["2d"]["coverage"].get<double>(), 0.5);
  EXPECT_GT(r["3d"]["miou"].get<double>(), 0.9);
  EXPECT_GT(r["3d"]["coverage"].get<double>(), 0.99);  // every GT point has a centre within 0.2
  EXPECT_LT(r["3d"]["mean_distance"].get<double>(), 0.05);
  // Visible GT points: a strict, non-empty subset (no view sees the building's ground surface).
  EXPECT_GT(r["3d_visible"]["gt_points"].get<int64_t>(), 1000);
  EXPECT_LT(r["3d_visible"]["gt_points"].get<int64_t>(), r["3d"]["gt_points"].get<int64_t>());
  EXPECT_GT(r["3d_visible"]["miou"].get<double>(), 0.8);  // measured 0.876: few visible ground points
  // Evaluated classes: exactly those labelled in the GT.
  std::set<std::string> in_gt;
  for (int32_t l : fixture().gt.labels)
    if (l >= 0) in_gt.insert(fixture().taxonomy.classes[size_t(l)].name);
  std::set<std::string> evaluated;
  for (const auto& c : r["classes"]) evaluated.insert(c.get<std::string>());
  EXPECT_EQ(evaluated, in_gt);
  EXPECT_TRUE(r["2d"]["per_class"].contains("wall"));
  EXPECT_GT(r["2d"]["per_class"]["wall"]["images"].get<int>(), 0);
  // Per class, the Gaussians its matched GT points go to: at least one and at most one per point, the
  // same count in the best labelling (it depends on the matching only).
  for (const auto& [name, c] : r["3d"]["per_class"].items()) {
    const int64_t gaussians = c["gaussians"].get<int64_t>(), points = c["gt"].get<int64_t>();
    EXPECT_LE(gaussians, points) << name;
    EXPECT_EQ(gaussians > 0, points > 0) << name;
    EXPECT_LE(gaussians, r["3d"]["gaussians"].get<int64_t>()) << name;
    EXPECT_EQ(r["3d"]["best_labelling"]["per_class"][name]["gaussians"], c["gaussians"]) << name;
  }
  EXPECT_TRUE(fs::exists(out / "views" / "0000_gt.png"));
  EXPECT_TRUE(fs::exists(out / "views" / "0000_pred.png"));
  // The other reading, LangSplat's relevancy, on the same views and GT: the correct field scores high too.
  EXPECT_EQ(r["relevance"], "cosine");
  const nlohmann::json& rel = r["2d_relevancy"];
  EXPECT_EQ(rel["valid_gt_pixels"], r["2d"]["valid_gt_pixels"]);
  EXPECT_GT(rel["wiou"].get<double>(), 0.9);
  EXPECT_GT(rel["per_class"]["roof"]["iou"].get<double>(), 0.9);
}

TEST(Evaluation, SwappedClassesScoreLow) {
  Fixture& f = fixture();
  const int wall = f.taxonomy.find("wall"), roof = f.taxonomy.find("roof");
  const nlohmann::json good = evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, options());
  const nlohmann::json bad = evaluate_model(f.scene, make_model(wall, roof), *f.provider, f.taxonomy, options());
  EXPECT_LT(bad["2d"]["miou"].get<double>(), good["2d"]["miou"].get<double>() - 0.3);
  EXPECT_LT(bad["3d"]["miou"].get<double>(), good["3d"]["miou"].get<double>() - 0.3);
  EXPECT_LT(bad["2d"]["per_class"]["wall"]["iou"].get<double>(), 0.2);
  EXPECT_LT(bad["2d_relevancy"]["per_class"]["wall"]["iou"].get<double>(), 0.2);
  EXPECT_LT(bad["2d_relevancy"]["miou"].get<double>(), good["2d_relevancy"]["miou"].get<double>() - 0.3);
  EXPECT_LT(bad["3d"]["per_class"]["roof"]["iou"].get<double>(), 0.2);
  // The best labelling of the Gaussians does not depend on the latents, and no field is more accurate.
  for (const char* group : {"3d", "3d_visible"}) {
    const nlohmann::json& best = good[group]["best_labelling"];
    EXPECT_DOUBLE_EQ(bad[group]["best_labelling"]["miou"].get<double>(), best["miou"].get<double>()) << group;
    EXPECT_GE(best["accuracy"].get<double>(), good[group]["accuracy"].get<double>()) << group;
    EXPECT_GE(best["accuracy"].get<double>(), bad[group]["accuracy"].get<double>()) << group;
    // per class too (what separates a class the Gaussians lose from one the field loses)
    ASSERT_EQ(best["per_class"].size(), good[group]["per_class"].size()) << group;
    for (const auto& [name, scores] : best["per_class"].items())
      EXPECT_DOUBLE_EQ(bad[group]["best_labelling"]["per_class"][name]["iou"].get<double>(), scores["iou"].get<double>())
          << group << " " << name;
    EXPECT_LT(bad[group]["per_class"]["roof"]["iou"].get<double>(), best["per_class"]["roof"]["iou"].get<double>() - 0.3)
        << group;
  }
}

TEST(Evaluation, LangSplatLevelRuleAndClassOption) {
  Fixture& f = fixture();
  EvaluationOptions o = options();
  o.level_rule = "langsplat";
  o.classes = {"wall", "roof", "building"};
  const nlohmann::json r = evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, o);
  EXPECT_EQ(r["classes"], (nlohmann::json{"wall", "roof", "building"}));
  // The building prototype's best cosine is in the level-3 field, wall's in level 1 or 2.
  EXPECT_EQ(r["3d"]["levels"][2], 3);
  EXPECT_NE(r["3d"]["levels"][0], 3);
  EXPECT_GT(r["2d"]["per_class"]["wall"]["iou"].get<double>(), 0.5);
  o.level_rule = "nearest";
  EXPECT_THROW(evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, o), UsageError);
  o.level_rule = "fallback";
  o.classes = {"no such class"};
  EXPECT_THROW(evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, o), UsageError);
}

TEST(Evaluation, TablesSideBySide) {
  nlohmann::json a = {{"classes", {"wall", "window"}},
                      {"2d", {{"gt_coverage", 0.5}, {"coverage", 0.9}, {"miou", 0.25}, {"wiou", 0.5}, {"accuracy", 0.6},
                              {"per_class", {{"wall", {{"iou", 0.5}, {"precision", 0.6}, {"recall", 0.7}}},
                                             {"window", {{"iou", 0.1}, {"precision", 0.2}, {"recall", 0.3}}}}}}},
                      {"3d", {{"coverage", 0.8}, {"mean_distance", 0.1}, {"miou", 0.04}, {"wiou", 0.07}}}};
  nlohmann::json b = a;
  b["2d"]["miou"] = 0.3;
  b["2d"]["per_class"]["window"]["iou"] = 0.05;
  const std::string md = evaluation_tables_markdown({{"LangSplat", a}, {"CityLangSplat", b}});
  EXPECT_NE(md.find("| LangSplat | 50.00 | 90.00 | 25.00 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| CityLangSplat | 50.00 | 90.00 | **30.00** |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Method | Cov. | Dist. | mIoU | wIoU |"), std::string::npos) << md;
  EXPECT_NE(md.find("| window | **10.00** | 20.00 | 30.00 | 5.00 | 20.00 | 30.00 |"), std::string::npos) << md;
  // A reference row (the label maps: 2D only) is shown, neither bolded nor compared against; the best
  // labelling's mIoU is a reference column, never bold.
  nlohmann::json ref = {{"reference", true}, {"classes", {"wall", "window"}}, {"2d", a["2d"]}};
  ref["2d"]["miou"] = 0.9;
  ref["2d"]["per_class"]["window"]["iou"] = 0.95;
  a["3d"]["best_labelling"] = {{"miou", 0.5}};
  b["3d"]["best_labelling"] = {{"miou", 0.6}};
  const std::string with_ref = evaluation_tables_markdown({{"LangSplat", a}, {"CityLangSplat", b}, {"labels", ref}});
  EXPECT_NE(with_ref.find("| CityLangSplat | 50.00 | 90.00 | **30.00** |"), std::string::npos) << with_ref;
  EXPECT_NE(with_ref.find("| labels | 50.00 | 90.00 | 90.00 | 50.00 | 60.00 |\n"), std::string::npos) << with_ref;
  EXPECT_NE(with_ref.find("| CityLangSplat | 80.00 | 0.10 | 4.00 | 7.00 | 60.00 |\n"), std::string::npos) << with_ref;
  EXPECT_NE(with_ref.find("| labels | - | - | - | - | - |\n"), std::string::npos) << with_ref;
  // Table 3: the reference's higher window IoU does not take the bold from LangSplat.
  EXPECT_NE(with_ref.find("| window | **10.00** | 20.00 | 30.00 | 5.00 | 20.00 | 30.00 | 95.00 | 20.00 | 30.00 |"),
            std::string::npos)
      << with_ref;
  EXPECT_EQ(with_ref.find("Table 1b"), std::string::npos) << "no method has covered scores";
}

// Label maps made from the projected GT itself score exactly 1 as a prediction; a window pixel is read
// at level 1 before its wall at level 2; "2d_covered" scores only where the coverage mask is set.
TEST(Evaluation, LabelMapsOfTheGtItselfScoreExactlyOne) {
  Fixture& f = fixture();
  const int window = f.taxonomy.find("window"), wall = f.taxonomy.find("wall");
  const fs::path labels = f.dir / "gt_labels";
  const std::vector<fs::path> dirs = label_map_dirs(f.scene, labels);
  const double radius = footprint_radius(f.gt, GtProjectionOptions{});
  int64_t gt_pixels = 0, covered_gt_pixels = 0;
  for (size_t k = 0; k < f.scene.views.size(); ++k) {
    const SceneView& v = f.scene.views[k];
    const int W = v.camera.width, H = v.camera.height;
    const cv::Mat proj = project_gt_labels(f.gt, v.camera, v.pose, radius, GtProjectionOptions{});
    std::vector<uint16_t> l1(size_t(W) * H, 0), l2(size_t(W) * H, 0), l3(size_t(W) * H, 0);
    std::vector<uint8_t> cov(size_t(W) * H, 0);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const int c = proj.at<int32_t>(y, x);
        const size_t i = size_t(y) * W + x;
        if (c == window) l1[i] = uint16_t(window + 1);
        if (c == window || c == wall) {
          l2[i] = uint16_t(wall + 1);
          ++gt_pixels;
          if (x >= W / 2) {  // the city model "covers" the right half only
            cov[i] = 255;
            ++covered_gt_pixels;
          }
        }
      }
    fs::create_directories(dirs[k]);
    write_png_u16(dirs[k] / "level1.png", l1, W, H);
    write_png_u16(dirs[k] / "level2.png", l2, W, H);
    write_png_u16(dirs[k] / "level3.png", l3, W, H);
    write_png_u8(dirs[k] / "coverage.png", cov, W, H);
  }
  ASSERT_GT(covered_gt_pixels, 100);
  ASSERT_LT(covered_gt_pixels, gt_pixels);
  EvaluationOptions o = options();
  o.classes = {"window", "wall"};
  o.labels_dir = labels.string();
  const nlohmann::json r = evaluate_label_maps(f.scene, f.taxonomy, o);
  EXPECT_EQ(r["2d"]["valid_gt_pixels"].get<int64_t>(), gt_pixels);
  EXPECT_EQ(r["2d"]["scored_pixels"].get<int64_t>(), gt_pixels);
  EXPECT_DOUBLE_EQ(r["2d"]["miou"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(r["2d"]["accuracy"].get<double>(), 1.0);
  EXPECT_EQ(r["2d"]["classes_in_miou"].get<int>(), 2);
  EXPECT_EQ(r["2d_covered"]["valid_gt_pixels"].get<int64_t>(), covered_gt_pixels);
  EXPECT_DOUBLE_EQ(r["2d_covered"]["miou"].get<double>(), 1.0);
  EXPECT_FALSE(r.contains("3d"));
  EXPECT_TRUE(r["reference"].get<bool>());
  // A level-1 class that is not evaluated falls through to level 2: with "door" at the window pixels of
  // level 1, those pixels read as wall, so every window pixel is a wall prediction.
  const int door = f.taxonomy.find("door");
  int64_t window_pixels = 0, wall_pixels = 0;
  for (size_t k = 0; k < f.scene.views.size(); ++k) {
    const SceneView& v = f.scene.views[k];
    const int W = v.camera.width, H = v.camera.height;
    const cv::Mat l1 = read_label_png(dirs[k] / "level1.png", CV_16UC1, H, W);
    const cv::Mat l2 = read_label_png(dirs[k] / "level2.png", CV_16UC1, H, W);
    std::vector<uint16_t> doors(size_t(W) * H, 0);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const bool is_window = l1.at<uint16_t>(y, x) == window + 1;
        window_pixels += is_window;
        wall_pixels += !is_window && l2.at<uint16_t>(y, x) == wall + 1;
        if (is_window) doors[size_t(y) * W + x] = uint16_t(door + 1);
      }
    write_png_u16(dirs[k] / "level1.png", doors, W, H);
  }
  ASSERT_GT(window_pixels, 0);
  const nlohmann::json d = evaluate_label_maps(f.scene, f.taxonomy, o);
  EXPECT_EQ(d["2d"]["per_class_pooled"]["window"]["pred"].get<int64_t>(), 0);
  EXPECT_EQ(d["2d"]["per_class_pooled"]["window"]["gt"].get<int64_t>(), window_pixels);
  EXPECT_EQ(d["2d"]["per_class_pooled"]["wall"]["pred"].get<int64_t>(), window_pixels + wall_pixels);
  // Label maps of another taxonomy are refused, naming their legend; the same taxonomy passes.
  write_text_atomic(labels / "legend.json", f.taxonomy.legend_json());
  EXPECT_NO_THROW(evaluate_label_maps(f.scene, f.taxonomy, o));
  Taxonomy other = f.taxonomy;
  std::swap(other.classes[0], other.classes[1]);
  write_text_atomic(labels / "legend.json", other.legend_json());
  try {
    evaluate_label_maps(f.scene, f.taxonomy, o);
    ADD_FAILURE() << "label maps of another taxonomy were accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("legend.json"), std::string::npos) << e.what();
  }
  fs::remove(labels / "legend.json");
  // A language model evaluated with the label maps also gets the covered scores.
  o.classes = {"window", "wall"};
  const nlohmann::json m = evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, o);
  EXPECT_EQ(m["2d_covered"]["valid_gt_pixels"].get<int64_t>(), covered_gt_pixels);
  // A label map of the wrong size is named.
  write_png_u8(dirs[0] / "coverage.png", std::vector<uint8_t>(4, 0), 2, 2);
  try {
    evaluate_label_maps(f.scene, f.taxonomy, o);
    FAIL() << "a 2 x 2 coverage map was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("coverage.png"), std::string::npos) << e.what();
  }
}

// --test-every N: "2d" is exactly the evaluation of a scene made of the held-out views alone, "2d_train"
// that of the training views alone; every view keeps its record, marked.
TEST(Evaluation, HeldOutViewsAreScoredApartFromTheTrainingViews) {
  Fixture& f = fixture();
  const LanguageModel model = make_model();
  EvaluationOptions o = options();
  o.test_every = 2;
  const nlohmann::json split = evaluate_model(f.scene, model, *f.provider, f.taxonomy, o);
  const ViewSplit views = split_views(f.scene, 2);
  ASSERT_FALSE(views.test.empty());
  ASSERT_FALSE(views.train.empty());
  auto only = [&](const std::vector<const SceneView*>& subset) {
    Scene s = f.scene;
    s.views.clear();
    for (const SceneView* v : subset) s.views.push_back(*v);
    return evaluate_model(s, model, *f.provider, f.taxonomy, options());
  };
  const nlohmann::json held = only(views.test), train = only(views.train);
  for (const char* field : {"miou", "wiou", "accuracy", "pixels", "scored_pixels", "confusion", "per_class"}) {
    EXPECT_EQ(split["2d"][field], held["2d"][field]) << field;
    EXPECT_EQ(split["2d_train"][field], train["2d"][field]) << field;
  }
  EXPECT_EQ(split["2d"]["views_scored"], views.test.size());
  ASSERT_EQ(split["2d"]["views"].size(), f.scene.views.size());
  size_t marked = 0;
  for (const auto& v : split["2d"]["views"]) marked += v["held_out"].get<bool>();
  EXPECT_EQ(marked, views.test.size());
  // Without a split there is no "2d_train" and every view is in "2d".
  EXPECT_FALSE(evaluate_model(f.scene, model, *f.provider, f.taxonomy, options()).contains("2d_train"));
}

TEST(Evaluation, CliWritesJsonAndMarkdownForTwoModels) {
  Fixture& f = fixture();
  save_language_model((f.dir / "model_good").string(), make_model());
  save_language_model((f.dir / "model_bad").string(), make_model(f.taxonomy.find("wall"), f.taxonomy.find("roof")));
  const fs::path out = f.dir / "cli_out";
  const auto r = test::run_cli("-q evaluate --scene " + (f.dir / "scene").string() + " --model bad=" +
                               (f.dir / "model_bad").string() + " --model good=" + (f.dir / "model_good").string() +
                               " --out " + out.string() + " --no-images");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(out / "eval.json"));
  EXPECT_EQ(j["methods"], (nlohmann::json{"bad", "good"}));
  EXPECT_GT(j["results"]["good"]["2d"]["miou"].get<double>(), j["results"]["bad"]["2d"]["miou"].get<double>());
  const std::string md = read_text_file(out / "eval.md");
  EXPECT_NE(md.find("Table 1"), std::string::npos);
  EXPECT_NE(md.find("| good |"), std::string::npos);
  EXPECT_FALSE(fs::exists(out / "good" / "views"));
  // Usage errors: no model, a malformed one.
  EXPECT_EQ(test::run_cli("-q evaluate --scene " + (f.dir / "scene").string() + " --out " + out.string()).status, 2);
  EXPECT_EQ(test::run_cli("-q evaluate --scene " + (f.dir / "scene").string() + " --model x --out " + out.string()).status, 2);
  // Label maps that are not there: named before any model is evaluated.
  const auto no_labels = test::run_cli("-q evaluate --scene " + (f.dir / "scene").string() + " --model good=" +
                                       (f.dir / "model_good").string() + " --labels " + (f.dir / "nowhere").string() +
                                       " --out " + out.string());
  EXPECT_EQ(no_labels.status, 1);
  EXPECT_NE(no_labels.err.find("nowhere"), std::string::npos) << no_labels.err;
}

// 2D ground truth as label images (one per photo): synth's exact labels (taxonomy id + 1) in place of the
// cloud's projection. The scored GT pixels are those of the PNGs, counted here with OpenCV; the same
// images with other codes through a class map score the same; no cloud, no 3D.
TEST(Evaluation, LabelImagesAreThe2dGroundTruth) {
  Fixture& f = fixture();
  const fs::path labels = f.dir / "scene" / "gt" / "labels";
  EvaluationOptions o = options();
  o.gt_points.clear();
  o.gt_images = labels.string();
  const nlohmann::json r = evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, o);
  EXPECT_FALSE(r.contains("3d"));
  std::set<int> evaluated;
  for (const auto& name : r["classes"]) evaluated.insert(f.taxonomy.find(name.get<std::string>()));
  int64_t labelled = 0;
  const fs::path coded = f.dir / "coded_labels";
  fs::create_directories(coded);
  for (const SceneView& v : f.scene.views) {
    const cv::Mat m = cv::imread((labels / v.name).string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(m.empty()) << v.name;
    cv::Mat m16;
    m.convertTo(m16, CV_16U);
    cv::Mat codes(m16.size(), CV_16U);
    for (int y = 0; y < m16.rows; ++y)
      for (int x = 0; x < m16.cols; ++x) {
        const int value = m16.at<uint16_t>(y, x);
        labelled += value > 0 && evaluated.count(value - 1);
        codes.at<uint16_t>(y, x) = uint16_t(value ? 10 * value + 5 : 0);
      }
    cv::imwrite((coded / v.name).string(), codes);
  }
  EXPECT_EQ(r["2d"]["valid_gt_pixels"].get<int64_t>(), labelled);
  EXPECT_GT(r["2d"]["wiou"].get<double>(), 0.9);  // the correct field against exact labels
  nlohmann::json map = {{"classes", {{"0", nullptr}}}};
  for (size_t k = 0; k < f.taxonomy.classes.size(); ++k)
    map["classes"][std::to_string(10 * (k + 1) + 5)] = f.taxonomy.classes[k].name;
  const fs::path map_file = f.dir / "codes_map.json";
  write_text_atomic(map_file, map.dump());
  EvaluationOptions mapped = o;
  mapped.gt_images = coded.string();
  mapped.class_map = map_file.string();
  const nlohmann::json m = evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, mapped);
  EXPECT_EQ(m["2d"].dump(), r["2d"].dump());
  // A mask of another size than its photo names the file.
  const SceneView& first = f.scene.views.front();
  const fs::path odd = f.dir / "odd_labels";
  fs::create_directories(odd);
  cv::imwrite((odd / first.name).string(), cv::Mat(7, 9, CV_16U, cv::Scalar(1)));
  EvaluationOptions bad = o;
  bad.gt_images = odd.string();
  const std::string message = test::error_of([&] { evaluate_model(f.scene, make_model(), *f.provider, f.taxonomy, bad); });
  EXPECT_NE(message.find((odd / first.name).string()), std::string::npos) << message;
  EXPECT_NE(message.find("label image of 9x7"), std::string::npos) << message;
}
