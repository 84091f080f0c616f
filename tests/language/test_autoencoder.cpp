// The shared autoencoder (paper 3.2): loss against hand-computed values, training on clustered unit
// vectors, shapes, determinism, save/load round trip and broken files.
#include <ATen/ATen.h>
#include <ATen/CPUGeneratorImpl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "error_of.h"
#include "core/error.h"
#include "language/autoencoder.h"
#include "language/autoencoder_test_util.h"
#include "models/temp_dir.h"
#include "models/weights/safetensors.h"

namespace cls {
namespace {

using cls::test::error_of;

namespace fs = std::filesystem;
using test::TempDir;

// A small layout so training stays fast; the defaults are checked separately.
AutoencoderConfig small_config() {
  AutoencoderConfig c;
  c.input_dim = 64;
  c.encoder_dims = {32, 16};
  c.decoder_dims = {32, 64};
  return c;
}

TEST(ReconstructionLoss, HandComputedValues) {
  // Row 0: f = (1,0,0), r = (0,1,0): |f-r|^2 = 2, cos = 0.
  // Row 1: f = r = (3,4,0): 0 and cos = 1.
  // Row 2: f = (1,2,2) (|f| = 3), r = (2,0,0): |f-r|^2 = 1+4+4 = 9, cos = 2/(3*2) = 1/3.
  const at::Tensor f = at::tensor({1.f, 0.f, 0.f, 3.f, 4.f, 0.f, 1.f, 2.f, 2.f}).reshape({3, 3});
  const at::Tensor r = at::tensor({0.f, 1.f, 0.f, 3.f, 4.f, 0.f, 2.f, 0.f, 0.f}).reshape({3, 3});
  const at::Tensor l = reconstruction_loss(f, r, 0.5);
  ASSERT_EQ(l.sizes(), (at::IntArrayRef{3}));
  EXPECT_NEAR(l[0].item<double>(), 2.0 + 0.5 * 1.0, 1e-6);
  EXPECT_NEAR(l[1].item<double>(), 0.0, 1e-6);
  EXPECT_NEAR(l[2].item<double>(), 9.0 + 0.5 * (1.0 - 1.0 / 3.0), 1e-5);
  // lambda_cos = 0 leaves the Euclidean term alone; the cosine term scales linearly.
  EXPECT_NEAR(reconstruction_loss(f, r, 0.0)[2].item<double>(), 9.0, 1e-5);
  EXPECT_NEAR(reconstruction_loss(f, r, 2.0)[0].item<double>(), 2.0 + 2.0, 1e-6);
  // Scale matters to the Euclidean term only: r = 2 f gives |f|^2 and cos = 1.
  EXPECT_NEAR(reconstruction_loss(f.slice(0, 2, 3), 2 * f.slice(0, 2, 3), 1.0)[0].item<double>(), 9.0, 1e-5);
  EXPECT_THROW(reconstruction_loss(f, r.slice(0, 0, 2), 1.0), Error);
}

TEST(Autoencoder, DefaultLayoutIs512To128) {
  const Autoencoder ae(AutoencoderConfig{}, 1);
  EXPECT_EQ(ae.config().latent_dim(), 128);
  const at::Tensor z = ae.encode(at::randn({3, 512}));
  EXPECT_EQ(z.sizes(), (at::IntArrayRef{3, 128}));
  // LangSplat normalises the latent.
  EXPECT_TRUE(at::allclose(z.norm(2, {1}), at::ones({3}), 1e-5, 1e-5));
  EXPECT_EQ(ae.decode(z).sizes(), (at::IntArrayRef{3, 512}));
}

TEST(Autoencoder, DecodeIsTheHiddenLayersThenTheLastLinearLayer) {
  // decode(z) = n(decode_hidden(z) W^T + b), computed here in double from the exposed parts, for our
  // layout (one hidden layer), LangSplat's (six, output normalised) and a decoder of one linear layer
  // (no hidden layer: decode_hidden gives the latents themselves).
  AutoencoderConfig one_layer = small_config();
  one_layer.decoder_dims = {one_layer.input_dim};
  for (const AutoencoderConfig& c : {small_config(), langsplat_autoencoder_config(64), one_layer}) {
    const bool has_hidden = c.decoder_dims.size() > 1;
    const Autoencoder ae(c, 4);
    const at::Tensor z = ae.encode(at::randn({9, c.input_dim}));
    const at::Tensor h = ae.decode_hidden(z).to(at::kDouble);
    const int64_t hidden = has_hidden ? c.decoder_dims[c.decoder_dims.size() - 2] : c.latent_dim();
    ASSERT_EQ(h.sizes(), (at::IntArrayRef{9, hidden}));
    ASSERT_EQ(ae.output_weight().sizes(), (at::IntArrayRef{c.input_dim, hidden}));
    at::Tensor expected = h.matmul(ae.output_weight().to(at::kDouble).t()) + ae.output_bias().to(at::kDouble);
    if (c.normalize_output) expected = expected / expected.norm(2, {1}, true);
    EXPECT_LT((ae.decode(z).to(at::kDouble) - expected).abs().max().item<double>(), 1e-5);
    if (has_hidden) EXPECT_GE(h.min().item<double>(), 0.0);  // after a ReLU
    else EXPECT_TRUE(at::equal(h.to(at::kFloat), z));
  }
}

TEST(Autoencoder, EncodeDecodeShapesAndErrors) {
  const Autoencoder ae(small_config(), 3);
  for (int64_t b : {0, 1, 7}) {
    const at::Tensor z = ae.encode(at::randn({b, 64}));
    EXPECT_EQ(z.sizes(), (at::IntArrayRef{b, 16}));
    EXPECT_FALSE(z.requires_grad());
    EXPECT_EQ(ae.decode(z).sizes(), (at::IntArrayRef{b, 64}));
  }
  // Other dtypes are converted; a wrong feature size is an error.
  EXPECT_EQ(ae.encode(at::randn({2, 64}, at::kDouble)).scalar_type(), at::kFloat);
  EXPECT_THROW(ae.encode(at::randn({2, 63})), Error);
  EXPECT_THROW(ae.encode(at::randn({64})), Error);
  EXPECT_THROW(ae.decode(at::randn({2, 64})), Error);
  // Eval mode: a sample's code does not depend on the rest of its batch (BatchNorm uses running stats).
  const at::Tensor x = at::randn({5, 64});
  EXPECT_TRUE(at::allclose(ae.encode(x).slice(0, 0, 1), ae.encode(x.slice(0, 0, 1)), 1e-5, 1e-6));
}

TEST(Autoencoder, InvalidConfigIsAnError) {
  AutoencoderConfig c = small_config();
  c.decoder_dims = {32, 60};
  EXPECT_THROW(Autoencoder(c, 1), Error);
  c = small_config();
  c.encoder_dims.clear();
  EXPECT_THROW(Autoencoder(c, 1), Error);
  c = small_config();
  c.encoder_dims = {32, 0};
  EXPECT_THROW(Autoencoder(c, 1), Error);
}

TEST(Autoencoder, LearnsClusteredUnitVectors) {
  // 20 cluster centres + noise in 512-d (the default layout): the held-out cosine goes from ~0 for
  // the untrained network to > 0.9 within a few epochs.
  const at::Tensor features = test::clustered_unit_vectors(1000, 512, 20, 0.3, 7);
  Autoencoder ae(AutoencoderConfig{}, 1);
  const double untrained =
      at::cosine_similarity(features, ae.decode(ae.encode(features)), 1).mean().item<double>();
  EXPECT_LT(std::abs(untrained), 0.3);
  AutoencoderTrainOptions o;
  o.epochs = 12;
  o.batch_size = 64;
  o.seed = 5;
  std::vector<double> losses;
  o.on_epoch = [&](int epoch, double loss) {
    EXPECT_EQ(epoch, static_cast<int>(losses.size()) + 1);
    losses.push_back(loss);
  };
  size_t batches = 0, per_epoch = 0;
  o.on_batch = [&](size_t n) { ++batches, per_epoch = n; };
  const AutoencoderReport r = ae.train(features, o);
  EXPECT_EQ(r.train_samples, 900);
  EXPECT_EQ(r.holdout_samples, 100);
  ASSERT_EQ(losses.size(), 12u);
  // 900 training rows in batches of 64: 14 full ones and one of 4, each epoch.
  EXPECT_EQ(per_epoch, (900u + 63) / 64);
  EXPECT_EQ(batches, 12 * per_epoch);
  EXPECT_LT(losses.back(), 0.5 * losses.front());
  EXPECT_DOUBLE_EQ(r.train_loss, losses.back());
  EXPECT_GT(r.holdout_cosine, 0.9);
  // The reported cosine is the mean cos(f, D(E(f))) of held-out rows: recompute it over all rows.
  const at::Tensor rec = ae.decode(ae.encode(features));
  const double all_cos = at::cosine_similarity(features, rec, 1).mean().item<double>();
  EXPECT_GT(all_cos, 0.9);
  EXPECT_NEAR(all_cos, r.holdout_cosine, 0.05);
}

TEST(Autoencoder, TrainedOnSamFeaturesItCarriesOtherFeaturesOfTheSameClasses) {
  // Paper 3.2: trained on SAM features only, applied to the CityGML features too. SAM-like features
  // normalise(u_c + 0.5 n) and CityGML-like ones normalise(u_c + 0.25 n') (fresh noise, never seen in
  // training) of the same 20 class directions u_c (the synthetic provider's structure).
  const int64_t classes = 20, dim = 512;
  at::Generator gen = at::detail::createCPUGenerator(77);
  at::Tensor u = at::randn({classes, dim}, gen);
  u = u / u.norm(2, {1}, true);
  auto around = [&](int64_t n, double noise) {
    const at::Tensor ids = at::arange(n, at::kLong).remainder(classes);
    at::Tensor e = at::randn({n, dim}, gen);
    e = e / e.norm(2, {1}, true);
    const at::Tensor f = u.index_select(0, ids) + noise * e;
    return std::make_pair(f / f.norm(2, {1}, true), ids);
  };
  const auto sam = around(1000, 0.5);
  const auto gml = around(200, 0.25);
  Autoencoder ae(AutoencoderConfig{}, 2);
  AutoencoderTrainOptions o;
  o.epochs = 12;
  o.batch_size = 64;
  ae.train(sam.first, o);

  // Decoded CityGML features point to their class: nearest class direction is the right one.
  const at::Tensor decoded = ae.decode(ae.encode(gml.first));
  const at::Tensor cos_to_classes = (decoded / decoded.norm(2, {1}, true)).matmul(u.t());
  const double correct = cos_to_classes.argmax(1).eq(gml.second).to(at::kDouble).mean().item<double>();
  EXPECT_GT(correct, 0.98);
  EXPECT_GT(cos_to_classes.gather(1, gml.second.unsqueeze(1)).mean().item<double>(), 0.9);
  // In latent space a CityGML code lies nearest to the mean SAM code of its own class (the language
  // loss mixes the two sources per pixel).
  const at::Tensor z_sam = ae.encode(sam.first), z_gml = ae.encode(gml.first);
  at::Tensor class_mean = at::zeros({classes, ae.config().latent_dim()});
  class_mean.index_add_(0, sam.second, z_sam);
  class_mean = class_mean / class_mean.norm(2, {1}, true);
  const at::Tensor nearest = z_gml.matmul(class_mean.t()).argmax(1);
  EXPECT_GT(nearest.eq(gml.second).to(at::kDouble).mean().item<double>(), 0.98);
}

TEST(Autoencoder, TrainingIsDeterministicForASeed) {
  const at::Tensor features = test::clustered_unit_vectors(200, 64, 5, 0.3, 11);
  AutoencoderTrainOptions o;
  o.epochs = 3;
  o.batch_size = 32;
  o.seed = 9;
  auto run = [&](uint64_t init_seed, uint64_t train_seed) {
    Autoencoder ae(small_config(), init_seed);
    o.seed = train_seed;
    const AutoencoderReport r = ae.train(features, o);
    return std::make_pair(r, ae.encode(features));
  };
  const auto a = run(1, 9), b = run(1, 9), c = run(1, 10), d = run(2, 9);
  EXPECT_TRUE(at::equal(a.second, b.second));
  EXPECT_EQ(a.first.train_loss, b.first.train_loss);
  EXPECT_EQ(a.first.holdout_cosine, b.first.holdout_cosine);
  EXPECT_FALSE(at::equal(a.second, c.second));  // another shuffle and split
  EXPECT_FALSE(at::equal(a.second, d.second));  // another initialisation
}

TEST(Autoencoder, TrainingRejectsBadInput) {
  Autoencoder ae(small_config(), 1);
  AutoencoderTrainOptions o;
  o.epochs = 1;
  at::Tensor bad = at::randn({10, 64});
  bad[3][5] = NAN;
  EXPECT_NE(error_of([&] { ae.train(bad, o); }).find("NaN"), std::string::npos);
  EXPECT_THROW(ae.train(at::randn({10, 32}), o), Error);
  EXPECT_THROW(ae.train(at::randn({1, 64}), o), Error);  // fewer than 2 training samples
  o.batch_size = 1;
  EXPECT_THROW(ae.train(at::randn({10, 64}), o), Error);
  // No held-out features: the cosine is NaN, not a training-set figure.
  o.batch_size = 4;
  o.holdout_fraction = 0;
  const AutoencoderReport r = ae.train(at::randn({9, 64}), o);  // 4 + 5: a last batch of 1 joins its neighbour
  EXPECT_EQ(r.holdout_samples, 0);
  EXPECT_TRUE(std::isnan(r.holdout_cosine));
  EXPECT_TRUE(std::isfinite(r.train_loss));
}

TEST(Autoencoder, SaveLoadRoundTripIsBitIdentical) {
  TempDir dir;
  const at::Tensor features = test::clustered_unit_vectors(200, 64, 5, 0.3, 3);
  AutoencoderConfig c = small_config();
  c.normalize_output = true;
  Autoencoder ae(c, 4);
  AutoencoderTrainOptions o;
  o.epochs = 2;
  o.batch_size = 32;
  ae.train(features, o);  // BatchNorm running statistics are no longer the initial ones
  const std::string path = (dir.path / "ae.safetensors").string();
  ae.save(path);
  const Autoencoder loaded = Autoencoder::load(path);
  EXPECT_EQ(loaded.config().encoder_dims, c.encoder_dims);
  EXPECT_EQ(loaded.config().decoder_dims, c.decoder_dims);
  EXPECT_TRUE(loaded.config().normalize_output);
  const at::Tensor z = ae.encode(features);
  EXPECT_TRUE(at::equal(z, loaded.encode(features)));
  EXPECT_TRUE(at::equal(ae.decode(z), loaded.decode(z)));
  // The names follow LangSplat's state_dict (encoder.0 Linear, encoder.1 BatchNorm1d, encoder.3 Linear).
  const WeightFile file = read_safetensors(path);
  EXPECT_TRUE(file.contains("encoder.0.weight"));
  EXPECT_TRUE(file.contains("encoder.1.running_var"));
  EXPECT_TRUE(file.contains("encoder.3.bias"));
  EXPECT_TRUE(file.contains("decoder.2.weight"));
  EXPECT_EQ(file.info("decoder.2.weight").shape, (std::vector<int64_t>{64, 32}));
}

// Rewrites `src` with entries changed by `edit` (same metadata unless `metadata` is given).
void rewrite(const std::string& src, const std::string& dst,
             const std::function<void(std::vector<SafetensorsEntry>&)>& edit,
             const std::map<std::string, std::string>* metadata = nullptr) {
  const WeightFile file = read_safetensors(src);
  std::vector<SafetensorsEntry> entries;
  for (const std::string& name : file.names()) {
    SafetensorsEntry e;
    e.name = name;
    e.data = file.get(name).clone();
    e.dtype = e.data.scalar_type();
    e.shape.assign(e.data.sizes().begin(), e.data.sizes().end());
    entries.push_back(e);
  }
  edit(entries);
  write_safetensors(dst, entries, metadata ? *metadata : file.metadata);
}

TEST(Autoencoder, BrokenFilesNameTheFileAndTensor) {
  TempDir dir;
  const std::string good = (dir.path / "good.safetensors").string();
  Autoencoder(small_config(), 1).save(good);
  const std::string bad = (dir.path / "bad.safetensors").string();
  auto expect_error = [&](const std::vector<std::string>& parts) {
    const std::string msg = error_of([&] { Autoencoder::load(bad); });
    EXPECT_NE(msg.find(bad), std::string::npos) << msg;
    for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << msg;
  };

  // Truncated.
  fs::copy_file(good, bad);
  fs::resize_file(bad, fs::file_size(good) / 2);
  expect_error({});
  // Mis-shaped tensor.
  rewrite(good, bad, [](std::vector<SafetensorsEntry>& es) {
    for (auto& e : es)
      if (e.name == "encoder.3.weight") {
        e.data = at::zeros({16, 31});
        e.shape = {16, 31};
      }
  });
  expect_error({"encoder.3.weight", "[16, 31]", "[16, 32]"});
  // Missing tensor.
  rewrite(good, bad, [](std::vector<SafetensorsEntry>& es) {
    es.erase(std::remove_if(es.begin(), es.end(), [](const auto& e) { return e.name == "decoder.0.bias"; }),
             es.end());
  });
  expect_error({"missing", "decoder.0.bias"});
  // A tensor the layout does not have.
  rewrite(good, bad, [](std::vector<SafetensorsEntry>& es) {
    SafetensorsEntry e;
    e.name = "decoder.9.weight";
    e.data = at::zeros({2});
    e.shape = {2};
    es.push_back(e);
  });
  expect_error({"unexpected", "decoder.9.weight"});
  // NaN weights.
  rewrite(good, bad, [](std::vector<SafetensorsEntry>& es) {
    for (auto& e : es)
      if (e.name == "encoder.0.bias") e.data[0] = NAN;
  });
  expect_error({"encoder.0.bias", "NaN"});
  // No config, or a config that does not fit the tensors.
  const std::map<std::string, std::string> none;
  rewrite(good, bad, [](std::vector<SafetensorsEntry>&) {}, &none);
  expect_error({"citylangsplat_autoencoder"});
  const std::map<std::string, std::string> wrong = {
      {"citylangsplat_autoencoder",
       R"({"format":"citylangsplat-autoencoder","version":1,"input_dim":64,"encoder_dims":[32,8],)"
       R"("decoder_dims":[32,64],"normalize_latent":true,"normalize_output":false})"}};
  rewrite(good, bad, [](std::vector<SafetensorsEntry>&) {}, &wrong);
  expect_error({"encoder.3.weight"});
  const std::map<std::string, std::string> garbage = {{"citylangsplat_autoencoder", "{not json"}};
  rewrite(good, bad, [](std::vector<SafetensorsEntry>&) {}, &garbage);
  expect_error({"JSON"});
  // Missing file.
  EXPECT_NE(error_of([&] { Autoencoder::load((dir.path / "none.safetensors").string()); }).find("none.safetensors"),
            std::string::npos);
}

}  // namespace
}  // namespace cls
