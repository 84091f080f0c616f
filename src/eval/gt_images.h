#pragma once
// 2D ground truth as labelled images: one mask per photo, as annotation tools and facade datasets deliver
// them, read into a view's undistorted frame at its loaded size.
#include <optional>
#include <string>
#include <vector>

#include "eval/class_map.h"
#include "scene/scene.h"

namespace cls {

// DIR/<the photo's name with .png>: single-channel 8- or 16-bit PNG of the photo's own size (the source
// camera's). Values: taxonomy id + 1 (0 = no label; what `synth` writes in SCENE/gt/labels), or a user's
// codes when `map` is given (class_map.h). Undistorted as the photo is (nearest neighbour: labels do not
// blend) and scaled (nearest) to the view's size. Returns H x W taxonomy ids (-1 = none), or nothing when
// DIR has no mask of this view. cls::Error naming the file for another size, channels or depth, or a code
// the map lacks.
std::optional<std::vector<int32_t>> read_gt_image(const std::string& dir, const SceneView& view,
                                                  const ClassMap* map = nullptr);

}  // namespace cls
