// The per-view feature files in LangSplat's layout (view_features.h), checked byte by byte against
// NumPy's .npy format specification (numpy/lib/format.py, version 1.0).
#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/npy.h"
#include "features/view_features.h"
#include "models/temp_dir.h"

namespace cls {
namespace {

// H = 2, W = 3; 2 SAM segments, 1 CityGML region, D = 4.
ViewFeatures tiny_view() {
  ViewFeatures f;
  f.height = 2;
  f.width = 3;
  f.sam_seg = {0, 0, 1, 1, -1, -1,   // default
               0, 0, 0, 0, 0, 0,     // s
               1, 1, 1, 1, 1, 1,     // m
               -1, -1, -1, -1, -1, -1};  // l
  f.sam_features = at::tensor({1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f}).reshape({2, 4});
  f.gml_seg = {0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 0, 0, 0, 0, 0};
  f.gml_features = at::tensor({0.f, 0.f, 0.6f, 0.8f}).reshape({1, 4});
  CityRegion r;
  r.level = 1;
  r.class_id = 2;
  r.class_name = "wall";
  r.pixels = 1;
  f.regions = {r};
  f.stamp = {{"alpha", 0.5}};
  return f;
}

// The header of a version-1.0 .npy file: magic, version, little-endian uint16 length, dict padded
// with spaces to a multiple of 64 bytes and ended by '\n'.
std::string npy_header(const std::string& bytes, size_t* data_offset) {
  EXPECT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 6), std::string("\x93NUMPY", 6));
  EXPECT_EQ(static_cast<unsigned char>(bytes[6]), 1);  // major
  EXPECT_EQ(static_cast<unsigned char>(bytes[7]), 0);  // minor
  const size_t len = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
  *data_offset = 10 + len;
  EXPECT_EQ(*data_offset % 64, 0u) << "data must start 64-byte aligned";
  const std::string header = bytes.substr(10, len);
  EXPECT_EQ(header.back(), '\n');
  // Only spaces between the dict's closing brace and the newline.
  const size_t close = header.rfind('}');
  for (size_t i = close + 1; i + 1 < header.size(); ++i) EXPECT_EQ(header[i], ' ');
  return header.substr(0, close + 1);
}

TEST(ViewFeatures, FilesFollowLangSplatLayoutByteForByte) {
  test::TempDir dir;
  write_view_features(dir.path, "0001", tiny_view());
  ASSERT_TRUE(view_features_complete(dir.path, "0001"));

  size_t off = 0;
  const std::string s = read_text_file(dir.path / "0001_s.npy");
  // LangSplat's preprocess.py saves seg maps from a float32 torch.zeros: '<f4', 4 x H x W.
  EXPECT_EQ(npy_header(s, &off), "{'descr': '<f4', 'fortran_order': False, 'shape': (4, 2, 3), }");
  ASSERT_EQ(s.size(), off + 4 * 6 * 4);
  float v[24];
  std::memcpy(v, s.data() + off, sizeof v);
  EXPECT_EQ(v[0], 0.f);
  EXPECT_EQ(v[2], 1.f);
  EXPECT_EQ(v[4], -1.f);
  EXPECT_EQ(v[12], 1.f);
  EXPECT_EQ(v[23], -1.f);

  const std::string f = read_text_file(dir.path / "0001_f.npy");
  EXPECT_EQ(npy_header(f, &off), "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 4), }");
  ASSERT_EQ(f.size(), off + 8 * 4);
  std::memcpy(v, f.data() + off, 8 * 4);
  EXPECT_EQ(v[0], 1.f);
  EXPECT_EQ(v[5], 1.f);

  const std::string g = read_text_file(dir.path / "0001_gml_s.npy");
  EXPECT_EQ(npy_header(g, &off), "{'descr': '<f4', 'fortran_order': False, 'shape': (3, 2, 3), }");
  const std::string gf = read_text_file(dir.path / "0001_gml_f.npy");
  EXPECT_EQ(npy_header(gf, &off), "{'descr': '<f4', 'fortran_order': False, 'shape': (1, 4), }");
  std::memcpy(v, gf.data() + off, 4 * 4);
  EXPECT_FLOAT_EQ(v[3], 0.8f);
}

TEST(ViewFeatures, ReadBackEqualsWritten) {
  test::TempDir dir;
  const ViewFeatures a = tiny_view();
  write_view_features(dir.path, "v", a);
  const ViewFeatures b = read_view_features(dir.path, "v");
  EXPECT_EQ(b.height, 2);
  EXPECT_EQ(b.width, 3);
  EXPECT_EQ(b.sam_seg, a.sam_seg);
  EXPECT_EQ(b.gml_seg, a.gml_seg);
  EXPECT_TRUE(at::equal(b.sam_features, a.sam_features));
  EXPECT_TRUE(at::equal(b.gml_features, a.gml_features));
  ASSERT_EQ(b.regions.size(), 1u);
  EXPECT_EQ(b.regions[0].class_name, "wall");
  EXPECT_EQ(b.regions[0].class_id, 2);
  EXPECT_EQ(b.regions[0].instance, -1);
  EXPECT_EQ(b.stamp, a.stamp);
  EXPECT_EQ(b.sam_at(2, 1, 2), 1);
  EXPECT_EQ(b.gml_at(3, 0, 0), 0);
  EXPECT_EQ(b.gml_at(1, 0, 1), -1);
}

TEST(ViewFeatures, IntegerSegMapsOfOtherToolsAreRead) {
  test::TempDir dir;
  const ViewFeatures a = tiny_view();
  write_view_features(dir.path, "v", a);
  write_npy(dir.path / "v_s.npy", make_npy<int32_t>({4, 2, 3}, a.sam_seg));
  EXPECT_EQ(read_view_features(dir.path, "v").sam_seg, a.sam_seg);
}

void expect_error_naming(const std::filesystem::path& dir, const std::string& file, const std::string& what) {
  try {
    read_view_features(dir, "v");
    ADD_FAILURE() << "no error for " << file;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

TEST(ViewFeatures, InconsistentFilesNameTheFile) {
  test::TempDir dir;
  const ViewFeatures a = tiny_view();
  // An id beyond the feature rows.
  write_view_features(dir.path, "v", a);
  std::vector<int32_t> bad = a.sam_seg;
  bad[0] = 7;
  write_npy(dir.path / "v_s.npy", make_npy<int32_t>({4, 2, 3}, bad));
  expect_error_naming(dir.path, "v_s.npy", "id 7");
  // A seg map of the wrong size.
  write_view_features(dir.path, "v", a);
  write_npy(dir.path / "v_gml_s.npy", make_npy<float>({3, 3, 3}, std::vector<float>(27, -1.f)));
  expect_error_naming(dir.path, "v_gml_s.npy", "3 x 3");
  // A non-integer id.
  write_view_features(dir.path, "v", a);
  std::vector<float> frac(24, 0.5f);
  write_npy(dir.path / "v_s.npy", make_npy<float>({4, 2, 3}, frac));
  expect_error_naming(dir.path, "v_s.npy", "not an id");
  // Fewer regions in the json than feature rows.
  write_view_features(dir.path, "v", a);
  write_npy(dir.path / "v_gml_f.npy", make_npy<float>({2, 4}, std::vector<float>(8, 0.f)));
  expect_error_naming(dir.path, "v_gml.json", "1 regions");
  // Feature widths differ.
  write_view_features(dir.path, "v", a);
  write_npy(dir.path / "v_gml_f.npy", make_npy<float>({1, 3}, std::vector<float>(3, 0.f)));
  expect_error_naming(dir.path, "v_gml_f.npy", "3 columns");
  // Truncated file.
  write_view_features(dir.path, "v", a);
  const std::string bytes = read_text_file(dir.path / "v_f.npy");
  test::write_bytes(dir.path / "v_f.npy", bytes.substr(0, bytes.size() - 3));
  expect_error_naming(dir.path, "v_f.npy", "");
  // Missing file.
  write_view_features(dir.path, "v", a);
  std::filesystem::remove(dir.path / "v_f.npy");
  EXPECT_FALSE(view_features_complete(dir.path, "v"));
  expect_error_naming(dir.path, "v_f.npy", "");
  // Malformed json.
  write_view_features(dir.path, "v", a);
  test::write_bytes(dir.path / "v_gml.json", std::string("{\"height\": 2"));
  expect_error_naming(dir.path, "v_gml.json", "malformed");
}

TEST(ViewFeatures, WriteRejectsInconsistentData) {
  test::TempDir dir;
  ViewFeatures a = tiny_view();
  a.gml_seg[0] = 1;  // only one region
  EXPECT_THROW(write_view_features(dir.path, "v", a), Error);
  EXPECT_FALSE(view_features_complete(dir.path, "v"));
}

}  // namespace
}  // namespace cls
