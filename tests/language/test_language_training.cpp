// Language training (paper 3.3) on a hand-made scene: a wall of Gaussians at depth 5 in front of
// three 16 x 12 cameras, hand-made per-view features (two SAM segments in the lower half, two
// CityGML regions in the upper half, defined in world coordinates so that every view agrees) and a
// tiny untrained autoencoder. Checks that rendered latents approach the encoded targets, that the
// baseline ignores the CityGML targets, and that a resumed run equals an uninterrupted one.
#include <ATen/ATen.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/interrupt.h"
#include "core/metrics_log.h"
#include "error_of.h"
#include "features/view_features.h"
#include "language/language_loss.h"
#include "language/language_model.h"
#include "language/language_training.h"
#include "models/temp_dir.h"
#include "scene/scene.h"
#include "splat/ply_gaussians.h"
#include "splat/rasterize.h"

namespace cls {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

constexpr int kW = 16, kH = 12, kDim = 8;
constexpr double kDepth = 5, kF = 16;
const double kCentres[3] = {-0.4, 0.0, 0.4};

AutoencoderConfig tiny_config() {
  AutoencoderConfig c;
  c.input_dim = kDim;
  c.encoder_dims = {6, 4};
  c.decoder_dims = {6, kDim};
  return c;
}

double world_x(int view, int x) { return (x + 0.5 - kW / 2.0) / kF * kDepth + kCentres[view]; }
double world_y(int y) { return (y + 0.5 - kH / 2.0) / kF * kDepth; }

at::Tensor unit_rows(int64_t n, uint64_t seed) {
  at::manual_seed(seed);
  const at::Tensor f = at::randn({n, kDim});
  return f / f.norm(2, {1}, true);
}

// SAM: lower half (world y > 0), segment 2k left of x = 0 and 2k + 1 right of it at seg level k;
// CityGML: upper half, region 2(l-1) left and 2(l-1) + 1 right at level l. M = upper half.
ViewFeatures view_features(int view, const at::Tensor& sam_f, const at::Tensor& gml_f) {
  ViewFeatures f;
  f.height = kH, f.width = kW;
  f.sam_seg.assign(4 * kH * kW, -1);
  f.gml_seg.assign(3 * kH * kW, -1);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const int right = world_x(view, x) > 0 ? 1 : 0;
      for (int k = 0; k < 4; ++k)
        if (world_y(y) > 0) f.sam_seg[(k * kH + y) * kW + x] = 2 * k + right;
      for (int l = 0; l < 3; ++l)
        if (world_y(y) < 0) f.gml_seg[(l * kH + y) * kW + x] = 2 * l + right;
    }
  f.sam_features = sam_f;
  f.gml_features = gml_f;
  for (int r = 0; r < 6; ++r) {
    CityRegion c;
    c.level = r / 2 + 1;
    c.class_id = r % 2;
    c.class_name = r % 2 ? "door" : "wall";
    c.pixels = kH * kW / 4;
    f.regions.push_back(c);
  }
  return f;
}

struct TinyScene {
  TempDir dir;
  Scene scene;
  LanguageTrainOptions options;
  at::Tensor sam_f = unit_rows(8, 11), gml_f = unit_rows(6, 12);

  TinyScene() {
    // A wall of 16 x 11 Gaussians at z = 5 covering every view.
    const int nx = 16, ny = 11;
    GaussianModel g = make_gaussians(nx * ny, 0, 0);
    auto means = g.means.accessor<float, 2>();
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        means[j * nx + i][0] = float(-3.0 + 0.4 * i);
        means[j * nx + i][1] = float(-2.0 + 0.4 * j);
        means[j * nx + i][2] = float(kDepth);
      }
    g.log_scales.fill_(std::log(0.22));
    g.opacity_logits.fill_(3.0);
    options.geometry_ply = (dir.path / "geometry.ply").string();
    write_gaussians_ply(options.geometry_ply, g);
    options.autoencoder_path = (dir.path / "ae.safetensors").string();
    Autoencoder(tiny_config(), 5).save(options.autoencoder_path);
    options.features_dir = (dir.path / "features").string();
    write_features();
    std::ofstream(dir.path / "features" / "features.json") << R"({"provider": {"provider": "hand-made"}})";
    for (int v = 0; v < 3; ++v) {
      SceneView sv;
      sv.name = "view" + std::to_string(v) + ".png";
      sv.camera = PinholeCamera{kF, kF, kW / 2.0, kH / 2.0, kW, kH};
      sv.pose.t = Vec3d{-kCentres[v], 0, 0};
      scene.views.push_back(sv);
    }
    options.out_dir = (dir.path / "model").string();
    options.iterations = 150;
    options.lr = 0.02;
    options.checkpoint_every = 0;
    options.device = "cpu";
  }
  // The same cameras as a COLMAP text model (scene/sparse/0), for the CLI.
  fs::path write_colmap() const {
    const fs::path root = dir.path / "scene";
    fs::create_directories(root / "sparse" / "0");
    std::ofstream(root / "sparse" / "0" / "cameras.txt") << "1 PINHOLE " << kW << " " << kH << " " << kF << " " << kF
                                                           << " " << kW / 2.0 << " " << kH / 2.0 << "\n";
    std::ofstream images(root / "sparse" / "0" / "images.txt");
    for (int v = 0; v < 3; ++v)
      images << v + 1 << " 1 0 0 0 " << -kCentres[v] << " 0 0 1 view" << v << ".png\n\n";
    std::ofstream(root / "sparse" / "0" / "points3D.txt") << "1 0 0 5 128 128 128 0.5\n";
    return root;
  }
  void write_features() {
    for (int v = 0; v < 3; ++v)
      write_view_features(options.features_dir, "view" + std::to_string(v), view_features(v, sam_f, gml_f));
  }
};

// Mean |rendered - target| over the target's valid pixels of every view at `level`, and the same
// for a zero rendering (the initial state). `cosine`: mean 1 - cos(rendered, target) instead, and 1 (a
// rendering orthogonal to the targets).
std::pair<double, double> target_error(const TinyScene& t, const LanguageModel& m, int level, bool gml,
                                       bool cosine = false) {
  const at::Tensor means = m.gaussians.means, scales = m.gaussians.scales(), quats = m.gaussians.quats,
                   opac = m.gaussians.opacities();
  double err = 0, base = 0, count = 0;
  for (int v = 0; v < 3; ++v) {
    const ViewFeatures f = view_features(v, t.sam_f, t.gml_f);
    // the space the field answers in: the autoencoder's latents, or the features themselves (sparse)
    const at::Tensor table = m.is_sparse() ? (gml ? t.gml_f : t.sam_f) : m.autoencoder->encode(gml ? t.gml_f : t.sam_f);
    const LatentTarget target =
        gml ? gather_latent_target(f.gml_seg.data() + (level - 1) * kH * kW, kH, kW, table)
            : gather_latent_target(f.sam_seg.data() + level * kH * kW, kH, kW, table);
    RasterizeSettings s;
    s.camera = t.scene.views[v].camera;
    s.pose = t.scene.views[v].pose;
    const SparseLevel& sl = m.sparse[size_t(level - 1)];
    const at::Tensor img =
        m.is_sparse()
            ? at::matmul(rasterize_sparse_features(means, scales, quats, opac, sl.weights, sl.indices,
                                                   int(sl.codebook.size(0)), {}, s).image, sl.codebook)
            : rasterize_features(means, scales, quats, opac, m.latents[level - 1], {}, s).image;
    // Pixels next to the segment boundary (x = 0) blend both sides: leave them out.
    at::Tensor w = target.valid.clone();
    for (int x = 0; x < kW; ++x)
      if (std::abs(world_x(v, x)) < 0.5) w.select(1, x).zero_();
    const at::Tensor distance = cosine ? 1 - at::cosine_similarity(img, target.latents, -1)
                                       : (img - target.latents).abs().sum(-1);
    err += (distance * w).sum().item<double>();
    base += ((cosine ? at::ones_like(w) : target.latents.abs().sum(-1)) * w).sum().item<double>();
    count += w.sum().item<double>();
  }
  return {err / count, base / count};
}

TEST(LanguageTraining, RenderedLatentsApproachTheTargets) {
  TinyScene t;
  const LanguageTrainReport r = train_language(t.scene, t.options);
  EXPECT_FALSE(r.interrupted);
  EXPECT_EQ(r.iterations, 3 * 150);
  const LanguageModel m = load_language_model(t.options.out_dir);
  EXPECT_EQ(m.info["method"], "citylangsplat");
  EXPECT_EQ(m.info["provider"]["provider"], "hand-made");
  EXPECT_EQ(m.info["iterations"], 150);
  EXPECT_EQ(m.info["lambda_citygml"], 0.5);
  for (int level = 1; level <= 3; ++level) {
    const auto [sam_err, sam_base] = target_error(t, m, level, false);
    const auto [gml_err, gml_base] = target_error(t, m, level, true);
    EXPECT_LT(sam_err, 0.05 * sam_base) << "level " << level << " SAM half";
    EXPECT_LT(gml_err, 0.05 * gml_base) << "level " << level << " CityGML half";
  }
  // The geometry is frozen: the model's PLY holds the input geometry unchanged.
  const GaussianModel in = read_gaussians_ply(t.options.geometry_ply);
  EXPECT_TRUE(at::equal(m.gaussians.means, in.means));
  EXPECT_TRUE(at::equal(m.gaussians.opacity_logits, in.opacity_logits));
}

// The sparse field (issue 36): K softmax weights over a codebook per level, no autoencoder; under the L1 its
// rendered features (weights times codebook) approach the targets in feature space, magnitude and all, and a
// resumed run equals an uninterrupted one (the logits, the codebook and both Adam states are checkpointed).
TEST(LanguageTraining, SparseFieldLearnsTheTargetsInFeatureSpace) {
  TinyScene t;
  t.options.field = "sparse";
  t.options.sparse_distance = "l1";  // the cosine leaves a feature's length free (its own test below)
  t.options.codebook_size = 8;
  t.options.top_k = 2;
  t.options.logit_lr = t.options.lr;  // the tiny scene's short schedule
  t.options.autoencoder_path.clear();  // the sparse field needs none
  train_language(t.scene, t.options);
  const LanguageModel m = load_language_model(t.options.out_dir);
  ASSERT_TRUE(m.is_sparse());
  EXPECT_EQ(m.info["field"], "sparse");
  EXPECT_EQ(m.info["top_k"], 2);
  EXPECT_FALSE(fs::exists(fs::path(t.options.out_dir) / "autoencoder.safetensors"));
  for (int level = 1; level <= 3; ++level) {
    const SparseLevel& sl = m.sparse[size_t(level - 1)];
    EXPECT_EQ(sl.codebook.sizes(), at::IntArrayRef({8, kDim}));
    EXPECT_EQ(sl.weights.sizes(), at::IntArrayRef({m.gaussians.size(), 2}));
    EXPECT_LT((sl.weights.sum(1) - 1).abs().max().item<double>(), 1e-5) << "softmax weights sum to 1";
    const auto [sam_err, sam_base] = target_error(t, m, level, false);
    const auto [gml_err, gml_base] = target_error(t, m, level, true);
    EXPECT_LT(sam_err, 0.1 * sam_base) << "level " << level << " SAM half";
    EXPECT_LT(gml_err, 0.1 * gml_base) << "level " << level << " CityGML half";
  }

  t.options.iterations = 10;
  t.options.out_dir = (t.dir.path / "sparse_full").string();
  train_language(t.scene, t.options);
  t.options.out_dir = (t.dir.path / "sparse_resumed").string();
  t.options.stop_after = 12;  // level 2, iteration 2: inside its warm-up (3 of 10 iterations)
  t.options.checkpoint_every = 3;
  EXPECT_TRUE(train_language(t.scene, t.options).interrupted);
  t.options.stop_after = 0;
  t.options.resume = true;
  train_language(t.scene, t.options);
  const LanguageModel full = load_language_model((t.dir.path / "sparse_full").string());
  const LanguageModel resumed = load_language_model(t.options.out_dir);
  for (int l = 0; l < 3; ++l) {
    EXPECT_TRUE(at::equal(full.sparse[l].indices, resumed.sparse[l].indices)) << "level " << l + 1;
    EXPECT_TRUE(at::equal(full.sparse[l].weights, resumed.sparse[l].weights)) << "level " << l + 1;
    EXPECT_TRUE(at::equal(full.sparse[l].codebook, resumed.sparse[l].codebook)) << "level " << l + 1;
  }
  t.options.resume = false;
  t.options.top_k = 9;
  EXPECT_THROW(train_language(t.scene, t.options), UsageError) << "K above the codebook";
  t.options.top_k = 2;
  t.options.lift_temperature = -0.1;
  EXPECT_THROW(train_language(t.scene, t.options), UsageError) << "a negative lifting temperature";
}

// The sparse field's first logits lifted from the targets (sparse_lifting.h; its own tests check the values):
// before any step the lifted field is nearer the targets than the jittered one, at every level, and model.json
// says how it started.
TEST(LanguageTraining, SparseFieldStartsNearerTheTargetsWhenLifted) {
  TinyScene t;
  t.options.field = "sparse";
  t.options.codebook_size = 8;
  t.options.top_k = 2;
  t.options.autoencoder_path.clear();
  t.options.iterations = 1;  // the metrics' one row per level holds the loss of the first logits
  std::map<double, std::vector<nlohmann::json>> rows;
  for (const double temperature : {0.0, 0.1}) {
    t.options.lift_temperature = temperature;
    t.options.out_dir = (t.dir.path / ("start_" + std::to_string(temperature))).string();
    train_language(t.scene, t.options);
    rows[temperature] = read_metrics(fs::path(t.options.out_dir) / "metrics.jsonl");
    ASSERT_EQ(rows[temperature].size(), 3u);
    EXPECT_EQ(load_language_model(t.options.out_dir).info["lift_temperature"].get<double>(), temperature);
  }
  for (size_t level = 0; level < 3; ++level)
    EXPECT_LT(rows[0.1][level]["loss"].get<double>(), rows[0.0][level]["loss"].get<double>()) << "level " << level + 1;
}

// The sparse field under the cosine distance (--sparse-distance cosine, sparse_loss.h): from the jittered start
// its rendered features turn towards the targets' directions at every level, and model.json says which
// distance trained it.
TEST(LanguageTraining, SparseFieldLearnsTheTargetsUnderTheCosineDistance) {
  TinyScene t;
  t.options.field = "sparse";
  t.options.codebook_size = 8;
  t.options.top_k = 2;
  t.options.logit_lr = t.options.lr;
  t.options.autoencoder_path.clear();
  t.options.lift_temperature = 0;  // what the loss learns, not what the lifting starts from
  EXPECT_EQ(t.options.sparse_distance, "cosine") << "the default";
  std::map<int, LanguageModel> models;
  for (const int iterations : {1, 150}) {
    t.options.iterations = iterations;
    t.options.out_dir = (t.dir.path / ("cosine_" + std::to_string(iterations))).string();
    train_language(t.scene, t.options);
    models.emplace(iterations, load_language_model(t.options.out_dir));
  }
  EXPECT_EQ(models.at(150).info["sparse_distance"], "cosine");
  // The distance reaches the loss: from the same start the first losses under the L1 differ at every level.
  const std::vector<nlohmann::json> cosine_rows = read_metrics(fs::path(t.dir.path / "cosine_1") / "metrics.jsonl");
  t.options.sparse_distance = "l1";
  t.options.iterations = 1;
  t.options.out_dir = (t.dir.path / "l1_1").string();
  train_language(t.scene, t.options);
  const std::vector<nlohmann::json> l1_rows = read_metrics(fs::path(t.options.out_dir) / "metrics.jsonl");
  ASSERT_EQ(cosine_rows.size(), 3u);
  ASSERT_EQ(l1_rows.size(), 3u);
  for (size_t level = 0; level < 3; ++level)
    EXPECT_GT(std::abs(cosine_rows[level]["loss"].get<double>() - l1_rows[level]["loss"].get<double>()),
              0.01 * l1_rows[level]["loss"].get<double>())
        << "level " << level + 1;
  for (int level = 1; level <= 3; ++level)
    for (const bool gml : {false, true}) {
      const double before = target_error(t, models.at(1), level, gml, true).first;
      const double after = target_error(t, models.at(150), level, gml, true).first;
      EXPECT_LT(after, 0.05) << "level " << level << (gml ? " CityGML" : " SAM") << " half, 1 - cos";
      EXPECT_LT(after, 0.2 * before) << "level " << level << (gml ? " CityGML" : " SAM") << " half";
    }
  // A checkpoint trained under the L1 does not resume under the cosine: the distance is part of its settings.
  t.options.out_dir = (t.dir.path / "l1_stopped").string();
  t.options.iterations = 4;
  t.options.stop_after = 2;
  EXPECT_TRUE(train_language(t.scene, t.options).interrupted);
  t.options.stop_after = 0;
  t.options.resume = true;
  t.options.sparse_distance = "cosine";
  EXPECT_NE(test::error_of([&] { train_language(t.scene, t.options); }).find("sparse_distance"), std::string::npos);
  t.options.resume = false;
  t.options.sparse_distance = "l2";
  EXPECT_THROW(train_language(t.scene, t.options), UsageError) << "a distance that is not l1 or cosine";
}

TEST(LanguageTraining, BaselineIgnoresCityGmlTargets) {
  TinyScene t;
  t.options.baseline = true;
  t.options.iterations = 60;
  train_language(t.scene, t.options);
  const LanguageModel a = load_language_model(t.options.out_dir);
  EXPECT_EQ(a.info["method"], "langsplat");
  const std::vector<nlohmann::json> rows = read_metrics(fs::path(t.options.out_dir) / "metrics.jsonl");
  ASSERT_EQ(rows.size(), 3u * 60);
  EXPECT_FALSE(rows[0].contains("l_citygml")) << "the baseline has no CityGML term";
  // Other CityGML features: the baseline trains to the same latents, bit for bit.
  t.gml_f = unit_rows(6, 99);
  t.write_features();
  t.options.out_dir = (t.dir.path / "model_b").string();
  train_language(t.scene, t.options);
  const LanguageModel b = load_language_model(t.options.out_dir);
  for (int l = 0; l < 3; ++l) EXPECT_TRUE(at::equal(a.latents[l], b.latents[l])) << l;
  // The SAM half is learnt, the CityGML half (no SAM segment there) is not.
  const auto [sam_err, sam_base] = target_error(t, a, 1, false);
  const auto [gml_err, gml_base] = target_error(t, a, 1, true);
  EXPECT_LT(sam_err, 0.05 * sam_base);
  EXPECT_GT(gml_err, 0.5 * gml_base);
}

// LangSplat's splatting: the model holds what was splatted, each seen Gaussian's latent divided by its
// norm (unseen ones stay zero), and the field still learns the targets.
TEST(LanguageTraining, NormalizedLatentsAreSplattedAndSavedAsUnitRows) {
  TinyScene t;
  t.options.normalize_latents = true;
  train_language(t.scene, t.options);
  const LanguageModel m = load_language_model(t.options.out_dir);
  EXPECT_EQ(m.info["normalize_latents"], true);
  for (int level = 1; level <= 3; ++level) {
    const at::Tensor norms = m.latents[level - 1].norm(2, {1});
    int64_t unit = 0;
    for (int64_t i = 0; i < norms.size(0); ++i) {
      const double n = norms[i].item<double>();
      EXPECT_TRUE(std::abs(n - 1) < 1e-5 || n == 0) << "level " << level << " row " << i << " norm " << n;
      unit += std::abs(n - 1) < 1e-5;
    }
    EXPECT_GT(unit, norms.size(0) / 2) << "level " << level;
    const auto [sam_err, sam_base] = target_error(t, m, level, false);
    EXPECT_LT(sam_err, sam_base) << "level " << level;  // it learns, if less well than raw latents (docs/language.md)
  }
}

TEST(LanguageTraining, ResumeEqualsUninterruptedRun) {
  TinyScene t;
  t.options.iterations = 20;
  train_language(t.scene, t.options);
  const LanguageModel full = load_language_model(t.options.out_dir);

  t.options.out_dir = (t.dir.path / "resumed").string();
  t.options.stop_after = 33;  // level 2, iteration 13 (mid-epoch of the 3-view order)
  t.options.checkpoint_every = 7;
  const LanguageTrainReport stopped = train_language(t.scene, t.options);
  EXPECT_TRUE(stopped.interrupted);
  EXPECT_EQ(stopped.iterations, 33);
  EXPECT_FALSE(fs::exists(fs::path(t.options.out_dir) / "model.json"));
  // Rows a killed run would have written after its checkpoint: the resume drops them.
  const fs::path curve = fs::path(t.options.out_dir) / "metrics.jsonl";
  std::ofstream(curve, std::ios::app) << R"({"level": 2, "iteration": 14, "loss": 9})" << "\n"
                                      << R"({"level": 3, "iteration": 1, "loss": 9})" << "\n";
  t.options.stop_after = 0;
  t.options.resume = true;
  const LanguageTrainReport rest = train_language(t.scene, t.options);
  EXPECT_FALSE(rest.interrupted);
  EXPECT_EQ(rest.iterations, 60 - 33);
  const LanguageModel resumed = load_language_model(t.options.out_dir);
  for (int l = 0; l < 3; ++l) EXPECT_TRUE(at::equal(full.latents[l], resumed.latents[l])) << "level " << l + 1;
  // The curve: a row per iteration of each level (interval 1 below 600), the resumed one equal to the
  // uninterrupted one but for the clock.
  const std::vector<nlohmann::json> full_rows = read_metrics(t.dir.path / "model" / "metrics.jsonl");
  const std::vector<nlohmann::json> resumed_rows = read_metrics(curve);
  ASSERT_EQ(full_rows.size(), 60u);
  ASSERT_EQ(resumed_rows.size(), 60u);
  for (size_t i = 0; i < 60; ++i) {
    EXPECT_EQ(full_rows[i]["level"], int(i) / 20 + 1);
    EXPECT_EQ(full_rows[i]["iteration"], int(i) % 20 + 1);
    for (const char* key : {"level", "iteration", "loss", "l_sam", "l_sam_gml", "l_citygml"})
      EXPECT_EQ(full_rows[i][key], resumed_rows[i][key]) << key << ", row " << i;
  }

  // An interrupt (the signal flag) stops at the next iteration with a checkpoint.
  t.options.out_dir = (t.dir.path / "signalled").string();
  t.options.resume = false;
  request_interrupt();
  const LanguageTrainReport sig = train_language(t.scene, t.options);
  reset_interrupt();
  EXPECT_TRUE(sig.interrupted);
  EXPECT_EQ(sig.iterations, 1);
  EXPECT_TRUE(fs::exists(fs::path(t.options.out_dir) / "checkpoints" / "language.safetensors"));

  // Resuming with other settings is refused, naming the checkpoint.
  t.options.resume = true;
  t.options.lambda_citygml = 0.25;
  try {
    train_language(t.scene, t.options);
    ADD_FAILURE() << "resume with another lambda was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("language.safetensors"), std::string::npos) << e.what();
  }
}

TEST(LanguageTraining, MismatchedFeatureSizeIsAnError) {
  TinyScene t;
  t.scene.views[1].camera.width = 20;
  try {
    train_language(t.scene, t.options);
    ADD_FAILURE() << "accepted features of another size";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("view1_s.npy"), std::string::npos) << e.what();
  }
}

// --test-every: the held-out views (every N-th by name: view0 and view2 for N = 2) are never read, so a
// held-out view whose features do not fit cannot stop the training; holding out all views is an error.
TEST(LanguageTraining, HeldOutViewsAreNeverRead) {
  TinyScene t;
  t.scene.views[0].camera.width = 20;  // its features are 64 wide: an error if it were read
  t.options.test_every = 2;
  t.options.iterations = 5;
  EXPECT_EQ(train_language(t.scene, t.options).iterations, 15);  // 5 per level
  t.options.test_every = 0;
  EXPECT_THROW(train_language(t.scene, t.options), Error);
  t.options.test_every = 1;
  EXPECT_THROW(train_language(t.scene, t.options), UsageError);
}

// Runs a shell script; returns the exit status and the combined output.
int run_shell(const std::string& script, std::string* output) {
  const std::string cmd = "(" + script + ") 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return -1;
  char buf[4096];
  output->clear();
  while (size_t n = fread(buf, 1, sizeof buf, pipe)) output->append(buf, n);
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
int run_cli(const std::string& arguments, std::string* output) {
  return run_shell(std::string(CLS_BINARY) + " " + arguments, output);
}

TEST(LanguageTraining, CommandLineTrainsAndStopsOnSigint) {
  TinyScene t;
  const fs::path scene = t.write_colmap();
  const std::string common = "train-language --scene " + scene.string() + " --model " + t.options.geometry_ply +
                             " --features " + t.options.features_dir + " --autoencoder " + t.options.autoencoder_path +
                             " --device cpu --lr 0.02";
  std::string out;
  // The reference: 20 iterations per level in one go.
  ASSERT_EQ(run_cli(common + " --iterations 20 --out " + (t.dir.path / "cli_full").string(), &out), 0) << out;
  const LanguageModel full = load_language_model((t.dir.path / "cli_full").string());
  EXPECT_EQ(full.info["method"], "citylangsplat");

  // SIGINT after the first checkpoint of a long run: exit 130, a checkpoint and a hint how to resume.
  const std::string long_out = (t.dir.path / "cli_long").string();
  const std::string checkpoint = long_out + "/checkpoints/language.safetensors";
  ASSERT_EQ(run_shell(std::string(CLS_BINARY) + " " + common + " --iterations 100000000 --checkpoint-every 1 --out " +
                          long_out + " & pid=$!; i=0; " + "while [ ! -e " + checkpoint +
                          " ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i+1)); done; kill -INT $pid; wait $pid",
                      &out),
            130)
      << out;
  EXPECT_NE(out.find("--resume"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists(checkpoint));
  EXPECT_FALSE(fs::exists(long_out + "/model.json"));
  // Resuming it with another lambda is refused, naming the checkpoint.
  EXPECT_EQ(run_cli(common + " --iterations 100000000 --lambda-citygml 0.3 --resume --out " + long_out, &out), 1) << out;
  EXPECT_NE(out.find("language.safetensors"), std::string::npos) << out;

  // Baseline and bad usage.
  ASSERT_EQ(run_cli(common + " --iterations 2 --baseline langsplat --out " + (t.dir.path / "cli_base").string(), &out), 0)
      << out;
  EXPECT_EQ(load_language_model((t.dir.path / "cli_base").string()).info["method"], "langsplat");
  EXPECT_EQ(run_cli(common + " --baseline other --out " + (t.dir.path / "x").string(), &out), 2) << out;
  EXPECT_EQ(run_cli("train-language --scene " + scene.string(), &out), 2) << out;
}

}  // namespace
}  // namespace cls
