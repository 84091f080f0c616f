#pragma once
// torchvision.ops.nms / batched_nms (all-zero categories) on CPU, as SAM's AMG calls it.
#include <array>
#include <vector>

namespace cls::amg {

using BoxF = std::array<float, 4>;  // XYXY, float32 as torchvision sees them

// Visits boxes in descending score with a *stable* sort (ties: lower index first), keeps a box
// unless an already kept box overlaps it with IoU > iou_threshold (float32 IoU compared in double;
// area = (x2 - x1) * (y2 - y1), no +1). Returns the kept indices in visiting order.
// This is torchvision's path for <= 1000 boxes on CPU; beyond that torchvision's per-class path
// keeps the same set but may order tied scores differently (see the fixtures README, item 14).
std::vector<int> box_nms(const std::vector<BoxF>& boxes, const std::vector<float>& scores,
                         double iou_threshold);

}  // namespace cls::amg
