// 3DGS PLY: exact round trip, lower SH degrees, extras by name, a file hand-written in the original
// layout loads and renders, and broken files give cls::Error.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <unistd.h>

#include "core/error.h"
#include "splat/ply_gaussians.h"
#include "splat/rasterize.h"

namespace cls {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() { return fs::temp_directory_path() / ("cls_splat_ply_" + std::to_string(::getpid())); }

fs::path temp_path(const std::string& name) {
  fs::create_directories(temp_dir());
  return temp_dir() / name;
}

// Removes the test's scratch files when the test binary ends.
class TempDirCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(temp_dir(), ec);
  }
};
const auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new TempDirCleanup);

GaussianModel random_model(int64_t n, int degree, int features) {
  torch::manual_seed(7 + degree);
  GaussianModel g = make_gaussians(n, degree, features);
  g.means = torch::randn({n, 3}) * 10;
  g.log_scales = torch::randn({n, 3}) - 3;
  g.quats = torch::randn({n, 4});
  g.opacity_logits = torch::randn({n, 1});
  g.sh_dc = torch::randn({n, 1, 3});
  g.sh_rest = torch::randn({n, (degree + 1) * (degree + 1) - 1, 3});
  if (features > 0) g.features = torch::randn({n, features});
  g.extras.push_back({"class", torch::randint(-1, 20, {n}, torch::kInt32)});
  g.extras.push_back({"score", torch::rand({n})});
  return g;
}

void expect_same(const GaussianModel& a, const GaussianModel& b) {
  EXPECT_TRUE(torch::equal(a.means, b.means));
  EXPECT_TRUE(torch::equal(a.log_scales, b.log_scales));
  EXPECT_TRUE(torch::equal(a.quats, b.quats));
  EXPECT_TRUE(torch::equal(a.opacity_logits, b.opacity_logits));
  EXPECT_TRUE(torch::equal(a.sh_dc, b.sh_dc));
  EXPECT_TRUE(torch::equal(a.sh_rest, b.sh_rest));
  ASSERT_EQ(a.features.defined(), b.features.defined());
  if (a.features.defined()) EXPECT_TRUE(torch::equal(a.features, b.features));
  ASSERT_EQ(a.extras.size(), b.extras.size());
  for (const auto& e : a.extras) {
    const GaussianExtra* r = b.extra(e.name);
    ASSERT_NE(r, nullptr) << e.name;
    EXPECT_EQ(r->values.scalar_type(), e.values.scalar_type()) << e.name;
    EXPECT_TRUE(torch::equal(r->values, e.values)) << e.name;
  }
}

TEST(SplatPly, RoundTripIsExact) {
  for (int degree = 0; degree <= 3; ++degree) {
    const GaussianModel g = random_model(257, degree, degree == 3 ? 16 : 0);
    const auto path = temp_path("rt" + std::to_string(degree) + ".ply");
    write_gaussians_ply(path, g);
    const GaussianModel r = read_gaussians_ply(path);
    EXPECT_EQ(r.sh_degree(), degree);
    expect_same(g, r);
  }
}

// Writes a PLY byte by byte in the original 3DGS layout (degree 3, channel-major f_rest).
void write_original_layout(const fs::path& path, const std::vector<std::vector<float>>& rows) {
  std::ofstream f(path, std::ios::binary);
  f << "ply\nformat binary_little_endian 1.0\nelement vertex " << rows.size() << "\n";
  for (const char* p : {"x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"}) f << "property float " << p << "\n";
  for (int k = 0; k < 45; ++k) f << "property float f_rest_" << k << "\n";
  f << "property float opacity\n";
  for (int k = 0; k < 3; ++k) f << "property float scale_" << k << "\n";
  for (int k = 0; k < 4; ++k) f << "property float rot_" << k << "\n";
  f << "end_header\n";
  for (const auto& r : rows) f.write(reinterpret_cast<const char*>(r.data()), 4 * r.size());
}

TEST(SplatPly, OriginalLayoutLoadsAndRenders) {
  // One Gaussian 4 units in front of the camera; degree-1 coefficient k = 2 (basis C1 * z) set per
  // channel in the channel-major f_rest block: f_rest_(c*15 + k).
  std::vector<float> row(62, 0.0f);
  row[2] = 4.0f;                                      // z
  row[6] = 0.2f, row[7] = -0.4f, row[8] = 0.6f;       // f_dc
  const float rest_k2[3] = {0.3f, 0.1f, -0.2f};
  for (int c = 0; c < 3; ++c) row[9 + c * 15 + 1] = rest_k2[c];  // k = 2 is index 1 of f_rest
  row[54] = 1.0f;                                     // opacity logit
  row[55] = row[56] = row[57] = std::log(0.1f);       // scales
  row[58] = 1.0f;                                     // rot w
  std::vector<float> far_row = row;
  far_row[2] = -5.0f;  // behind the camera: culled
  const auto path = temp_path("original.ply");
  write_original_layout(path, {row, far_row});
  const GaussianModel g = read_gaussians_ply(path);
  ASSERT_EQ(g.size(), 2);
  ASSERT_EQ(g.sh_degree(), 3);
  EXPECT_FLOAT_EQ(g.sh_rest[0][1][0].item<float>(), 0.3f);
  EXPECT_FLOAT_EQ(g.sh_rest[0][1][2].item<float>(), -0.2f);
  EXPECT_TRUE(g.extras.empty());

  RasterizeSettings s;
  s.camera = PinholeCamera{50, 50, 16.5, 12.5, 32, 24};  // the mean projects onto the centre of pixel (16, 12)
  const auto o = rasterize_sh(g.means, g.scales(), g.quats, g.opacities(), g.sh(), 3, {}, s);
  const double C0 = 0.28209479177387814, C1 = 0.4886025119029199, alpha = 1 / (1 + std::exp(-1.0));
  const float dc[3] = {0.2f, -0.4f, 0.6f};
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(o.image[12][16][c].item<float>(), alpha * (0.5 + C0 * dc[c] + C1 * rest_k2[c]), 1e-6) << c;
  EXPECT_NEAR(o.depth[12][16].item<float>(), alpha * 4.0, 1e-6);
  EXPECT_EQ(o.radii[1].item<int>(), 0);
  EXPECT_EQ(o.alpha[0][0].item<float>(), 0.0f);
}

TEST(SplatPly, BrokenFilesAreErrors) {
  const GaussianModel g = random_model(10, 1, 0);
  const auto path = temp_path("broken.ply");
  write_gaussians_ply(path, g);
  const auto size = fs::file_size(path);
  fs::resize_file(path, size - 7);
  EXPECT_THROW(read_gaussians_ply(path), Error);
  EXPECT_THROW(read_gaussians_ply(temp_path("missing.ply")), Error);
  {
    std::ofstream f(path);
    f << "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nend_header\n";
  }
  EXPECT_THROW(read_gaussians_ply(path), Error);
  {
    std::ofstream f(path, std::ios::binary);
    f << "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
         "property float z\nproperty float f_rest_0\nend_header\n";
  }
  try {
    read_gaussians_ply(path);
    FAIL() << "one f_rest property accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("f_rest"), std::string::npos) << e.what();
  }
  GaussianModel bad = random_model(4, 0, 0);
  bad.means = torch::zeros({3, 3});
  EXPECT_THROW(write_gaussians_ply(path, bad), Error);
}

// The two damaged files a user met: a header promising 99,999,999,999 vertices (once std::bad_alloc,
// exit 3) and a model whose values are NaN (once rendered without a word). Both name the file and
// what is wrong. Every property is 4 bytes (float32 or int32) in the files write_gaussians_ply makes.
TEST(SplatPly, AHeaderThatPromisesTooMuchAndNonFiniteValuesAreErrors) {
  const auto message = [](const fs::path& path) {
    try {
      read_gaussians_ply(path);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const auto path = temp_path("damaged.ply");
  write_gaussians_ply(path, random_model(5, 0, 0));
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto count_at = bytes.find("element vertex 5\n");
  ASSERT_NE(count_at, std::string::npos);
  std::string promising = bytes;
  promising.replace(count_at, 17, "element vertex 99999999999\n");
  std::ofstream(path, std::ios::binary) << promising;
  const std::string promise = message(path);
  EXPECT_EQ(promise.rfind(path.string() + ": truncated PLY: the header promises 99999999999 vertices", 0), 0u) << promise;

  // Non-finite values, put into a valid file's bytes (the writer refuses them): vertex 3's property.
  const size_t data_at = bytes.find("end_header\n") + 11;
  std::vector<std::string> properties;
  for (size_t at = bytes.find("property "); at < data_at; at = bytes.find("property ", at + 1)) {
    const size_t name = bytes.find(' ', at + 9) + 1;  // after "property TYPE "
    properties.push_back(bytes.substr(name, bytes.find('\n', at) - name));
  }
  for (const std::string property : {"x", "opacity", "scale_1", "rot_3", "f_dc_2"}) {
    const size_t column = std::find(properties.begin(), properties.end(), property) - properties.begin();
    ASSERT_LT(column, properties.size()) << property;
    std::string damaged = bytes;
    const float bad = property == "rot_3" ? std::numeric_limits<float>::infinity() : std::nanf("");
    std::memcpy(&damaged[data_at + (3 * properties.size() + column) * 4], &bad, 4);
    std::ofstream(path, std::ios::binary) << damaged;
    const std::string nan = message(path);
    EXPECT_EQ(nan.rfind(path.string() + ": vertex 3 has " + property + " = ", 0), 0u) << nan;
  }
  // And the writer refuses them, writing nothing.
  GaussianModel diverged = random_model(5, 0, 0);
  diverged.log_scales[2][1] = std::nanf("");
  const auto fresh = temp_path("diverged.ply");
  EXPECT_THROW(write_gaussians_ply(fresh, diverged), Error);
  EXPECT_FALSE(fs::exists(fresh));
}

}  // namespace
}  // namespace cls
