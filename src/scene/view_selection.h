#pragma once
// Which of a scene's views a stage works on, and what their files are called.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace cls {

// A view name as a file stem: sub-folders joined with '_', extension dropped ("a/0001.png" -> "a_0001").
std::string view_stem(const std::string& name);

// The views named in `names` (full names or names without extension), in that order; every view
// when `names` is empty. cls::UsageError "<command>: no view named ..." listing some known views.
std::vector<const SceneView*> find_views(const Scene& scene, const std::vector<std::string>& names,
                                         const std::string& command);

// The train/test split of 3DGS's llffhold: views sorted by name, index % test_every == 0 held out
// for testing (test_every = 0: all views train).
struct ViewSplit {
  std::vector<const SceneView*> train, test;  // each sorted by name
};
ViewSplit split_views(const Scene& scene, int test_every);

}  // namespace cls
