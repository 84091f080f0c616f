#include "models/model_registry.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace cls {
namespace fs = std::filesystem;

const std::vector<KnownModel>& known_models() {
  // Sizes and checksums of the official files as published by their authors / widely recorded;
  // the OpenAI CLIP URL carries the file's sha256 as its directory name. Unknown values are left
  // empty: such files are still downloaded and their sha256 printed, but not verified.
  static const std::vector<KnownModel> models = {
      {"openclip-vit-b-16-laion2b", "clip", "ViT-B-16", "ViT-B-16-laion2b_s34b_b88k.bin",
       {"open_clip_pytorch_model.bin", "ViT-B-16-laion2b_s34b_b88k.safetensors", "open_clip_model.safetensors"},
       "https://huggingface.co/laion/CLIP-ViT-B-16-laion2B-s34B-b88K/resolve/main/open_clip_pytorch_model.bin",
       0, "",
       "OpenCLIP ViT-B-16 laion2b_s34b_b88k (LangSplat's CLIP; torch.save state dict, GELU)"},
      {"openai-clip-vit-b-16", "clip", "ViT-B-16", "ViT-B-16.pt", {},
       "https://openaipublic.azureedge.net/clip/models/"
       "5806e77cd80f8b59890b7e101eabd078d9fb84e6937f9e85e4ecb61988df416f/ViT-B-16.pt",
       0, "5806e77cd80f8b59890b7e101eabd078d9fb84e6937f9e85e4ecb61988df416f",
       "OpenAI CLIP ViT-B/16 (TorchScript archive, read as weights only; QuickGELU)"},
      {"sam-vit-b", "sam", "vit_b", "sam_vit_b_01ec64.pth", {},
       "https://dl.fbaipublicfiles.com/segment_anything/sam_vit_b_01ec64.pth", 375042383,
       "ec2df62732614e57411cdcf32a23ffdf28910380d03139ee0f4fcbe91eb8c912", "Segment Anything ViT-B (official)"},
      {"sam-vit-l", "sam", "vit_l", "sam_vit_l_0b3195.pth", {},
       "https://dl.fbaipublicfiles.com/segment_anything/sam_vit_l_0b3195.pth", 1249524607,
       "3adcc4315b642a4d2101128f611684e8734c41232a17c648ed1693702a49a622", "Segment Anything ViT-L (official)"},
      {"sam-vit-h", "sam", "vit_h", "sam_vit_h_4b8939.pth", {},
       "https://dl.fbaipublicfiles.com/segment_anything/sam_vit_h_4b8939.pth", 2564550879,
       "a7bf3b02f3ebf1267aba913ff637d9a2d5c33d3173bb679e46d9f338c26f262e",
       "Segment Anything ViT-H (official; LangSplat's SAM)"},
  };
  return models;
}

const KnownModel* find_known_model(const std::string& name) {
  std::string n;
  for (const char c : name) n += c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const KnownModel& m : known_models()) {
    if (n == m.name) return &m;
    if (m.family == "sam" && (n == "sam-" + m.name.substr(4) || n == m.name.substr(4))) return &m;  // "vit-h"
  }
  if (n == "vit-b-16/laion2b-s34b-b88k" || n == "vit-b-16-laion2b-s34b-b88k") return &known_models()[0];
  return nullptr;
}

std::vector<fs::path> model_search_dirs(const std::string& models_dir) {
  std::vector<fs::path> dirs;
  if (!models_dir.empty()) dirs.emplace_back(models_dir);
  if (const char* env = std::getenv("CITYLANGSPLAT_MODELS"); env && *env) dirs.emplace_back(env);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
    dirs.push_back(fs::path(xdg) / "citylangsplat" / "models");
  } else if (const char* home = std::getenv("HOME"); home && *home) {
    dirs.push_back(fs::path(home) / ".cache" / "citylangsplat" / "models");
  } else {
    dirs.emplace_back(".citylangsplat-models");
  }
  return dirs;
}

fs::path model_download_dir(const std::string& models_dir) { return model_search_dirs(models_dir).front(); }

std::optional<fs::path> find_model_file(const KnownModel& m, const std::vector<fs::path>& dirs) {
  std::vector<std::string> names = {m.file_name};
  names.insert(names.end(), m.other_names.begin(), m.other_names.end());
  for (const auto& dir : dirs)
    for (const auto& n : names) {
      std::error_code ec;
      if (fs::is_regular_file(dir / n, ec)) return dir / n;
    }
  return std::nullopt;
}

}  // namespace cls
