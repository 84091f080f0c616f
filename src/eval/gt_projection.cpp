#include "eval/gt_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "eval/kd_tree.h"

namespace cls {

double estimate_point_spacing(const LabelledPoints& points, size_t samples) {
  const size_t n = points.size();
  if (n < 2) return 0;
  const KdTree tree(points.positions);
  const size_t m = std::min(n, std::max<size_t>(samples, 1));
  std::vector<double> d;
  d.reserve(m);
  for (size_t k = 0; k < m; ++k) {
    const size_t i = k * n / m;
    const NearestHit hit = tree.nearest(points.positions[i], std::numeric_limits<double>::infinity(), int64_t(i));
    if (hit.index >= 0) d.push_back(hit.distance);
  }
  if (d.empty()) return 0;
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

double footprint_radius(const LabelledPoints& points, const GtProjectionOptions& options) {
  if (options.point_radius > 0) return options.point_radius;
  return options.spacing_factor * estimate_point_spacing(points);
}

cv::Mat project_gt_labels(const LabelledPoints& points, const PinholeCamera& camera, const Pose& pose,
                          double radius, const GtProjectionOptions& options, cv::Mat* depth, cv::Mat* winner) {
  const int W = camera.width, H = camera.height;
  cv::Mat labels(H, W, CV_32SC1, cv::Scalar(-1));
  cv::Mat zbuf(H, W, CV_32FC1, cv::Scalar(std::numeric_limits<float>::infinity()));
  cv::Mat index(H, W, CV_32SC1, cv::Scalar(-1));
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3d p = pose.R * points.positions[i] + pose.t;
    if (!(p.z > options.near)) continue;
    const double u = camera.fx * p.x / p.z + camera.cx;
    const double v = camera.fy * p.y / p.z + camera.cy;
    const double r = std::clamp(camera.fx * radius / p.z, options.min_radius_px, options.max_radius_px);
    // Pixel centres i + 0.5 within r of u: i in [ceil(u - r - 0.5), floor(u + r - 0.5)].
    const int x0 = std::max(0, int(std::ceil(u - r - 0.5))), x1 = std::min(W - 1, int(std::floor(u + r - 0.5)));
    const int y0 = std::max(0, int(std::ceil(v - r - 0.5))), y1 = std::min(H - 1, int(std::floor(v + r - 0.5)));
    if (x0 > x1 || y0 > y1) continue;
    const float z = float(p.z);
    const double r2 = r * r;
    for (int y = y0; y <= y1; ++y) {
      const double dy = y + 0.5 - v;
      float* zrow = zbuf.ptr<float>(y);
      int32_t* lrow = labels.ptr<int32_t>(y);
      int32_t* irow = index.ptr<int32_t>(y);
      for (int x = x0; x <= x1; ++x) {
        const double dx = x + 0.5 - u;
        if (dx * dx + dy * dy > r2) continue;
        if (z < zrow[x]) {  // nearest wins; equal depth: the earlier point stays
          zrow[x] = z;
          lrow[x] = points.labels[i] < 0 ? -1 : points.labels[i];
          irow[x] = int32_t(i);
        }
      }
    }
  }
  if (depth) {
    cv::Mat d = zbuf.clone();
    d.setTo(0, zbuf == std::numeric_limits<float>::infinity());
    *depth = d;
  }
  if (winner) *winner = index;
  return labels;
}

}  // namespace cls
