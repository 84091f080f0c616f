#pragma once
// Surface materials of the synthetic scenes.
#include <cstdint>

#include "citymodel/taxonomy.h"

namespace cls::synth {

enum class Material : uint8_t {
  Wall,          // plaster or brick, chosen per building by the seed
  Glass,         // window: frame border, mullions, fake sky reflection
  Door,          // wooden panels in a frame
  RoofTiles,
  BuildingGround,
  Installation,
  PlainSurface,  // any other city-model class
  Terrain,       // grass, with an asphalt road band
  Bark,
  Foliage,
  CarPaint,
  CarWindow,
  Tyre,
  Wood,
};

// Material of a city-model face, from the CityGML/CityJSON types its class maps (so a user
// taxonomy with other class names still gets windows, doors, walls and roofs right).
Material material_for_class(const SemanticClass& cls);

}  // namespace cls::synth
