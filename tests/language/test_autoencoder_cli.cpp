// `citylangsplat autoencoder` on a temporary directory of LangSplat-layout .npy feature files.
#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cli_runner.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/npy.h"
#include "language/autoencoder.h"
#include "language/autoencoder_stage.h"
#include "language/autoencoder_test_util.h"
#include "models/temp_dir.h"
#include "models/weights/npy_tensor.h"

namespace cls {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::TempDir;

void write_features(const fs::path& path, const at::Tensor& f) { write_npy(path, to_npy(f.contiguous())); }

// Three views' SAM features (40 + 60 + 0 rows) around 6 clusters, a CityGML file that must be ignored
// (wrong width: reading it would fail) and a seg map that is not a feature file.
void make_features_dir(const fs::path& dir) {
  const at::Tensor f = test::clustered_unit_vectors(100, 512, 6, 0.3, 21);
  fs::create_directories(dir / "sub");
  write_features(dir / "a_f.npy", f.slice(0, 0, 40));
  write_features(dir / "sub" / "b_f.npy", f.slice(0, 40, 100));
  write_features(dir / "c_f.npy", at::zeros({0, 512}));
  write_npy(dir / "a_gml_f.npy", make_npy<float>({2, 7}, std::vector<float>(14, 0.f)));
  write_npy(dir / "a_s.npy", make_npy<int32_t>({4, 2, 2}, std::vector<int32_t>(16, -1)));
}

TEST(AutoencoderStage, FindsSamFeatureFilesOnly) {
  TempDir dir;
  make_features_dir(dir.path);
  const auto files = find_sam_feature_files(dir.path);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].filename(), "a_f.npy");
  EXPECT_EQ(files[1].filename(), "c_f.npy");
  EXPECT_EQ(files[2].filename(), "b_f.npy");
  const at::Tensor f = read_sam_features(files, 512);
  EXPECT_EQ(f.sizes(), (at::IntArrayRef{100, 512}));
  EXPECT_THROW(find_sam_feature_files(dir.path / "a_f.npy"), Error);
}

TEST(AutoencoderStage, ReadsAFileInSeveralTilesOnce) {
  // Tile 1 holds a, sub/b and c; tile 0 holds c, sub/b (a view in both tiles) and d: one pool of four
  // files, ordered by their path within the tile, each shared one taken from the first directory given.
  TempDir dir;
  make_features_dir(dir.path / "tile1");
  fs::create_directories(dir.path / "tile0" / "sub");
  for (const char* shared : {"c_f.npy", "sub/b_f.npy"}) fs::copy_file(dir.path / "tile1" / shared, dir.path / "tile0" / shared);
  write_features(dir.path / "tile0" / "d_f.npy", at::ones({5, 512}));
  const auto files = find_sam_feature_files(std::vector<fs::path>{dir.path / "tile0", dir.path / "tile1"});
  const std::vector<fs::path> expected = {dir.path / "tile1" / "a_f.npy", dir.path / "tile0" / "c_f.npy",
                                          dir.path / "tile0" / "d_f.npy", dir.path / "tile0" / "sub" / "b_f.npy"};
  EXPECT_EQ(files, expected);
  EXPECT_EQ(read_sam_features(files, 512).size(0), 40 + 0 + 5 + 60);
  fs::create_directories(dir.path / "empty");
  EXPECT_THROW(find_sam_feature_files(std::vector<fs::path>{dir.path / "tile0", dir.path / "empty"}), Error);
}

TEST(AutoencoderStage, SamplesRowsUniformlyAcrossFiles) {
  // 40 rows in files of 7, 0, 21 and 12 rows, row r holding r in its first column; 10 of them kept.
  TempDir dir;
  const int64_t sizes[] = {7, 0, 21, 12}, total = 40, keep = 10;
  std::vector<fs::path> files;
  int64_t next = 0;
  for (size_t i = 0; i < 4; ++i) {
    at::Tensor f = at::zeros({sizes[i], 4});
    if (sizes[i] > 0) f.select(1, 0).copy_(at::arange(next, next + sizes[i], at::kFloat));
    next += sizes[i];
    files.push_back(dir.path / ("v" + std::to_string(i) + "_f.npy"));
    write_features(files.back(), f);
  }
  std::vector<int> count(total, 0);
  const int seeds = 1500;
  for (int seed = 0; seed < seeds; ++seed) {
    int64_t read = 0;
    const at::Tensor s = read_sam_features(files, 4, keep, seed, &read);
    ASSERT_EQ(read, total);
    ASSERT_EQ(s.size(0), keep);
    std::set<int> rows;
    for (int64_t k = 0; k < keep; ++k) rows.insert(static_cast<int>(s[k][0].item<float>()));
    ASSERT_EQ(rows.size(), static_cast<size_t>(keep)) << "a row was drawn twice (seed " << seed << ")";
    for (int r : rows) ++count[r];
  }
  // Each row is kept with probability 1/4: 375 of 1500 draws, standard deviation 16.8; 6 of them allowed.
  for (int r = 0; r < total; ++r) EXPECT_NEAR(count[r], seeds * keep / total, 100) << "row " << r;
  // Fewer rows than asked: every row, once.
  const at::Tensor all = read_sam_features(files, 4, 100, 1);
  EXPECT_EQ(all.size(0), total);
  EXPECT_EQ(all.select(1, 0).max().item<float>(), total - 1);
  EXPECT_EQ(std::get<0>(at::_unique(all.select(1, 0))).size(0), total);
}

TEST(AutoencoderCli, TrainsAndWritesModelAndReport) {
  TempDir dir;
  make_features_dir(dir.path / "features");
  const fs::path out = dir.path / "model" / "ae.safetensors";
  const auto r = run_cli("autoencoder --features '" + (dir.path / "features").string() + "' --out '" +
                         out.string() + "' --epochs 15 --batch-size 16 --encoder-dims 64,32 --decoder-dims 64,512"
                         " --holdout 0.2 --seed 3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("epoch 15/15"), std::string::npos) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(out.string() + ".json"));
  EXPECT_EQ(j["samples"], 100);
  EXPECT_EQ(j["holdout_samples"], 20);
  EXPECT_EQ(j["train_samples"], 80);
  EXPECT_EQ(j["files"], 3);
  EXPECT_EQ(j["epochs"], 15);
  EXPECT_EQ(j["config"]["encoder_dims"], (std::vector<int>{64, 32}));
  EXPECT_GT(j["holdout_cosine"].get<double>(), 0.8);
  EXPECT_TRUE(std::isfinite(j["train_loss"].get<double>()));
  EXPECT_GE(j["seconds"].get<double>(), 0.0);

  const Autoencoder ae = Autoencoder::load(out.string());
  EXPECT_EQ(ae.config().latent_dim(), 32);
  EXPECT_EQ(ae.config().input_dim, 512);
  // No temporaries left beside the outputs.
  int entries = 0;
  for (const auto& e : fs::directory_iterator(out.parent_path())) entries += e.is_regular_file();
  EXPECT_EQ(entries, 2);
}

// --preset langsplat: LangSplat's published sizes and settings (autoencoder/train.py run as process.sh does), both ends
// normalised, as the langsplat-original baseline trains it.
TEST(AutoencoderCli, LangSplatPresetHasLangSplatsSizesAndSettings) {
  TempDir dir;
  make_features_dir(dir.path / "features");
  const fs::path out = dir.path / "ae.safetensors";
  const std::string base = "autoencoder --features '" + (dir.path / "features").string() + "' --out '" + out.string() + "'";
  const auto r = run_cli(base + " --preset langsplat --epochs 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(out.string() + ".json"));
  EXPECT_EQ(j["config"]["encoder_dims"], (std::vector<int>{256, 128, 64, 32, 3}));
  EXPECT_EQ(j["config"]["decoder_dims"], (std::vector<int>{16, 32, 64, 128, 256, 256, 512}));
  EXPECT_EQ(j["batch_size"], 64);
  EXPECT_DOUBLE_EQ(j["lr"].get<double>(), 7e-4);  // LangSplat's process.sh
  EXPECT_DOUBLE_EQ(j["lambda_cos"].get<double>(), 0.512);
  const Autoencoder ae = Autoencoder::load(out.string());
  const at::Tensor f = test::clustered_unit_vectors(8, 512, 2, 0.3, 5);
  const at::Tensor z = ae.encode(f), back = ae.decode(z);
  ASSERT_EQ(z.size(1), 3);
  EXPECT_TRUE(at::allclose(z.norm(2, {1}), at::ones({8}), 1e-5, 1e-5));
  EXPECT_TRUE(at::allclose(back.norm(2, {1}), at::ones({8}), 1e-5, 1e-5));
  EXPECT_EQ(run_cli(base + " --preset langsplat --lr 0.01").status, 2);
  EXPECT_EQ(run_cli(base + " --preset other").status, 2);
}

TEST(AutoencoderCli, ClearErrors) {
  TempDir dir;
  const fs::path features = dir.path / "features";
  fs::create_directories(features);
  const std::string out = (dir.path / "ae.safetensors").string();
  const std::string base = "autoencoder --epochs 1 --features '" + features.string() + "' --out '" + out + "'";

  // No feature files (a CityGML file alone does not count).
  write_npy(features / "x_gml_f.npy", make_npy<float>({1, 512}, std::vector<float>(512, 0.1f)));
  auto r = run_cli(base);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no SAM feature files"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  // Wrong width, named.
  write_npy(features / "v1_f.npy", make_npy<float>({3, 500}, std::vector<float>(1500, 0.1f)));
  r = run_cli(base);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("v1_f.npy"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[3, 500]"), std::string::npos) << r.err;

  // NaN, named with its row.
  std::vector<float> values(3 * 512, 0.05f);
  values[2 * 512 + 7] = NAN;
  write_npy(features / "v1_f.npy", make_npy<float>({3, 512}, values));
  r = run_cli(base);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("v1_f.npy"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("row 2"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  // Usage errors exit 2.
  EXPECT_EQ(run_cli("autoencoder --out '" + out + "'").status, 2);
  EXPECT_EQ(run_cli(base + " --encoder-dims 256,x").status, 2);
  EXPECT_EQ(run_cli(base + " --batch-size 1").status, 2);
  // A decoder that does not end in the feature size of the files.
  values[2 * 512 + 7] = 0.05f;
  write_npy(features / "v1_f.npy", make_npy<float>({3, 512}, values));
  r = run_cli(base + " --decoder-dims 256,256");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("v1_f.npy"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace cls
