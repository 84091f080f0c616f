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

ClipConfig clip_config(const ClipArch& arch, Activation activation) {
  ClipConfig c;
  c.arch = arch;
  c.vision_heads = std::max(1, arch.vision_width / 64);  // at least one head for tiny widths
  c.transformer_heads = std::max(1, arch.transformer_width / 64);
  c.activation = activation;
  return c;
}

ClipConfig clip_preset(const std::string& name, Activation activation) {
  return clip_config(clip_arch(name), activation);
}

ClipConfig read_clip_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(path, "cannot open the CLIP config");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
    ClipArch a;
    a.name = "custom";
    a.embed_dim = j.at("embed_dim");
    a.image_resolution = j.at("image_resolution");
    a.vision_layers = j.at("vision_layers");
    a.vision_width = j.at("vision_width");
    a.vision_patch_size = j.at("vision_patch_size");
    a.context_length = j.at("context_length");
    a.vocab_size = j.at("vocab_size");
    a.transformer_width = j.at("transformer_width");
    a.transformer_layers = j.at("transformer_layers");
    ClipConfig c = clip_config(a, parse_activation(j.value("activation", std::string("quick_gelu"))));
    c.vision_heads = j.value("vision_heads", c.vision_heads);
    c.transformer_heads = j.value("transformer_heads", c.transformer_heads);
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
  ClipArch a;
  a.name = "custom";
  const std::vector<int64_t>& conv = get("visual.conv1.weight", 4);
  a.vision_width = static_cast<int>(conv[0]);
  a.vision_patch_size = static_cast<int>(conv[3]);
  a.vision_layers = count_layers("visual.transformer.resblocks.");
  const int tokens = static_cast<int>(get("visual.positional_embedding", 2)[0]);
  const int grid = static_cast<int>(std::lround(std::sqrt(double(tokens - 1))));
  a.image_resolution = grid * a.vision_patch_size;
  a.embed_dim = static_cast<int>(get("text_projection", 2)[1]);
  a.context_length = static_cast<int>(get("positional_embedding", 2)[0]);
  a.vocab_size = static_cast<int>(get("token_embedding.weight", 2)[0]);
  a.transformer_width = static_cast<int>(get("ln_final.weight", 1)[0]);
  a.transformer_layers = count_layers("transformer.resblocks.");
  return clip_config(a, activation);
}

}  // namespace cls::clip
