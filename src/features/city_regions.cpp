#include "features/city_regions.h"

#include <ATen/ATen.h>
#include <opencv2/imgproc.hpp>

#include <map>
#include <set>
#include <tuple>

#include "core/error.h"

namespace cls {

namespace {

void check_map(const cv::Mat& m, int type, int h, int w, const std::string& what, const char* name) {
  if (m.type() != type || m.rows != h || m.cols != w)
    throw Error(what + ": " + name + " must be " + (type == CV_16UC1 ? "16-bit" : "8-bit") + " single-channel " +
                std::to_string(w) + " x " + std::to_string(h));
}

}  // namespace

CityRegionSet extract_city_regions(const std::array<cv::Mat, 3>& labels, const cv::Mat& coverage, const cv::Mat& building,
                                   RegionMode mode, const Taxonomy& taxonomy, int min_pixels, const std::string& what) {
  const int h = coverage.rows, w = coverage.cols;
  check_map(coverage, CV_8UC1, h, w, what, "coverage");
  for (const cv::Mat& l : labels) check_map(l, CV_16UC1, h, w, what, "level map");
  if (mode == RegionMode::Instance) check_map(building, CV_16UC1, h, w, what, "building map");
  const size_t hw = size_t(h) * w;
  const int num_classes = static_cast<int>(taxonomy.classes.size());

  CityRegionSet out;
  out.seg.assign(3 * hw, -1);
  for (int level = 1; level <= 3; ++level) {
    const cv::Mat& lab = labels[level - 1];
    // Groups: (class, building) -> a 0/255 mask; building = -1 in class mode.
    std::map<std::pair<int, int>, cv::Mat> groups;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int k = lab.at<uint16_t>(y, x);
        if (k == 0 || !coverage.at<uint8_t>(y, x)) continue;
        if (k > num_classes)
          throw Error(what + ": level-" + std::to_string(level) + " label " + std::to_string(k) + " at (" + std::to_string(x) +
                      ", " + std::to_string(y) + ") is not a class of the taxonomy (" + std::to_string(num_classes) +
                      " classes)");
        const int b = mode == RegionMode::Instance ? int(building.at<uint16_t>(y, x)) - 1 : -1;
        cv::Mat& m = groups[{k - 1, b}];
        if (m.empty()) m = cv::Mat::zeros(h, w, CV_8UC1);
        m.at<uint8_t>(y, x) = 255;
      }
    std::map<int, int64_t> next_instance;  // per class: instance counter over buildings
    for (const auto& [key, mask] : groups) {
      const auto [class_id, b] = key;
      std::vector<cv::Mat> parts;
      if (mode == RegionMode::Class) {
        parts.push_back(mask);
      } else {
        cv::Mat comp;
        const int n = cv::connectedComponents(mask, comp, 8, CV_32S);  // labels in raster order of first pixel
        for (int c = 1; c < n; ++c) parts.push_back(comp == c);
      }
      for (const cv::Mat& part : parts) {
        const int64_t pixels = cv::countNonZero(part);
        if (pixels < min_pixels) continue;
        const int32_t id = static_cast<int32_t>(out.regions.size());
        CityRegion r;
        r.level = level;
        r.class_id = class_id;
        r.class_name = taxonomy.classes[class_id].name;
        r.pixels = pixels;
        if (mode == RegionMode::Instance) {
          r.instance = next_instance[class_id]++;
          r.building = b;
        }
        out.regions.push_back(r);
        RegionMask rm;
        rm.mask = part;
        rm.level = level;
        rm.class_id = class_id;
        out.masks.push_back(rm);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            if (part.at<uint8_t>(y, x)) out.seg[(size_t(level - 1) * h + y) * w + x] = id;
      }
    }
  }
  return out;
}

at::Tensor fuse_features(const at::Tensor& gml, const at::Tensor& txt, double alpha) {
  if (alpha < 0 || alpha > 1) throw Error("fusion weight alpha must be in [0, 1], got " + std::to_string(alpha));
  if (!gml.sizes().equals(txt.sizes())) throw Error("fuse_features: image and text features differ in shape");
  if (gml.size(0) == 0) return gml.to(at::kFloat);
  const at::Tensor f = (1.0 - alpha) * gml.to(at::kFloat) + alpha * txt.to(at::kFloat);
  // A zero sum (opposite directions at alpha = 0.5) has no direction: leave it zero, not NaN.
  return f / f.norm(2, 1, true).clamp_min(1e-12);
}

}  // namespace cls
