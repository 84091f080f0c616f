#include "citymodel/gml_vocabulary.h"

#include <cstring>
#include <utility>

namespace cls {

std::string_view local_name(const char* qualified) {
  const char* colon = std::strrchr(qualified, ':');
  return colon ? colon + 1 : qualified;
}

pugi::xml_attribute prefixed_attribute(pugi::xml_node n, std::string_view local) {
  for (pugi::xml_attribute a : n.attributes()) {
    const char* colon = std::strchr(a.name(), ':');
    if (colon && local == colon + 1 && std::strncmp(a.name(), "xmlns:", 6) != 0) return a;
  }
  return {};
}

int structural_level(std::string_view type) {
  static const std::pair<std::string_view, int> kRoles[] = {
      {"Building", 3},           {"BuildingPart", 3},
      {"WallSurface", 2},        {"RoofSurface", 2},
      {"GroundSurface", 2},      {"ClosureSurface", 2},
      {"OuterCeilingSurface", 2}, {"OuterFloorSurface", 2},
      {"InteriorWallSurface", 2}, {"CeilingSurface", 2},
      {"FloorSurface", 2},       {"BuildingInstallation", 2},
      {"IntBuildingInstallation", 2}, {"BuildingConstructiveElement", 2},
      {"Window", 1},             {"Door", 1},
      {"WindowSurface", 1},      {"DoorSurface", 1},
  };
  for (const auto& [name, level] : kRoles)
    if (name == type) return level;
  return 0;
}

int surface_lod(std::string_view name) {
  if (name.size() < 5 || name.substr(0, 3) != "lod" || name[3] < '0' || name[3] > '4' || name[4] < 'A' ||
      name[4] > 'Z')
    return -1;
  for (std::string_view kind : {"Curve", "TerrainIntersection", "Implicit", "Point", "RoofEdge"})
    if (name.find(kind) != std::string_view::npos) return -1;
  return name[3] - '0';
}

}  // namespace cls
