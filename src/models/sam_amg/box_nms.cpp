#include "models/sam_amg/box_nms.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"

namespace cls::amg {

std::vector<int> box_nms(const std::vector<BoxF>& boxes, const std::vector<float>& scores,
                         double iou_threshold) {
  if (boxes.size() != scores.size()) throw Error("box_nms: boxes and scores differ in length");
  const size_t n = boxes.size();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return scores[a] > scores[b]; });
  std::vector<float> areas(n);
  for (size_t i = 0; i < n; ++i) areas[i] = (boxes[i][2] - boxes[i][0]) * (boxes[i][3] - boxes[i][1]);

  std::vector<char> suppressed(n, 0);
  std::vector<int> keep;
  for (size_t oi = 0; oi < n; ++oi) {
    const int i = order[oi];
    if (suppressed[i]) continue;
    keep.push_back(i);
    const BoxF& a = boxes[i];
    for (size_t oj = oi + 1; oj < n; ++oj) {
      const int j = order[oj];
      if (suppressed[j]) continue;
      const BoxF& b = boxes[j];
      const float xx1 = std::max(a[0], b[0]), yy1 = std::max(a[1], b[1]);
      const float xx2 = std::min(a[2], b[2]), yy2 = std::min(a[3], b[3]);
      const float w = std::max(0.0f, xx2 - xx1), h = std::max(0.0f, yy2 - yy1);
      const float inter = w * h;
      const float ovr = inter / (areas[i] + areas[j] - inter);
      if (static_cast<double>(ovr) > iou_threshold) suppressed[j] = 1;
    }
  }
  return keep;
}

}  // namespace cls::amg
