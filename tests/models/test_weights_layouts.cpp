#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include "error_of.h"
#include "models/temp_dir.h"
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/weights/clip_weights.h"
#include "models/weights/safetensors.h"
#include "models/weights/sam_weights.h"

namespace fs = std::filesystem;
using namespace cls;
using test::TempDir;

namespace {

using cls::test::error_of;

std::vector<ExpectedTensor> real_sam_keys(const std::string& model) {
  const auto j = nlohmann::json::parse(read_text_file(fs::path(CLS_TEST_FIXTURES) / ("sam/real_" + model + "_keys.json")));
  std::vector<ExpectedTensor> out;
  for (const auto& t : j["tensors"]) {
    EXPECT_EQ(t["dtype"], "float32");
    out.push_back({t["name"].get<std::string>(), t["shape"].get<std::vector<int64_t>>()});
  }
  EXPECT_EQ(out.size(), j["num_tensors"].get<size_t>());
  return out;
}

// A sparse safetensors file: real names and shapes, no data on disk (see write_safetensors).
void write_sparse(const fs::path& p, const std::vector<std::pair<std::string, std::vector<int64_t>>>& entries,
                  at::ScalarType dtype = at::kFloat) {
  std::vector<SafetensorsEntry> e;
  for (const auto& [name, shape] : entries) e.push_back({name, dtype, shape, {}});
  write_safetensors(p.string(), e);
}

// Hugging Face CLIPModel names, written out independently of the loader's table (modeling_clip.py).
std::vector<std::pair<std::string, std::vector<int64_t>>> hf_clip_keys(const ClipArch& a) {
  std::vector<std::pair<std::string, std::vector<int64_t>>> k;
  const int64_t vw = a.vision_width, tw = a.transformer_width, g = a.image_resolution / a.vision_patch_size;
  auto tower = [&](const std::string& t, int layers, int64_t w) {
    for (int i = 0; i < layers; ++i) {
      const std::string l = t + ".encoder.layers." + std::to_string(i) + ".";
      for (const char* p : {"q_proj", "k_proj", "v_proj", "out_proj"}) {
        k.push_back({l + "self_attn." + p + ".weight", {w, w}});
        k.push_back({l + "self_attn." + p + ".bias", {w}});
      }
      for (const char* n : {"layer_norm1", "layer_norm2"}) {
        k.push_back({l + n + ".weight", {w}});
        k.push_back({l + n + ".bias", {w}});
      }
      k.push_back({l + "mlp.fc1.weight", {4 * w, w}});
      k.push_back({l + "mlp.fc1.bias", {4 * w}});
      k.push_back({l + "mlp.fc2.weight", {w, 4 * w}});
      k.push_back({l + "mlp.fc2.bias", {w}});
    }
  };
  k.push_back({"text_model.embeddings.token_embedding.weight", {a.vocab_size, tw}});
  k.push_back({"text_model.embeddings.position_embedding.weight", {a.context_length, tw}});
  k.push_back({"text_model.embeddings.position_ids", {1, a.context_length}});
  tower("text_model", a.transformer_layers, tw);
  k.push_back({"text_model.final_layer_norm.weight", {tw}});
  k.push_back({"text_model.final_layer_norm.bias", {tw}});
  k.push_back({"vision_model.embeddings.class_embedding", {vw}});
  k.push_back({"vision_model.embeddings.patch_embedding.weight", {vw, 3, a.vision_patch_size, a.vision_patch_size}});
  k.push_back({"vision_model.embeddings.position_embedding.weight", {g * g + 1, vw}});
  k.push_back({"vision_model.embeddings.position_ids", {1, g * g + 1}});
  k.push_back({"vision_model.pre_layrnorm.weight", {vw}});
  k.push_back({"vision_model.pre_layrnorm.bias", {vw}});
  tower("vision_model", a.vision_layers, vw);
  k.push_back({"vision_model.post_layernorm.weight", {vw}});
  k.push_back({"vision_model.post_layernorm.bias", {vw}});
  k.push_back({"visual_projection.weight", {a.embed_dim, vw}});
  k.push_back({"text_projection.weight", {a.embed_dim, tw}});
  k.push_back({"logit_scale", {}});
  return k;
}

std::vector<std::pair<std::string, std::vector<int64_t>>> as_entries(const std::vector<ExpectedTensor>& e) {
  std::vector<std::pair<std::string, std::vector<int64_t>>> out;
  for (const auto& t : e) out.push_back({t.name, t.shape});
  return out;
}

void expect_canonical(const WeightFile& w, const std::vector<ExpectedTensor>& expected) {
  ASSERT_EQ(w.size(), expected.size());
  for (const auto& e : expected) {
    ASSERT_TRUE(w.contains(e.name)) << e.name;
    EXPECT_EQ(w.info(e.name).shape, e.shape) << e.name;
  }
}

}  // namespace

// The generated SAM lists are the real architectures' state_dict keys, shapes and order.
TEST(SamLayout, ExpectedTensorsAreTheRealKeyLists) {
  for (const std::string model : {"vit_b", "vit_l", "vit_h"}) {
    const auto real = real_sam_keys(model);
    const auto mine = sam_expected_tensors(sam_arch(model));
    ASSERT_EQ(mine.size(), real.size()) << model;
    for (size_t i = 0; i < real.size(); ++i) {
      EXPECT_EQ(mine[i].name, real[i].name) << model << " #" << i;
      EXPECT_EQ(mine[i].shape, real[i].shape) << model << " " << real[i].name;
    }
  }
  EXPECT_THROW(sam_arch("vit_x"), Error);
  EXPECT_EQ(sam_arch("sam_vit_h").name, "vit_h");
}

TEST(SamLayout, HuggingFaceNames) {
  EXPECT_EQ(sam_official_to_hf("image_encoder.blocks.0.norm1.weight"), "vision_encoder.layers.0.layer_norm1.weight");
  EXPECT_EQ(sam_official_to_hf("image_encoder.patch_embed.proj.bias"), "vision_encoder.patch_embed.projection.bias");
  EXPECT_EQ(sam_official_to_hf("image_encoder.blocks.31.attn.rel_pos_h"), "vision_encoder.layers.31.attn.rel_pos_h");
  EXPECT_EQ(sam_official_to_hf("image_encoder.neck.1.bias"), "vision_encoder.neck.layer_norm1.bias");
  EXPECT_EQ(sam_official_to_hf("image_encoder.neck.2.weight"), "vision_encoder.neck.conv2.weight");
  EXPECT_EQ(sam_official_to_hf("prompt_encoder.mask_downscaling.4.weight"), "prompt_encoder.mask_embed.layer_norm2.weight");
  EXPECT_EQ(sam_official_to_hf("prompt_encoder.point_embeddings.3.weight"), "prompt_encoder.point_embed.3.weight");
  EXPECT_EQ(sam_official_to_hf("mask_decoder.transformer.layers.1.norm4.bias"), "mask_decoder.transformer.layers.1.layer_norm4.bias");
  EXPECT_EQ(sam_official_to_hf("mask_decoder.transformer.norm_final_attn.weight"),
            "mask_decoder.transformer.layer_norm_final_attn.weight");
  EXPECT_EQ(sam_official_to_hf("mask_decoder.output_upscaling.1.weight"), "mask_decoder.upscale_layer_norm.weight");
  EXPECT_EQ(sam_official_to_hf("mask_decoder.output_hypernetworks_mlps.2.layers.0.weight"),
            "mask_decoder.output_hypernetworks_mlps.2.proj_in.weight");
  EXPECT_EQ(sam_official_to_hf("mask_decoder.output_hypernetworks_mlps.2.layers.1.bias"),
            "mask_decoder.output_hypernetworks_mlps.2.layers.0.bias");
  EXPECT_EQ(sam_official_to_hf("mask_decoder.iou_prediction_head.layers.2.weight"),
            "mask_decoder.iou_prediction_head.proj_out.weight");
  EXPECT_EQ(sam_official_to_hf("mask_decoder.iou_prediction_head.layers.1.weight"),
            "mask_decoder.iou_prediction_head.layers.0.weight");
}

// Acceptance: a file with the real names and shapes loads without a single unmatched key, in the
// official layout, the Hugging Face layout (with either copy of the shared positional matrix) and
// with a DataParallel "module." prefix. Full-size files are sparse: only headers are read.
TEST(SamLayout, RealLayoutsLoadWithoutUnmatchedKeys) {
  TempDir dir;
  for (const std::string model : {"vit_b", "vit_l", "vit_h"}) {
    const auto real = real_sam_keys(model);
    const SamArch arch = sam_arch(model);
    std::vector<std::vector<std::pair<std::string, std::vector<int64_t>>>> variants(4);
    for (const auto& t : real) {
      variants[0].push_back({t.name, t.shape});
      variants[1].push_back({"module." + t.name, t.shape});
      const std::string hf = t.name == "prompt_encoder.pe_layer.positional_encoding_gaussian_matrix"
                                 ? "shared_image_embedding.positional_embedding"
                                 : sam_official_to_hf(t.name);
      variants[2].push_back({hf, t.shape});
      variants[3].push_back({hf == "shared_image_embedding.positional_embedding"
                                 ? "prompt_encoder.shared_embedding.positional_embedding" : hf, t.shape});
    }
    variants[2].push_back({"prompt_encoder.shared_embedding.positional_embedding", {2, 128}});  // tied copy
    for (size_t v = 0; v < variants.size(); ++v) {
      const fs::path p = dir.path / (model + std::to_string(v) + ".safetensors");
      write_sparse(p, variants[v]);
      WeightFile w;
      ASSERT_NO_THROW(w = load_sam_checkpoint(p.string(), arch)) << error_of([&] { load_sam_checkpoint(p.string(), arch); });
      expect_canonical(w, real);
      fs::remove(p);
    }
  }
}

// Every problem is reported at once, by name, before any tensor is read.
TEST(SamLayout, ReportsAllMissingUnexpectedMisshapedAndBadDtypes) {
  TempDir dir;
  auto entries = as_entries(sam_expected_tensors(sam_arch("vit_b")));
  entries.erase(entries.begin() + 5);                        // image_encoder.blocks.0.attn.rel_pos_h
  entries[6].second = {2304, 767};                           // blocks.0.attn.qkv.weight
  entries.push_back({"image_encoder.blocks.12.norm1.weight", {768}});  // a 13th block
  const fs::path p = dir.path / "bad.safetensors";
  write_sparse(p, entries);
  const std::string e = error_of([&] { load_sam_checkpoint(p.string(), sam_arch("vit_b")); });
  EXPECT_EQ(e.rfind(p.string() + ": weights do not match SAM vit_b (closest layout: official)", 0), 0u) << e;
  EXPECT_NE(e.find("1 missing:\n    image_encoder.blocks.0.attn.rel_pos_h"), std::string::npos) << e;
  EXPECT_NE(e.find("1 unexpected:\n    image_encoder.blocks.12.norm1.weight"), std::string::npos) << e;
  EXPECT_NE(e.find("image_encoder.blocks.0.attn.qkv.weight: expected [2304, 768], stored image_encoder.blocks.0.attn.qkv.weight [2304, 767]"),
            std::string::npos) << e;
  // The wrong model: a ViT-B file read as ViT-H.
  write_sparse(p, as_entries(sam_expected_tensors(sam_arch("vit_b"))));
  const std::string h = error_of([&] { load_sam_checkpoint(p.string(), sam_arch("vit_h")); });
  EXPECT_NE(h.find("\n  280 missing:"), std::string::npos) << h.substr(0, 300);  // blocks 12..31, 14 tensors each
  // Integer tensors where weights are expected.
  write_sparse(p, as_entries(sam_expected_tensors(sam_arch("vit_b"))), at::kLong);
  const std::string d = error_of([&] { load_sam_checkpoint(p.string(), sam_arch("vit_b")); });
  EXPECT_NE(d.find("314 with a wrong dtype"), std::string::npos) << d.substr(0, 300);
}

// Values pass through the mapping unchanged (tiny architecture, random weights, HF layout).
TEST(SamLayout, HuggingFaceValuesMapUnchanged) {
  TempDir dir;
  SamArch tiny = sam_arch("vit_b");
  tiny.encoder_embed_dim = 32, tiny.encoder_depth = 2, tiny.encoder_num_heads = 2, tiny.global_attn_indexes = {1};
  tiny.prompt_embed_dim = 32, tiny.decoder_mlp_dim = 64, tiny.iou_head_hidden_dim = 32, tiny.name = "tiny";
  tiny.image_size = 256;
  at::manual_seed(3);
  std::vector<SafetensorsEntry> entries;
  std::map<std::string, at::Tensor> truth;
  for (const auto& e : sam_expected_tensors(tiny)) {
    const at::Tensor v = at::randn(e.shape).to(at::kHalf);
    truth[e.name] = v;
    const std::string hf = e.name == "prompt_encoder.pe_layer.positional_encoding_gaussian_matrix"
                               ? "shared_image_embedding.positional_embedding" : sam_official_to_hf(e.name);
    entries.push_back({hf, at::kHalf, e.shape, v});
  }
  const fs::path p = dir.path / "tiny.safetensors";
  write_safetensors(p.string(), entries);
  const WeightFile w = load_sam_checkpoint(p.string(), tiny);
  for (const auto& [name, v] : truth) {
    EXPECT_TRUE(at::equal(w.get(name), v)) << name;
    EXPECT_EQ(w.get(name, at::kFloat).scalar_type(), at::kFloat);
  }
}

// The generated CLIP list is exactly the fixture models' state_dict (config.json "tensors").
TEST(ClipLayout, ExpectedTensorsMatchTheFixtureConfigs) {
  for (const std::string model : {"tiny_gelu", "tiny_quickgelu"}) {
    const auto c = nlohmann::json::parse(
        read_text_file(fs::path(CLS_TEST_FIXTURES) / "clip/models" / model / "config.json"));
    ClipArch a;
    a.name = model;
    a.embed_dim = c["embed_dim"], a.image_resolution = c["image_resolution"], a.vision_layers = c["vision_layers"];
    a.vision_width = c["vision_width"], a.vision_patch_size = c["vision_patch_size"];
    a.context_length = c["context_length"], a.vocab_size = c["vocab_size"];
    a.transformer_width = c["transformer_width"], a.transformer_layers = c["transformer_layers"];
    const auto mine = clip_expected_tensors(a);
    ASSERT_EQ(mine.size(), c["tensors"].size()) << model;
    for (const auto& e : mine) {
      ASSERT_TRUE(c["tensors"].contains(e.name)) << e.name;
      EXPECT_EQ(e.shape, c["tensors"][e.name]["shape"].get<std::vector<int64_t>>()) << e.name;
    }
  }
  EXPECT_EQ(clip_arch("ViT-L/14").vision_width, 1024);
  EXPECT_THROW(clip_arch("RN50"), Error);
}

TEST(ClipLayout, RealLayoutsLoadWithoutUnmatchedKeys) {
  TempDir dir;
  for (const std::string model : {"ViT-B-32", "ViT-B-16", "ViT-L-14"}) {
    const ClipArch arch = clip_arch(model);
    const auto expected = clip_expected_tensors(arch);
    // OpenCLIP / OpenAI state dict, and the extras of OpenAI's TorchScript archives.
    auto openai = as_entries(expected);
    auto jit = openai;
    jit.push_back({"input_resolution", {}});
    jit.push_back({"context_length", {}});
    jit.push_back({"vocab_size", {}});
    for (int i = 0; i < arch.transformer_layers; ++i)
      jit.push_back({"transformer.resblocks." + std::to_string(i) + ".attn_mask", {77, 77}});
    for (const auto& [tag, entries] : {std::make_pair("openai", openai), std::make_pair("jit", jit),
                                       std::make_pair("hf", hf_clip_keys(arch))}) {
      const fs::path p = dir.path / (model + tag + ".safetensors");
      write_sparse(p, entries, at::kHalf);
      WeightFile w;
      ASSERT_NO_THROW(w = load_clip_checkpoint(p.string(), arch))
          << error_of([&] { load_clip_checkpoint(p.string(), arch); });
      expect_canonical(w, expected);
      fs::remove(p);
    }
  }
}

// Hugging Face values: q/k/v concatenated in that order, projections transposed back.
TEST(ClipLayout, HuggingFaceValuesMapToOpenAILayout) {
  TempDir dir;
  ClipArch a = clip_arch("ViT-B-16");
  a.name = "tiny", a.embed_dim = 8, a.image_resolution = 32, a.vision_layers = 2, a.vision_width = 16;
  a.vision_patch_size = 16, a.context_length = 5, a.vocab_size = 11, a.transformer_width = 12, a.transformer_layers = 1;
  at::manual_seed(7);
  std::map<std::string, at::Tensor> canonical;
  for (const auto& e : clip_expected_tensors(a)) canonical[e.name] = at::randn(e.shape);
  std::vector<SafetensorsEntry> hf;
  for (const auto& [name, shape] : hf_clip_keys(a)) {
    at::Tensor v;
    auto c = [&](const std::string& n) { return canonical.at(n); };
    const std::string vis = "vision_model.encoder.layers.", txt = "text_model.encoder.layers.";
    if (name.find("position_ids") != std::string::npos) {
      hf.push_back({name, at::kLong, shape, at::arange(shape[1]).view({1, shape[1]})});
      continue;
    }
    if (name == "visual_projection.weight") v = c("visual.proj").t();
    else if (name == "text_projection.weight") v = c("text_projection").t();
    else if (name == "logit_scale") v = c("logit_scale");
    else if (name == "vision_model.embeddings.class_embedding") v = c("visual.class_embedding");
    else if (name == "vision_model.embeddings.patch_embedding.weight") v = c("visual.conv1.weight");
    else if (name == "vision_model.embeddings.position_embedding.weight") v = c("visual.positional_embedding");
    else if (name == "vision_model.pre_layrnorm.weight") v = c("visual.ln_pre.weight");
    else if (name == "vision_model.pre_layrnorm.bias") v = c("visual.ln_pre.bias");
    else if (name == "vision_model.post_layernorm.weight") v = c("visual.ln_post.weight");
    else if (name == "vision_model.post_layernorm.bias") v = c("visual.ln_post.bias");
    else if (name == "text_model.embeddings.token_embedding.weight") v = c("token_embedding.weight");
    else if (name == "text_model.embeddings.position_embedding.weight") v = c("positional_embedding");
    else if (name == "text_model.final_layer_norm.weight") v = c("ln_final.weight");
    else if (name == "text_model.final_layer_norm.bias") v = c("ln_final.bias");
    else {
      const bool is_vis = name.rfind(vis, 0) == 0;
      const std::string rest = name.substr((is_vis ? vis : txt).size());
      const std::string idx = rest.substr(0, rest.find('.'));
      const std::string field = rest.substr(idx.size() + 1);
      const std::string b = (is_vis ? "visual.transformer.resblocks." : "transformer.resblocks.") + idx + ".";
      const std::string kind = field.substr(field.rfind('.') + 1);
      const int qkv = field.rfind("self_attn.q_proj", 0) == 0 ? 0 : field.rfind("self_attn.k_proj", 0) == 0 ? 1
                    : field.rfind("self_attn.v_proj", 0) == 0 ? 2 : -1;
      if (qkv >= 0) v = c(b + "attn.in_proj_" + kind).chunk(3, 0)[qkv];
      else if (field.rfind("self_attn.out_proj", 0) == 0) v = c(b + "attn.out_proj." + kind);
      else if (field.rfind("layer_norm1", 0) == 0) v = c(b + "ln_1." + kind);
      else if (field.rfind("layer_norm2", 0) == 0) v = c(b + "ln_2." + kind);
      else if (field.rfind("mlp.fc1", 0) == 0) v = c(b + "mlp.c_fc." + kind);
      else if (field.rfind("mlp.fc2", 0) == 0) v = c(b + "mlp.c_proj." + kind);
    }
    ASSERT_TRUE(v.defined()) << name;
    hf.push_back({name, at::kFloat, shape, v.contiguous()});
  }
  const fs::path p = dir.path / "hf.safetensors";
  write_safetensors(p.string(), hf);
  const WeightFile w = load_clip_checkpoint(p.string(), a);
  for (const auto& [name, v] : canonical) EXPECT_TRUE(at::equal(w.get(name), v)) << name;
}
