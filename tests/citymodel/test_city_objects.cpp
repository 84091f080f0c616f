// The city-object table with BuildingPart hierarchies (building -> part -> part), as nearly every
// official LoD2 dataset stores multi-part buildings, and the rule that a table made from a city
// model the readers accept always passes the checks a table read from a file gets.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "citymodel/city_model.h"
#include "citymodel/city_objects.h"
#include "core/error.h"
#include "core/log.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "cls_test_city_objects";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

int index_of(const CityObjects& t, const std::string& id) {
  for (size_t k = 0; k < t.objects.size(); ++k)
    if (t.objects[k].id == id) return static_cast<int>(k);
  ADD_FAILURE() << "no object " << id;
  return -1;
}

// A wall in the plane y = `y` with a window in its hole, as CityGML 2.0 writes it.
std::string gml_wall(const std::string& id, double y) {
  const auto ring = [&](double x0, double z0, double x1, double z1) {
    return cat(x0, ' ', y, ' ', z0, ' ', x1, ' ', y, ' ', z0, ' ', x1, ' ', y, ' ', z1, ' ', x0, ' ', y, ' ', z1, ' ', x0,
               ' ', y, ' ', z0);
  };
  return "<bldg:boundedBy><bldg:WallSurface gml:id=\"" + id + "\"><bldg:lod3MultiSurface><gml:MultiSurface>"
         "<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>" + ring(0, 0, 10, 10) +
         "</gml:posList></gml:LinearRing></gml:exterior><gml:interior><gml:LinearRing><gml:posList>" +
         ring(3, 3, 5, 5) + "</gml:posList></gml:LinearRing></gml:interior></gml:Polygon></gml:surfaceMember>"
         "</gml:MultiSurface></bldg:lod3MultiSurface><bldg:opening><bldg:Window gml:id=\"" + id +
         "-win\"><bldg:lod3MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon><gml:exterior>"
         "<gml:LinearRing><gml:posList>" + ring(3, 3, 5, 5) + "</gml:posList></gml:LinearRing></gml:exterior>"
         "</gml:Polygon></gml:surfaceMember></gml:MultiSurface></bldg:lod3MultiSurface></bldg:Window></bldg:opening>"
         "</bldg:WallSurface></bldg:boundedBy>";
}

std::string citygml(const std::string& ns_version, const std::string& buildings) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<core:CityModel xmlns:core=\"http://www.opengis.net/citygml/" +
         ns_version + "\" xmlns:bldg=\"http://www.opengis.net/citygml/building/" + ns_version +
         "\" xmlns:gml=\"http://www.opengis.net/gml\">" + buildings + "</core:CityModel>";
}

// Building B with a wall, its part P1 with a wall, and P1's own part P2 with a wall; a second
// building C with a part Q: the layout of a state LoD2 tile, one level deeper.
std::string nested_parts_gml(const std::string& ns_version) {
  const std::string part2 = "<bldg:consistsOfBuildingPart><bldg:BuildingPart gml:id=\"P2\">" + gml_wall("P2-wall", 20) +
                            "</bldg:BuildingPart></bldg:consistsOfBuildingPart>";
  const std::string part1 = "<bldg:consistsOfBuildingPart><bldg:BuildingPart gml:id=\"P1\">" + gml_wall("P1-wall", 10) +
                            part2 + "</bldg:BuildingPart></bldg:consistsOfBuildingPart>";
  return citygml(ns_version,
                 "<core:cityObjectMember><bldg:Building gml:id=\"B\">" + gml_wall("B-wall", 0) + part1 +
                     "</bldg:Building></core:cityObjectMember><core:cityObjectMember><bldg:Building gml:id=\"C\">"
                     "<bldg:consistsOfBuildingPart><bldg:BuildingPart gml:id=\"Q\">" +
                     gml_wall("Q-wall", 40) + "</bldg:BuildingPart></bldg:consistsOfBuildingPart>"
                     "</bldg:Building></core:cityObjectMember>");
}

// The same hierarchy in CityJSON 2.0 ("children" / "parents"), one wall with a window per object.
std::string nested_parts_cityjson() {
  std::string objects, vertices;
  int v = 0;
  const auto add = [&](const std::string& id, const std::string& type, const std::string& links, double y) {
    if (y < 0) {  // no geometry of its own, as a multi-part Building of a state tile
      objects += cat(objects.empty() ? "" : ",", "\"", id, "\":{\"type\":\"", type, "\"", links, "}");
      return;
    }
    // wall: outer square 0..10 with a hole 3..5; window: the hole.
    for (auto [x, z] : std::vector<std::pair<double, double>>{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 3}, {3, 5}, {5, 5}, {5, 3}})
      vertices += cat(vertices.empty() ? "" : ",", "[", x, ",", y, ",", z, "]");
    const auto idx = [&](int k) { return std::to_string(v + k); };
    objects += cat(objects.empty() ? "" : ",", "\"", id, "\":{\"type\":\"", type, "\"", links,
                   ",\"geometry\":[{\"type\":\"MultiSurface\",\"lod\":\"3\",\"boundaries\":[[[", idx(0), ",", idx(1), ",",
                   idx(2), ",", idx(3), "],[", idx(4), ",", idx(5), ",", idx(6), ",", idx(7), "]],[[", idx(7), ",", idx(6),
                   ",", idx(5), ",", idx(4), "]]],\"semantics\":{\"surfaces\":[{\"type\":\"WallSurface\",\"id\":\"", id,
                   "-wall\"},{\"type\":\"Window\",\"parent\":0,\"id\":\"", id, "-wall-win\"}],\"values\":[0,1]}}]}");
    v += 8;
  };
  add("B", "Building", ",\"children\":[\"P1\"]", 0);
  add("P1", "BuildingPart", ",\"parents\":[\"B\"],\"children\":[\"P2\"]", 10);
  add("P2", "BuildingPart", ",\"parents\":[\"P1\"]", 20);
  add("C", "Building", ",\"children\":[\"Q\"]", -1);
  add("Q", "BuildingPart", ",\"parents\":[\"C\"]", 40);
  return "{\"type\":\"CityJSON\",\"version\":\"2.0\",\"transform\":{\"scale\":[1,1,1],\"translate\":[0,0,0]},"
         "\"CityObjects\":{" + objects + "},\"vertices\":[" + vertices + "]}";
}

}  // namespace

// Every encoding of the nested hierarchy gives a table whose parts chain up to their building, that
// survives objects.json, and whose whole-building level answers with the Building itself.
TEST(CityObjects, NestedBuildingPartsAnswerWithTheirBuilding) {
  const Taxonomy tax = Taxonomy::builtin();
  const std::map<std::string, fs::path> files = {
      {"CityGML 1.0", write_temp("parts1.gml", nested_parts_gml("1.0"))},
      {"CityGML 2.0", write_temp("parts2.gml", nested_parts_gml("2.0"))},
      {"CityJSON 2.0", write_temp("parts.city.json", nested_parts_cityjson())}};
  for (const auto& [format, path] : files) {
    SCOPED_TRACE(format);
    const SemanticMesh mesh = load_city_model(path.string(), tax, 0);
    const CityObjects t = CityObjects::from_json(city_objects(mesh, tax).to_json(), "objects.json");
    ASSERT_EQ(mesh.buildings.size(), 2u);  // B and C; parts are not buildings of their own
    const int b = index_of(t, "B"), p1 = index_of(t, "P1"), p2 = index_of(t, "P2"), c = index_of(t, "C"),
              q = index_of(t, "Q");
    EXPECT_EQ(t.objects[p1].parent, b);
    EXPECT_EQ(t.objects[p2].parent, p1);
    EXPECT_EQ(t.objects[q].parent, c);
    for (int part : {p1, p2, q}) EXPECT_EQ(t.objects[part].level, 3);
    for (const std::string owner : {"B", "P1", "P2", "Q"}) {  // C has no geometry of its own
      const int wall = index_of(t, owner + "-wall"), window = index_of(t, owner + "-wall-win");
      const int building = owner == "Q" ? c : b;
      EXPECT_EQ(t.class_name(wall), "wall") << owner;
      EXPECT_EQ(t.class_name(window), "window") << owner;
      EXPECT_EQ(t.at_level(window, 1), window) << owner;
      EXPECT_EQ(t.at_level(window, 2), wall) << owner;
      EXPECT_EQ(t.at_level(window, 3), building) << owner;
      EXPECT_EQ(t.at_level(wall, 3), building) << owner;
    }
    EXPECT_EQ(t.at_level(p2, 3), b);
    EXPECT_EQ(t.at_level(p2, 1), p2);  // nothing finer: the part answers for itself
    // building.png agrees: every triangle's building is B's or C's.
    const std::vector<int32_t> of_entity = building_of_entities(mesh);
    EXPECT_EQ(of_entity[p2], of_entity[b]);
    EXPECT_EQ(of_entity[q], of_entity[c]);
    EXPECT_NE(of_entity[b], of_entity[c]);
  }
}

// A table made from a model the readers accept is ours: it must pass from_json's checks, or a run
// would stop with "bad input" naming a file the user never wrote. Every real sample the project
// ships (data/citygml, read from the folder) is such a model.
TEST(CityObjects, EveryModelTheReadersAcceptGivesATableThatReadsBack) {
  const Taxonomy tax = Taxonomy::builtin();
  size_t models = 0, objects = 0;
  for (const auto& entry : fs::recursive_directory_iterator(std::string(CLS_TEST_DATA) + "/citygml")) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".gml" && ext != ".json" && ext != ".jsonl")) continue;
    SCOPED_TRACE(entry.path().string());
    SemanticMesh mesh;
    try {
      mesh = load_city_model(entry.path().string(), tax, 0);
    } catch (const Error& e) {
      // The samples of bad input (citygml4j's invalid building; cjval's sem.json, whose semantics do not
      // match its boundaries: test_cityjson_reader.cpp); any other file must load.
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name == "invalid_building_v3.gml" || name == "sem.json") << e.what();
      continue;
    }
    const CityObjects t = city_objects(mesh, tax);
    const CityObjects back = CityObjects::from_json(t.to_json(), "objects.json");
    ASSERT_EQ(back.objects.size(), mesh.entities.size());
    for (size_t k = 0; k < back.objects.size(); ++k) {
      ASSERT_EQ(back.objects[k].parent, mesh.entities[k].parent);
      ASSERT_EQ(back.objects[k].id, mesh.entities[k].source_id);
    }
    ++models;
    objects += back.objects.size();
  }
  EXPECT_GE(models, 5u);  // the folder holds more; a glob that finds none must not pass
  EXPECT_GT(objects, 0u);
}

TEST(CityObjects, ATableFromAFileIsCheckedAndAMeshThatBreaksTheRulesIsABug) {
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = load_city_model(write_temp("p.gml", nested_parts_gml("2.0")).string(), tax, 0);
  const nlohmann::json good = city_objects(mesh, tax).to_json();
  const auto message = [](const nlohmann::json& j) {
    try {
      CityObjects::from_json(j, "labels/objects.json");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(good), "accepted");
  nlohmann::json after = good;  // the building inside its own window: a parent after its child
  after["objects"][0]["parent"] = static_cast<int>(good["objects"].size()) - 1;
  EXPECT_NE(message(after).find("labels/objects.json: object 0 has parent"), std::string::npos) << message(after);
  nlohmann::json finer = good;  // a wall (level 2) as the parent of its building's part (level 3)
  const int p1 = index_of(CityObjects::from_json(good, "t"), "P1");
  const int wall = index_of(CityObjects::from_json(good, "t"), "B-wall");
  ASSERT_LT(wall, p1);
  finer["objects"][p1]["parent"] = wall;
  EXPECT_NE(message(finer).find("same or a coarser level"), std::string::npos) << message(finer);

  SemanticMesh broken = mesh;  // the same rule broken by a mesh: std::logic_error, exit 3
  broken.entities[1].parent = 1;
  EXPECT_THROW(city_objects(broken, tax), std::logic_error);
}

// An official state tile as published (Geobasis NRW, CityGML 1.0, parts inline in their Building):
// the counts come from the file's own tags, not from our reader.
TEST(CityObjects, APublishedLod2TileKeepsEveryPartWithItsBuilding) {
  const fs::path tile = fs::path(CLS_TEST_DATA) / "citygml/nrw/LoD2_32_329_5730_1_NW.gml";
  std::ifstream in(tile, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto tags = [&](const std::string& tag) {
    size_t n = 0;
    for (size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + 1)) ++n;
    return n;
  };
  const size_t buildings = tags("<bldg:Building "), parts = tags("<bldg:BuildingPart ");
  ASSERT_GT(parts, 0u);
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = load_city_model(tile.string(), tax, 0);
  const CityObjects t = CityObjects::from_json(city_objects(mesh, tax).to_json(), "objects.json");
  EXPECT_EQ(mesh.buildings.size(), buildings);
  size_t seen_parts = 0, part_surfaces = 0;
  const std::vector<int32_t> building_of = building_of_entities(mesh);
  for (size_t k = 0; k < t.objects.size(); ++k) {
    const CityObject& o = t.objects[k];
    if (o.level != 3 || o.parent < 0) continue;
    ++seen_parts;  // a level-3 object inside another one: a BuildingPart
    const int32_t building = t.objects[o.parent].parent < 0 ? o.parent : -1;
    EXPECT_GE(building, 0) << o.id << ": the tile's parts lie directly in their Building";
    EXPECT_EQ(t.at_level(static_cast<int32_t>(k), 3), building) << o.id;
    for (size_t s = 0; s < t.objects.size(); ++s)
      if (t.objects[s].parent == static_cast<int32_t>(k)) {
        ++part_surfaces;
        EXPECT_EQ(t.at_level(static_cast<int32_t>(s), 3), building) << t.objects[s].id;
        EXPECT_EQ(t.at_level(static_cast<int32_t>(s), 2), static_cast<int32_t>(s)) << t.objects[s].id;
        EXPECT_EQ(building_of[s], building_of[building]) << t.objects[s].id;
      }
  }
  EXPECT_EQ(seen_parts, parts);
  EXPECT_GT(part_surfaces, parts);  // every part has walls, a roof and a ground of its own
}

// CityJSON "parents" that come back to where they started are bad input, named, not a hang.
TEST(CityObjects, ACityJsonPartsCycleIsAnError) {
  const std::string cycle = R"({"type":"CityJSON","version":"2.0","transform":{"scale":[1,1,1],"translate":[0,0,0]},
    "CityObjects":{
      "A":{"type":"BuildingPart","parents":["B"],"children":["B"],"geometry":[{"type":"MultiSurface","lod":"2",
        "boundaries":[[[0,1,2]]]}]},
      "B":{"type":"BuildingPart","parents":["A"],"children":["A"]}},
    "vertices":[[0,0,0],[1,0,0],[1,1,0]]})";
  try {
    load_city_model(write_temp("cycle.city.json", cycle).string(), Taxonomy::builtin(), 0);
    FAIL() << "a cycle of parts accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("comes back to"), std::string::npos) << e.what();
  }
}

// A BuildingPart inside a wall is not a hierarchy the levels can answer with: bad input, named at its
// element, never the "internal error" a table breaking its rules would be.
TEST(CityObjects, AFeatureInsideAFinerOneIsBadInputNamedAtItsElement) {
  const std::string wall_with_part =
      "<core:cityObjectMember><bldg:Building gml:id=\"B\"><bldg:boundedBy><bldg:WallSurface gml:id=\"W\">"
      "<bldg:consistsOfBuildingPart><bldg:BuildingPart gml:id=\"P\">" + gml_wall("P-wall", 0) +
      "</bldg:BuildingPart></bldg:consistsOfBuildingPart></bldg:WallSurface></bldg:boundedBy></bldg:Building>"
      "</core:cityObjectMember>";
  const fs::path path = write_temp("wall_with_part.gml", citygml("2.0", wall_with_part));
  try {
    load_city_model(path.string(), Taxonomy::builtin(), 0);
    FAIL() << "a part inside a wall accepted";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path.string(), 0), 0u) << m;
    EXPECT_NE(m.find("BuildingPart: object \"P\" (level 3) lies inside \"W\" (level 2)"), std::string::npos) << m;
  }
}
