#include "synth/sparse_points.h"

#include <algorithm>
#include <cmath>

#include "raycast/pixel_ray.h"
#include "synth/random.h"

namespace cls::synth {

namespace {
struct Observation {
  uint32_t view;
  double x, y;
};

struct Candidate {
  Vec3d surface;  // noise-free surface point
  Vec3d noisy;
  std::array<uint8_t, 3> rgb;
  std::vector<Observation> track;
};

// Depth-test tolerance: the noise, plus the depth change across a pixel on oblique surfaces.
double depth_tolerance(double depth, double sigma) { return 4 * sigma + 0.01 * depth; }

std::vector<Observation> find_track(const Vec3d& X, const std::vector<SynthView>& views,
                                    const std::vector<RenderedView>& rendered, double sigma) {
  std::vector<Observation> track;
  for (uint32_t w = 0; w < views.size(); ++w) {
    const PinholeCamera& c = views[w].camera;
    const Vec3d p = views[w].pose.R * X + views[w].pose.t;
    if (p.z <= 0) continue;
    const double x = c.fx * p.x / p.z + c.cx, y = c.fy * p.y / p.z + c.cy;
    if (!(x >= 0 && x < c.width && y >= 0 && y < c.height)) continue;
    const float depth = rendered[w].depth[static_cast<size_t>(y) * c.width + static_cast<size_t>(x)];
    if (std::abs(depth - p.z) > depth_tolerance(p.z, sigma)) continue;  // occluded (or sky: inf)
    track.push_back({w, x, y});
  }
  return track;
}
}  // namespace

ColmapModel make_colmap_model(const std::vector<SynthView>& views, const std::vector<RenderedView>& rendered,
                              const SparsePointOptions& options) {
  ColmapModel model;
  const PinholeCamera& cam = views.front().camera;
  model.cameras[1] = Camera{1, CameraModel::Pinhole, cam.width, cam.height, {cam.fx, cam.fy, cam.cx, cam.cy}};
  for (uint32_t v = 0; v < views.size(); ++v) {
    ColmapImage image;
    image.id = v + 1;
    image.qvec = rotation_to_qvec(views[v].pose.R);
    image.tvec = {views[v].pose.t.x, views[v].pose.t.y, views[v].pose.t.z};
    image.camera_id = 1;
    image.name = views[v].name;
    model.images[image.id] = image;
  }

  const int stride =
      std::max(2, static_cast<int>(std::lround(std::sqrt(double(cam.width) * cam.height / options.samples_per_view))));
  std::vector<std::vector<Candidate>> per_view(views.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int v = 0; v < static_cast<int>(views.size()); ++v) {
    const SynthView& view = views[v];
    const PinholeCamera& c = view.camera;
    Rng rng(options.seed, Stream::SparsePoints, static_cast<uint64_t>(v));
    const Vec3d eye = view.pose.center();
    for (int gy = 0; gy + stride <= c.height; gy += stride)
      for (int gx = 0; gx + stride <= c.width; gx += stride) {
        const int i = gx + rng.below(stride), j = gy + rng.below(stride);
        const Vec3d noise{rng.gaussian(), rng.gaussian(), rng.gaussian()};
        const float depth = rendered[v].depth[static_cast<size_t>(j) * c.width + i];
        if (!std::isfinite(depth)) continue;
        Candidate p;
        p.surface = eye + static_cast<double>(depth) *
                              camera_to_world_dir(view.pose.R, pixel_ray_camera<double>(c.fx, c.fy, c.cx, c.cy, i, j));
        p.noisy = p.surface + options.noise_sigma * noise;
        const cv::Vec3b bgr = rendered[v].image.at<cv::Vec3b>(j, i);
        p.rgb = {bgr[2], bgr[1], bgr[0]};
        p.track = find_track(p.surface, views, rendered, options.noise_sigma);
        if (static_cast<int>(p.track.size()) >= options.min_track) per_view[v].push_back(std::move(p));
      }
  }

  uint64_t next_id = 1;
  for (const auto& candidates : per_view)
    for (const Candidate& p : candidates) {
      ColmapPoint3D point;
      point.id = next_id++;
      point.xyz = {p.noisy.x, p.noisy.y, p.noisy.z};
      point.rgb = p.rgb;
      double error_sum = 0;
      for (const Observation& o : p.track) {
        ColmapImage& image = model.images[o.view + 1];
        point.track.push_back({image.id, static_cast<uint32_t>(image.points2d.size())});
        image.points2d.push_back({o.x, o.y, point.id});
        const Vec3d q = views[o.view].pose.R * p.noisy + views[o.view].pose.t;
        const PinholeCamera& c = views[o.view].camera;
        error_sum += std::hypot(c.fx * q.x / q.z + c.cx - o.x, c.fy * q.y / q.z + c.cy - o.y);
      }
      point.error = error_sum / static_cast<double>(p.track.size());
      model.points[point.id] = std::move(point);
    }
  return model;
}

}  // namespace cls::synth
