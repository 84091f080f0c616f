#include "scene/image_loader.h"

#include <cmath>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "scene/path_query.h"
#include "core/log.h"

namespace cls {
namespace fs = std::filesystem;

void check_scene_options(const SceneOptions& options) {
  const int r = options.resolution_factor;
  if (r != 1 && r != 2 && r != 4 && r != 8)
    throw Error("resolution factor must be 1, 2, 4 or 8, not " + std::to_string(r));
  if (options.target_width < 0) throw Error("target width must not be negative");
  if (options.max_side < 0) throw Error("the longest image side must not be negative");
  if (options.max_height < 0) throw Error("the largest image height must not be negative");
  if (options.target_width > 0 && r != 1) throw Error("give either a resolution factor or a target width, not both");
}

PinholeCamera scale_to_resolution(const PinholeCamera& full, const SceneOptions& options) {
  check_scene_options(options);
  int w, h;
  const int long_side = std::max(full.width, full.height);
  if (options.target_width > 0) {
    const double global_down = double(full.width) / options.target_width;
    w = options.target_width;
    h = static_cast<int>(full.height / global_down);
  } else if (options.resolution_factor == 1 && ((options.max_side > 0 && long_side > options.max_side) ||
                                                  (options.max_height > 0 && full.height > options.max_height))) {
    // 3DGS and LangSplat truncate, as here.
    const double global_down = std::max(options.max_side > 0 ? double(long_side) / options.max_side : 1.0,
                                        options.max_height > 0 ? double(full.height) / options.max_height : 1.0);
    w = static_cast<int>(full.width / global_down);
    h = static_cast<int>(full.height / global_down);
  } else {
    // std::nearbyint rounds half to even in the default rounding mode, like Python's round().
    w = static_cast<int>(std::nearbyint(double(full.width) / options.resolution_factor));
    h = static_cast<int>(std::nearbyint(double(full.height) / options.resolution_factor));
  }
  w = std::max(w, 1);
  h = std::max(h, 1);
  const double sx = double(w) / full.width, sy = double(h) / full.height;
  return PinholeCamera{full.fx * sx, full.fy * sy, full.cx * sx, full.cy * sy, w, h};
}

std::shared_ptr<const ImageLoader::CachedMaps> ImageLoader::maps_for(const LensCamera& lens,
                                                                     const std::string& image_path) {
  const LensKey key{lens.fx,
                    lens.fy,
                    lens.cx,
                    lens.cy,
                    lens.distortion.k1,
                    lens.distortion.k2,
                    lens.distortion.k3,
                    lens.distortion.p1,
                    lens.distortion.p2,
                    double(lens.width),
                    double(lens.height)};
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = cache_.begin(); it != cache_.end(); ++it)
    if (it->first == key) {
      cache_.splice(cache_.begin(), cache_, it);
      return cache_.front().second;
    }
  auto entry = std::make_shared<CachedMaps>();
  entry->undistorted = undistorted_pinhole(lens, image_path);
  entry->maps = undistortion_maps(lens, entry->undistorted);
  cache_.emplace_front(key, entry);
  if (cache_.size() > max_cached_) cache_.pop_back();
  return entry;
}

cv::Mat ImageLoader::load(const SceneView& view) {
  const std::string& path = view.image_path;
  if (!is_file(path)) fail(path, "image not found (view '" + view.name + "')");
  auto decode = [&path](int flags) {
    cv::Mat m;
    try {
      m = cv::imread(path, flags);
    } catch (const cv::Exception& e) {
      fail(path, std::string("cannot decode image: ") + e.what());
    }
    if (m.empty()) fail(path, "cannot decode image (corrupt file or unsupported format)");
    return m;
  };
  // The pixels as stored: COLMAP (3.7 on) and Pix4D calibrate them so, whatever a phone's EXIF
  // Orientation says. A calibration of the turned photo (a tool that applied the tag) is met too: the
  // turned decode is taken when it, not the stored one, has the camera's size.
  const Camera& cam = view.source_camera;
  auto fits = [&cam](const cv::Mat& m) { return m.cols == cam.width && m.rows == cam.height; };
  cv::Mat image = decode(cv::IMREAD_COLOR | cv::IMREAD_IGNORE_ORIENTATION);
  if (!fits(image)) {
    cv::Mat turned = decode(cv::IMREAD_COLOR);
    if (fits(turned)) image = turned;
  }
  if (!fits(image))
    fail(path, "image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) + " but camera " +
                   std::to_string(cam.id) + " is " + std::to_string(cam.width) + "x" + std::to_string(cam.height));

  const LensCamera lens = lens_from_camera(cam, view.source_radial_k3);
  if (!lens.distortion.is_zero()) image = undistort_image(image, maps_for(lens, path)->maps);
  if (image.cols != view.camera.width || image.rows != view.camera.height) {
    cv::Mat resized;
    cv::resize(image, resized, cv::Size(view.camera.width, view.camera.height), 0, 0, cv::INTER_AREA);
    image = resized;
  }
  return image;
}

}  // namespace cls
