// The language model directory (language_model.h): save/load round trip and broken directories.
#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "error_of.h"
#include "core/error.h"
#include "language/language_model.h"
#include "models/temp_dir.h"
#include "models/weights/safetensors.h"

namespace cls {
namespace {

using cls::test::error_of;

namespace fs = std::filesystem;
using test::TempDir;

AutoencoderConfig tiny_config() {
  AutoencoderConfig c;
  c.input_dim = 8;
  c.encoder_dims = {6, 4};
  c.decoder_dims = {6, 8};
  return c;
}

LanguageModel make_model(int64_t n) {
  GaussianModel g = make_gaussians(n, 1, 0);
  g.means = at::arange(n * 3, at::kFloat).view({n, 3}) * 0.1;
  g.opacity_logits = at::linspace(-1, 1, n).view({n, 1});
  LanguageModel m{std::move(g), {}, Autoencoder(tiny_config(), 3), {{"method", "citylangsplat"}, {"lambda_sam", 1.0}}};
  for (int l = 0; l < 3; ++l) m.latents[l] = at::randn({n, 4}) + l;
  return m;
}

TEST(LanguageModel, SaveLoadRoundTrip) {
  TempDir dir;
  const std::string d = (dir.path / "model").string();
  const LanguageModel m = make_model(5);
  save_language_model(d, m);
  for (const char* f : {"model.json", "point_cloud.ply", "latents.safetensors", "autoencoder.safetensors"})
    EXPECT_TRUE(fs::exists(fs::path(d) / f)) << f;
  const LanguageModel r = load_language_model(d);
  ASSERT_EQ(r.gaussians.size(), 5);
  EXPECT_TRUE(at::equal(r.gaussians.means, m.gaussians.means));
  EXPECT_TRUE(at::equal(r.gaussians.opacity_logits, m.gaussians.opacity_logits));
  EXPECT_EQ(r.gaussians.sh_degree(), 1);
  for (int l = 0; l < 3; ++l) EXPECT_TRUE(at::equal(r.latents[l], m.latents[l])) << l;
  EXPECT_EQ(r.info["method"], "citylangsplat");
  EXPECT_EQ(r.info["gaussians"], 5);
  EXPECT_EQ(r.info["latent_dim"], 4);
  const at::Tensor f = at::randn({3, 8});
  EXPECT_TRUE(at::allclose(r.autoencoder->encode(f), m.autoencoder->encode(f)));
}

TEST(LanguageModel, MissingOrInconsistentPartsNameTheFile) {
  TempDir dir;
  const std::string d = (dir.path / "model").string();
  EXPECT_NE(error_of([&] { load_language_model(d); }).find("model.json"), std::string::npos);
  save_language_model(d, make_model(4));
  // Latents for a different number of Gaussians.
  write_safetensors((fs::path(d) / "latents.safetensors").string(),
                    {{"level1", at::kFloat, {3, 4}, at::zeros({3, 4})},
                     {"level2", at::kFloat, {4, 4}, at::zeros({4, 4})},
                     {"level3", at::kFloat, {4, 4}, at::zeros({4, 4})}});
  std::string e = error_of([&] { load_language_model(d); });
  EXPECT_NE(e.find("latents.safetensors"), std::string::npos) << e;
  EXPECT_NE(e.find("level1"), std::string::npos) << e;
  // A level missing.
  write_safetensors((fs::path(d) / "latents.safetensors").string(),
                    {{"level1", at::kFloat, {4, 4}, at::zeros({4, 4})}, {"level2", at::kFloat, {4, 4}, at::zeros({4, 4})}});
  e = error_of([&] { load_language_model(d); });
  EXPECT_NE(e.find("level3"), std::string::npos) << e;
  // A broken model.json.
  std::ofstream(fs::path(d) / "model.json") << "{not json";
  e = error_of([&] { load_language_model(d); });
  EXPECT_NE(e.find("model.json"), std::string::npos) << e;
  // Wrong latent shapes are refused on save, naming the file.
  LanguageModel bad = make_model(4);
  bad.latents[1] = at::zeros({4, 5});
  e = error_of([&] { save_language_model(d, bad); });
  EXPECT_NE(e.find("level2"), std::string::npos) << e;
}

}  // namespace
}  // namespace cls
