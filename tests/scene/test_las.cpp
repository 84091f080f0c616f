// LAS point clouds (scene/las.h) against laspy's own assertions about its sample files
// (data/las/laspy/expected.json), the producers' header bounding boxes, the stride, and damaged files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "error_of.h"
#include "hand_las.h"
#include "models/temp_dir.h"
#include "scene/las.h"

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace cls;

namespace {

const fs::path kLas = CLS_TEST_DATA "/las/laspy";

json expected(const std::string& file) { return json::parse(read_text_file(kLas / "expected.json")).at(file); }

// The integer a coordinate was stored as.
int64_t unscaled(double v, const LasHeader& h, int axis) {
  return std::llround((v - h.offset[axis]) / h.scale[axis]);
}

void check_against_laspy(const std::string& file) {
  const json e = expected(file);
  const std::string path = (kLas / file).string();
  const LasPoints las = read_las(path);
  const LasHeader& h = las.header;
  EXPECT_EQ(h.version_major, e["version"][0]);
  EXPECT_EQ(h.version_minor, e["version"][1]);
  EXPECT_EQ(h.point_format, e["point_format"]);
  ASSERT_EQ(las.xyz.size(), h.point_count);
  if (e.contains("point_count")) EXPECT_EQ(h.point_count, e["point_count"].get<uint64_t>());
  // Every record read: the points end where the file ends.
  EXPECT_EQ(h.point_offset + h.point_count * h.record_length, fs::file_size(path));
  for (int k = 0; k < 3; ++k) {
    int64_t lo = INT64_MAX, hi = INT64_MIN;
    double dlo = INFINITY, dhi = -INFINITY;
    for (const Vec3d& p : las.xyz) {
      lo = std::min(lo, unscaled(p[k], h, k));
      hi = std::max(hi, unscaled(p[k], h, k));
      dlo = std::min(dlo, p[k]);
      dhi = std::max(dhi, p[k]);
    }
    EXPECT_EQ(lo, e["unscaled_min"][k].get<int64_t>()) << file << " axis " << k;
    EXPECT_EQ(hi, e["unscaled_max"][k].get<int64_t>()) << file << " axis " << k;
    // the producer's bounding box in the header
    EXPECT_NEAR(dlo, h.min[k], h.scale[k]) << file << " axis " << k;
    EXPECT_NEAR(dhi, h.max[k], h.scale[k]) << file << " axis " << k;
  }
  const auto [cmin, cmax] = std::minmax_element(las.classification.begin(), las.classification.end());
  EXPECT_EQ(*cmin, e["classification_range"][0]);
  EXPECT_EQ(*cmax, e["classification_range"][1]);
  if (e.contains("class_counts"))
    for (const auto& [cls_code, count] : e["class_counts"].items())
      EXPECT_EQ(std::count(las.classification.begin(), las.classification.end(), std::stoi(cls_code)), count.get<long>());
  if (e.contains("red")) {
    ASSERT_EQ(las.rgb.size(), las.xyz.size());
    const char* names[] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) {
      const auto [lo, hi] = std::minmax_element(las.rgb.begin(), las.rgb.end(),
                                                [c](const auto& a, const auto& b) { return a[c] < b[c]; });
      EXPECT_EQ((*lo)[c], e[names[c]][0]) << names[c];
      EXPECT_EQ((*hi)[c], e[names[c]][1]) << names[c];
    }
  } else {
    EXPECT_TRUE(las.rgb.empty());
  }
}

}  // namespace

TEST(Las, Version12Format3AsLaspyReadsIt) { check_against_laspy("simple.las"); }

TEST(Las, Version14Format6AsLaspyReadsIt) { check_against_laspy("test1_4.las"); }

TEST(Las, BufferParserAndStreamingReaderAgreeWithAStride) {
  const std::string path = (kLas / "simple.las").string();
  const LasPoints all = read_las(path);
  const std::string bytes = read_text_file(path);
  for (uint64_t stride : {1, 7, 1000, 5000}) {
    const LasPoints streamed = read_las(path, stride), parsed = parse_las(bytes, path, stride);
    ASSERT_EQ(streamed.xyz.size(), (all.xyz.size() + stride - 1) / stride) << stride;
    ASSERT_EQ(parsed.xyz.size(), streamed.xyz.size());
    for (size_t i = 0; i < streamed.xyz.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(streamed.xyz[i][k], all.xyz[i * stride][k]);
        EXPECT_EQ(parsed.xyz[i][k], all.xyz[i * stride][k]);
      }
      EXPECT_EQ(parsed.rgb[i], all.rgb[i * stride]);
    }
  }
}

TEST(Las, DamagedFilesAreRefusedNamingTheFile) {
  const std::string good = read_text_file(kLas / "simple.las");
  auto with = [&](size_t at, const void* v, size_t n) {
    std::string b = good;
    std::memcpy(b.data() + at, v, n);
    return b;
  };
  const uint32_t huge = 0xFFFFFFFFu;
  const uint8_t fmt11 = 11, laz = 0x83;
  const uint16_t short_record = 20;
  const double zero = 0, nan = NAN;
  const std::map<std::string, std::string> cases = {
      {"promises", with(107, &huge, 4)},
      {"truncated LAS", good.substr(0, good.size() - 1)},
      {"format 11", with(104, &fmt11, 1)},
      {"LAZ", with(104, &laz, 1)},
      {"shorter than format 3", with(105, &short_record, 2)},
      {"scale or offset", with(131, &zero, 8)},
      {"not finite", with(155 + 8, &nan, 8)},
      {"LASF", "LASX" + good.substr(4)},
      {"header truncated", good.substr(0, 100)},
  };
  for (const auto& [needle, bytes] : cases) {
    const std::string message = test::error_of([&] { parse_las(bytes, "cloud.las"); });
    EXPECT_NE(message.find("cloud.las"), std::string::npos) << needle << ": " << message;
    EXPECT_NE(message.find(needle), std::string::npos) << needle << ": " << message;
  }
}

TEST(Las, CompressedLazSaysWhatToRun) {
  const std::string message = test::error_of([&] { read_las((kLas / "simple.laz").string()); });
  EXPECT_NE(message.find("simple.laz"), std::string::npos) << message;
  EXPECT_NE(message.find("laszip"), std::string::npos) << message;
}

// Files written byte by byte from the specification's tables (tests/hand_las.h), in the point formats
// labelled clouds come in (1 and 3: LAS 1.2; 6 and 7: LAS 1.4), with a scale and an offset of a
// projected CRS: every point reads back to integer * scale + offset, its class (without the flag bits of
// formats 0-5) and, where the format has them, its colours.
TEST(Las, HandWrittenFormats1367ReadToTheSamePoints) {
  const std::array<double, 3> scale{0.001, 0.002, 0.01}, offset{691000.0, 5335000.0, 500.0};
  std::vector<test::HandLasPoint> points;
  for (int i = 0; i < 37; ++i) {
    test::HandLasPoint p;
    p.x = -20000 + 1234 * i;
    p.y = 7 * i * i - 300;
    p.z = (i % 5) * 100000 - 1;
    p.classification = uint8_t((i * 7) % 31);
    p.flag_bits = uint8_t(i % 8);
    p.rgb = {uint16_t(i * 1000), uint16_t(65535 - i), uint16_t(i * 257)};
    points.push_back(p);
  }
  test::TempDir dir("las_hand");
  for (int format : {1, 3, 6, 7}) {
    const fs::path path = dir.path / ("f" + std::to_string(format) + ".las");
    write_text_atomic(path, test::hand_las(format, points, scale, offset));
    const LasPoints las = read_las(path.string());
    EXPECT_EQ(las.header.point_format, format);
    EXPECT_EQ(las.header.version_minor, format >= 6 ? 4 : 2);
    ASSERT_EQ(las.xyz.size(), points.size()) << format;
    ASSERT_EQ(las.classification.size(), points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const test::HandLasPoint& p = points[i];
      EXPECT_EQ(las.xyz[i][0], p.x * scale[0] + offset[0]) << format << " point " << i;
      EXPECT_EQ(las.xyz[i][1], p.y * scale[1] + offset[1]) << format << " point " << i;
      EXPECT_EQ(las.xyz[i][2], p.z * scale[2] + offset[2]) << format << " point " << i;
      EXPECT_EQ(las.classification[i], p.classification) << format << " point " << i;
    }
    const bool colour = format == 3 || format == 7;
    ASSERT_EQ(las.rgb.size(), colour ? points.size() : 0u) << format;
    if (colour)  // 16-bit colours (some above 255): scaled to 8 bits
      for (size_t i = 0; i < points.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(las.rgb[i][c], (points[i].rgb[c] + 128) / 257) << format << " point " << i;
    EXPECT_TRUE(las.field.empty());
  }
}

// A label in an extra-bytes field (as labelled MLS clouds store it), after undocumented extra bytes.
TEST(Las, AnExtraBytesFieldIsReadByName) {
  std::vector<test::HandLasPoint> points(5);
  for (size_t i = 0; i < points.size(); ++i) points[i].label = uint16_t(300 + i * 11), points[i].x = int32_t(i);
  test::TempDir dir("las_extra");
  for (int format : {1, 6}) {
    const fs::path path = dir.path / ("f" + std::to_string(format) + ".las");
    write_text_atomic(path, test::hand_las(format, points, {0.01, 0.01, 0.01}, {0, 0, 0}, true));
    const LasPoints las = read_las(path.string(), 1, "label");
    ASSERT_EQ(las.header.extra_fields.size(), 1u);  // the undocumented bytes are no field
    EXPECT_EQ(las.header.extra_fields[0].name, "label");
    ASSERT_EQ(las.field.size(), points.size());
    for (size_t i = 0; i < points.size(); ++i) EXPECT_EQ(las.field[i], points[i].label) << format;
    EXPECT_EQ(las.xyz[3][0], 0.03);
    const LasPoints strided = parse_las(read_text_file(path), path.string(), 2, "label");
    ASSERT_EQ(strided.field.size(), 3u);
    EXPECT_EQ(strided.field[2], points[4].label);
    const std::string message = test::error_of([&] { read_las(path.string(), 1, "class"); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("no extra-bytes field 'class' (it has: label"), std::string::npos) << message;
  }
}

// A real file with extra bytes (PDAL's writer, laspy's test data): arrays and undocumented bytes before the
// scalar fields. PDAL copied each record's intensity into "Intensity" and its GPS time, truncated, into
// "Time": the record's own bytes, read here without the reader, are the truth.
TEST(Las, PdalsExtraBytesReadAsTheRecordsOwnFields) {
  const std::string path = (kLas / "extrabytes.las").string();
  const std::string bytes = read_text_file(path);
  const LasHeader h = read_las_header(path);
  std::vector<std::string> names;
  for (const LasExtraField& f : h.extra_fields) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"Intensity", "Time"}));  // Colors, Reserved, Flags: not scalars
  const LasPoints intensity = read_las(path, 1, "Intensity"), time = read_las(path, 1, "Time");
  ASSERT_EQ(intensity.field.size(), h.point_count);
  ASSERT_EQ(time.field.size(), h.point_count);
  for (uint64_t i = 0; i < h.point_count; ++i) {
    const char* r = bytes.data() + h.point_offset + i * h.record_length;
    uint16_t record_intensity;
    double gps_time;
    std::memcpy(&record_intensity, r + 12, 2);
    std::memcpy(&gps_time, r + 20, 8);
    EXPECT_EQ(intensity.field[i], record_intensity) << i;
    EXPECT_EQ(time.field[i], std::floor(gps_time)) << i;
  }
  EXPECT_NE(test::error_of([&] { read_las(path, 1, "Colors"); }).find("(it has: Intensity, Time;"), std::string::npos);
}
