#include "models/sam_amg/small_regions.h"

#include <opencv2/imgproc.hpp>
#include <vector>

namespace cls::amg {

bool remove_small_regions(BinaryMask& mask, int64_t min_area, SmallRegionMode mode) {
  if (mask.height == 0 || mask.width == 0) return false;
  const bool holes = mode == SmallRegionMode::Holes;
  cv::Mat working(mask.height, mask.width, CV_8U);
  for (int y = 0; y < mask.height; ++y) {
    uint8_t* row = working.ptr<uint8_t>(y);
    for (int x = 0; x < mask.width; ++x) row[x] = static_cast<uint8_t>((mask.at(y, x) != 0) != holes);
  }
  cv::Mat labels, stats, centroids;
  const int n_labels = cv::connectedComponentsWithStats(working, labels, stats, centroids, 8, CV_32S);
  // fill[label]: whether pixels of that label end up set. Label 0 is the background of `working`.
  std::vector<char> small(n_labels, 0);
  bool any_small = false;
  for (int l = 1; l < n_labels; ++l)
    if (stats.at<int>(l, cv::CC_STAT_AREA) < min_area) small[l] = 1, any_small = true;
  if (!any_small) return false;

  std::vector<char> fill(n_labels, 0);
  if (holes) {
    fill[0] = 1;  // the mask itself
    for (int l = 1; l < n_labels; ++l) fill[l] = small[l];
  } else {
    bool any = false;
    for (int l = 1; l < n_labels; ++l) fill[l] = !small[l], any = any || fill[l];
    if (!any) {  // every island is small: keep the largest (np.argmax: first maximum)
      int best = 1;
      for (int l = 2; l < n_labels; ++l)
        if (stats.at<int>(l, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA)) best = l;
      fill[best] = 1;
    }
  }
  for (int y = 0; y < mask.height; ++y) {
    const int* row = labels.ptr<int>(y);
    for (int x = 0; x < mask.width; ++x)
      mask.pixels[static_cast<size_t>(y) * mask.width + x] = fill[row[x]] ? 1 : 0;
  }
  return true;
}

}  // namespace cls::amg
