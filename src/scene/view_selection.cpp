#include "scene/view_selection.h"

#include <algorithm>
#include <filesystem>

#include "core/error.h"

namespace cls {
namespace fs = std::filesystem;

std::string view_stem(const std::string& name) {
  std::string s = fs::path(name).replace_extension().string();
  std::replace(s.begin(), s.end(), '/', '_');
  return s;
}

std::vector<const SceneView*> find_views(const Scene& scene, const std::vector<std::string>& names,
                                         const std::string& command) {
  std::vector<const SceneView*> out;
  if (names.empty()) {
    for (const auto& v : scene.views) out.push_back(&v);
    return out;
  }
  for (const auto& n : names) {
    const SceneView* found = nullptr;
    for (const auto& v : scene.views)
      if (v.name == n || fs::path(v.name).replace_extension().string() == n) found = &v;
    if (!found) {
      std::string known;
      for (size_t i = 0; i < scene.views.size() && i < 5; ++i) known += (i ? ", " : "") + scene.views[i].name;
      if (scene.views.size() > 5) known += ", ...";
      throw UsageError(command + ": no view named '" + n + "' in " + scene.root + " (views: " + known + ")");
    }
    out.push_back(found);
  }
  return out;
}

ViewSplit split_views(const Scene& scene, int test_every) {
  std::vector<const SceneView*> sorted;
  for (const SceneView& v : scene.views) sorted.push_back(&v);
  std::stable_sort(sorted.begin(), sorted.end(), [](const SceneView* a, const SceneView* b) { return a->name < b->name; });
  ViewSplit split;
  for (size_t i = 0; i < sorted.size(); ++i)
    (test_every > 0 && i % size_t(test_every) == 0 ? split.test : split.train).push_back(sorted[i]);
  return split;
}

}  // namespace cls
