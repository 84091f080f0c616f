#include "synth/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "raycast/pixel_ray.h"

namespace cls::synth {

namespace {
// Shadow rays start this far off the surface (scene units: metres) to avoid self-hits.
constexpr float kShadowOffset = 2e-3f;

Mat3f to_float(const Mat3d& A) {
  Mat3f R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R.m[i][j] = static_cast<float>(A.m[i][j]);
  return R;
}
}  // namespace

Vec3f surface_point(const SynthGeometry& g, uint32_t tri, float u, float v) {
  const auto& t = g.triangles[tri];
  return (1 - u - v) * g.vertices[t[0]] + u * g.vertices[t[1]] + v * g.vertices[t[2]];
}

ViewRenderer::ViewRenderer(const SynthGeometry& g, const SemanticMesh& mesh, const SurfaceShader& shader)
    : g_(g), shader_(shader), raycaster_(g.vertices, g.triangles, g.priority) {
  triangle_label_.assign(g.triangles.size(), 0);
  triangle_normal_.resize(g.triangles.size());
  for (uint32_t t = 0; t < g.triangles.size(); ++t) {
    triangle_normal_[t] = g.triangle_normal(t);
    const TriangleOrigin& o = g.origins[t];
    if (o.source == SurfaceSource::City) triangle_label_[t] = static_cast<uint16_t>(mesh.tri_level_class[o.index][0] + 1);
  }
}

RenderedView ViewRenderer::render(const SynthView& view) const {
  const PinholeCamera& cam = view.camera;
  const int W = cam.width, H = cam.height;
  RenderedView out;

  // Labels and depth: one ray per pixel centre.
  std::vector<RayHit> hits;
  raycaster_.cast_view(cam, view.pose, hits);
  out.labels = cv::Mat(H, W, CV_16UC1);
  out.depth.resize(static_cast<size_t>(W) * H);
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const RayHit& h = hits[static_cast<size_t>(j) * W + i];
      const bool hit = h.prim != kNoHit;
      out.labels.at<uint16_t>(j, i) = hit ? triangle_label_[h.prim] : 0;
      out.depth[static_cast<size_t>(j) * W + i] = hit ? h.depth : std::numeric_limits<float>::infinity();
    }

  // Colour: 2x2 samples per pixel (the doubled camera's pixel centres are the quarter points).
  PinholeCamera fine = cam;
  fine.fx *= 2, fine.fy *= 2, fine.cx *= 2, fine.cy *= 2, fine.width *= 2, fine.height *= 2;
  raycaster_.cast_view(fine, view.pose, hits);
  const Mat3f R = to_float(view.pose.R);
  const size_t n = hits.size();
  std::vector<Vec3f> albedo(n), normal(n), position(n);
  std::vector<uint8_t> wants_sun(n, 0);
#pragma omp parallel for schedule(dynamic, 8)
  for (int j = 0; j < fine.height; ++j)
    for (int i = 0; i < fine.width; ++i) {
      const size_t s = static_cast<size_t>(j) * fine.width + i;
      const Vec3f dir = camera_to_world_dir(
          R, pixel_ray_camera<float>(static_cast<float>(fine.fx), static_cast<float>(fine.fy), static_cast<float>(fine.cx),
                                     static_cast<float>(fine.cy), i, j));
      const RayHit& h = hits[s];
      if (h.prim == kNoHit) {
        albedo[s] = shader_.sky(normalized(dir));
        continue;
      }
      Vec3f nrm = triangle_normal_[h.prim];
      if (dot(nrm, dir) > 0) nrm = -nrm;
      position[s] = surface_point(g_, h.prim, h.u, h.v);
      normal[s] = nrm;
      albedo[s] = shader_.albedo(h.prim, position[s], nrm);
      wants_sun[s] = dot(nrm, shader_.lighting().sun_dir) > 0;
    }
  std::vector<Ray> shadow_rays;
  for (size_t s = 0; s < n; ++s)
    if (wants_sun[s]) shadow_rays.push_back({position[s] + kShadowOffset * normal[s], shader_.lighting().sun_dir});
  std::vector<RayHit> shadow_hits;
  raycaster_.cast(shadow_rays, shadow_hits);

  std::vector<Vec3f> color(n);
  size_t next_ray = 0;
  for (size_t s = 0; s < n; ++s) {
    if (hits[s].prim == kNoHit) {
      color[s] = albedo[s];
    } else {
      const bool sunlit = wants_sun[s] && shadow_hits[next_ray].prim == kNoHit;
      color[s] = shader_.shade(albedo[s], normal[s], sunlit);
    }
    if (wants_sun[s]) ++next_ray;
  }
  out.image = cv::Mat(H, W, CV_8UC3);
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const size_t s00 = static_cast<size_t>(2 * j) * fine.width + 2 * i, s10 = s00 + fine.width;
      const Vec3f c = 0.25f * (color[s00] + color[s00 + 1] + color[s10] + color[s10 + 1]);
      const auto to8 = [](float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
      out.image.at<cv::Vec3b>(j, i) = cv::Vec3b(to8(c.z), to8(c.y), to8(c.x));
    }
  return out;
}

}  // namespace cls::synth
