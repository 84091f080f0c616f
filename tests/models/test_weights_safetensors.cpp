#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include "models/temp_dir.h"
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/npy.h"
#include "models/weights/npy_tensor.h"
#include "models/weights/safetensors.h"
#include "models/weights/weight_file.h"

namespace fs = std::filesystem;
using namespace cls;
using test::TempDir;
using test::write_bytes;

namespace {

const fs::path kClip = fs::path(CLS_TEST_FIXTURES) / "clip/models/tiny_quickgelu";

// A safetensors file from a raw header string and data bytes (no padding applied).
std::string safetensors_bytes(const std::string& header, const std::string& data) {
  std::string out(8, '\0');
  for (int k = 0; k < 8; ++k) out[k] = static_cast<char>((header.size() >> (8 * k)) & 0xff);
  return out + header + data;
}

std::string error_of(const fs::path& p) {
  try {
    read_safetensors(p.string());
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The real fixture (written by the reference's author to the safetensors spec): every key, shape
// and dtype of config.json, and values: token_embedding.weight[tokens] must reproduce the reference
// run's embedding lookup within fp16 rounding (the F16 file is the F32 weights rounded).
TEST(Safetensors, ReadsTheF16FixtureWithTheConfigKeysAndValues) {
  const WeightFile w = read_safetensors((kClip / "weights_fp16.safetensors").string());
  const nlohmann::json config = nlohmann::json::parse(read_text_file(kClip / "config.json"));
  ASSERT_EQ(w.size(), config["tensors"].size());
  for (const auto& [name, t] : config["tensors"].items()) {
    ASSERT_TRUE(w.contains(name)) << name;
    EXPECT_EQ(w.info(name).shape, t["shape"].get<std::vector<int64_t>>()) << name;
    EXPECT_EQ(w.info(name).dtype, at::kHalf) << name;
  }
  const at::Tensor table = w.get("token_embedding.weight", at::kFloat);
  EXPECT_EQ(table.scalar_type(), at::kFloat);
  const at::Tensor tokens = to_tensor(read_npy(kClip / "tokens.npy"));
  const at::Tensor expected = to_tensor(read_npy(kClip / "intermediates/token_embedding.npy"));
  const at::Tensor got = table.index_select(0, tokens.flatten()).view(expected.sizes());
  // fp16 has an 11-bit significand: relative rounding error <= 2^-11 (plus subnormal spacing).
  const at::Tensor bound = expected.abs() * std::ldexp(1.0, -11) + std::ldexp(1.0, -24);
  EXPECT_TRUE(((got - expected).abs() <= bound).all().item<bool>());
  EXPECT_GT((got - expected).abs().max().item<float>(), 0.f);  // it really is the rounded copy
  // 0-d tensor.
  EXPECT_TRUE(w.info("logit_scale").shape.empty());
  EXPECT_NEAR(w.get("logit_scale", at::kFloat).item<float>(), config["logit_scale_stored"].get<double>(), 2e-3);
  // Zero-copy: two loads view the same mapped bytes.
  EXPECT_EQ(w.get("text_projection").data_ptr(), w.get("text_projection").data_ptr());
}

TEST(Safetensors, RoundTripsEveryDtypeAndMetadata) {
  TempDir dir;
  const fs::path p = dir.path / "t.safetensors";
  const at::Tensor f = at::arange(12, at::kFloat).view({3, 4}) / 7;
  const at::Tensor bf = at::tensor({1.5f, -2.25f, 1e3f}).to(at::kBFloat16);
  const at::Tensor h = at::tensor({0.1f, 65504.f}).to(at::kHalf);
  const at::Tensor l = at::tensor({int64_t{-1}, int64_t{1} << 40});
  const at::Tensor i = at::tensor({7, -9, 11}, at::kInt);
  const at::Tensor b = at::tensor({1, 0}, at::kByte).to(at::kBool);
  const at::Tensor d = at::tensor({3.141592653589793}, at::kDouble);
  write_safetensors(p.string(),
                    {{"f", at::kFloat, {3, 4}, f}, {"bf", at::kBFloat16, {3}, bf}, {"h", at::kHalf, {2}, h},
                     {"l", at::kLong, {2}, l}, {"i", at::kInt, {3}, i}, {"b", at::kBool, {2}, b},
                     {"d", at::kDouble, {1}, d}, {"empty", at::kFloat, {0, 5}, at::zeros({0, 5})}},
                    {{"format", "pt"}});
  const WeightFile w = read_safetensors(p.string());
  EXPECT_EQ(w.metadata.at("format"), "pt");
  EXPECT_EQ(w.names(), (std::vector<std::string>{"b", "bf", "d", "empty", "f", "h", "i", "l"}));
  for (const auto& [name, t] : std::vector<std::pair<std::string, at::Tensor>>{
           {"f", f}, {"bf", bf}, {"h", h}, {"l", l}, {"i", i}, {"b", b}, {"d", d}}) {
    const at::Tensor r = w.get(name);
    EXPECT_EQ(r.scalar_type(), t.scalar_type()) << name;
    EXPECT_TRUE(at::equal(r, t)) << name;
  }
  EXPECT_EQ(w.info("empty").shape, (std::vector<int64_t>{0, 5}));
  // Conversion on request: bf16 -> f32 is exact.
  EXPECT_TRUE(at::equal(w.get("bf", at::kFloat), at::tensor({1.5f, -2.25f, 1000.f})));
  // Header JSON is padded so the data starts 8-byte aligned.
  std::ifstream in(p, std::ios::binary);
  uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), 8);
  EXPECT_EQ(n % 8, 0u);
}

TEST(Safetensors, UnalignedDataIsCopiedNotMisread) {
  TempDir dir;
  const fs::path p = dir.path / "odd.safetensors";
  const std::vector<float> v = {1.f, 2.f, -3.5f};
  // A 1-byte tensor first puts the float data at an odd address (legal, if unusual).
  const std::string header =
      R"({"a":{"dtype":"U8","shape":[1],"data_offsets":[0,1]},"x":{"dtype":"F32","shape":[3],"data_offsets":[1,13]}})";
  write_bytes(p, safetensors_bytes(header, std::string("\x05", 1) + std::string(reinterpret_cast<const char*>(v.data()), 12)));
  const WeightFile w = read_safetensors(p.string());
  EXPECT_TRUE(at::equal(w.get("x"), at::tensor(v)));
  EXPECT_EQ(w.get("a").item<uint8_t>(), 5);
}

TEST(Safetensors, CorruptFilesGiveErrorsNamingFileAndTensor) {
  TempDir dir;
  const fs::path p = dir.path / "bad.safetensors";
  const std::string data(16, '\0');
  auto check = [&](const std::string& header, const std::string& bytes, const std::string& expect) {
    write_bytes(p, safetensors_bytes(header, bytes));
    const std::string e = error_of(p);
    EXPECT_EQ(e.rfind(p.string() + ": ", 0), 0u) << e;
    EXPECT_NE(e.find(expect), std::string::npos) << "expected '" << expect << "' in: " << e;
  };
  const std::string ok = R"({"w":{"dtype":"F32","shape":[2,2],"data_offsets":[0,16]}})";
  check(ok, data.substr(0, 12), "tensor 'w': data [0, 16) lies beyond");
  check(R"({"w":{"dtype":"F32","shape":[2,3],"data_offsets":[0,16]}})", data, "tensor 'w': F32 [2, 3] needs 24 bytes");
  check(R"({"w":{"dtype":"Q4","shape":[2,2],"data_offsets":[0,16]}})", data, "tensor 'w': unsupported safetensors dtype 'Q4'");
  check(R"({"w":{"dtype":"F32","shape":[2,-2],"data_offsets":[0,16]}})", data, "non-negative");
  check(R"({"w":{"dtype":"F32","shape":[2,2],"data_offsets":[16,0]}})", data, "end before");
  check(R"({"w":{"dtype":"F32","shape":[2,2]}})", data, "tensor 'w': entry needs");
  check(R"({"w":{"dtype":"F32","shape":[2,2],"data_offsets":[0,16]},)", data, "bad safetensors header JSON");
  check(R"({"a":{"dtype":"F32","shape":[2],"data_offsets":[0,8]},"b":{"dtype":"F32","shape":[3],"data_offsets":[4,16]}})",
        data, "tensor 'b': data overlaps");
  check(R"({"a":{"dtype":"F32","shape":[2],"data_offsets":[0,8]},"b":{"dtype":"F32","shape":[1],"data_offsets":[12,16]}})",
        data, "tensor 'b': hole of 4 bytes");
  check(R"({"a":{"dtype":"F32","shape":[2],"data_offsets":[0,8]}})", data, "8 bytes after the last tensor");
  check(R"({"__metadata__":{"k":1},"w":{"dtype":"F32","shape":[2,2],"data_offsets":[0,16]}})", data,
        "__metadata__ value 'k'");
  check(R"({"w":{"dtype":"F32","shape":[4611686018427387904,4],"data_offsets":[0,16]}})", data, "too many");
  check(R"([1,2])", data, "not a JSON object");
  // A header size pointing past the end of the file, and every truncation of a valid file.
  write_bytes(p, std::string("\xff\xff\xff\x00\x00\x00\x00\x00{}", 10));
  EXPECT_NE(error_of(p).find("exceeds the file"), std::string::npos);
  const std::string good = safetensors_bytes(ok, data);
  for (size_t n = 0; n < good.size(); ++n) {
    write_bytes(p, good.substr(0, n));
    ASSERT_EQ(error_of(p).rfind(p.string() + ": ", 0), 0u) << "cut at " << n << ": " << error_of(p);
  }
  write_bytes(p, good);
  EXPECT_EQ(error_of(p), "");
  EXPECT_NE(error_of(dir.path / "missing.safetensors").find("cannot open"), std::string::npos);
  // Asking for a tensor that is not there names the file and the tensor.
  try {
    read_safetensors(p.string()).get("nope");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), p.string() + ": no tensor 'nope'");
  }
}

TEST(Safetensors, SparseFullSizeFilesCostNoDisk) {
  TempDir dir;
  const fs::path p = dir.path / "big.safetensors";
  write_safetensors(p.string(), {{"a", at::kFloat, {1024, 1024, 256}}, {"b", at::kHalf, {7}}});  // 1 GiB + 14 B
  struct stat st {};
  ASSERT_EQ(::stat(p.c_str(), &st), 0);
  EXPECT_GT(st.st_size, 1ll << 30);
  EXPECT_LT(st.st_blocks * 512, 1 << 20);  // holes, not data
  const WeightFile w = read_safetensors(p.string());
  EXPECT_EQ(w.info("a").shape, (std::vector<int64_t>{1024, 1024, 256}));
  EXPECT_EQ(w.get("b").sum().item<float>(), 0.f);
}

TEST(WeightFile, DispatchesByContentAndExplainsLegacyPickles) {
  TempDir dir;
  write_safetensors((dir.path / "x.bin").string(), {{"t", at::kFloat, {2}, at::ones({2})}});
  EXPECT_TRUE(load_weight_file((dir.path / "x.bin").string()).contains("t"));
  // Legacy torch.save: a pickle starting with PROTO 2 and the magic number.
  write_bytes(dir.path / "old.pth", std::string("\x80\x02\x8a\x0a\x6c\xfc\x9c\x46\xf9\x20\x6a\xa8\x50\x19.", 15));
  try {
    load_weight_file((dir.path / "old.pth").string());
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("old.pth: legacy (pre-zip) PyTorch pickle"), std::string::npos) << m;
    EXPECT_NE(m.find("torch.save(torch.load("), std::string::npos) << m;
  }
}

TEST(NpyTensor, RoundTripsEveryNpyType) {
  for (const NpyArray& a : {make_npy<float>({2, 3}, {1, 2, 3, 4, 5, 6}), make_npy<double>({1}, {0.5}),
                            make_npy<int32_t>({2}, {-4, 4}), make_npy<int64_t>({}, {9}),
                            make_npy<uint8_t>({3}, {0, 128, 255}), make_npy<bool>({2}, {false, true}),
                            make_npy<uint16_t>({1}, {0x3c00})}) {
    const at::Tensor t = to_tensor(a);
    EXPECT_EQ(std::vector<int64_t>(t.sizes().begin(), t.sizes().end()), a.shape);
    const NpyArray back = to_npy(t);
    EXPECT_EQ(back.dtype, a.dtype);
    EXPECT_EQ(back.data, a.data);
  }
  EXPECT_EQ(to_tensor(make_npy<uint16_t>({1}, {0x3c00})).item<float>(), 1.f);
  EXPECT_EQ(to_tensor(make_npy<float>({2, 2}, {1, 2, 3, 4}))[1][0].item<float>(), 3.f);
  EXPECT_THROW(to_npy(at::ones({2}, at::kBFloat16)), Error);
}
