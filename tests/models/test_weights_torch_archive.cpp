#include <gtest/gtest.h>

#include "models/temp_dir.h"
#include <torch/csrc/jit/serialization/pickle.h>
#include <torch/script.h>
#include <caffe2/serialize/inline_container.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "models/weights/pickle_reader.h"
#include "models/weights/torch_archive.h"
#include "models/weights/weight_file.h"

namespace fs = std::filesystem;
using namespace cls;
using test::TempDir;
using test::write_bytes;

namespace {

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

namespace {
// Pickle opcodes (protocol 2) for the data.pkl Python's torch.save writes for a state dict:
// OrderedDict() filled with torch._utils._rebuild_tensor_v2(persistent storage, offset, size,
// stride, requires_grad, backward_hooks) values.
std::string pickle_str(const std::string& s) {
  std::string out = "X";
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((s.size() >> (8 * k)) & 0xff));
  return out + s;
}
std::string python_tensor_pickle(const std::string& storage_type, const std::string& key, int rows, int cols,
                                 int storage_numel = -1) {
  const std::string K = "K";
  auto int1 = [&](int v) { return K + static_cast<char>(v); };
  return "ctorch._utils\n_rebuild_tensor_v2\n(" +                                  // GLOBAL, MARK
         std::string("(") + pickle_str("storage") + "ctorch\n" + storage_type + "\n" +  // persistent id tuple
         pickle_str(key) + pickle_str("cpu") + int1(storage_numel < 0 ? rows * cols : storage_numel) + "tQ" +            // TUPLE, BINPERSID
         int1(0) + int1(rows) + int1(cols) + "\x86" + int1(cols) + int1(1) + "\x86" +  // offset, size, stride
         "\x89" + "ccollections\nOrderedDict\n)R" + "tR";                           // requires_grad, hooks
}
}  // namespace

// The layout Python's torch.save (PyTorch >= 1.6) writes, e.g. the official SAM checkpoints:
// archive/data.pkl with an OrderedDict and archive/data/<key> storages (also half precision).
// (LibTorch 1.13's own unpickler turns these OrderedDicts into None; our reader must not.)
void write_archive(const fs::path& p, const std::string& pkl, const std::vector<float>& w, const at::Tensor& h) {
  caffe2::serialize::PyTorchStreamWriter writer(p.string());
  writer.writeRecord("data.pkl", pkl.data(), pkl.size());
  writer.writeRecord("byteorder", "little", 6);
  writer.writeRecord("data/0", w.data(), w.size() * sizeof(float));
  writer.writeRecord("data/1", h.data_ptr(), 8);
  writer.writeEndOfFile();
}

TEST(TorchArchive, ReadsAPythonStyleStateDict) {
  TempDir dir;
  const std::vector<float> w = {1, 2, 3, 4, 5, 6};
  const at::Tensor h = at::tensor({0.5f, -2.f, 3.f, 4.f}).to(at::kHalf).view({2, 2});
  // Python batches dict items with MARK ... SETITEMS, and uses SETITEM for a batch of one.
  std::string pkl = std::string("\x80\x02") + "ccollections\nOrderedDict\nq\x05)Rq\x06(";
  pkl += pickle_str("image_encoder.pos_embed") + python_tensor_pickle("FloatStorage", "0", 2, 3);
  pkl += pickle_str("mask_decoder.iou_token.weight") + python_tensor_pickle("HalfStorage", "1", 2, 2);
  pkl += "u" + pickle_str("extra") + python_tensor_pickle("FloatStorage", "0", 3, 2) + "s.";
  const fs::path p = dir.path / "sam_like.pth";
  write_archive(p, pkl, w, h);
  const WeightFile f = load_weight_file(p.string());
  EXPECT_EQ(f.names(), (std::vector<std::string>{"extra", "image_encoder.pos_embed", "mask_decoder.iou_token.weight"}));
  EXPECT_TRUE(at::equal(f.get("image_encoder.pos_embed"), at::tensor(w).view({2, 3})));
  // size (3, 2) with stride (2, 1) over the same storage
  EXPECT_TRUE(at::equal(f.get("extra"), at::tensor(w).view({3, 2})));
  EXPECT_EQ(f.info("mask_decoder.iou_token.weight").dtype, at::kHalf);
  EXPECT_TRUE(at::equal(f.get("mask_decoder.iou_token.weight"), h));

  // Every truncation of the pickle program is an error naming the file, never a crash.
  for (size_t n = 0; n + 1 < pkl.size(); ++n) {
    const fs::path cut = dir.path / "cut.pth";
    write_archive(cut, pkl.substr(0, n), w, h);
    try {
      load_weight_file(cut.string());
      ADD_FAILURE() << "no error for data.pkl cut at " << n;
    } catch (const Error& e) {
      ASSERT_EQ(std::string(e.what()).rfind(cut.string() + ": ", 0), 0u) << e.what();
    }
  }
  // A view reaching beyond its storage (6 floats) is refused before any read.
  std::string big = std::string("\x80\x02}(") + pickle_str("w") + python_tensor_pickle("FloatStorage", "0", 4, 3, 6) + "u.";
  write_archive(p, big, w, h);
  try {
    load_weight_file(p.string());
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("tensor 'w': view exceeds its storage"), std::string::npos) << e.what();
  }
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

// What fuzz_weights found: protocol-0 PUT / GET with a memo index that is not a number ended in
// std::invalid_argument (an internal error) instead of a cls::Error naming the file.
TEST(TorchArchive, APickleMemoIndexThatIsNotANumberIsAnError) {
  for (const std::string program : {std::string("N") + "pabc\n.", std::string("N") + "p1\ng\n.",
                                    std::string("N") + "p99999999999999999999999\n."}) {
    try {
      read_pickle(program, "sd.pt");
      ADD_FAILURE() << "accepted: " << program;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("sd.pt: data.pkl: memo index", 0), 0u) << e.what();
    }
  }
}
