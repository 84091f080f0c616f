#pragma once
// Everything the synthetic camera sees, as one triangle soup for one Raycaster: the city mesh,
// a terrain plane and clutter that is not in the city model, with a table from each triangle
// back to where it came from.
#include <array>
#include <cstdint>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"
#include "synth/box.h"
#include "synth/material.h"

namespace cls::synth {

enum class SurfaceSource : uint8_t { City = 0, Terrain = 1, Clutter = 2 };

struct TriangleOrigin {
  SurfaceSource source = SurfaceSource::City;
  uint32_t index = 0;  // City: triangle of the SemanticMesh; Clutter: object in SynthGeometry::clutter
  Material material = Material::PlainSurface;
};

enum class ClutterKind : uint8_t { Tree, Conifer, Car, Bench, Fence };

struct ClutterObject {
  ClutterKind kind = ClutterKind::Tree;
  Vec3d base{};        // centre of the footprint on the terrain
  double heading = 0;  // rotation about z (radians)
  double radius = 0;   // footprint radius used to keep objects apart
  uint32_t color_key = 0;
};

// A straight road band across the terrain: asphalt where |p[axis] - offset| < half_width.
struct Road {
  int axis = 0;
  double offset = 0, half_width = 3;
};

struct SynthGeometry {
  std::vector<Vec3f> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint8_t> priority;  // openings 1, everything else 0 (Raycaster tie-break)
  std::vector<TriangleOrigin> origins;
  std::vector<ClutterObject> clutter;
  Box3d city_bounds;
  double terrain_z = 0;
  double terrain_half_extent = 0;
  Box3d clutter_area;  // the region clutter is placed in (terrain samples of the GT cloud come from it)
  Road road;
  bool brick_walls = false;

  uint32_t add_vertex(Vec3d p);
  void add_triangle(uint32_t a, uint32_t b, uint32_t c, TriangleOrigin origin, uint8_t priority = 0);
  Vec3f triangle_normal(uint32_t tri) const;  // unit geometric normal (v1 - v0) x (v2 - v0)
  double triangle_area(uint32_t tri) const;
};

// Distance of the terrain plane below the model's lowest point (m): close enough that the
// building does not float, far enough to avoid depth fighting with its ground surface.
constexpr double kTerrainGap = 0.03;

// Builds the scene: city triangles first (geometry index = SemanticMesh triangle index), then
// terrain and clutter placed deterministically by the seed outside the building footprint, then
// `occluders` extra trees in front of its facades (place_occluders). The mesh must have a triangle.
SynthGeometry build_synth_geometry(const SemanticMesh& mesh, const Taxonomy& taxonomy, uint64_t seed, int occluders = 0);

}  // namespace cls::synth
