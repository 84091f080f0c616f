#include "models/clip/clip_config.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace cls::clip {

Activation parse_activation(const std::string& name) {
  if (name == "gelu") return Activation::Gelu;
  if (name == "quick_gelu" || name == "quickgelu") return Activation::QuickGelu;
  throw Error("unknown CLIP activation '" + name + "' (expected gelu or quick_gelu)");
}

const char* activation_name(Activation a) { return a == Activation::Gelu ? "gelu" : "quick_gelu"; }

ClipConfig clip_preset(const std::string& name, Activation activation) {
  ClipConfig c;
  c.activation = activation;
  std::string n = name;
  for (char& ch : n)
    if (ch == '/') ch = '-';
  if (n == "ViT-B-32" || n == "ViT-B-16") {
    c.vision_patch_size = n == "ViT-B-32" ? 32 : 16;
  } else if (n == "ViT-L-14") {
    c.embed_dim = 768;
    c.vision_layers = 24;
    c.vision_width = 1024;
    c.vision_heads = 16;
    c.vision_patch_size = 14;
    c.transformer_width = 768;
    c.transformer_heads = 12;
  } else {
    throw Error("unknown CLIP model '" + name + "' (known: ViT-B-32, ViT-B-16, ViT-L-14)");
  }
  return c;
}

ClipConfig read_clip_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(path, "cannot open the CLIP config");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
    ClipConfig c;
    c.embed_dim = j.at("embed_dim");
    c.image_resolution = j.at("image_resolution");
    c.vision_layers = j.at("vision_layers");
    c.vision_width = j.at("vision_width");
    c.vision_patch_size = j.at("vision_patch_size");
    c.vision_heads = j.value("vision_heads", c.vision_width / 64);
    c.context_length = j.at("context_length");
    c.vocab_size = j.at("vocab_size");
    c.transformer_width = j.at("transformer_width");
    c.transformer_heads = j.value("transformer_heads", c.transformer_width / 64);
    c.transformer_layers = j.at("transformer_layers");
    c.activation = parse_activation(j.value("activation", std::string("quick_gelu")));
    return c;
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("bad CLIP config: ") + e.what());
  } catch (const Error& e) {
    fail(path, e.what());
  }
}

ClipConfig infer_clip_config(const std::map<std::string, std::vector<int64_t>>& state, Activation activation) {
  auto get = [&](const std::string& k, size_t dims) -> const std::vector<int64_t>& {
    auto it = state.find(k);
    if (it == state.end()) throw Error("CLIP weights: no tensor '" + k + "' to infer the model size from");
    if (it->second.size() != dims)
      throw Error("CLIP weights: '" + k + "' must have " + std::to_string(dims) + " dimensions");
    return it->second;
  };
  auto count_layers = [&](const std::string& prefix) {
    int n = 0;
    while (state.count(prefix + std::to_string(n) + ".ln_1.weight")) ++n;
    return n;
  };
  ClipConfig c;
  c.activation = activation;
  const std::vector<int64_t>& conv = get("visual.conv1.weight", 4);
  c.vision_width = static_cast<int>(conv[0]);
  c.vision_patch_size = static_cast<int>(conv[3]);
  c.vision_layers = count_layers("visual.transformer.resblocks.");
  c.vision_heads = std::max(1, c.vision_width / 64);  // at least one head for tiny widths
  const int tokens = static_cast<int>(get("visual.positional_embedding", 2)[0]);
  const int grid = static_cast<int>(std::lround(std::sqrt(double(tokens - 1))));
  c.image_resolution = grid * c.vision_patch_size;
  c.embed_dim = static_cast<int>(get("text_projection", 2)[1]);
  c.context_length = static_cast<int>(get("positional_embedding", 2)[0]);
  c.vocab_size = static_cast<int>(get("token_embedding.weight", 2)[0]);
  c.transformer_width = static_cast<int>(get("ln_final.weight", 1)[0]);
  c.transformer_heads = std::max(1, c.transformer_width / 64);
  c.transformer_layers = count_layers("transformer.resblocks.");
  return c;
}

}  // namespace cls::clip
