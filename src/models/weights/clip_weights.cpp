#include "models/weights/clip_weights.h"

#include <map>
#include <regex>

#include "core/error.h"

namespace cls {

ClipArch clip_arch(const std::string& name) {
  std::string n = name;
  for (char& ch : n)
    if (ch == '/') ch = '-';
  ClipArch a;
  if (n == "ViT-B-32") {
    a.vision_patch_size = 32;
  } else if (n == "ViT-B-16") {
    a.vision_patch_size = 16;
  } else if (n == "ViT-L-14") {
    a.embed_dim = 768, a.vision_layers = 24, a.vision_width = 1024, a.vision_patch_size = 14;
    a.transformer_width = 768;
  } else {
    throw Error("unknown CLIP model '" + name + "' (known: ViT-B-32, ViT-B-16, ViT-L-14)");
  }
  a.name = n;
  return a;
}

std::vector<ExpectedTensor> clip_expected_tensors(const ClipArch& a) {
  std::vector<ExpectedTensor> t;
  auto add = [&](const std::string& name, std::vector<int64_t> shape) { t.push_back({name, std::move(shape)}); };
  auto blocks = [&](const std::string& prefix, int layers, int64_t w) {
    for (int i = 0; i < layers; ++i) {
      const std::string b = prefix + std::to_string(i);
      add(b + ".attn.in_proj_weight", {3 * w, w});
      add(b + ".attn.in_proj_bias", {3 * w});
      add(b + ".attn.out_proj.weight", {w, w});
      add(b + ".attn.out_proj.bias", {w});
      add(b + ".ln_1.weight", {w});
      add(b + ".ln_1.bias", {w});
      add(b + ".mlp.c_fc.weight", {4 * w, w});
      add(b + ".mlp.c_fc.bias", {4 * w});
      add(b + ".mlp.c_proj.weight", {w, 4 * w});
      add(b + ".mlp.c_proj.bias", {w});
      add(b + ".ln_2.weight", {w});
      add(b + ".ln_2.bias", {w});
    }
  };
  const int64_t vw = a.vision_width, tw = a.transformer_width, grid = a.image_resolution / a.vision_patch_size;
  add("positional_embedding", {a.context_length, tw});
  add("text_projection", {tw, a.embed_dim});
  add("logit_scale", {});
  add("visual.class_embedding", {vw});
  add("visual.positional_embedding", {grid * grid + 1, vw});
  add("visual.proj", {vw, a.embed_dim});
  add("visual.conv1.weight", {vw, 3, a.vision_patch_size, a.vision_patch_size});
  add("visual.ln_pre.weight", {vw});
  add("visual.ln_pre.bias", {vw});
  blocks("visual.transformer.resblocks.", a.vision_layers, vw);
  add("visual.ln_post.weight", {vw});
  add("visual.ln_post.bias", {vw});
  blocks("transformer.resblocks.", a.transformer_layers, tw);
  add("token_embedding.weight", {a.vocab_size, tw});
  add("ln_final.weight", {tw});
  add("ln_final.bias", {tw});
  return t;
}

namespace {

// transformers' CLIPModel names for a canonical key (modeling_clip.py module names).
TensorRecipe hf_clip_recipe(const std::string& c) {
  using Op = TensorRecipe::Op;
  static const std::map<std::string, TensorRecipe> kFixed = {
      {"positional_embedding", {{"text_model.embeddings.position_embedding.weight"}, Op::Same}},
      {"token_embedding.weight", {{"text_model.embeddings.token_embedding.weight"}, Op::Same}},
      {"ln_final.weight", {{"text_model.final_layer_norm.weight"}, Op::Same}},
      {"ln_final.bias", {{"text_model.final_layer_norm.bias"}, Op::Same}},
      {"text_projection", {{"text_projection.weight"}, Op::Transpose}},  // nn.Linear [out, in]
      {"logit_scale", {{"logit_scale"}, Op::Same}},
      {"visual.class_embedding", {{"vision_model.embeddings.class_embedding"}, Op::Same}},
      {"visual.positional_embedding", {{"vision_model.embeddings.position_embedding.weight"}, Op::Same}},
      {"visual.conv1.weight", {{"vision_model.embeddings.patch_embedding.weight"}, Op::Same}},
      {"visual.ln_pre.weight", {{"vision_model.pre_layrnorm.weight"}, Op::Same}},  // sic
      {"visual.ln_pre.bias", {{"vision_model.pre_layrnorm.bias"}, Op::Same}},
      {"visual.ln_post.weight", {{"vision_model.post_layernorm.weight"}, Op::Same}},
      {"visual.ln_post.bias", {{"vision_model.post_layernorm.bias"}, Op::Same}},
      {"visual.proj", {{"visual_projection.weight"}, Op::Transpose}},
  };
  if (const auto it = kFixed.find(c); it != kFixed.end()) return it->second;
  static const std::regex block(R"(^(visual\.)?transformer\.resblocks\.(\d+)\.(.+)$)");
  std::smatch m;
  if (!std::regex_match(c, m, block)) return {{c}, Op::Same};
  const std::string layer = (m[1].matched ? "vision_model" : "text_model") + std::string(".encoder.layers.") +
                            m[2].str() + ".";
  const std::string rest = m[3].str();
  if (rest == "attn.in_proj_weight" || rest == "attn.in_proj_bias") {
    const std::string kind = rest == "attn.in_proj_weight" ? "weight" : "bias";
    // nn.MultiheadAttention packs q, k, v in this order along dim 0.
    return {{layer + "self_attn.q_proj." + kind, layer + "self_attn.k_proj." + kind, layer + "self_attn.v_proj." + kind},
            Op::Concat0};
  }
  static const std::map<std::string, std::string> kBlock = {
      {"attn.out_proj.weight", "self_attn.out_proj.weight"}, {"attn.out_proj.bias", "self_attn.out_proj.bias"},
      {"ln_1.weight", "layer_norm1.weight"},                 {"ln_1.bias", "layer_norm1.bias"},
      {"mlp.c_fc.weight", "mlp.fc1.weight"},                 {"mlp.c_fc.bias", "mlp.fc1.bias"},
      {"mlp.c_proj.weight", "mlp.fc2.weight"},               {"mlp.c_proj.bias", "mlp.fc2.bias"},
      {"ln_2.weight", "layer_norm2.weight"},                 {"ln_2.bias", "layer_norm2.bias"},
  };
  if (const auto it = kBlock.find(rest); it != kBlock.end()) return {{layer + it->second}, Op::Same};
  return {{c}, Op::Same};
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::vector<KeyLayout> clip_layouts() {
  // OpenAI's TorchScript archives carry bookkeeping tensors (input_resolution, context_length,
  // vocab_size) and the text mask as a block attribute; OpenCLIP may save attn_mask buffers.
  KeyLayout openai{"openai/openclip",
                   [](const std::string& c) { return TensorRecipe{{c}, TensorRecipe::Op::Same}; },
                   [](const std::string& s) {
                     return s == "input_resolution" || s == "context_length" || s == "vocab_size" ||
                            s == "attn_mask" || ends_with(s, ".attn_mask");
                   }};
  KeyLayout hf{"huggingface", hf_clip_recipe,
               [](const std::string& s) { return ends_with(s, "embeddings.position_ids"); }};
  return {openai, hf};
}

WeightFile load_clip_checkpoint(const std::string& path, const ClipArch& arch) {
  return map_weights_strict(load_weight_file(path), clip_expected_tensors(arch), clip_layouts(), "CLIP " + arch.name);
}

}  // namespace cls
