#pragma once
// How the CityGML reader recognises what it reads, shared with the tools that edit CityGML documents
// (synth --drop-openings): element and attribute names without their namespace prefix, the building
// model's feature types and their level, and the geometry properties of a LoD.
#include <pugixml.hpp>

#include <string_view>

namespace cls {

// "bldg:WallSurface" -> "WallSurface".
std::string_view local_name(const char* qualified);
inline std::string_view local_name(pugi::xml_node n) { return local_name(n.name()); }

// An attribute by local name with any namespace prefix ("gml:id", "xlink:href"); never an xmlns declaration.
pugi::xml_attribute prefixed_attribute(pugi::xml_node n, std::string_view local);

template <class F>
void for_each_element_child(pugi::xml_node n, F&& f) {
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element) f(c);
}

// Entity level of a CityGML feature type by its role in the building model (3 building, 2 boundary
// surface or installation, 1 opening); 0 for other types.
int structural_level(std::string_view type);

// LoD of a geometry property holding surfaces ("lod3MultiSurface" -> 3, "lod2Solid" -> 2), or -1
// for other elements and for curve, point and implicit geometry ("lod2MultiCurve").
int surface_lod(std::string_view name);

}  // namespace cls
