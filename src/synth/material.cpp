#include "synth/material.h"

#include <algorithm>
#include <string>

namespace cls::synth {

Material material_for_class(const SemanticClass& cls) {
  const auto maps = [&](std::initializer_list<const char*> types) {
    return std::any_of(types.begin(), types.end(), [&](const char* t) {
      return std::find(cls.source_types.begin(), cls.source_types.end(), std::string(t)) != cls.source_types.end();
    });
  };
  if (maps({"Window", "WindowSurface"})) return Material::Glass;
  if (maps({"Door", "DoorSurface"})) return Material::Door;
  if (maps({"WallSurface"})) return Material::Wall;
  if (maps({"RoofSurface"})) return Material::RoofTiles;
  if (maps({"GroundSurface"})) return Material::BuildingGround;
  if (maps({"BuildingInstallation", "BuildingConstructiveElement"})) return Material::Installation;
  return Material::PlainSurface;
}

}  // namespace cls::synth
