// Embree 3 implementation of raycaster.h.
//
// Speed: pixels are traced as coherent packets of 16 rays (a 4x4 pixel tile) where the CPU runs
// 16-wide natively (AVX-512), else 8 rays (4x2); OpenMP threads take 32x32-pixel blocks.
//
// Priority tie rule (openings over their walls): the main scene returns the closest hit t0. Only
// if that triangle has a low priority AND a higher-priority triangle could lie within the tie
// tolerance of the hit point is the ray re-tested, as a short segment [t0 - tol, t0 + tol] against
// a small scene that holds only the higher-priority triangles (one scene per priority level,
// highest first; the first level that is hit wins). A tie partner hit at ray-parameter distance
// dt lies |dir| * dt from the hit point, so the re-test is needed only if some higher-priority
// triangle's bounding box comes within reach = |dir| * tol of the hit point. Precomputed per
// triangle (TieGate): the smallest box gap to any higher-priority triangle, and the boxes of the
// nearby ones (merged where they touch, e.g. the triangles of one window). A wall hit far from
// its windows, roofs and ground never pay for the rule; models without priorities build no tie
// scenes at all.
#include "raycast/raycaster.h"

#include <xmmintrin.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "raycast/embree_scene.h"
#include "raycast/pixel_ray.h"

namespace cls {
namespace {

constexpr int kBlock = 32;  // pixels per side of the block one thread takes at a time

float tie_tolerance(float depth) { return 1e-4f * depth + 1e-5f; }

// Embree asks for flush-to-zero / denormals-are-zero in every tracing thread; restored on exit so
// the caller's floating-point environment is unchanged.
class DenormalsAreZero {
 public:
  DenormalsAreZero() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
  ~DenormalsAreZero() { _mm_setcsr(saved_); }
  DenormalsAreZero(const DenormalsAreZero&) = delete;
  DenormalsAreZero& operator=(const DenormalsAreZero&) = delete;

 private:
  unsigned saved_;
};

template <int N>
void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RTCRayHitNt<N>& rayhit);
template <>
void intersect<8>(const int* valid, RTCScene scene, RTCIntersectContext* context, RTCRayHitNt<8>& rayhit) {
  rtcIntersect8(valid, scene, context, reinterpret_cast<RTCRayHit8*>(&rayhit));
}
template <>
void intersect<16>(const int* valid, RTCScene scene, RTCIntersectContext* context, RTCRayHitNt<16>& rayhit) {
  rtcIntersect16(valid, scene, context, reinterpret_cast<RTCRayHit16*>(&rayhit));
}

struct Box {
  Vec3f lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  void add(Vec3f p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
};

Box triangle_box(const std::vector<Vec3f>& vertices, const std::array<uint32_t, 3>& tri) {
  Box b;
  for (uint32_t v : tri) b.add(vertices[v]);
  return b;
}

bool box_within(const Box& b, Vec3f p, float reach) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < b.lo[k] - reach || p[k] > b.hi[k] + reach) return false;
  return true;
}

Box box_union(const Box& a, const Box& b) {
  Box u = a;
  u.add(b.lo);
  u.add(b.hi);
  return u;
}

float box_distance(const Box& a, const Box& b) {
  float d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const float gap = std::max({0.0f, a.lo[k] - b.hi[k], b.lo[k] - a.hi[k]});
    d2 += gap * gap;
  }
  return std::sqrt(d2);
}

// Merges boxes closer than `touch` until none are, then everything into one box if more than
// `max_count` remain: the partner boxes of a wall triangle become about one box per opening.
void merge_boxes(std::vector<Box>& boxes, float touch, size_t max_count) {
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t a = 0; a < boxes.size() && !merged; ++a)
      for (size_t b = a + 1; b < boxes.size() && !merged; ++b)
        if (box_distance(boxes[a], boxes[b]) <= touch) {
          boxes[a] = box_union(boxes[a], boxes[b]);
          boxes.erase(boxes.begin() + b);
          merged = true;
        }
  }
  if (boxes.size() > max_count) {
    for (size_t k = 1; k < boxes.size(); ++k) boxes[0] = box_union(boxes[0], boxes[k]);
    boxes.resize(1);
  }
}

// Per low-priority triangle: when a hit on it needs the tie re-test (see the top of the file).
struct TieGate {
  float gap = INFINITY;           // lower bound of the distance to any higher-priority triangle
  uint32_t first = 0, count = 0;  // boxes in Impl::tie_boxes covering those within near_distance
};

constexpr size_t kMaxPartnerBoxes = 4;

// Triangles of one priority level, traced only to settle ties.
struct TieScene {
  uint8_t priority = 0;
  RTCScene scene = nullptr;
  std::vector<uint32_t> prims;  // local primitive id -> triangle id
};

}  // namespace

struct Raycaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  size_t num_triangles = 0;
  int packet_width = 8;
  std::vector<Vec3f> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint8_t> priority;     // per triangle; empty when there are no tie scenes
  std::vector<TieScene> tie_scenes;  // highest priority first
  std::vector<TieGate> tie_gates;    // per triangle
  std::vector<Box> tie_boxes;        // partner boxes of all gates
  float near_distance = 0;           // partner boxes cover higher-priority triangles this close

  ~Impl() {
    for (auto& t : tie_scenes) rtcReleaseScene(t.scene);
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  void build_tie_scenes();
  template <int N>
  void resolve_ties(const int* valid, RTCRayHitNt<N>& rh, const float* tnear) const;
  template <int N>
  void cast_view_packets(const PinholeCamera& camera, const Pose& pose, std::vector<RayHit>& out) const;
  template <int N>
  void cast_packets(const std::vector<Ray>& rays, std::vector<RayHit>& out) const;
};

namespace {
// State of the box query of one triangle: its box, the smallest gap so far and the nearby boxes.
struct GapQuery {
  const std::vector<Vec3f>* vertices;
  const std::vector<std::array<uint32_t, 3>>* triangles;
  const TieScene* tie;
  Box box;
  float half_diagonal;
  float near_distance;
  float best;
  std::vector<Box> near;
};

// Point-query callback from the box centre: a box within gap g of the query box lies within
// g + half diagonal of the centre, so the radius shrinks to max(best, near) + half diagonal.
bool visit_gap(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<GapQuery*>(args->userPtr);
  const Box other = triangle_box(*q->vertices, (*q->triangles)[q->tie->prims[args->primID]]);
  const float d = box_distance(q->box, other);
  if (d <= q->near_distance) q->near.push_back(other);
  if (d >= q->best) return false;
  q->best = d;
  args->query->radius = std::min(args->query->radius, std::max(d, q->near_distance) + q->half_diagonal);
  return true;
}
}  // namespace

void Raycaster::Impl::build_tie_scenes() {
  std::vector<std::vector<uint32_t>> by_priority(256);
  for (uint32_t i = 0; i < priority.size(); ++i) by_priority[priority[i]].push_back(i);
  const int lowest = *std::min_element(priority.begin(), priority.end());
  for (int p = 255; p > lowest; --p) {
    if (by_priority[p].empty()) continue;
    TieScene t;
    t.priority = static_cast<uint8_t>(p);
    t.prims = std::move(by_priority[p]);
    t.scene = build_triangle_scene(device, vertices, triangles, &t.prims);
    tie_scenes.push_back(std::move(t));
  }
  if (tie_scenes.empty()) {
    priority.clear();  // all equal: the rule never applies
    return;
  }

  // Gates from Embree point queries on the tie scenes. Partner boxes cover higher-priority
  // triangles within 1% of the model's size: farther away the tie tolerance reaches them only from
  // about 100 model sizes away, where the plain gap test takes over.
  Box all;
  for (const auto& v : vertices) all.add(v);
  near_distance = 0.01f * norm(all.hi - all.lo);
  const uint8_t top = tie_scenes.front().priority;
  tie_gates.assign(triangles.size(), TieGate{});
  std::vector<std::vector<Box>> near(triangles.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t i = 0; i < static_cast<int64_t>(triangles.size()); ++i) {
    if (priority[i] >= top) continue;
    GapQuery q{&vertices, &triangles, nullptr, triangle_box(vertices, triangles[i]), 0, near_distance, INFINITY, {}};
    const Vec3f c = 0.5f * (q.box.lo + q.box.hi);
    q.half_diagonal = 0.5f * norm(q.box.hi - q.box.lo);
    for (const auto& t : tie_scenes) {
      if (t.priority <= priority[i]) break;
      q.tie = &t;
      RTCPointQuery query{c.x, c.y, c.z, 0.0f, INFINITY};
      RTCPointQueryContext context;
      rtcInitPointQueryContext(&context);
      rtcPointQuery(t.scene, &query, &context, visit_gap, &q);
    }
    merge_boxes(q.near, 1e-6f * near_distance, kMaxPartnerBoxes);
    tie_gates[i].gap = q.best;
    near[i] = std::move(q.near);
  }
  for (size_t i = 0; i < triangles.size(); ++i) {
    tie_gates[i].first = static_cast<uint32_t>(tie_boxes.size());
    tie_gates[i].count = static_cast<uint32_t>(near[i].size());
    tie_boxes.insert(tie_boxes.end(), near[i].begin(), near[i].end());
  }
}

// Re-tests the lanes whose closest hit is a low-priority triangle with a possible tie partner.
template <int N>
void Raycaster::Impl::resolve_ties(const int* valid, RTCRayHitNt<N>& rh, const float* tnear) const {
  alignas(64) int pending[N];
  float t0[N], tol[N];
  uint8_t lane_priority[N];
  const uint8_t top = tie_scenes.front().priority;
  bool any = false;
  for (int i = 0; i < N; ++i) {
    pending[i] = 0;
    if (!valid[i] || rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
    const uint32_t prim = rh.hit.primID[i];
    if (priority[prim] >= top) continue;
    t0[i] = rh.ray.tfar[i];
    tol[i] = tie_tolerance(t0[i]);
    const TieGate& gate = tie_gates[prim];
    const Vec3f dir{rh.ray.dir_x[i], rh.ray.dir_y[i], rh.ray.dir_z[i]};
    const float reach = norm(dir) * tol[i];
    if (gate.gap > reach) continue;
    if (reach <= near_distance) {
      // Widened by float rounding of the hit point, so a partner is never missed by an ulp.
      const Vec3f org{rh.ray.org_x[i], rh.ray.org_y[i], rh.ray.org_z[i]};
      const Vec3f hit = org + t0[i] * dir;
      const float slack = reach + 1e-6f * (std::fabs(hit.x) + std::fabs(hit.y) + std::fabs(hit.z) + t0[i] * norm(dir));
      bool near = false;
      for (uint32_t k = gate.first; k < gate.first + gate.count && !near; ++k)
        near = box_within(tie_boxes[k], hit, slack);
      if (!near) continue;
    }
    pending[i] = -1;
    lane_priority[i] = priority[prim];
    any = true;
  }
  if (!any) return;

  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) RTCRayHitNt<N> q;
  for (const auto& t : tie_scenes) {
    alignas(64) int active[N];
    bool any_active = false;
    for (int i = 0; i < N; ++i) {
      active[i] = (pending[i] && t.priority > lane_priority[i]) ? -1 : 0;
      if (!active[i]) continue;
      any_active = true;
      q.ray.org_x[i] = rh.ray.org_x[i];
      q.ray.org_y[i] = rh.ray.org_y[i];
      q.ray.org_z[i] = rh.ray.org_z[i];
      q.ray.dir_x[i] = rh.ray.dir_x[i];
      q.ray.dir_y[i] = rh.ray.dir_y[i];
      q.ray.dir_z[i] = rh.ray.dir_z[i];
      q.ray.tnear[i] = std::max(tnear[i], t0[i] - tol[i]);
      q.ray.tfar[i] = t0[i] + tol[i];
      q.ray.time[i] = 0;
      q.ray.mask[i] = ~0u;
      q.ray.id[i] = i;
      q.ray.flags[i] = 0;
      q.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    if (!any_active) continue;
    intersect<N>(active, t.scene, &context, q);
    for (int i = 0; i < N; ++i) {
      if (!active[i] || q.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
      rh.hit.primID[i] = t.prims[q.hit.primID[i]];
      rh.hit.u[i] = q.hit.u[i];
      rh.hit.v[i] = q.hit.v[i];
      rh.ray.tfar[i] = q.ray.tfar[i];
      pending[i] = 0;
    }
  }
}

namespace {
template <int N>
void init_packet(RTCRayHitNt<N>& rh, int i, Vec3f org, Vec3f dir, float tnear, float tfar) {
  rh.ray.org_x[i] = org.x;
  rh.ray.org_y[i] = org.y;
  rh.ray.org_z[i] = org.z;
  rh.ray.dir_x[i] = dir.x;
  rh.ray.dir_y[i] = dir.y;
  rh.ray.dir_z[i] = dir.z;
  rh.ray.tnear[i] = tnear;
  rh.ray.tfar[i] = tfar;
  rh.ray.time[i] = 0;
  rh.ray.mask[i] = ~0u;
  rh.ray.id[i] = i;
  rh.ray.flags[i] = 0;
  rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
}

template <int N>
RayHit hit_of(const RTCRayHitNt<N>& rh, int i) {
  RayHit h;
  if (rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) return h;
  h.depth = rh.ray.tfar[i];
  h.prim = rh.hit.primID[i];
  h.u = rh.hit.u[i];
  h.v = rh.hit.v[i];
  return h;
}
}  // namespace

template <int N>
void Raycaster::Impl::cast_view_packets(const PinholeCamera& cam, const Pose& pose,
                                        std::vector<RayHit>& out) const {
  constexpr int kTileW = 4, kTileH = N / 4;
  const int W = cam.width, H = cam.height;
  out.resize(static_cast<size_t>(W) * H);  // every pixel is written below
  Mat3f R;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R.m[r][c] = static_cast<float>(pose.R.m[r][c]);
  const Vec3f origin = cls::cast<float>(pose.center());
  const float fx = static_cast<float>(cam.fx), fy = static_cast<float>(cam.fy);
  const float cx = static_cast<float>(cam.cx), cy = static_cast<float>(cam.cy);
  const int blocks_x = (W + kBlock - 1) / kBlock, blocks_y = (H + kBlock - 1) / kBlock;

#pragma omp parallel
  {
    DenormalsAreZero ftz;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) RTCRayHitNt<N> rh;
    alignas(64) int valid[N];
    float tnear[N] = {};
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < blocks_x * blocks_y; ++b) {
      const int bx = (b % blocks_x) * kBlock, by = (b / blocks_x) * kBlock;
      for (int ty = by; ty < std::min(by + kBlock, H); ty += kTileH) {
        for (int tx = bx; tx < std::min(bx + kBlock, W); tx += kTileW) {
          for (int k = 0; k < N; ++k) {
            const int i = tx + k % kTileW, j = ty + k / kTileW;
            valid[k] = (i < W && j < H) ? -1 : 0;
            const Vec3f d = camera_to_world_dir(R, pixel_ray_camera(fx, fy, cx, cy, i, j));
            init_packet(rh, k, origin, d, 0.0f, INFINITY);
          }
          intersect<N>(valid, scene, &context, rh);
          if (!tie_scenes.empty()) resolve_ties<N>(valid, rh, tnear);
          for (int k = 0; k < N; ++k) {
            if (!valid[k]) continue;
            const int i = tx + k % kTileW, j = ty + k / kTileW;
            out[static_cast<size_t>(j) * W + i] = hit_of(rh, k);
          }
        }
      }
    }
  }
}

template <int N>
void Raycaster::Impl::cast_packets(const std::vector<Ray>& rays, std::vector<RayHit>& out) const {
  out.resize(rays.size());  // every ray is written below
  const int64_t packets = (static_cast<int64_t>(rays.size()) + N - 1) / N;
#pragma omp parallel
  {
    DenormalsAreZero ftz;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(64) RTCRayHitNt<N> rh;
    alignas(64) int valid[N];
    float tnear[N];
#pragma omp for schedule(dynamic, 64)
    for (int64_t p = 0; p < packets; ++p) {
      for (int k = 0; k < N; ++k) {
        const size_t r = static_cast<size_t>(p) * N + k;
        valid[k] = r < rays.size() ? -1 : 0;
        const Ray ray = valid[k] ? rays[r] : Ray{};
        tnear[k] = ray.tnear;
        init_packet(rh, k, ray.origin, ray.dir, ray.tnear, ray.tfar);
      }
      intersect<N>(valid, scene, &context, rh);
      if (!tie_scenes.empty()) resolve_ties<N>(valid, rh, tnear);
      for (int k = 0; k < N; ++k)
        if (valid[k]) out[static_cast<size_t>(p) * N + k] = hit_of(rh, k);
    }
  }
}

Raycaster::Raycaster(const std::vector<Vec3f>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles,
                     const std::vector<uint8_t>& priority)
    : impl_(std::make_unique<Impl>()) {
  if (!priority.empty() && priority.size() != triangles.size())
    throw Error(cat("raycaster: ", priority.size(), " priorities for ", triangles.size(), " triangles"));
  validate_triangle_mesh(vertices, triangles, "raycaster");

  Impl& im = *impl_;
  im.device = new_embree_device();
  im.packet_width = rtcGetDeviceProperty(im.device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) ? 16 : 8;
  im.vertices = vertices;
  im.triangles = triangles;
  im.num_triangles = triangles.size();
  im.scene = build_triangle_scene(im.device, vertices, triangles);
  if (!priority.empty()) {
    im.priority = priority;
    im.build_tie_scenes();
  }
  log_verbose(cat("raycaster: ", triangles.size(), " triangles, ", im.tie_scenes.size(),
                  " priority level(s) above the lowest, ", im.packet_width, "-ray packets"));
}

Raycaster::~Raycaster() = default;

void Raycaster::cast_view(const PinholeCamera& camera, const Pose& pose, std::vector<RayHit>& out) const {
  if (camera.width <= 0 || camera.height <= 0 || !(camera.fx > 0) || !(camera.fy > 0))
    throw Error(cat("raycaster: invalid camera (", camera.width, "x", camera.height, ", fx ", camera.fx, ", fy ",
                    camera.fy, ")"));
  if (impl_->packet_width == 16)
    impl_->cast_view_packets<16>(camera, pose, out);
  else
    impl_->cast_view_packets<8>(camera, pose, out);
}

void Raycaster::cast(const std::vector<Ray>& rays, std::vector<RayHit>& out) const {
  if (impl_->packet_width == 16)
    impl_->cast_packets<16>(rays, out);
  else
    impl_->cast_packets<8>(rays, out);
}

size_t Raycaster::num_triangles() const { return impl_->num_triangles; }

}  // namespace cls
