#include "citymodel/city_objects.h"

#include <stdexcept>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The first of `object` and its ancestors on `level` or coarser, -1 for none. Parents come before their
// children (from_json checks it), so every chain ends.
int32_t first_at(const std::vector<CityObject>& objects, int32_t object, int level) {
  while (object >= 0 && static_cast<size_t>(object) < objects.size() && objects[object].level < level)
    object = objects[object].parent;
  return object >= 0 && static_cast<size_t>(object) < objects.size() ? object : -1;
}

}  // namespace

int32_t CityObjects::at_level(int32_t object, int level) const {
  object = first_at(objects, object, level);
  // The whole-building level answers with the Building, not one of its BuildingParts.
  if (object >= 0 && level >= 3 && objects[object].level == 3)
    while (objects[object].parent >= 0 && objects[objects[object].parent].level == 3) object = objects[object].parent;
  return object;
}

int32_t CityObjects::part_of(int32_t object) const {
  object = first_at(objects, object, 3);
  return object >= 0 && objects[object].parent >= 0 && objects[objects[object].parent].level == 3 ? object : -1;
}

std::string CityObjects::class_name(int32_t object) const {
  if (object < 0 || static_cast<size_t>(object) >= objects.size()) return "";
  const int c = objects[object].class_id;
  return c >= 0 && static_cast<size_t>(c) < class_names.size() ? class_names[c] : "";
}

json CityObjects::to_json() const {
  json rows = json::array();
  for (size_t i = 0; i < objects.size(); ++i) {
    const CityObject& o = objects[i];
    rows.push_back({{"index", i}, {"id", o.id}, {"level", o.level}, {"class", o.class_id}, {"parent", o.parent}});
  }
  return {{"source", source}, {"classes", class_names}, {"objects", rows}};
}

namespace {

// What makes a table unusable, "" when nothing does: parents and classes out of range, a parent after
// its child (so no chain comes back to where it started), or on a finer level. The same level is fine:
// a BuildingPart in its Building or in another part, a surface of a BuildingInstallation.
std::string table_problem(const CityObjects& t) {
  const int64_t n = static_cast<int64_t>(t.objects.size());
  for (int64_t i = 0; i < n; ++i) {
    const CityObject& o = t.objects[i];
    if (o.parent < -1 || o.parent >= n) return cat("object ", i, " has parent ", o.parent, " of ", n, " objects");
    if (o.class_id < -1 || o.class_id >= static_cast<int>(t.class_names.size()))
      return cat("object ", i, " has class ", o.class_id, " of ", t.class_names.size(), " classes");
    if (o.parent >= i) return cat("object ", i, " has parent ", o.parent, "; a parent comes before its children");
    if (o.parent >= 0 && t.objects[o.parent].level < o.level)
      return cat("object ", i, " (level ", o.level, ") has parent ", o.parent, " on level ", t.objects[o.parent].level,
                 "; a parent lies on the same or a coarser level");
  }
  return "";
}

}  // namespace

CityObjects CityObjects::from_json(const json& j, const std::string& file) {
  CityObjects t;
  try {
    t.source = j.value("source", "");
    t.class_names = j.at("classes").get<std::vector<std::string>>();
    for (const json& row : j.at("objects")) {
      CityObject o;
      o.id = row.at("id").get<std::string>();
      o.level = row.at("level").get<int>();
      o.class_id = row.at("class").get<int>();
      o.parent = row.at("parent").get<int32_t>();
      t.objects.push_back(std::move(o));
    }
  } catch (const json::exception& e) {
    fail(file, std::string("not a city-object table (source, classes, objects[id, level, class, parent]): ") + e.what());
  }
  if (const std::string problem = table_problem(t); !problem.empty()) fail(file, problem);
  return t;
}

CityObjects city_objects(const SemanticMesh& mesh, const Taxonomy& taxonomy) {
  CityObjects t;
  t.source = mesh.source_path;
  for (const SemanticClass& c : taxonomy.classes) t.class_names.push_back(c.name);
  for (const SemanticEntity& e : mesh.entities) t.objects.push_back({e.source_id, e.level, e.class_id, e.parent});
  // A table made from a city model the readers accepted is ours: if it breaks a rule, that is a bug
  // (exit 3), never a "bad input" naming a file the user did not write.
  if (const std::string problem = table_problem(t); !problem.empty())
    throw std::logic_error(cat("the city-object table of ", mesh.source_path, " breaks its own rules: ", problem));
  return t;
}

std::vector<int32_t> finest_object_of_triangles(const SemanticMesh& mesh) {
  std::vector<int32_t> object(mesh.num_triangles(), -1);
  for (size_t t = 0; t < object.size() && t < mesh.tri_entity.size(); ++t)
    for (int l = 0; l < 3 && object[t] < 0; ++l) object[t] = mesh.tri_entity[t][l];
  return object;
}

std::vector<int32_t> building_of_entities(const SemanticMesh& mesh) {
  std::vector<int32_t> own(mesh.entities.size(), -1);
  for (size_t b = 0; b < mesh.buildings.size(); ++b) {
    const int32_t e = mesh.buildings[b];
    if (e < 0 || static_cast<size_t>(e) >= mesh.entities.size())
      throw Error(cat(mesh.source_path, ": building ", b, " refers to entity ", e, " of ", mesh.entities.size()));
    if (own[e] < 0) own[e] = static_cast<int32_t>(b);
  }
  std::vector<int32_t> result(mesh.entities.size(), -1);
  for (size_t e = 0; e < mesh.entities.size(); ++e) {
    int32_t cur = static_cast<int32_t>(e);
    // The chain is at most entities.size() long unless it has a cycle; stop there either way.
    for (size_t steps = 0; cur >= 0 && steps <= mesh.entities.size(); ++steps) {
      if (static_cast<size_t>(cur) >= mesh.entities.size()) break;
      if (own[cur] >= 0) {
        result[e] = own[cur];
        break;
      }
      cur = mesh.entities[cur].parent;
    }
  }
  return result;
}

std::vector<int32_t> building_of_triangles(const SemanticMesh& mesh) {
  const std::vector<int32_t> building = building_of_entities(mesh);
  std::vector<int32_t> result(mesh.num_triangles(), -1);
  for (size_t t = 0; t < result.size() && t < mesh.tri_entity.size(); ++t) {
    const int32_t whole = mesh.tri_entity[t][2];
    if (whole >= 0 && static_cast<size_t>(whole) < building.size()) result[t] = building[whole];
  }
  return result;
}

void write_city_objects(const fs::path& path, const CityObjects& objects) {
  write_text_atomic(path, objects.to_json().dump(1) + "\n");
}

CityObjects read_city_objects(const fs::path& path) {
  if (!fs::exists(path)) fail(path.string(), "missing (the city-object table written by `raycast`)");
  json j;
  try {
    j = json::parse(read_text_file(path));
  } catch (const json::exception& e) {
    fail(path.string(), std::string("not valid JSON: ") + e.what());
  }
  return CityObjects::from_json(j, path.string());
}

}  // namespace cls
