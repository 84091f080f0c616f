#include "language/provenance.h"

#include <ATen/ATen.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "raycast/label_export.h"
#include "raycast/label_map_io.h"

namespace cls {
namespace fs = std::filesystem;

nlohmann::json GaussianProvenance::summary(const ProvenanceSettings& s) const {
  return {{"gaussians", object.size()},
          {"assigned", assigned},
          {"views", views},
          {"rule", "majority of the label maps' finest city object at the Gaussian's centre over the views where "
                   "the centre lies on the first hit (|z - depth| <= max(relative * depth, scale * max scale))"},
          {"relative_depth_tolerance", s.relative_depth_tolerance},
          {"scale_tolerance", s.scale_tolerance}};
}

GaussianProvenance assign_provenance(const GaussianModel& gaussians, const Scene& scene, const fs::path& labels_dir,
                                     const ProvenanceSettings& settings) {
  const int64_t n = gaussians.size();
  const at::Tensor means = gaussians.means.detach().to(at::kCPU, at::kFloat).contiguous();
  const at::Tensor max_scale = std::get<0>(gaussians.scales().detach().to(at::kCPU, at::kFloat).max(1)).contiguous();
  const float* m = means.data_ptr<float>();
  const float* ms = max_scale.data_ptr<float>();

  // Votes per Gaussian as (object, count); a Gaussian sees few objects, so a short list is enough.
  std::vector<std::vector<std::pair<int32_t, int32_t>>> votes(n);
  const std::vector<fs::path> dirs = label_map_dirs(scene, labels_dir);
  Progress progress("provenance", scene.views.size(), "views");
  for (size_t k = 0; k < scene.views.size(); ++k) {
    const SceneView& view = scene.views[k];
    const int W = view.camera.width, H = view.camera.height;
    const auto [object, depth] = read_view_hits(dirs[k], W, H);
    const Mat3d& R = view.pose.R;
    const Vec3d& t = view.pose.t;
    const PinholeCamera& c = view.camera;
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < n; ++i) {
      const double x = m[3 * i], y = m[3 * i + 1], z = m[3 * i + 2];
      const double xc = R.m[0][0] * x + R.m[0][1] * y + R.m[0][2] * z + t.x;
      const double yc = R.m[1][0] * x + R.m[1][1] * y + R.m[1][2] * z + t.y;
      const double zc = R.m[2][0] * x + R.m[2][1] * y + R.m[2][2] * z + t.z;
      if (!(zc > 0)) continue;
      const double u = std::floor(c.fx * xc / zc + c.cx), v = std::floor(c.fy * yc / zc + c.cy);
      if (!(u >= 0 && u < W && v >= 0 && v < H)) continue;
      const size_t p = static_cast<size_t>(v) * W + static_cast<size_t>(u);
      const double d = depth.data[p];
      if (!(d > 0)) continue;  // the ray hits nothing of the city model
      if (std::abs(zc - d) > std::max(settings.relative_depth_tolerance * d, settings.scale_tolerance * ms[i])) continue;
      auto& list = votes[i];
      const auto it = std::find_if(list.begin(), list.end(), [&](const auto& e) { return e.first == object[p]; });
      if (it == list.end()) list.emplace_back(object[p], 1);
      else ++it->second;
    }
    progress.advance();
  }
  progress.finish();

  GaussianProvenance result;
  result.views = scene.views.size();
  result.object.assign(n, -1);
  result.support.assign(n, 0.0f);
  for (int64_t i = 0; i < n; ++i) {
    int32_t best = -1, best_votes = 0, none_votes = 0, total = 0;
    for (const auto& [obj, count] : votes[i]) {
      total += count;
      if (obj < 0) none_votes += count;
      else if (count > best_votes || (count == best_votes && obj < best)) best = obj, best_votes = count;
    }
    if (best >= 0 && best_votes >= none_votes) {
      result.object[i] = best;
      result.support[i] = static_cast<float>(best_votes) / total;
      ++result.assigned;
    } else if (total > 0) {
      result.support[i] = static_cast<float>(none_votes) / total;
    }
  }
  return result;
}

void attach_provenance(GaussianModel& gaussians, const GaussianProvenance& p) {
  const int64_t n = gaussians.size();
  if (static_cast<int64_t>(p.object.size()) != n || static_cast<int64_t>(p.support.size()) != n)
    throw Error(cat("provenance of ", p.object.size(), " Gaussians for a model of ", n));
  auto& extras = gaussians.extras;
  extras.erase(std::remove_if(extras.begin(), extras.end(),
                              [](const GaussianExtra& e) { return e.name == kObjectProperty || e.name == kObjectSupportProperty; }),
               extras.end());
  extras.push_back({kObjectProperty, at::tensor(at::ArrayRef<int32_t>(p.object), at::kInt).clone()});
  extras.push_back({kObjectSupportProperty, at::tensor(at::ArrayRef<float>(p.support), at::kFloat).clone()});
}

}  // namespace cls
