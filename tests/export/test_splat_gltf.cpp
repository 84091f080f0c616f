// Gaussians as glTF (export/splat_gltf.h, export_job.h) on hand-made models: every value read back from
// the GLB's bytes against what the KHR_gaussian_splatting, EXT_mesh_features and EXT_structural_metadata
// specifications say it must be, computed here by hand. Khronos' glTF-Validator checks a trained model's
// file (tests/export/gltf_check.py).
#include <gtest/gtest.h>
#include <torch/torch.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "error_of.h"
#include "export/export_job.h"
#include "export/splat_gltf.h"
#include "export/spz.h"
#include "export/tileset.h"
#include "scene/scene_test_util.h"
#include "splat/ply_gaussians.h"
#include "splat/sh.h"

namespace cls {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// A GLB read back by the letter of the glTF 2.0 container: 12-byte header, JSON chunk, BIN chunk.
struct Glb {
  json doc;
  std::string bin;
  explicit Glb(const std::string& bytes) {
    auto u32 = [&](size_t at) {
      uint32_t v;
      std::memcpy(&v, bytes.data() + at, 4);
      return v;
    };
    EXPECT_EQ(u32(0), 0x46546C67u);  // "glTF"
    EXPECT_EQ(u32(4), 2u);
    EXPECT_EQ(u32(8), bytes.size());
    const uint32_t json_length = u32(12);
    EXPECT_EQ(u32(16), 0x4E4F534Au);  // "JSON"
    EXPECT_EQ(json_length % 4, 0u);
    doc = json::parse(bytes.substr(20, json_length));
    const size_t bin_at = 20 + json_length;
    EXPECT_EQ(u32(bin_at + 4), 0x004E4942u);  // "BIN\0"
    EXPECT_EQ(u32(bin_at) % 4, 0u);
    bin = bytes.substr(bin_at + 8, u32(bin_at));
    EXPECT_GE(bin.size(), doc["buffers"][0]["byteLength"].get<size_t>());
  }
  // The bytes of buffer view `v`.
  std::string view(int v) const {
    const json& bv = doc["bufferViews"][v];
    return bin.substr(bv["byteOffset"].get<size_t>(), bv["byteLength"].get<size_t>());
  }
  template <class T>
  std::vector<T> accessor(int a) const {
    const json& acc = doc["accessors"][a];
    const std::string bytes = view(acc["bufferView"].get<int>());
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
  }
  const json& primitive() const { return doc["meshes"][0]["primitives"][0]; }
  template <class T>
  std::vector<T> attribute(const std::string& name) const {
    return accessor<T>(primitive()["attributes"][name].get<int>());
  }
  // A STRING column of the property table: values split at the offsets.
  std::vector<std::string> strings(const json& property) const {
    const std::string values = view(property["values"].get<int>()), offsets = view(property["stringOffsets"].get<int>());
    std::vector<uint32_t> o(offsets.size() / 4);
    std::memcpy(o.data(), offsets.data(), offsets.size());
    std::vector<std::string> out;
    for (size_t k = 0; k + 1 < o.size(); ++k) out.push_back(values.substr(o[k], o[k + 1] - o[k]));
    return out;
  }
};

// Building B (row 0) with BuildingPart P (1); wall W (2) of the part with window A (3); roof R (4) of B.
CityObjects hand_objects() {
  CityObjects t;
  t.source = "hand.gml";
  t.class_names = {"window", "wall", "roof", "building"};
  t.objects = {{"B", 3, 3, -1}, {"P", 3, 3, 0}, {"W", 2, 1, 1}, {"A", 1, 0, 2}, {"R", 2, 2, 0}};
  return t;
}

// Three Gaussians, SH degree 1, with values whose glTF form is worked out in the test.
GaussianModel hand_gaussians() {
  GaussianModel g = make_gaussians(3, 1);
  g.means = torch::tensor({1.0f, 2.0f, 3.0f, -1.0f, 0.5f, 0.0f, 4.0f, -2.0f, 8.0f}).reshape({3, 3});
  g.log_scales = torch::tensor({0.0f, std::log(2.0f), std::log(0.5f), -1.0f, -2.0f, -3.0f, 1.0f, 0.0f, 0.0f}).reshape({3, 3});
  // (w, x, y, z): (2, 0, 0, 0) is the identity unnormalised; (0, 0, 0, 1) 180 deg about z.
  g.quats = torch::tensor({2.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f}).reshape({3, 4});
  g.opacity_logits = torch::tensor({0.0f, std::log(3.0f), -100.0f}).reshape({3, 1});
  g.sh_dc = torch::tensor({0.1f, 0.2f, 0.3f, -5.0f, 0.0f, 5.0f, 0.0f, 0.0f, 0.0f}).reshape({3, 1, 3});
  // Coefficient k (of 3) of channel c of Gaussian i = 100 i + 10 k + c.
  g.sh_rest = torch::zeros({3, 3, 3});
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) g.sh_rest[i][k][c] = 100 * i + 10 * k + c;
  return g;
}

Glb glb_of(const GltfBuilder& b) { return Glb(b.glb()); }

TEST(SplatGltf, TheGaussiansAsTheExtensionDefinesThem) {
  const Glb glb = glb_of(splat_gltf(hand_gaussians(), nullptr, {}, {}));
  const json& p = glb.primitive();
  EXPECT_EQ(p["mode"], 0);  // POINTS
  EXPECT_EQ(p["extensions"]["KHR_gaussian_splatting"]["kernel"], "ellipse");
  EXPECT_EQ(p["extensions"]["KHR_gaussian_splatting"]["colorSpace"], "srgb_rec709_display");
  EXPECT_EQ(glb.doc["extensionsUsed"], json::array({"KHR_gaussian_splatting"}));

  const std::vector<float> pos = glb.attribute<float>("POSITION");
  EXPECT_EQ(pos, std::vector<float>({1, 2, 3, -1, 0.5, 0, 4, -2, 8}));
  const json& pos_acc = glb.doc["accessors"][p["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(pos_acc["min"], json::array({-1.0, -2.0, 0.0}));
  EXPECT_EQ(pos_acc["max"], json::array({4.0, 2.0, 8.0}));

  // Unit quaternions in glTF's (x, y, z, w) order.
  const std::vector<float> rot = glb.attribute<float>("KHR_gaussian_splatting:ROTATION");
  const std::vector<float> rot_expected{0, 0, 0, 1, 0, 0, 1, 0, float(M_SQRT1_2), 0, 0, float(M_SQRT1_2)};
  for (size_t k = 0; k < rot.size(); ++k) EXPECT_NEAR(rot[k], rot_expected[k], 1e-7) << k;
  // Linear scales, opacity after the sigmoid (1 / (1 + 1/3) = 0.75).
  const std::vector<float> scale = glb.attribute<float>("KHR_gaussian_splatting:SCALE");
  const std::vector<float> scale_expected{1, 2, 0.5, std::exp(-1.0f), std::exp(-2.0f), std::exp(-3.0f), std::exp(1.0f), 1, 1};
  for (size_t k = 0; k < scale.size(); ++k) EXPECT_NEAR(scale[k], scale_expected[k], 1e-6) << k;
  const std::vector<float> opacity = glb.attribute<float>("KHR_gaussian_splatting:OPACITY");
  EXPECT_NEAR(opacity[0], 0.5, 1e-7);
  EXPECT_NEAR(opacity[1], 0.75, 1e-7);
  EXPECT_NEAR(opacity[2], 0.0, 1e-7);

  // SH: degree 0 the DC; degree 1's COEF_n is 3DGS's coefficient n + 1 (m = -1, 0, 1), RGB per splat.
  EXPECT_EQ(glb.attribute<float>("KHR_gaussian_splatting:SH_DEGREE_0_COEF_0"),
            std::vector<float>({0.1f, 0.2f, 0.3f, -5, 0, 5, 0, 0, 0}));
  for (int n = 0; n < 3; ++n) {
    const std::vector<float> coef = glb.attribute<float>("KHR_gaussian_splatting:SH_DEGREE_1_COEF_" + std::to_string(n));
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(coef[3 * i + c], 100 * i + 10 * n + c) << n << " " << i << " " << c;
  }
  EXPECT_FALSE(p["attributes"].contains("KHR_gaussian_splatting:SH_DEGREE_2_COEF_0"));

  // The fallback colour: 0.5 + C0 * DC clamped, sRGB decoded to linear, times 255; alpha the opacity.
  const std::vector<uint8_t> rgba = glb.attribute<uint8_t>("COLOR_0");
  auto linear = [](double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); };
  EXPECT_EQ(rgba[0], std::lround(255 * linear(0.5 + 0.28209479177387814 * 0.1)));
  EXPECT_EQ(rgba[3], 128);  // opacity 0.5
  EXPECT_EQ(rgba[4], 0);    // 0.5 - 5 C0 < 0: clamped
  EXPECT_EQ(rgba[6], 255);  // 0.5 + 5 C0 > 1: clamped
  EXPECT_EQ(rgba[7], 191);  // opacity 0.75
  EXPECT_TRUE(glb.doc["accessors"][p["attributes"]["COLOR_0"].get<int>()]["normalized"].get<bool>());
}

TEST(SplatGltf, ShAttributesFollowTheSpecificationsBasisAndOrder) {
  // The extension's Appendix A (real SH with the Condon-Shortley phase), typed from the specification,
  // against splat/sh.h in the attribute order sh_attribute_name gives.
  const double x = 0.48, y = -0.6, z = 0.64;  // unit
  const double spec[16] = {0.2820947917738781,
                           -0.4886025119029199 * y, 0.4886025119029199 * z, -0.4886025119029199 * x,
                           1.092548430592079 * x * y, -1.092548430592079 * y * z,
                           0.3153915652525200 * (2 * z * z - x * x - y * y), -1.092548430592079 * x * z,
                           0.5462742152960395 * (x * x - y * y),
                           -0.5900435899266435 * y * (3 * x * x - y * y), 2.890611442640554 * x * y * z,
                           -0.4570457994644657 * y * (4 * z * z - x * x - y * y),
                           0.3731763325901154 * z * (2 * z * z - 3 * x * x - 3 * y * y),
                           -0.4570457994644657 * x * (4 * z * z - x * x - y * y),
                           1.445305721320277 * z * (x * x - y * y), -0.5900435899266435 * x * (x * x - 3 * y * y)};
  const char* names[16] = {"0_COEF_0", "1_COEF_0", "1_COEF_1", "1_COEF_2", "2_COEF_0", "2_COEF_1", "2_COEF_2", "2_COEF_3",
                           "2_COEF_4", "3_COEF_0", "3_COEF_1", "3_COEF_2", "3_COEF_3", "3_COEF_4", "3_COEF_5", "3_COEF_6"};
  double ours[16];
  sh_basis(3, x, y, z, ours);
  for (int k = 0; k < 16; ++k) {
    EXPECT_NEAR(ours[k], spec[k], 1e-12) << k;
    EXPECT_EQ(sh_attribute_name(k), std::string("KHR_gaussian_splatting:SH_DEGREE_") + names[k]);
  }
}

TEST(SplatGltf, FeatureIdsPerLevelIntoTheTableOfCityObjects) {
  const CityObjects objects = hand_objects();
  // Gaussians on window A, wall W, roof R, on nothing, on the part P itself.
  GaussianModel g = make_gaussians(5, 0);
  SplatSemantics semantics{&objects, {3, 2, 4, -1, 1}};
  const Glb glb = glb_of(splat_gltf(g, &semantics, {}, {}));
  const json& features = glb.primitive()["extensions"]["EXT_mesh_features"]["featureIds"];
  ASSERT_EQ(features.size(), 3u);
  const float null = 5;  // one past the table's rows
  // Level 1: A, W (a wall without a finer object answers for itself), R, none, P.
  // Level 2: W, W, R, none, P. Level 3: the whole building B for all but the Gaussian on nothing.
  const std::vector<std::vector<float>> expected{{3, 2, 4, null, 1}, {2, 2, 4, null, 1}, {0, 0, 0, null, 0}};
  const std::vector<size_t> distinct{4, 3, 1};
  for (int l = 0; l < 3; ++l) {
    EXPECT_EQ(features[l]["attribute"], l);
    EXPECT_EQ(features[l]["propertyTable"], 0);
    EXPECT_EQ(features[l]["nullFeatureId"], 5);
    EXPECT_EQ(features[l]["featureCount"], distinct[l]) << l;
    EXPECT_EQ(glb.attribute<float>("_FEATURE_ID_" + std::to_string(l)), expected[l]) << l;
  }
  EXPECT_EQ(features[2]["label"], "level3_building");

  const json& metadata = glb.doc["extensions"]["EXT_structural_metadata"];
  const json& table = metadata["propertyTables"][0];
  EXPECT_EQ(table["class"], "cityObject");
  EXPECT_EQ(table["count"], 5);
  EXPECT_EQ(glb.strings(table["properties"]["id"]), std::vector<std::string>({"B", "P", "W", "A", "R"}));
  EXPECT_EQ(glb.strings(table["properties"]["class"]),
            std::vector<std::string>({"building", "building", "wall", "window", "roof"}));
  EXPECT_EQ(glb.strings(table["properties"]["building"]), std::vector<std::string>({"B", "B", "B", "B", "B"}));
  EXPECT_EQ(glb.strings(table["properties"]["part"]), std::vector<std::string>({"", "P", "P", "P", ""}));
  const std::string levels = glb.view(table["properties"]["level"]["values"].get<int>());
  EXPECT_EQ(levels, std::string({3, 3, 2, 1, 2}));
  for (const char* p : {"id", "class", "level", "building", "part"})
    EXPECT_TRUE(metadata["schema"]["classes"]["cityObject"]["properties"].contains(p)) << p;
  // Table columns are aligned to their component size (EXT_structural_metadata), here 4 at least.
  for (const json& view : glb.doc["bufferViews"]) EXPECT_EQ(view["byteOffset"].get<size_t>() % 4, 0u);
}

TEST(SplatGltf, QueryScoresAsPropertyAttributes) {
  GaussianModel g = make_gaussians(2, 0);
  const Glb glb = glb_of(splat_gltf(g, nullptr, {{"score_window", "window", 1, {0.25f, 0.75f}}}, {}));
  EXPECT_EQ(glb.attribute<float>("_SCORE_0"), std::vector<float>({0.25f, 0.75f}));
  const json& metadata = glb.doc["extensions"]["EXT_structural_metadata"];
  EXPECT_EQ(metadata["propertyAttributes"][0]["properties"]["score_window"]["attribute"], "_SCORE_0");
  EXPECT_EQ(metadata["schema"]["classes"]["queryScores"]["properties"]["score_window"]["name"], "window");
  EXPECT_EQ(glb.primitive()["extensions"]["EXT_structural_metadata"]["propertyAttributes"], json::array({0}));
}

TEST(SplatGltf, AValueAGltfCannotCarryIsRefused) {
  GaussianModel g = make_gaussians(2, 0);
  g.means[1][2] = NAN;
  EXPECT_NE(test::error_of([&] { splat_gltf(g, nullptr, {}, {}); }).find("positions holds a value that is not finite"),
            std::string::npos);
  EXPECT_NE(test::error_of([&] { splat_gltf(make_gaussians(0, 0), nullptr, {}, {}); }).find("no Gaussians"),
            std::string::npos);
}

TEST(SplatGltf, TheCityMatrixTakesTheSceneToTheCrsYUp) {
  // scene = 2 * Rz(90 deg) * crs + (10, 0, 0): the CRS point (1000, 2000, 30) lies in the scene at
  // 2 * (-2000, 1000, 30) + (10, 0, 0) = (-3990, 2000, 60).
  Mat3d rz;
  rz.m[0][0] = 0, rz.m[0][1] = -1, rz.m[0][2] = 0;
  rz.m[1][0] = 1, rz.m[1][1] = 0, rz.m[1][2] = 0;
  rz.m[2][0] = 0, rz.m[2][1] = 0, rz.m[2][2] = 1;
  const CityTransform scene_from_crs = similarity_transform(2, rz, {10, 0, 0});
  const std::array<double, 16> m = gltf_city_matrix(scene_from_crs, {900, 1900, 0});
  const double p[4] = {-3990, 2000, 60, 1};
  double q[4] = {0, 0, 0, 0};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) q[r] += m[4 * c + r] * p[c];  // column-major
  // CRS minus origin = (100, 100, 30): glTF (E, U, -N) = (100, 30, -100).
  EXPECT_NEAR(q[0], 100, 1e-9);
  EXPECT_NEAR(q[1], 30, 1e-9);
  EXPECT_NEAR(q[2], -100, 1e-9);
  EXPECT_EQ(q[3], 1);
}

TEST(SplatGltf, AGltfWithItsBufferBeside) {
  const fs::path dir = test::fresh_dir("gltf_bin");
  const GltfBuilder b = splat_gltf(hand_gaussians(), nullptr, {}, {});
  b.write(dir / "model.gltf");
  const json doc = json::parse(read_text_file(dir / "model.gltf"));
  EXPECT_EQ(doc["buffers"][0]["uri"], "model.bin");
  EXPECT_EQ(doc["buffers"][0]["byteLength"].get<size_t>(), fs::file_size(dir / "model.bin"));
  EXPECT_EQ(read_text_file(dir / "model.bin"), Glb(b.glb()).bin.substr(0, fs::file_size(dir / "model.bin")));
  fs::remove_all(dir);
}

TEST(ExportJob, APlyGoesOutInItsOwnFrameAndOptionsAreChecked) {
  const fs::path dir = test::fresh_dir("export_ply");
  write_gaussians_ply((dir / "model.ply").string(), hand_gaussians());
  ExportOptions o;
  o.input = (dir / "model.ply").string();
  const json done = run_export(o);
  EXPECT_EQ(done["file"], (dir / "model.glb").string());
  EXPECT_EQ(done["frame"]["frame"], "scene");
  EXPECT_TRUE(done["semantics"].is_null());
  const Glb glb(read_text_file(dir / "model.glb"));
  EXPECT_FALSE(glb.doc["nodes"][0].contains("matrix"));
  EXPECT_EQ(glb.doc["asset"]["extras"]["citylangsplat"]["frame"], "scene");

  o.queries = {"window"};
  EXPECT_NE(test::error_of([&] { run_export(o); }).find("text queries need a language model"), std::string::npos);
  o.queries.clear();
  o.out = (dir / "x.gltf").string();
  EXPECT_NE(test::error_of([&] { run_export(o); }).find("does not end in .glb"), std::string::npos);
  o.format = "obj";
  EXPECT_NE(test::error_of([&] { run_export(o); }).find("--format must be glb, gltf or 3dtiles"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "x.gltf"));
  fs::remove_all(dir);
}

// The SPZ stream inflated (zlib, gzip header) as SPZ version 2's layout says.
std::string gunzip(const std::string& in) {
  z_stream z{};
  EXPECT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
  std::string out(1 << 16, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  inflateEnd(&z);
  return out;
}

TEST(Spz, SignsOfTheShCoefficientsWhenXAndZFlip) {
  // By hand from the basis (splat/sh.h) under (x, y, z) -> (-x, y, -z): degree 1 is y, z, x; degree 2
  // xy, yz, 2zz - xx - yy, xz, xx - yy; degree 3 y(3xx - yy), xyz, y(4zz - xx - yy), z(...), x(...), z(xx - yy), x(xx - 3yy).
  const int expected[16] = {1, 1, -1, -1, -1, -1, 1, 1, 1, 1, 1, 1, -1, -1, -1, -1};
  for (int k = 0; k < 16; ++k) EXPECT_EQ(spz_flip_sign(k), expected[k]) << k;
}

TEST(Spz, OneGaussianByteByByte) {
  GaussianModel g = make_gaussians(1, 1);
  g.means = torch::tensor({1.5f, -2.0f, 0.25f}).reshape({1, 3});
  g.log_scales = torch::tensor({0.0f, -10.0f, 1.0f}).reshape({1, 3});
  g.quats = torch::tensor({-2.0f, 0.0f, 2.0f, 0.0f}).reshape({1, 4});  // (w, x, y, z): w < 0, y = 2
  g.opacity_logits = torch::tensor({0.0f}).reshape({1, 1});
  g.sh_dc = torch::tensor({0.0f, 1.0f, -1.0f}).reshape({1, 1, 3});
  g.sh_rest = torch::tensor({0.5f, 0.0f, 0.0f, 0.5f, 0.0f, 0.0f, 0.5f, 0.0f, 0.0f}).reshape({1, 3, 3});
  const std::string raw = gunzip(spz_v2(g));
  ASSERT_EQ(raw.size(), 16u + 9 + 1 + 3 + 3 + 3 + 9);
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, raw.data() + at, 4);
    return v;
  };
  EXPECT_EQ(u32(0), 0x5053474eu);
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), 1u);
  EXPECT_EQ(raw[12], 1);   // SH degree
  EXPECT_EQ(raw[13], 12);  // fractional bits: 2 * 4096 fits 2^23
  auto byte = [&](size_t at) { return static_cast<uint8_t>(raw[at]); };
  auto fixed24 = [&](size_t at) {
    int32_t v = byte(at) | byte(at + 1) << 8 | byte(at + 2) << 16;
    return v >= (1 << 23) ? v - (1 << 24) : v;
  };
  // Positions with x and z flipped (glTF's LUF to SPZ's RUB), times 4096.
  EXPECT_EQ(fixed24(16), -6144);
  EXPECT_EQ(fixed24(19), -8192);
  EXPECT_EQ(fixed24(22), -1024);
  EXPECT_EQ(byte(25), 128);  // alpha sigmoid(0) * 255 = 127.5, rounded half away from zero
  EXPECT_EQ(byte(26), 128);  // colour 0 * 38.25 + 127.5
  EXPECT_EQ(byte(27), 166);  // 38.25 + 127.5 = 165.75
  EXPECT_EQ(byte(28), 89);   // -38.25 + 127.5 = 89.25
  EXPECT_EQ(byte(29), 160);  // (0 + 10) * 16
  EXPECT_EQ(byte(30), 0);    // (-10 + 10) * 16
  EXPECT_EQ(byte(31), 176);  // 11 * 16
  // The unit quaternion (x, y, z, w) = (0, 0.7071, 0, -0.7071), made w >= 0 by negating: (0, -0.7071, 0);
  // the half turn about y keeps y: byte -0.7071 * 127.5 + 127.5 = 37.35.
  EXPECT_EQ(byte(32), 128);
  EXPECT_EQ(byte(33), 37);
  EXPECT_EQ(byte(34), 128);
  // SH of degree 1, red 0.5 on each coefficient: signs +, -, - (y, z, x), then 8 bits, buckets of 8:
  // 0.5 * 128 + 128 = 192 -> 192; -0.5 -> 64; green and blue 0 -> 128.
  const uint8_t sh[9] = {192, 128, 128, 64, 128, 128, 64, 128, 128};
  for (int k = 0; k < 9; ++k) EXPECT_EQ(byte(35 + k), sh[k]) << k;
  // Stored as CesiumJS reads them: the same but for positions and SH signs, which do not flip.
  const std::string stored = gunzip(spz_v2(g, SpzAxes::AsStored));
  ASSERT_EQ(stored.size(), raw.size());
  auto stored24 = [&](size_t at) {
    int32_t v = uint8_t(stored[at]) | uint8_t(stored[at + 1]) << 8 | uint8_t(stored[at + 2]) << 16;
    return v >= (1 << 23) ? v - (1 << 24) : v;
  };
  EXPECT_EQ(stored24(16), 6144);
  EXPECT_EQ(stored24(19), -8192);
  EXPECT_EQ(stored24(22), 1024);
  EXPECT_EQ(stored.substr(25, 10), raw.substr(25, 10));  // alpha, colour, scales, the quaternion (x = z = 0)
  for (int k = 0; k < 9; ++k) EXPECT_EQ(uint8_t(stored[35 + k]), k % 3 == 0 ? 192 : 128) << k;
}

TEST(Spz, TheGltfHoldsThePayloadAndAccessorsWithoutData) {
  const Glb glb = glb_of(splat_gltf(hand_gaussians(), nullptr, {}, {SplatCompression::Spz, SpzAxes::Luf, std::nullopt, json::object()}));
  const json& ext = glb.primitive()["extensions"]["KHR_gaussian_splatting"];
  const int view = ext["extensions"]["KHR_gaussian_splatting_compression_spz_2"]["bufferView"].get<int>();
  EXPECT_EQ(glb.view(view), spz_v2(hand_gaussians()));
  for (const char* e : {"KHR_gaussian_splatting", "KHR_gaussian_splatting_compression_spz_2"})
    EXPECT_NE(std::find(glb.doc["extensionsRequired"].begin(), glb.doc["extensionsRequired"].end(), e),
              glb.doc["extensionsRequired"].end()) << e;
  const json& attributes = glb.primitive()["attributes"];
  for (const char* a : {"POSITION", "COLOR_0", "KHR_gaussian_splatting:ROTATION", "KHR_gaussian_splatting:SCALE",
                        "KHR_gaussian_splatting:SH_DEGREE_1_COEF_2"}) {
    ASSERT_TRUE(attributes.contains(a)) << a;
    const json& accessor = glb.doc["accessors"][attributes[a].get<int>()];
    EXPECT_FALSE(accessor.contains("bufferView")) << a;
    EXPECT_EQ(accessor["count"], 3) << a;
  }
  // The payload holds the opacity and the DC term (the extension's example leaves both out).
  EXPECT_FALSE(attributes.contains("KHR_gaussian_splatting:OPACITY"));
  EXPECT_FALSE(attributes.contains("KHR_gaussian_splatting:SH_DEGREE_0_COEF_0"));
}

TEST(Tileset, TheLocalFrameOnTheGlobeWhereUtmIsKnownInClosedForm) {
  // UTM 32N (WGS 84) at easting 500000, northing 0 is latitude 0, longitude 9 deg exactly, where the
  // projection's scale is k0 = 0.9996 (a grid metre is 1 / k0 metres on the ground) and grid north is
  // true north: east is (-sin 9, cos 9, 0) / k0, north (0, 0, 1) / k0, up (cos 9, sin 9, 0); the origin
  // at height 0 above the geoid lies N (EGM96) above the ellipsoid, at (a + N) (cos 9, sin 9, 0) with
  // a = 6378137 m. Central differences over +-10 m leave ~5e-6 of the curvature.
  const CrsToGeocentric to_ecef("EPSG:32632");
  const Egm96Geoid geoid;
  const double n = geoid.undulation(0, 9).value_or(0);
  const std::array<double, 16> m = ecef_tile_transform(to_ecef, {500000, 0, 0});
  const double c = std::cos(9 * M_PI / 180), s = std::sin(9 * M_PI / 180), k = 1 / 0.9996;
  const double expected[16] = {-k * s, k * c, 0, 0, 0, 0, k, 0, c, s, 0, 0, (6378137 + n) * c, (6378137 + n) * s, 0, 1};
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(m[i], expected[i], 1e-5) << i;
  for (int i = 12; i < 15; ++i) EXPECT_NEAR(m[i], expected[i], 1e-3) << i;
  EXPECT_EQ(m[15], 1);
  if (!geoid.available()) GTEST_SKIP() << "EGM96's grid is not installed: heights went on as ellipsoidal";
  EXPECT_GT(std::abs(n), 1.0);  // the test says something about the geoid only where N is not ~0
}

TEST(Tileset, TheBoxHoldsEveryGaussianWithItsRadius) {
  const std::array<double, 12> box = bounding_box({{0, 0, 0}, {10, -4, 2}, {99, 99, 99}}, {1, 0.5, 1}, {0, 1});
  const std::array<double, 12> expected{4.75, -1.75, 0.75, 5.75, 0, 0, 0, 2.75, 0, 0, 0, 1.75};  // x -1..10.5, y -4.5..1, z -1..2.5
  EXPECT_EQ(box, expected);
}

TEST(Tileset, APlyWithoutACityFrameIsRefused) {
  const fs::path dir = test::fresh_dir("export_tiles");
  write_gaussians_ply((dir / "model.ply").string(), hand_gaussians());
  ExportOptions o;
  o.input = (dir / "model.ply").string();
  o.format = "3dtiles";
  EXPECT_NE(test::error_of([&] { run_export(o); }).find("a 3D Tiles tileset needs the city model's CRS"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "model_3dtiles"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cls
