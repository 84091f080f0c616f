#include "eval/gt_images.h"

#include <climits>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "scene/undistort.h"

namespace cls {
namespace fs = std::filesystem;

std::optional<std::vector<int32_t>> read_gt_image(const std::string& dir, const SceneView& view, const ClassMap* map) {
  const fs::path file = fs::path(dir) / fs::path(view.name).replace_extension(".png");
  if (!fs::is_regular_file(file)) return std::nullopt;
  cv::Mat mask = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (mask.empty()) fail(file.string(), "not a readable PNG");
  if (mask.channels() != 1 || (mask.depth() != CV_8U && mask.depth() != CV_16U))
    fail(file.string(), "a label image must be one channel of 8 or 16 bits (" + std::to_string(mask.channels()) +
                            " channels here): one class code per pixel, not a colour picture");
  const LensCamera lens = lens_from_camera(view.source_camera, view.source_radial_k3);
  if (mask.cols != lens.width || mask.rows != lens.height)
    fail(file.string(), "label image of " + std::to_string(mask.cols) + "x" + std::to_string(mask.rows) +
                            ", the photo " + view.name + " is " + std::to_string(lens.width) + "x" +
                            std::to_string(lens.height));
  if (mask.depth() == CV_8U) mask.convertTo(mask, CV_16U);
  if (!lens.distortion.is_zero()) {  // as the photo is undistorted, but without blending codes
    const UndistortMaps maps = undistortion_maps(lens, undistorted_pinhole(lens, view.image_path));
    cv::Mat out;
    cv::remap(mask, out, maps.map_x, maps.map_y, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
    mask = out;
  }
  if (mask.cols != view.camera.width || mask.rows != view.camera.height) {
    cv::Mat out;
    cv::resize(mask, out, cv::Size(view.camera.width, view.camera.height), 0, 0, cv::INTER_NEAREST);
    mask = out;
  }
  // Every 16-bit code's class, once: taxonomy id + 1 without a map, the map's class (kUnmapped: none) with one.
  constexpr int32_t kUnmapped = INT32_MIN;
  std::vector<int32_t> class_of(65536, kUnmapped);
  for (int32_t v = 0; v < 65536; ++v)
    if (!map) class_of[size_t(v)] = v - 1;
    else if (const auto it = map->classes.find(v); it != map->classes.end()) class_of[size_t(v)] = it->second;
  std::vector<int32_t> ids(size_t(mask.rows) * size_t(mask.cols));
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) {
      const uint16_t v = mask.at<uint16_t>(y, x);
      if (class_of[v] == kUnmapped)
        fail(file.string(), "label value " + std::to_string(v) + " is not in the class map " + map->file +
                                ": add it there (null leaves its pixels unlabelled)");
      ids[size_t(y) * size_t(mask.cols) + size_t(x)] = class_of[v];
    }
  return ids;
}

}  // namespace cls
