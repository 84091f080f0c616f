#pragma once
// Images of a scene, loaded one view at a time: a scene of 1,000 photos never sits in memory.
// Each load reads the source file, undistorts it into the view's pinhole camera at full
// resolution (undistort.h) and downscales it to the loaded resolution with cv::INTER_AREA.
// The only state kept between loads is a small cache of undistortion maps, one per lens.
#include <array>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <utility>

#include <opencv2/core.hpp>

#include "scene/scene.h"
#include "scene/undistort.h"

namespace cls {

// The loaded-resolution camera for an undistorted full-resolution camera, by 3DGS's rules:
// -r N gives round(W / N) x round(H / N) (round half to even, as Python's round), a target width
// T gives T x int(H / (W / T)), and with neither a long side L over max_side M gives
// int(W / (L / M)) x int(H / (L / M)); intrinsics scale with the image (pixel edges stay aligned, so
// f and c scale by new_size / old_size per axis). Bad options are a cls::Error.
PinholeCamera scale_to_resolution(const PinholeCamera& full, const SceneOptions& options);
void check_scene_options(const SceneOptions& options);

class ImageLoader {
 public:
  explicit ImageLoader(size_t max_cached_lenses = 4) : max_cached_(max_cached_lenses) {}

  // The view's image as 8-bit BGR at view.camera's size. A missing, unreadable or wrongly sized
  // image is a cls::Error naming the file. Thread-safe.
  cv::Mat load(const SceneView& view);

 private:
  using LensKey = std::array<double, 11>;
  struct CachedMaps {
    PinholeCamera undistorted;  // full-resolution target of the maps
    UndistortMaps maps;
  };
  std::shared_ptr<const CachedMaps> maps_for(const LensCamera& lens, const std::string& image_path);

  size_t max_cached_;
  std::mutex mutex_;
  std::list<std::pair<LensKey, std::shared_ptr<const CachedMaps>>> cache_;  // most recently used first
};

}  // namespace cls
