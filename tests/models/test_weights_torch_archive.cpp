#include <gtest/gtest.h>
#include <torch/csrc/jit/serialization/pickle.h>
#include <torch/script.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "models/weights/torch_archive.h"
#include "models/weights/weight_file.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("cls_archive_test_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

void write_bytes(const fs::path& p, const std::vector<char>& bytes) {
  std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

// A zip-format state dict as torch.save writes it (torch::jit::pickle_save produces the same format).
TEST(TorchArchive, ReadsAPickledStateDict) {
  TempDir dir;
  c10::Dict<std::string, at::Tensor> state;
  const at::Tensor w = at::arange(6, at::kFloat).view({2, 3});
  const at::Tensor h = at::tensor({0.5f, -1.f}).to(at::kHalf);
  state.insert("visual.conv1.weight", w);
  state.insert("logit_scale", at::scalar_tensor(4.6f));
  state.insert("half", h);
  write_bytes(dir.path / "sd.pt", torch::jit::pickle_save(c10::IValue(state)));
  const WeightFile f = load_weight_file((dir.path / "sd.pt").string());
  EXPECT_EQ(f.names(), (std::vector<std::string>{"half", "logit_scale", "visual.conv1.weight"}));
  EXPECT_TRUE(at::equal(f.get("visual.conv1.weight"), w));
  EXPECT_TRUE(at::equal(f.get("half"), h));
  EXPECT_TRUE(f.info("logit_scale").shape.empty());
  EXPECT_FLOAT_EQ(f.get("logit_scale").item<float>(), 4.6f);
  // Nested checkpoints ({"model": state_dict, "epoch": 3}) flatten with a dot.
  c10::impl::GenericDict nested(c10::StringType::get(), c10::AnyType::get());
  nested.insert("model", state);
  nested.insert("epoch", 3);
  write_bytes(dir.path / "ckpt.pt", torch::jit::pickle_save(c10::IValue(nested)));
  const WeightFile n = read_torch_archive((dir.path / "ckpt.pt").string());
  EXPECT_EQ(n.size(), 3u);
  EXPECT_TRUE(n.contains("model.visual.conv1.weight"));
}

// A TorchScript archive (like OpenAI's CLIP .pt): module objects with parameters, buffers and a
// submodule list. The archive's code is garbled after saving, so loading it proves the reader only
// reads data (compiling the code, or even extracting its record, would fail).
TEST(TorchArchive, ReadsTorchScriptArchivesWithoutRunningCode) {
  TempDir dir;
  torch::jit::Module root("__torch__.model.CLIP");
  torch::jit::Module visual("__torch__.model.VisionTransformer");
  torch::jit::Module blocks("__torch__.torch.nn.modules.container.Sequential");
  torch::jit::Module block("__torch__.model.ResidualAttentionBlock");
  const at::Tensor in_proj = at::randn({12, 4});
  block.register_parameter("in_proj_weight", in_proj, false);
  block.register_attribute("attn_mask", c10::TensorType::get(), at::zeros({3, 3}));
  blocks.register_module("0", block);
  visual.register_module("resblocks", blocks);
  visual.register_parameter("proj", at::ones({4, 2}).to(at::kHalf), false);
  root.register_module("visual", visual);
  root.register_parameter("text_projection", at::eye(2), false);
  root.register_buffer("input_resolution", at::tensor(224));
  root.register_attribute("name", c10::StringType::get(), std::string("not a tensor"));
  root.define("def forward(self, x):\n  return torch.mm(x, self.text_projection)\n", nullptr);
  std::ostringstream saved;
  root.save(saved);
  std::string bytes = saved.str();
  size_t garbled = 0;
  const std::string code = "__annotations__ = []";  // in the (uncompressed) Sequential source
  for (size_t at = bytes.find(code); at != std::string::npos; at = bytes.find(code, at)) {
    bytes.replace(at, code.size(), std::string(code.size(), '@'));
    ++garbled;
  }
  ASSERT_GT(garbled, 0u);
  write_bytes(dir.path / "ViT-B-16.pt", std::vector<char>(bytes.begin(), bytes.end()));
  EXPECT_ANY_THROW(torch::jit::load((dir.path / "ViT-B-16.pt").string()));

  const WeightFile f = load_weight_file((dir.path / "ViT-B-16.pt").string());
  EXPECT_EQ(f.names(), (std::vector<std::string>{"input_resolution", "text_projection", "visual.proj",
                                                 "visual.resblocks.0.attn_mask",
                                                 "visual.resblocks.0.in_proj_weight"}));
  EXPECT_TRUE(at::equal(f.get("visual.resblocks.0.in_proj_weight"), in_proj));
  EXPECT_EQ(f.info("visual.proj").dtype, at::kHalf);
  EXPECT_TRUE(at::equal(f.get("visual.proj", at::kFloat), at::ones({4, 2})));
}

TEST(TorchArchive, CorruptArchivesGiveErrorsNamingTheFile) {
  TempDir dir;
  c10::Dict<std::string, at::Tensor> state;
  state.insert("w", at::randn({64, 64}));
  const std::vector<char> good = torch::jit::pickle_save(c10::IValue(state));
  // Truncations at several points, including inside the tensor data and the zip directory.
  for (const size_t keep : {size_t{10}, good.size() / 3, good.size() / 2, good.size() - 30, good.size() - 1}) {
    const fs::path p = dir.path / ("cut" + std::to_string(keep) + ".pt");
    write_bytes(p, std::vector<char>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(keep)));
    try {
      load_weight_file(p.string()).get("w");
      ADD_FAILURE() << "no error for a file cut at " << keep;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(p.string() + ": ", 0), 0u) << e.what();
    }
  }
  // A zip that is not a PyTorch archive.
  std::vector<char> other = good;
  for (size_t i = 0; i + 8 < other.size(); ++i)
    if (std::string(other.data() + i, 8) == "data.pkl") other[i] = 'x';  // rename data.pkl
  write_bytes(dir.path / "other.zip", other);
  EXPECT_THROW(load_weight_file((dir.path / "other.zip").string()), Error);
}
