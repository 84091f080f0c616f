#include "synth/shading.h"

#include <algorithm>
#include <cmath>

#include "synth/noise.h"
#include "synth/random.h"

namespace cls::synth {

namespace {
constexpr float kPi = 3.14159265f;

Vec3f mul(Vec3f a, Vec3f b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
Vec3f mix(Vec3f a, Vec3f b, float t) { return a + t * (b - a); }
float fract(float x) { return x - std::floor(x); }
float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}
// Horizontal axis of a surface with normal n (x where the surface is horizontal).
Vec3f horizontal_axis(Vec3f n) {
  const Vec3f h = cross(Vec3f{0, 0, 1}, n);
  return norm(h) > 1e-3f ? normalized(h) : Vec3f{1, 0, 0};
}
template <size_t N>
Vec3f pick(const Vec3f (&palette)[N], Rng& rng) {
  return palette[static_cast<size_t>(rng.below(static_cast<int>(N)))];
}

// Noise keys per material, so that no two materials share a pattern.
enum NoiseKey : uint64_t { kPlaster = 1, kStains, kBrick, kTile, kTileNoise, kGrass, kGrassFine, kDirt, kAsphalt,
                           kWood, kFoliage, kBark, kConcrete, kClouds };
}  // namespace

SurfaceShader::SurfaceShader(const SynthGeometry& g, const SemanticMesh& mesh, uint64_t seed)
    : g_(g), openings_(build_opening_frames(g, mesh)), key_(hash_keys(seed, static_cast<uint64_t>(Stream::Materials))) {
  Rng rng(seed, Stream::Lighting);
  const float azimuth = static_cast<float>(rng.uniform(0, 2 * kPi));
  const float elevation = static_cast<float>(rng.uniform(40, 55)) * kPi / 180;
  lighting_.sun_dir = {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                       std::sin(elevation)};
  Rng palette(seed, Stream::Materials);
  const Vec3f plasters[] = {{0.90f, 0.86f, 0.76f}, {0.86f, 0.85f, 0.82f}, {0.92f, 0.84f, 0.62f}, {0.90f, 0.76f, 0.66f}};
  const Vec3f bricks[] = {{0.62f, 0.30f, 0.22f}, {0.70f, 0.42f, 0.30f}, {0.55f, 0.36f, 0.30f}};
  const Vec3f roofs[] = {{0.60f, 0.24f, 0.15f}, {0.30f, 0.30f, 0.33f}, {0.50f, 0.30f, 0.22f}};
  const Vec3f frames[] = {{0.93f, 0.93f, 0.91f}, {0.25f, 0.26f, 0.28f}, {0.45f, 0.30f, 0.18f}};
  const Vec3f doors[] = {{0.45f, 0.28f, 0.15f}, {0.20f, 0.32f, 0.25f}, {0.55f, 0.15f, 0.12f}};
  plaster_ = pick(plasters, palette);
  brick_ = pick(bricks, palette);
  roof_ = pick(roofs, palette);
  window_frame_ = pick(frames, palette);
  door_wood_ = pick(doors, palette);
}

Vec3f SurfaceShader::sky(Vec3f d) const {
  const float e = d.z;
  const Vec3f horizon{0.80f, 0.86f, 0.93f}, zenith{0.33f, 0.52f, 0.83f};
  if (e <= 0) return mix(horizon, Vec3f{0.70f, 0.73f, 0.76f}, std::min(1.0f, -e * 4));
  Vec3f c = mix(horizon, zenith, std::sqrt(e));
  // Soft clouds on a plane far above: a function of the direction only.
  const float s = 1.0f / (e + 0.15f);
  const float cloud = smoothstep(0.55f, 0.8f, fbm(d.x * s * 1.5f, d.y * s * 1.5f, 0.5f, 4, key_ + kClouds));
  return mix(c, Vec3f{0.96f, 0.96f, 0.97f}, 0.8f * cloud * std::min(1.0f, e * 6));
}

Vec3f SurfaceShader::shade(Vec3f albedo, Vec3f n, bool sun_visible) const {
  const Vec3f ambient = mix(lighting_.ground_ambient, lighting_.sky_ambient, 0.5f + 0.5f * n.z);
  const float direct = sun_visible ? std::max(0.0f, dot(n, lighting_.sun_dir)) : 0.0f;
  return mul(albedo, ambient + direct * lighting_.sun);
}

Vec3f SurfaceShader::wall(Vec3f p, Vec3f n) const {
  if (!g_.brick_walls) {
    const float fine = fbm(p.x * 4, p.y * 4, p.z * 4, 3, key_ + kPlaster);
    const float stains = fbm(p.x * 0.35f, p.y * 0.35f, p.z * 0.7f, 3, key_ + kStains);
    Vec3f c = (0.86f + 0.14f * fine) * (0.9f + 0.12f * stains) * plaster_;
    // A darker plinth along the foot of the wall.
    if (p.z < g_.city_bounds.lo.z + 0.45) c = (0.62f + 0.1f * fine) * Vec3f{0.85f, 0.84f, 0.82f};
    return c;
  }
  constexpr float kBrickW = 0.30f, kBrickH = 0.10f, kMortar = 0.015f;
  const float u = dot(p, horizontal_axis(n)), v = p.z;
  const float row = std::floor(v / kBrickH);
  const float shifted = u + (static_cast<int64_t>(row) & 1 ? 0.5f * kBrickW : 0.0f);
  const float col = std::floor(shifted / kBrickW);
  const bool mortar = fract(v / kBrickH) * kBrickH < kMortar || fract(shifted / kBrickW) * kBrickW < kMortar;
  const float grain = fbm(p.x * 6, p.y * 6, p.z * 6, 2, key_ + kBrick);
  if (mortar) return (0.72f + 0.1f * grain) * Vec3f{0.85f, 0.83f, 0.78f};
  const float tone = cell_random(static_cast<int64_t>(col), static_cast<int64_t>(row), 0, key_ + kBrick);
  return (0.75f + 0.35f * tone) * (0.9f + 0.15f * grain) * brick_;
}

Vec3f SurfaceShader::glass(const OpeningFrame& f, Vec3f p) const {
  constexpr float kFrame = 0.07f, kBar = 0.035f;
  const float u = dot(p, f.axis_u), v = dot(p, f.axis_v);
  const float width = f.u_max - f.u_min, height = f.v_max - f.v_min;
  const bool frame = f.distance_to_border(p) < kFrame;
  const bool mullion = width > 0.7f && std::abs(u - 0.5f * (f.u_min + f.u_max)) < kBar;
  const bool transom = height > 1.0f && std::abs(v - (f.v_min + 0.68f * height)) < kBar;
  if (frame || mullion || transom) return window_frame_;
  // Fake reflection: sky-like gradient from the top of the pane, a diagonal highlight band.
  const float t = height > 0 ? std::clamp((v - f.v_min) / height, 0.0f, 1.0f) : 0.5f;
  Vec3f c = mix(Vec3f{0.14f, 0.18f, 0.24f}, Vec3f{0.55f, 0.66f, 0.78f}, t * t);
  if (fract((u + 0.7f * v) / 1.6f) < 0.14f) c = c + Vec3f{0.12f, 0.12f, 0.12f};
  return c;
}

Vec3f SurfaceShader::door(const OpeningFrame& f, Vec3f p) const {
  constexpr float kFrame = 0.06f, kGroove = 0.025f, kMargin = 0.12f;
  if (f.distance_to_border(p) < kFrame) return window_frame_;
  const float u = dot(p, f.axis_u) - f.u_min, v = dot(p, f.axis_v) - f.v_min;
  const float width = f.u_max - f.u_min, height = f.v_max - f.v_min;
  // Door knob.
  const float ku = u - 0.85f * width, kv = v - 0.45f * height;
  if (ku * ku + kv * kv < 0.04f * 0.04f) return {0.80f, 0.75f, 0.55f};
  const float grain = fbm(u * 2, v * 12, 0.0f, 3, key_ + kWood);
  Vec3f c = (0.8f + 0.3f * grain) * door_wood_;
  // Two columns x three rows of recessed panels: grooves around each.
  const float pu = std::clamp((u - kMargin) / std::max(width - 2 * kMargin, 1e-3f), 0.0f, 0.9999f) * 2;
  const float pv = std::clamp((v - kMargin) / std::max(height - 2 * kMargin, 1e-3f), 0.0f, 0.9999f) * 3;
  const float du = std::min(fract(pu), 1 - fract(pu)) * (width - 2 * kMargin) / 2;
  const float dv = std::min(fract(pv), 1 - fract(pv)) * (height - 2 * kMargin) / 3;
  const bool inside = u > kMargin && u < width - kMargin && v > kMargin && v < height - kMargin;
  if (inside && std::min(du, dv) < kGroove) c = 0.6f * c;
  return c;
}

Vec3f SurfaceShader::roof(Vec3f p, Vec3f n) const {
  constexpr float kRow = 0.33f, kTile = 0.25f;
  const Vec3f across = horizontal_axis(n);
  const Vec3f downhill = cross(across, n);  // in the roof plane, perpendicular to the eaves
  const float a = dot(p, across), d = dot(p, downhill) * (downhill.z > 0 ? -1.0f : 1.0f);
  const float row = std::floor(d / kRow);
  const float shifted = a + (static_cast<int64_t>(row) & 1 ? 0.5f * kTile : 0.0f);
  const float col = std::floor(shifted / kTile);
  const float in_row = fract(d / kRow), in_col = fract(shifted / kTile);
  const float tone = cell_random(static_cast<int64_t>(col), static_cast<int64_t>(row), 1, key_ + kTile);
  const float noise = fbm(p.x * 5, p.y * 5, p.z * 5, 2, key_ + kTileNoise);
  // Each row is shadowed towards its lower edge where the next row overlaps it.
  float shade = 0.75f + 0.25f * in_row;
  if (in_col < 0.06f) shade *= 0.75f;
  return (shade * (0.85f + 0.25f * tone) * (0.9f + 0.15f * noise)) * roof_;
}

Vec3f SurfaceShader::terrain(Vec3f p) const {
  // Fine detail fades out far from the building, where the views see the terrain at grazing
  // angles: a function of position, so views still agree, but little aliasing in the distance.
  const Vec3d centre = g_.city_bounds.center();
  const float r = std::hypot(p.x - static_cast<float>(centre.x), p.y - static_cast<float>(centre.y));
  const float detail = std::clamp((70.0f - r) / 40.0f, 0.0f, 1.0f);
  const Road& road = g_.road;
  const float across = p[road.axis] - static_cast<float>(road.offset);
  const float along = p[1 - road.axis];
  if (std::abs(across) < road.half_width) {
    const float n = 0.5f + detail * (fbm(p.x * 3, p.y * 3, 0.0f, 3, key_ + kAsphalt) - 0.5f);
    const bool centre_line = std::abs(across) < 0.07f && fract(along / 6.0f) < 0.5f;
    const bool edge_line = std::abs(std::abs(across) - static_cast<float>(road.half_width - 0.25)) < 0.06f;
    if (centre_line || edge_line) return Vec3f{0.85f, 0.85f, 0.80f};
    return (0.85f + 0.3f * n) * Vec3f{0.26f, 0.26f, 0.27f};
  }
  const float coarse = fbm(p.x * 0.25f, p.y * 0.25f, 0.0f, 3, key_ + kGrass);
  const float fine = 0.5f + detail * (fbm(p.x * 3, p.y * 3, 0.0f, 3, key_ + kGrassFine) - 0.5f);
  Vec3f grass = (0.7f + 0.45f * coarse) * (0.85f + 0.3f * fine) * Vec3f{0.30f, 0.46f, 0.18f};
  const float dirt = smoothstep(0.66f, 0.74f, fbm(p.x * 0.12f, p.y * 0.12f, 0.0f, 3, key_ + kDirt));
  return mix(grass, (0.8f + 0.3f * fine) * Vec3f{0.48f, 0.40f, 0.28f}, dirt);
}

Vec3f SurfaceShader::albedo(uint32_t tri, Vec3f p, Vec3f n) const {
  const TriangleOrigin& o = g_.origins[tri];
  switch (o.material) {
    case Material::Wall: return wall(p, n);
    case Material::Glass: return glass(openings_.frames[openings_.frame_of_triangle[tri]], p);
    case Material::Door: return door(openings_.frames[openings_.frame_of_triangle[tri]], p);
    case Material::RoofTiles: return roof(p, n);
    case Material::BuildingGround:
    case Material::Installation: {
      const float c = fbm(p.x * 3, p.y * 3, p.z * 3, 3, key_ + kConcrete);
      return (0.75f + 0.3f * c) * Vec3f{0.58f, 0.57f, 0.55f};
    }
    case Material::PlainSurface: return {0.72f, 0.72f, 0.74f};
    case Material::Terrain: return terrain(p);
    case Material::Bark: return (0.75f + 0.4f * fbm(p.x * 8, p.y * 8, p.z * 2, 2, key_ + kBark)) * Vec3f{0.33f, 0.24f, 0.16f};
    case Material::Foliage: {
      const float f = fbm(p.x * 2.5f, p.y * 2.5f, p.z * 2.5f, 4, key_ + kFoliage);
      return (0.55f + 0.7f * f) * Vec3f{0.20f, 0.38f, 0.12f};
    }
    case Material::CarPaint:
    case Material::CarWindow: {
      const Vec3f paints[] = {{0.70f, 0.10f, 0.08f}, {0.12f, 0.25f, 0.60f}, {0.88f, 0.88f, 0.86f},
                              {0.55f, 0.56f, 0.58f}, {0.10f, 0.10f, 0.11f}};
      const Vec3f paint = paints[g_.clutter[o.index].color_key % 5];
      if (o.material == Material::CarWindow && std::abs(n.z) < 0.7f) return {0.10f, 0.12f, 0.15f};
      return paint;
    }
    case Material::Tyre: return {0.07f, 0.07f, 0.07f};
    case Material::Wood: return (0.8f + 0.3f * fbm(p.x * 10, p.y * 10, p.z * 1.5f, 2, key_ + kWood)) * Vec3f{0.52f, 0.38f, 0.24f};
  }
  return {0.5f, 0.5f, 0.5f};
}

}  // namespace cls::synth
