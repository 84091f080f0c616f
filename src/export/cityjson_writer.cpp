#include "export/cityjson_writer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "core/math.h"
#include "core/log.h"
#include "georef/crs_name.h"

namespace cls {
using nlohmann::json;

namespace {

// CityJSON 2.0's semantic surface types of buildings and their installations (specs, "Semantics of
// geometric primitives"), and the building CityObject types a level-2 entity can be.
const std::vector<std::string> kSurfaceTypes = {"RoofSurface",  "GroundSurface",     "WallSurface",         "ClosureSurface",
                                                "OuterCeilingSurface", "OuterFloorSurface", "Window", "Door",
                                                "InteriorWallSurface", "CeilingSurface", "FloorSurface"};
const std::vector<std::string> kInstallationTypes = {"BuildingInstallation", "BuildingConstructiveElement"};

// The first of the class's source types in `allowed`, "" if none.
std::string cityjson_type(const Taxonomy& taxonomy, int class_id, const std::vector<std::string>& allowed) {
  if (class_id < 0) return "";
  for (const std::string& t : taxonomy.classes[class_id].source_types)
    if (std::find(allowed.begin(), allowed.end(), t) != allowed.end()) return t;
  return "";
}

double ring_area(const std::vector<uint32_t>& ring, const std::vector<std::array<double, 3>>& v) {
  Vec3d n{0, 0, 0};
  for (size_t i = 0; i < ring.size(); ++i) {
    const auto& a = v[ring[i]];
    const auto& b = v[ring[(i + 1) % ring.size()]];
    n = n + Vec3d{(a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]), (a[0] - b[0]) * (a[1] + b[1])};
  }
  return 0.5 * norm(n);
}

}  // namespace

std::vector<std::vector<uint32_t>> polygon_rings(const std::vector<std::array<uint32_t, 3>>& triangles,
                                                 const std::vector<std::array<double, 3>>& vertices) {
  // Undirected edge -> how many triangles use it; a boundary edge keeps its triangle's direction.
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::multimap<uint32_t, uint32_t> next;  // boundary edges a -> b
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (uses[std::minmax(t[k], t[(k + 1) % 3])] == 1) next.emplace(t[k], t[(k + 1) % 3]);
  std::vector<std::vector<uint32_t>> rings;
  while (!next.empty()) {
    auto edge = next.begin();
    const uint32_t start = edge->first;
    std::vector<uint32_t> ring;
    while (true) {
      ring.push_back(edge->first);
      const uint32_t to = edge->second;
      next.erase(edge);
      if (to == start) break;
      edge = next.find(to);
      if (edge == next.end()) {  // an open chain: no closed boundary (the triangles were not one polygon)
        ring.clear();
        break;
      }
    }
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }
  std::stable_sort(rings.begin(), rings.end(), [&](const auto& a, const auto& b) {
    return ring_area(a, vertices) > ring_area(b, vertices);
  });
  return rings;
}

std::vector<json> cityjson_sequence(const json& document) {
  const json& objects = document.at("CityObjects");
  const json& vertices = document.at("vertices");
  json header = document;
  header["CityObjects"] = json::object();
  header["vertices"] = json::array();
  std::vector<json> lines{std::move(header)};
  for (auto top = objects.begin(); top != objects.end(); ++top) {
    if (top->contains("parents")) continue;
    json feature{{"type", "CityJSONFeature"}, {"id", top.key()}, {"CityObjects", json::object()}, {"vertices", json::array()}};
    std::unordered_map<int64_t, int64_t> local;
    // Boundaries nest arrays of vertex indices (surfaces of rings here; solids nest deeper): walk to the numbers.
    const std::function<void(json&)> renumber = [&](json& b) {
      if (b.is_array()) {
        for (json& x : b) renumber(x);
        return;
      }
      const int64_t v = b.get<int64_t>();
      const auto [it, first] = local.try_emplace(v, static_cast<int64_t>(local.size()));
      if (first) feature["vertices"].push_back(vertices.at(v));
      b = it->second;
    };
    std::vector<std::string> pending{top.key()};
    while (!pending.empty()) {
      const std::string id = pending.back();
      pending.pop_back();
      json object = objects.at(id);
      if (object.contains("geometry"))
        for (json& geometry : object["geometry"]) renumber(geometry.at("boundaries"));
      for (const json& child : object.value("children", json::array())) pending.push_back(child.get<std::string>());
      feature["CityObjects"][id] = std::move(object);
    }
    lines.push_back(std::move(feature));
  }
  return lines;
}

std::string cityjson_reference_system(const std::string& crs_name) {
  const std::optional<CrsName> crs = parse_crs_name(crs_name);
  return crs ? cat("https://www.opengis.net/def/crs/EPSG/0/", crs->horizontal_epsg) : "";
}

CityJsonDocument semantic_mesh_cityjson(const SemanticMesh& mesh, const Taxonomy& taxonomy,
                                        const std::string& reference_system) {
  const auto& entities = mesh.entities;
  const int num_entities = static_cast<int>(entities.size());
  // Which entities are CityObjects, and their unique ids.
  std::vector<std::string> object_type(num_entities);
  for (int e = 0; e < num_entities; ++e) {
    const SemanticEntity& s = entities[e];
    if (s.parent >= e) throw std::logic_error(cat("CityJSON: entity ", e, " has parent ", s.parent));
    if (s.level == 3) object_type[e] = s.parent >= 0 && entities[s.parent].level == 3 ? "BuildingPart" : "Building";
    else if (s.level == 2) object_type[e] = cityjson_type(taxonomy, s.class_id, kInstallationTypes);
  }
  CityJsonDocument out;
  out.places.resize(num_entities);
  std::vector<int> owner(num_entities, -1);  // the CityObject entity each entity lies in (itself for one)
  std::unordered_map<std::string, int> taken;
  for (int e = 0; e < num_entities; ++e) {
    if (!object_type[e].empty()) {
      owner[e] = e;
      std::string id = entities[e].source_id.empty() ? cat("entity-", e) : entities[e].source_id;
      for (int k = 2; taken.count(id); ++k) id = cat(entities[e].source_id, "#", k);
      taken[id] = e;
      out.places[e].object = id;
      out.places[e].is_object = true;
    } else if (entities[e].parent >= 0) {
      owner[e] = owner[entities[e].parent];
    }
  }

  json objects = json::object();
  for (int e = 0; e < num_entities; ++e) {
    if (object_type[e].empty()) continue;
    json o{{"type", object_type[e]}};
    const int p = entities[e].parent >= 0 ? owner[entities[e].parent] : -1;
    if (p >= 0) {
      o["parents"] = {out.places[p].object};
      objects[out.places[p].object]["children"].push_back(out.places[e].object);
    }
    json& slot = objects[out.places[e].object];
    for (auto& [k, v] : o.items()) slot[k] = v;
  }

  // Vertices in millimetres about the origin, shared between polygons.
  std::map<std::array<int64_t, 3>, uint32_t> vertex_index;
  json vertices = json::array();
  const auto quantised = [&](uint32_t v) {
    std::array<int64_t, 3> q{};
    for (int a = 0; a < 3; ++a) q[a] = std::llround(mesh.vertices[v][a] * 1000.0);
    const auto [it, added] = vertex_index.emplace(q, static_cast<uint32_t>(vertex_index.size()));
    if (added) vertices.push_back({q[0], q[1], q[2]});
    return it->second;
  };

  // Triangles by source polygon, in mesh order.
  std::vector<std::vector<std::array<uint32_t, 3>>> polygon_triangles(mesh.polygon_ids.size());
  std::vector<int> polygon_entity(mesh.polygon_ids.size(), -1);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int32_t p = mesh.tri_polygon[t];
    polygon_triangles[p].push_back(mesh.triangles[t]);
    const auto& chain = mesh.tri_entity[t];
    polygon_entity[p] = chain[0] >= 0 ? chain[0] : chain[1] >= 0 ? chain[1] : chain[2];
  }
  struct Geometry {
    json boundaries = json::array();
    json surfaces = json::array();
    json values = json::array();
    std::unordered_map<int, int> surface_of;  // entity -> semantic surface index
  };
  std::map<int, Geometry> geometries;  // by CityObject entity
  // The semantic surface of entity e in its object's geometry, made on first use (its parent first).
  const std::function<int(Geometry&, int)> surface_index = [&](Geometry& g, int e) -> int {
    if (!object_type[e].empty()) return -1;
    const auto found = g.surface_of.find(e);
    if (found != g.surface_of.end()) return found->second;
    const std::string type = cityjson_type(taxonomy, entities[e].class_id, kSurfaceTypes);
    int index = -1;
    if (!type.empty()) {
      const int parent = entities[e].parent >= 0 ? surface_index(g, entities[e].parent) : -1;
      index = static_cast<int>(g.surfaces.size());
      g.surfaces.push_back({{"type", type}});
      if (parent >= 0) {
        g.surfaces[index]["parent"] = parent;
        g.surfaces[parent]["children"].push_back(index);
      }
    }
    g.surface_of[e] = index;
    return index;
  };

  for (size_t p = 0; p < polygon_triangles.size(); ++p) {
    const int e = polygon_entity[p];
    if (e < 0 || owner[e] < 0) continue;  // a face of no building: not part of a CityObject
    std::vector<std::vector<uint32_t>> rings = polygon_rings(polygon_triangles[p], mesh.vertices);
    json boundary = json::array();
    for (const auto& ring : rings) {
      json r = json::array();
      for (const uint32_t v : ring) {
        const uint32_t q = quantised(v);
        if (r.empty() || r.back() != q) r.push_back(q);
      }
      if (r.size() > 1 && r.front() == r.back()) r.erase(r.size() - 1);
      if (r.size() >= 3) boundary.push_back(std::move(r));
      else if (boundary.empty()) break;  // the exterior collapsed at millimetres: no polygon
    }
    if (boundary.empty()) continue;
    Geometry& g = geometries[owner[e]];
    const int s = surface_index(g, e);
    g.boundaries.push_back(std::move(boundary));
    g.values.push_back(s >= 0 ? json(s) : json(nullptr));
  }
  for (auto& [e, g] : geometries) {
    json geometry{{"type", "MultiSurface"}, {"lod", std::to_string(mesh.lod)}, {"boundaries", std::move(g.boundaries)}};
    if (!g.surfaces.empty()) geometry["semantics"] = {{"surfaces", std::move(g.surfaces)}, {"values", std::move(g.values)}};
    objects[out.places[e].object]["geometry"] = json::array({std::move(geometry)});
    for (const auto& [entity, index] : g.surface_of) out.places[entity] = {out.places[e].object, index, false};
  }
  for (int e = 0; e < num_entities; ++e) {
    if (out.places[e].object.empty() && owner[e] >= 0) out.places[e].object = out.places[owner[e]].object;
    if (!object_type[e].empty() && !objects[out.places[e].object].contains("geometry"))
      objects[out.places[e].object]["geometry"] = json::array();  // a building whose polygons lie in its parts
  }

  json metadata = json::object();
  if (!reference_system.empty()) metadata["referenceSystem"] = reference_system;
  out.document = {{"type", "CityJSON"},
                  {"version", "2.0"},
                  {"transform", {{"scale", {0.001, 0.001, 0.001}}, {"translate", {mesh.origin[0], mesh.origin[1], mesh.origin[2]}}}},
                  {"metadata", metadata},
                  {"CityObjects", std::move(objects)},
                  {"vertices", std::move(vertices)}};
  return out;
}

}  // namespace cls
