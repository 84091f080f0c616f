#pragma once
// Helpers shared by the scene tests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <exiv2/exiv2.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <map>

#include "core/error.h"
#include "core/math.h"
#include "scene/undistort.h"

namespace cls::test {

// Expects `fn` to throw a cls::Error whose message contains every one of `parts`.
inline void expect_error(const std::function<void()>& fn, const std::vector<std::string>& parts) {
  try {
    fn();
    ADD_FAILURE() << "expected a cls::Error";
  } catch (const Error& e) {
    const std::string msg = e.what();
    for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
  }
}

// A small photo (JPEG or PNG by the name) with the given EXIF tags, written by libexiv2 as a camera
// writes them: key -> value in exiv2's text form, e.g. {"Exif.GPSInfo.GPSLatitude", "48/1 51/1 296/10"}, or
// "ascii:TEXT" for a tag written as text whatever its type should be.
inline std::filesystem::path photo_with_exif(const std::filesystem::path& dir, const std::string& name,
                                             const std::map<std::string, std::string>& tags) {
  const std::filesystem::path path = dir / name;
  EXPECT_TRUE(cv::imwrite(path.string(), cv::Mat(30, 40, CV_8UC3, cv::Scalar(40, 90, 160))));
  if (tags.empty()) return path;
  auto image = Exiv2::ImageFactory::open(path.string());
  image->readMetadata();
  Exiv2::ExifData exif;
  for (const auto& [key, value] : tags) {
    if (value.rfind("ascii:", 0) == 0) {  // a tag written with the wrong type, as some tools do
      Exiv2::AsciiValue text(value.substr(6));
      exif.add(Exiv2::ExifKey(key), &text);
    } else {
      exif[key] = value;
    }
  }
  image->setExifData(exif);
  image->writeMetadata();
  return path;
}

inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("cls_test_scene_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// A checkerboard on the normalized image plane: squares of side `kSquare` (camera units).
constexpr double kSquare = 0.1;
inline uint8_t checker(double x, double y) {
  return ((static_cast<long>(std::floor(x / kSquare)) + static_cast<long>(std::floor(y / kSquare))) & 1) ? 255 : 0;
}
// Distance (in normalized units) from (x, y) to the nearest checker edge.
inline double checker_edge_distance(double x, double y) {
  auto d = [](double t) { return std::abs(t / kSquare - std::round(t / kSquare)) * kSquare; };
  return std::min(d(x), d(y));
}

// What a camera with this lens photographs of the checkerboard: each pixel takes the colour at
// its centre's undistorted position. 8-bit BGR.
inline cv::Mat distorted_checkerboard(const LensCamera& lens) {
  cv::Mat img(lens.height, lens.width, CV_8UC3);
  for (int j = 0; j < lens.height; ++j)
    for (int i = 0; i < lens.width; ++i) {
      double x, y;
      undistort_normalized(lens.distortion, (i + 0.5 - lens.cx) / lens.fx, (j + 0.5 - lens.cy) / lens.fy, x, y);
      const uint8_t c = checker(x, y);
      img.at<cv::Vec3b>(j, i) = cv::Vec3b(c, c, c);
    }
  return img;
}

// Compares an undistorted image with the analytic checkerboard of its pinhole camera at pixels
// at least `margin_px` from an edge; returns the fraction of pixels that were compared.
inline double expect_matches_checkerboard(const cv::Mat& img, const PinholeCamera& cam, double margin_px,
                                          int tolerance) {
  EXPECT_EQ(img.cols, cam.width);
  EXPECT_EQ(img.rows, cam.height);
  long compared = 0, wrong = 0;
  for (int j = 0; j < img.rows; ++j)
    for (int i = 0; i < img.cols; ++i) {
      const double x = (i + 0.5 - cam.cx) / cam.fx, y = (j + 0.5 - cam.cy) / cam.fy;
      if (checker_edge_distance(x, y) * std::min(cam.fx, cam.fy) < margin_px) continue;
      ++compared;
      const cv::Vec3b p = img.at<cv::Vec3b>(j, i);
      if (std::abs(int(p[1]) - int(checker(x, y))) > tolerance) ++wrong;
    }
  EXPECT_EQ(wrong, 0) << "of " << compared << " compared pixels";
  return double(compared) / (double(img.rows) * img.cols);
}

template <class T>
inline void put_bytes(std::string& s, size_t at, T v) {
  std::memcpy(&s[at], &v, sizeof v);
}

// LAS 1.2, point format 2 (x, y, z, ..., red, green, blue: 26 bytes), scale 1 mm, holding `points`
// (output CRS coordinates) with 16-bit colours 257 * (10 i, 20 i, 30 i).
inline std::string las_file(const std::vector<Vec3d>& points, size_t first_index) {
  const size_t header = 227, record = 26;
  std::string s(header + points.size() * record, '\0');
  std::memcpy(&s[0], "LASF", 4);
  s[24] = 1, s[25] = 2;
  put_bytes<uint16_t>(s, 94, header);
  put_bytes<uint32_t>(s, 96, header);
  s[104] = 2;
  put_bytes<uint16_t>(s, 105, record);
  put_bytes<uint32_t>(s, 107, static_cast<uint32_t>(points.size()));
  const Vec3d scale{0.001, 0.001, 0.001}, offset{356000, 5645000, 0};
  for (int k = 0; k < 3; ++k) put_bytes(s, 131 + 8 * k, scale[k]), put_bytes(s, 155 + 8 * k, offset[k]);
  for (size_t i = 0; i < points.size(); ++i) {
    const size_t at = header + i * record;
    for (int k = 0; k < 3; ++k)
      put_bytes<int32_t>(s, at + 4 * k, static_cast<int32_t>(std::llround((points[i][k] - offset[k]) / scale[k])));
    const size_t n = first_index + i;
    for (int c = 0; c < 3; ++c) put_bytes<uint16_t>(s, at + 20 + 2 * c, static_cast<uint16_t>(257 * 10 * (c + 1) * n));
  }
  return s;
}

}  // namespace cls::test
