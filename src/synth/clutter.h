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

// Appends up to `count` trees (broad-leaved or conifers) to `placed`, each standing 0.1 to 2.5 m beyond
// its canopy's reach of the footprint box of `city` on a random side, off the road and clear of the
// objects already placed: occluders in front of the facades that the city model does not have. Its own
// random stream, so the other clutter is the same with and without them. A tree that finds no free
// place in 200 tries is left out.
void place_occluders(const Box3d& city, const Road& road, double terrain_z, uint64_t seed, int count,
                     std::vector<ClutterObject>& placed);

// Appends the triangles of clutter object `index` of g.clutter (Clutter source, its materials).
void add_clutter_mesh(SynthGeometry& g, uint32_t index);

}  // namespace cls::synth
