#pragma once
// Procedural appearance of the synthetic scenes: per-material albedo keyed on world position
// (identical in every view), a sky gradient, and Lambert sun + hemispherical ambient lighting.
// All colours are display RGB in [0, 1].
#include <cstdint>

#include "citymodel/semantic_mesh.h"
#include "synth/opening_frames.h"
#include "synth/synth_geometry.h"

namespace cls::synth {

struct Lighting {
  Vec3f sun_dir{0, 0, 1};  // unit vector towards the sun
  Vec3f sun{0.9f, 0.86f, 0.78f};
  Vec3f sky_ambient{0.48f, 0.51f, 0.58f}, ground_ambient{0.28f, 0.27f, 0.24f};
};

class SurfaceShader {
 public:
  // Keeps references to `g`; the lighting and palette are drawn from the seed.
  SurfaceShader(const SynthGeometry& g, const SemanticMesh& mesh, uint64_t seed);

  // Material colour at point p on triangle tri (n: the triangle's unit normal, either side).
  Vec3f albedo(uint32_t tri, Vec3f p, Vec3f n) const;
  // Lit colour: `n` faces the viewer, `sun_visible` tells whether the shadow ray reached the sky.
  Vec3f shade(Vec3f albedo, Vec3f n, bool sun_visible) const;
  // Colour of the sky in unit direction d (depends on direction only, as a sky at infinity does).
  Vec3f sky(Vec3f d) const;

  const Lighting& lighting() const { return lighting_; }

 private:
  Vec3f wall(Vec3f p, Vec3f n) const;
  Vec3f glass(const OpeningFrame& f, Vec3f p) const;
  Vec3f door(const OpeningFrame& f, Vec3f p) const;
  Vec3f roof(Vec3f p, Vec3f n) const;
  Vec3f terrain(Vec3f p) const;

  const SynthGeometry& g_;
  OpeningFrames openings_;
  Lighting lighting_;
  uint64_t key_;  // noise key derived from the seed
  Vec3f plaster_, brick_, roof_, window_frame_, door_wood_;
};

}  // namespace cls::synth
