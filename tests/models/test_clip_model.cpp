// CLIP ViT image/text towers against the reference fixtures (openai/CLIP d05afc4, float32, see
// tests/fixtures/clip/models/*/README.md): features, logits and every captured intermediate within
// the README's suggested tolerance (atol = rtol = 1e-4, ~25x the observed fp32-vs-fp64 spread).
#include <gtest/gtest.h>

#include <ATen/ATen.h>
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/clip/clip_loader.h"
#include "models/clip/clip_model.h"
#include "test_clip_fixture.h"
#include "test_device.h"

namespace {

using namespace cls::clip;
using namespace cls::clip::testing;

constexpr double kTol = 1e-4;

void expect_close(const at::Tensor& got, const at::Tensor& want, const std::string& what, double tol = kTol) {
  ASSERT_EQ(got.sizes(), want.sizes()) << what;
  const at::Tensor g = got.to(at::kCPU, at::kDouble), w = want.to(at::kCPU, at::kDouble);
  const double max_diff = (g - w).abs().max().item<double>();
  EXPECT_TRUE(at::allclose(g, w, tol, tol)) << what << ": max abs diff " << max_diff;
}

struct Fixture {
  ClipConfig config;
  std::map<std::string, at::Tensor> state;
  at::Tensor images, tokens;
};

Fixture load(const std::string& model, const std::string& weights = "weights_rows.safetensors") {
  Fixture f;
  const std::string dir = fixture_dir(model);
  f.config = read_clip_config(dir + "/config.json");
  f.state = load_state(dir + "/" + weights, f.config.arch.vocab_size);
  f.images = load_npy(dir + "/images.npy");
  f.tokens = load_npy(dir + "/tokens.npy");
  return f;
}

class ClipParity : public ::testing::TestWithParam<std::string> {};

TEST_P(ClipParity, FeaturesLogitsAndIntermediates) {
  const std::string model = GetParam();
  const std::string dir = fixture_dir(model);
  const Fixture f = load(model);
  const nlohmann::json cfg = fixture_config(model);
  const std::string act = cfg.at("activation");
  ASSERT_TRUE(act == "gelu" || act == "quick_gelu") << act;
  EXPECT_EQ(f.config.activation, act == "gelu" ? Activation::Gelu : Activation::QuickGelu);
  const ClipModel clip(f.config, f.state, {cls::testing::test_device()}, dir);
  ClipTrace trace;
  const at::Tensor img = clip.encode_image(f.images, &trace);
  const at::Tensor txt = clip.encode_text(f.tokens, &trace);
  expect_close(img, load_npy(dir + "/image_features.npy"), "image_features");
  expect_close(txt, load_npy(dir + "/text_features.npy"), "text_features");
  expect_close(clip.logits_per_image(img, txt), load_npy(dir + "/logits_per_image.npy"), "logits_per_image");
  // The captured intermediates: block 0 in detail and every block's output (layer counts from
  // config.json); they must be exactly the files of intermediates/, so none goes unchecked.
  std::vector<std::string> names = {"visual.conv1", "visual.ln_pre", "visual.ln_post", "token_embedding", "ln_final",
                                    "text_pooled"};
  const std::pair<std::string, int> towers[] = {{"visual.transformer.resblocks.", cfg.at("vision_layers").get<int>()},
                                                {"transformer.resblocks.", cfg.at("transformer_layers").get<int>()}};
  for (const auto& [tower, layers] : towers) {
    for (const std::string part : {".ln_1", ".attn", ".ln_2", ".mlp"}) names.push_back(tower + "0" + part);
    for (int i = 0; i < layers; ++i) names.push_back(tower + std::to_string(i));
  }
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir + "/intermediates"))
    if (e.path().extension() == ".npy") files.push_back(e.path().stem().string());
  std::sort(files.begin(), files.end());
  std::vector<std::string> sorted_names = names;
  std::sort(sorted_names.begin(), sorted_names.end());
  EXPECT_EQ(sorted_names, files);
  for (const std::string& name : names) {
    ASSERT_TRUE(trace.count(name)) << name;
    expect_close(trace.at(name), load_npy(dir + "/intermediates/" + name + ".npy"), name);
  }
}

TEST_P(ClipParity, OneSampleAtATimeMatchesTheBatch) {
  const std::string model = GetParam();
  const Fixture f = load(model);
  const ClipModel clip(f.config, f.state, {cls::testing::test_device()});
  const at::Tensor img = clip.encode_image(f.images), txt = clip.encode_text(f.tokens);
  for (int64_t i = 0; i < f.images.size(0); ++i)
    expect_close(clip.encode_image(f.images.narrow(0, i, 1)), img.narrow(0, i, 1), "image " + std::to_string(i));
  for (int64_t i = 0; i < f.tokens.size(0); ++i)
    expect_close(clip.encode_text(f.tokens.narrow(0, i, 1)), txt.narrow(0, i, 1), "text " + std::to_string(i));
}

INSTANTIATE_TEST_SUITE_P(Fixtures, ClipParity, ::testing::Values("tiny_gelu", "tiny_quickgelu"));

// The wrong activation must be detected far above the tolerance (the test can fail).
TEST(ClipModel, SwappedActivationIsVisible) {
  Fixture f = load("tiny_gelu");
  f.config.activation = f.config.activation == Activation::Gelu ? Activation::QuickGelu : Activation::Gelu;
  const ClipModel clip(f.config, f.state);
  const at::Tensor want = load_npy(fixture_dir("tiny_gelu") + "/image_features.npy");
  EXPECT_GT((clip.encode_image(f.images) - want).abs().max().item<double>(), 1e-3);
}

TEST(ClipModel, Fp16WeightsUpcastMatchTheirReference) {
  const std::string dir = fixture_dir("tiny_quickgelu");
  const Fixture f = load("tiny_quickgelu", "weights_fp16.safetensors");
  EXPECT_EQ(f.state.at("visual.proj").scalar_type(), at::kHalf);
  const ClipModel clip(f.config, f.state);  // computes in float32
  const at::Tensor img = clip.encode_image(f.images), txt = clip.encode_text(f.tokens);
  expect_close(img, load_npy(dir + "/from_fp16_weights/image_features.npy"), "image_features (fp16 weights)");
  expect_close(txt, load_npy(dir + "/from_fp16_weights/text_features.npy"), "text_features (fp16 weights)");
  expect_close(clip.logits_per_image(img, txt), load_npy(dir + "/from_fp16_weights/logits_per_image.npy"),
               "logits (fp16 weights)");
}

// The reduced-precision path: weights and activations in bf16 (and fp16 on CUDA), LayerNorm in fp32.
// bf16 keeps ~3 significant digits, so only closeness.
TEST(ClipModel, ReducedPrecisionComputeStaysCloseToFloat32) {
  const Fixture f = load("tiny_quickgelu");
  const std::string dir = fixture_dir("tiny_quickgelu");
  const c10::Device device = cls::testing::test_device();
  std::vector<at::ScalarType> dtypes = {at::kBFloat16};
  if (device.is_cuda()) dtypes.push_back(at::kHalf);
  for (const at::ScalarType dtype : dtypes) {
    const ClipModel clip(f.config, f.state, {device, dtype});
    const at::Tensor img = clip.encode_image(f.images), txt = clip.encode_text(f.tokens);
    EXPECT_EQ(img.scalar_type(), dtype);
    expect_close(img, load_npy(dir + "/image_features.npy"), std::string(c10::toString(dtype)) + " image_features", 0.1);
    expect_close(txt, load_npy(dir + "/text_features.npy"), std::string(c10::toString(dtype)) + " text_features", 0.1);
  }
}

TEST(ClipModel, InferredConfigMatchesTheFixtureConfig) {
  const Fixture f = load("tiny_quickgelu");
  std::map<std::string, std::vector<int64_t>> shapes;
  for (const auto& [name, t] : f.state) shapes[name] = t.sizes().vec();
  const ClipConfig c = infer_clip_config(shapes, Activation::QuickGelu);
  // What the reference recorded (config.json, read here as plain JSON, not by the code under test).
  const auto recorded = nlohmann::json::parse(cls::read_text_file(fixture_dir("tiny_quickgelu") + "/config.json"));
  EXPECT_EQ(c.arch.vision_width, recorded.at("vision_width").get<int>());
  EXPECT_EQ(c.arch.vision_layers, recorded.at("vision_layers").get<int>());
  EXPECT_EQ(c.arch.vision_patch_size, recorded.at("vision_patch_size").get<int>());
  EXPECT_EQ(c.arch.image_resolution, recorded.at("image_resolution").get<int>());
  EXPECT_EQ(c.arch.embed_dim, recorded.at("embed_dim").get<int>());
  EXPECT_EQ(c.arch.transformer_width, recorded.at("transformer_width").get<int>());
  EXPECT_EQ(c.arch.transformer_layers, recorded.at("transformer_layers").get<int>());
  // width / 64 as build_model() derives it; the text heads are not derivable from the shapes.
  EXPECT_EQ(c.vision_heads, recorded.at("vision_heads").get<int>());
}

TEST(ClipModel, BadWeightsAreReportedByNameBeforeCompute) {
  const Fixture f = load("tiny_quickgelu");
  auto message = [&](std::map<std::string, at::Tensor> state) -> std::string {
    try {
      ClipModel clip(f.config, state, {}, "w.safetensors");
    } catch (const cls::Error& e) {
      return e.what();
    }
    return "";
  };
  // Sizes of this fixture: the last vision block, one past it, and text_projection's shape.
  const nlohmann::json cfg = fixture_config("tiny_quickgelu");
  const int layers = cfg.at("vision_layers");
  const std::string last_block = "visual.transformer.resblocks." + std::to_string(layers - 1) + ".";
  const std::string past_block = "visual.transformer.resblocks." + std::to_string(layers) + ".";
  auto missing = f.state;
  missing.erase(last_block + "mlp.c_fc.bias");
  EXPECT_NE(message(missing).find("1 missing:\n    " + last_block + "mlp.c_fc.bias"), std::string::npos);
  auto extra = f.state;
  extra[past_block + "ln_1.weight"] = at::zeros({cfg.at("vision_width").get<int64_t>()});
  extra["input_resolution"] = at::zeros({});  // OpenAI JIT extras are ignored
  EXPECT_NE(message(extra).find("1 unexpected:\n    " + past_block + "ln_1.weight"), std::string::npos);
  auto shape = f.state;
  const auto proj = cfg.at("tensors").at("text_projection").at("shape").get<std::vector<int64_t>>();
  shape["text_projection"] = at::zeros({proj.at(0), proj.at(1) / 2});
  auto dims = [](int64_t a, int64_t b) { return "[" + std::to_string(a) + ", " + std::to_string(b) + "]"; };
  const std::string m = message(shape);
  EXPECT_NE(m.find("text_projection: expected " + dims(proj[0], proj[1]) + ", stored text_projection " +
                   dims(proj[0], proj[1] / 2)),
            std::string::npos)
      << m;
  EXPECT_EQ(m.rfind("w.safetensors: ", 0), 0u) << m;
  auto dtype = f.state;
  dtype["logit_scale"] = at::zeros({}, at::kLong);
  const std::string d = message(dtype);
  EXPECT_NE(d.find("1 with a wrong dtype:\n    logit_scale"), std::string::npos) << d;
}

TEST(ClipModel, BadInputsAreErrors) {
  const Fixture f = load("tiny_quickgelu");
  const ClipModel clip(f.config, f.state);
  const int64_t res = f.config.arch.image_resolution, ctx = f.config.arch.context_length;
  EXPECT_THROW(clip.encode_image(at::zeros({1, 3, res / 2, res / 2})), cls::Error);
  EXPECT_THROW(clip.encode_text(at::zeros({1, ctx - 1}, at::kLong)), cls::Error);
  EXPECT_THROW(clip.encode_text(at::full({1, ctx}, f.config.arch.vocab_size, at::kLong)), cls::Error);  // id = vocab size
  cls::clip::ClipOptions half;
  half.dtype = at::kHalf;
  EXPECT_THROW(ClipModel(f.config, f.state, half), cls::Error);  // fp16 is CUDA-only
}

TEST(ClipModel, PresetsHaveTheReferenceSizes) {
  const ClipConfig b16 = clip_preset("ViT-B/16", Activation::Gelu);
  EXPECT_EQ(b16.vision_tokens(), 197);
  EXPECT_EQ(b16.arch.embed_dim, 512);
  EXPECT_EQ(clip_preset("ViT-B-32", Activation::QuickGelu).vision_tokens(), 50);
  const ClipConfig l14 = clip_preset("ViT-L-14", Activation::QuickGelu);
  EXPECT_EQ(l14.vision_tokens(), 257);
  EXPECT_EQ(l14.arch.embed_dim, 768);
  EXPECT_THROW(clip_preset("RN50", Activation::QuickGelu), cls::Error);
}

}  // namespace

namespace {

// The full path from a weight file: the fp16 fixture through load_weight_file, config inferred
// except the text heads (not derivable, as in the reference build_model()).
TEST(ClipLoader, LoadsAWeightFileAndChecksItFirst) {
  const std::string dir = fixture_dir("tiny_quickgelu");
  ClipConfig config = read_clip_config(dir + "/config.json");
  const ClipModel clip = load_clip_model(dir + "/weights_fp16.safetensors", Activation::QuickGelu, config);
  expect_close(clip.encode_image(load_npy(dir + "/images.npy")),
               load_npy(dir + "/from_fp16_weights/image_features.npy"), "image_features via loader");
  // Inferred sizes (text heads max(1, width / 64), not the fixture's count): the shapes check passes.
  EXPECT_NO_THROW(load_clip_model(dir + "/weights_fp16.safetensors", Activation::QuickGelu));
  // A wrong config (one text block too many) is reported with the file name before any tensor is
  // read: every tensor of that block is missing (as many as block 0 has in config.json).
  const int layers = config.arch.transformer_layers;
  config.arch.transformer_layers = layers + 1;
  const nlohmann::json tensors = fixture_config("tiny_quickgelu").at("tensors");
  size_t per_block = 0;
  for (const auto& [name, t] : tensors.items()) per_block += name.rfind("transformer.resblocks.0.", 0) == 0;
  try {
    load_clip_model(dir + "/weights_fp16.safetensors", Activation::QuickGelu, config);
    ADD_FAILURE() << "no error";
  } catch (const cls::Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("weights_fp16.safetensors"), std::string::npos) << m;
    EXPECT_NE(m.find(std::to_string(per_block) + " missing:\n    transformer.resblocks." + std::to_string(layers) +
                     ".attn.in_proj_weight"),
              std::string::npos)
        << m;
  }
}

}  // namespace

namespace {

// Hugging Face transformers CLIPModel names/values (modeling_clip.py), written from the canonical
// state dict independently of the loader's table: q/k/v split, nn.Linear projections transposed.
cls::WeightFile to_huggingface(const std::map<std::string, at::Tensor>& s, const cls::ClipArch& arch) {
  cls::WeightFile w("hf-layout");
  auto tower = [&](const std::string& from, const std::string& to, int layers) {
    for (int i = 0; i < layers; ++i) {
      const std::string a = from + std::to_string(i) + ".", b = to + ".encoder.layers." + std::to_string(i) + ".";
      const auto qkv_w = s.at(a + "attn.in_proj_weight").chunk(3, 0), qkv_b = s.at(a + "attn.in_proj_bias").chunk(3, 0);
      const char* names[] = {"q_proj", "k_proj", "v_proj"};
      for (int k = 0; k < 3; ++k) {
        w.add(b + "self_attn." + names[k] + ".weight", qkv_w[k].contiguous());
        w.add(b + "self_attn." + names[k] + ".bias", qkv_b[k].contiguous());
      }
      const std::pair<const char*, const char*> same[] = {
          {"attn.out_proj", "self_attn.out_proj"}, {"ln_1", "layer_norm1"}, {"ln_2", "layer_norm2"},
          {"mlp.c_fc", "mlp.fc1"}, {"mlp.c_proj", "mlp.fc2"}};
      for (const auto& [x, y] : same) {
        w.add(b + y + ".weight", s.at(a + x + ".weight"));
        w.add(b + y + ".bias", s.at(a + x + ".bias"));
      }
    }
  };
  tower("transformer.resblocks.", "text_model", arch.transformer_layers);
  tower("visual.transformer.resblocks.", "vision_model", arch.vision_layers);
  w.add("text_model.embeddings.token_embedding.weight", s.at("token_embedding.weight"));
  w.add("text_model.embeddings.position_embedding.weight", s.at("positional_embedding"));
  w.add("text_model.final_layer_norm.weight", s.at("ln_final.weight"));
  w.add("text_model.final_layer_norm.bias", s.at("ln_final.bias"));
  w.add("vision_model.embeddings.class_embedding", s.at("visual.class_embedding"));
  w.add("vision_model.embeddings.patch_embedding.weight", s.at("visual.conv1.weight"));
  w.add("vision_model.embeddings.position_embedding.weight", s.at("visual.positional_embedding"));
  w.add("vision_model.pre_layrnorm.weight", s.at("visual.ln_pre.weight"));
  w.add("vision_model.pre_layrnorm.bias", s.at("visual.ln_pre.bias"));
  w.add("vision_model.post_layernorm.weight", s.at("visual.ln_post.weight"));
  w.add("vision_model.post_layernorm.bias", s.at("visual.ln_post.bias"));
  w.add("visual_projection.weight", s.at("visual.proj").t().contiguous());
  w.add("text_projection.weight", s.at("text_projection").t().contiguous());
  w.add("logit_scale", s.at("logit_scale"));
  return w;
}

TEST(ClipLoader, HuggingFaceLayoutGivesTheSameFeatures) {
  const Fixture f = load("tiny_gelu");
  const std::string dir = fixture_dir("tiny_gelu");
  const ClipModel clip(f.config, to_huggingface(f.state, f.config.arch));
  expect_close(clip.encode_image(f.images), load_npy(dir + "/image_features.npy"), "image_features (HF layout)");
  expect_close(clip.encode_text(f.tokens), load_npy(dir + "/text_features.npy"), "text_features (HF layout)");
}

}  // namespace
