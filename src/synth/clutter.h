#pragma once
// Objects around the building that are not in the city model (trees, cars, a bench, a fence),
// so that the label maps' coverage is not everywhere, as in real photos.
#include <cstdint>
#include <vector>

#include "synth/synth_geometry.h"

namespace cls::synth {

// Places a few objects on the terrain at z = terrain_z, deterministically by the seed: outside
// the xy footprint of `city` (plus a margin), inside `area`, not overlapping each other; cars on
// the road, everything else off it.
std::vector<ClutterObject> place_clutter(const Box3d& city, const Box3d& area, const Road& road, double terrain_z,
                                         uint64_t seed);

// Appends the triangles of clutter object `index` of g.clutter (Clutter source, its materials).
void add_clutter_mesh(SynthGeometry& g, uint32_t index);

}  // namespace cls::synth
