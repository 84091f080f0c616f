// CityJSON / CityJSONSeq reader against the sample files' verified figures
// (data/citygml/README.md) and hand-made documents.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "citymodel/cityjson_reader.h"
#include "citymodel/mesh_stats.h"
#include "core/error.h"

using namespace cls;

namespace {

const std::string kData = CLS_TEST_DATA;

struct ClassFigures {
  size_t triangles = 0, objects = 0;
  double area = 0;
};

std::map<std::string, ClassFigures> figures(const SemanticMesh& mesh, const Taxonomy& tax) {
  std::map<std::string, ClassFigures> out;
  for (const ClassStats& c : compute_mesh_stats(mesh, tax).classes) out[c.name] = {c.triangles, c.objects, c.area};
  return out;
}

// Entities of a class whose parent is an entity of another given class.
size_t entities_under(const SemanticMesh& mesh, const Taxonomy& tax, const std::string& cls_name,
                      const std::string& parent_name) {
  size_t n = 0;
  for (const SemanticEntity& e : mesh.entities)
    if (e.class_id == tax.find(cls_name) && e.parent >= 0 &&
        mesh.entities[e.parent].class_id == tax.find(parent_name))
      ++n;
  return n;
}

SemanticMesh parse(const std::string& json, int lod = 0) {
  return parse_cityjson(json, "test.json", Taxonomy::builtin(), lod);
}

}  // namespace

TEST(CityJsonReader, StationHasItsOpeningsUnderTheirWalls) {
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = read_cityjson(kData + "/citygml/cityjson/texture4.city.json", tax, 0);
  EXPECT_EQ(mesh.format, "CityJSON");
  EXPECT_EQ(mesh.version, "2.0");
  EXPECT_EQ(mesh.crs, "http://www.opengis.net/def/crs/EPSG/0/3068");
  EXPECT_EQ(mesh.lod, 3);
  auto f = figures(mesh, tax);
  EXPECT_EQ(f["window"].objects, 15u);
  EXPECT_EQ(f["door"].objects, 6u);
  EXPECT_EQ(f["wall"].objects, 9u);
  EXPECT_EQ(f["roof"].objects, 3u);
  EXPECT_EQ(f["ground"].objects, 1u);
  EXPECT_EQ(f["installation"].objects, 2u);  // the two chimneys
  EXPECT_EQ(f.count("surface"), 0u);         // every face of the building has semantics
  EXPECT_EQ(mesh.buildings.size(), 1u);
  // Every opening sits under a wall (its semantic "parent"), every wall under the building.
  EXPECT_EQ(entities_under(mesh, tax, "window", "wall"), 15u);
  EXPECT_EQ(entities_under(mesh, tax, "door", "wall"), 6u);
  EXPECT_EQ(entities_under(mesh, tax, "wall", "building"), 9u);
  EXPECT_EQ(entities_under(mesh, tax, "installation", "building"), 2u);
  for (const char* c : {"window", "door", "wall", "roof", "ground", "installation"}) {
    EXPECT_GT(f[c].triangles, 0u) << c;
    EXPECT_GT(f[c].area, 0.0) << c;
  }
  // A window face: level 1 window, level 2 its wall, level 3 the building.
  bool found = false;
  for (size_t t = 0; t < mesh.num_triangles() && !found; ++t) {
    if (mesh.tri_class[t] != tax.find("window")) continue;
    found = true;
    EXPECT_EQ(mesh.tri_level_class[t][0], tax.find("window"));
    EXPECT_EQ(mesh.tri_level_class[t][1], tax.find("wall"));
    EXPECT_EQ(mesh.tri_level_class[t][2], tax.find("building"));
    EXPECT_EQ(mesh.entities[mesh.tri_entity[t][2]].source_id, "GMLID_BUI184698_512_898");
  }
  EXPECT_TRUE(found);
}

TEST(CityJsonReader, PolygonIdsNameObjectGeometryAndSurface) {
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = read_cityjson(kData + "/citygml/cityjson/texture4.city.json", tax, 3);
  // The building's geometry 0 has 174 surfaces; all of them are non-degenerate here.
  std::set<std::string> ids(mesh.polygon_ids.begin(), mesh.polygon_ids.end());
  EXPECT_TRUE(ids.count("GMLID_BUI184698_512_898/0/0"));
  EXPECT_TRUE(ids.count("GMLID_BUI184698_512_898/0/173"));
  EXPECT_FALSE(ids.count("GMLID_BUI184698_512_898/0/174"));
}

TEST(CityJsonReader, HundredBuildingsDocumentAndSequenceAgreeWithReadme) {
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh doc = read_cityjson(kData + "/citygml/citygml4j/lod2_buildings_v2.json", tax, 0);
  const SemanticMesh seq =
      read_cityjson(kData + "/citygml/citygml4j/lod2_buildings_as_CityJSON_features.jsonl", tax, 0);
  for (const SemanticMesh* mesh : {&doc, &seq}) {
    EXPECT_EQ(mesh->buildings.size(), 100u);
    EXPECT_EQ(mesh->lod, 2);
    auto f = figures(*mesh, tax);
    EXPECT_EQ(f["ground"].objects, 100u);
    EXPECT_EQ(f["roof"].objects, 200u);
    EXPECT_EQ(f["wall"].objects, 400u);
    EXPECT_NEAR(f["ground"].area, 4800, 4800 * 0.005);
    EXPECT_NEAR(f["roof"].area, 9582, 9582 * 0.005);
    EXPECT_NEAR(f["wall"].area, 16460, 16460 * 0.005);
    EXPECT_EQ(f.count("surface"), 0u);  // every face has semantics
  }
  // Same geometry: identical counts, areas equal to rounding.
  auto a = figures(doc, tax), b = figures(seq, tax);
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [name, fa] : a) {
    EXPECT_EQ(fa.triangles, b[name].triangles) << name;
    EXPECT_EQ(fa.objects, b[name].objects) << name;
    EXPECT_NEAR(fa.area, b[name].area, 1e-6 * fa.area) << name;
  }
  EXPECT_EQ(doc.num_triangles(), seq.num_triangles());
}

TEST(CityJsonReader, SequenceDetectionByContent) {
  EXPECT_TRUE(is_cityjson_seq("{\"type\":\"CityJSON\"}\n{\"type\":\"CityJSONFeature\"}\n"));
  EXPECT_FALSE(is_cityjson_seq("{\"type\":\"CityJSON\"}\n"));                // a one-line document
  EXPECT_FALSE(is_cityjson_seq("{\n  \"type\": \"CityJSON\"\n}\n"));          // pretty-printed
  EXPECT_FALSE(is_cityjson_seq("<CityModel/>\n<x/>\n"));
}

// multi_lod.json: 10 buildings, each with LoD 1.2 (180 surfaces in all, no semantics), 1.3 (224,
// no semantics) and 2.2 (348: 204 wall, 84 roof, 60 ground). Only one geometry per building may
// be used, or the copies overlap.
TEST(CityJsonReader, MultiLodTakesOneGeometryPerObject) {
  const Taxonomy tax = Taxonomy::builtin();
  const std::string path = kData + "/citygml/cityjson/multi_lod.json";
  auto geometry_indices = [](const SemanticMesh& m) {
    std::set<std::string> g;
    for (const std::string& id : m.polygon_ids) g.insert(id.substr(id.find('/') + 1, id.rfind('/') - id.find('/') - 1));
    return g;
  };
  const SemanticMesh lod1 = read_cityjson(path, tax, 1);
  EXPECT_EQ(lod1.lod, 1);
  EXPECT_EQ(geometry_indices(lod1), std::set<std::string>{"1"});  // the 1.3 geometries, not 1.2
  EXPECT_LE(lod1.polygon_ids.size(), 224u);
  EXPECT_GE(lod1.polygon_ids.size(), 200u);  // a few may be degenerate
  EXPECT_EQ(figures(lod1, tax).count("surface"), 1u);
  EXPECT_EQ(lod1.buildings.size(), 10u);

  const SemanticMesh lod2 = read_cityjson(path, tax, 2);
  const SemanticMesh highest = read_cityjson(path, tax, 0);
  EXPECT_EQ(geometry_indices(lod2), std::set<std::string>{"2"});
  EXPECT_EQ(highest.lod, 2);
  EXPECT_EQ(highest.num_triangles(), lod2.num_triangles());
  auto f = figures(lod2, tax);
  EXPECT_EQ(f.count("surface"), 0u);
  EXPECT_GT(f["wall"].area, 0.0);
  EXPECT_GT(f["roof"].area, 0.0);
  EXPECT_GT(f["ground"].area, 0.0);

  try {
    read_cityjson(path, tax, 3);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("LoD 3"), std::string::npos) << what;
    EXPECT_NE(what.find("1, 2"), std::string::npos) << what;
  }
}

TEST(CityJsonReader, RotterdamSubset) {
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = read_cityjson(kData + "/citygml/cityjson/rotterdam_subset.json", tax, 0);
  EXPECT_EQ(mesh.buildings.size(), 16u);
  auto f = figures(mesh, tax);
  EXPECT_GT(f["wall"].triangles, 0u);
  EXPECT_GT(f["roof"].triangles, 0u);
  EXPECT_GT(f["ground"].triangles, 0u);
  // Local origin: the floor of the bounding-box minimum, near the transform's translate.
  EXPECT_NEAR(mesh.origin[0], 90409, 1000);
  EXPECT_NEAR(mesh.origin[1], 435440, 1000);
}

// A hand-made CityJSON 1.1 document: one 2 x 3 m rectangle (area 6) with a 1 x 1 m hole,
// transform scale 0.5, large translate.
TEST(CityJsonReader, TransformHolesAndVersion11) {
  const std::string json = R"({"type":"CityJSON","version":"1.1",
    "transform":{"scale":[0.5,0.5,0.5],"translate":[500000.0,5400000.0,100.0]},
    "metadata":{"referenceSystem":"https://www.opengis.net/def/crs/EPSG/0/25832"},
    "CityObjects":{"b":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"2",
      "boundaries":[[[0,1,2,3],[4,5,6,7]]],
      "semantics":{"surfaces":[{"type":"WallSurface"}],"values":[0]}}]}},
    "vertices":[[0,0,0],[4,0,0],[4,0,6],[0,0,6],[1,0,1],[1,0,3],[3,0,3],[3,0,1]]})";
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = parse(json);
  EXPECT_EQ(mesh.version, "1.1");
  EXPECT_EQ(mesh.crs, "https://www.opengis.net/def/crs/EPSG/0/25832");
  EXPECT_EQ(mesh.origin[0], 500000.0);
  EXPECT_EQ(mesh.origin[1], 5400000.0);
  EXPECT_EQ(mesh.origin[2], 100.0);
  auto f = figures(mesh, tax);
  EXPECT_NEAR(f["wall"].area, 2.0 * 3.0 - 1.0 * 1.0, 1e-9);
  EXPECT_EQ(mesh.polygon_ids, std::vector<std::string>{"b/0/0"});
  // A vertex: (4, 0, 6) * 0.5 + translate - origin = (2, 0, 3).
  bool corner = false;
  for (const auto& v : mesh.vertices) corner |= v[0] == 2.0 && v[1] == 0.0 && v[2] == 3.0;
  EXPECT_TRUE(corner);
}

// CityJSON 1.0: no transform (real coordinates), numeric lod; a BuildingPart and an installation
// belong to their building; faces without semantics are "surface".
TEST(CityJsonReader, Version10PartsAndInstallations) {
  const std::string json = R"({"type":"CityJSON","version":"1.0",
    "CityObjects":{
      "main":{"type":"Building","children":["part","chimney"]},
      "part":{"type":"BuildingPart","parents":["main"],"geometry":[{"type":"MultiSurface","lod":2,
        "boundaries":[[[0,1,2]]]}]},
      "chimney":{"type":"BuildingInstallation","parents":["main"],"geometry":[{"type":"MultiSurface","lod":2,
        "boundaries":[[[0,2,3]]]}]},
      "road":{"type":"Road","geometry":[{"type":"MultiSurface","lod":2,"boundaries":[[[0,1,3]]]}]}},
    "vertices":[[0.0,0.0,0.0],[2.0,0.0,0.0],[2.0,2.0,0.0],[0.0,2.0,0.0]]})";
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = parse(json);
  ASSERT_EQ(mesh.num_triangles(), 2u);  // the road is not a building
  ASSERT_EQ(mesh.buildings.size(), 1u);
  EXPECT_EQ(mesh.entities[mesh.buildings[0]].source_id, "main");
  for (size_t t = 0; t < 2; ++t) {
    EXPECT_EQ(mesh.tri_entity[t][2], mesh.buildings[0]);  // the part's face belongs to "main"
    EXPECT_EQ(mesh.tri_level_class[t][2], tax.find("building"));
  }
  auto f = figures(mesh, tax);
  EXPECT_NEAR(f["surface"].area, 2.0, 1e-12);
  EXPECT_NEAR(f["installation"].area, 2.0, 1e-12);
  EXPECT_EQ(f["building"].objects, 2u);  // the building and its part
  EXPECT_EQ(entities_under(mesh, tax, "installation", "building"), 1u);
}

// Solid and CompositeSolid nesting with semantics values nested the same way; an opening whose
// semantic parent is a wall; a geometry template placed twice.
TEST(CityJsonReader, SolidsOpeningsAndTemplates) {
  const std::string json = R"({"type":"CityJSON","version":"2.0",
    "transform":{"scale":[1,1,1],"translate":[0,0,0]},
    "CityObjects":{
      "s":{"type":"Building","geometry":[{"type":"Solid","lod":"2.2",
        "boundaries":[[[[0,1,2,3]],[[0,1,5,4]]]],
        "semantics":{"surfaces":[{"type":"GroundSurface"},{"type":"WallSurface","children":[2]},
                                 {"type":"Window","parent":1}],"values":[[0,1]]}}]},
      "c":{"type":"Building","geometry":[{"type":"CompositeSolid","lod":"2",
        "boundaries":[[[[[0,1,2,3]]]],[[[[4,5,6,7]]]]],
        "semantics":{"surfaces":[{"type":"RoofSurface"},{"type":"Window","parent":0}],"values":[[[0]],[[1]]]}}]},
      "t":{"type":"Building","geometry":[
        {"type":"GeometryInstance","template":0,"boundaries":[8],
         "transformationMatrix":[2,0,0,0, 0,2,0,0, 0,0,2,0, 0,0,0,1]},
        {"type":"GeometryInstance","template":0,"boundaries":[0],
         "transformationMatrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]}},
    "geometry-templates":{"templates":[{"type":"MultiSurface","lod":"2","boundaries":[[[0,1,2]]],
        "semantics":{"surfaces":[{"type":"RoofSurface"}],"values":[0]}}],
      "vertices-templates":[[0,0,0],[1,0,0],[0,1,0]]},
    "vertices":[[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1],[10,10,10]]})";
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = parse(json);
  auto f = figures(mesh, tax);
  EXPECT_NEAR(f["ground"].area, 1.0, 1e-12);
  EXPECT_NEAR(f["wall"].area, 1.0, 1e-12);
  // c: a roof (1) and a window on it (1); t: template triangle 0.5 scaled by 2 (area 2) + 0.5.
  EXPECT_NEAR(f["roof"].area, 1.0 + 2.0 + 0.5, 1e-12);
  EXPECT_NEAR(f["window"].area, 1.0, 1e-12);
  EXPECT_EQ(f["window"].objects, 1u);  // s's window has no face of its own
  EXPECT_EQ(entities_under(mesh, tax, "window", "roof"), 1u);
  EXPECT_EQ(mesh.buildings.size(), 3u);
  // The placed template: (2*(1,0,0) + (10,10,10)) = (12,10,10) is a vertex (origin is 0).
  bool placed = false;
  for (const auto& v : mesh.vertices) placed |= v[0] == 12.0 && v[1] == 10.0 && v[2] == 10.0;
  EXPECT_TRUE(placed);
}

// Each broken input is a cls::Error whose message names the file and says what is wrong.
TEST(CityJsonReader, BrokenInputsNameTheFileAndTheProblem) {
  const Taxonomy tax = Taxonomy::builtin();
  const std::string ok_head = R"({"type":"CityJSON","version":"2.0","transform":{"scale":[1,1,1],"translate":[0,0,0]},)";
  const std::string one_triangle =
      R"("CityObjects":{"b":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"2","boundaries":[[[0,1,2]]]}]}},)";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"type\":\"CityJSON\",", "malformed JSON"},
      {"[1,2,3]", "not a JSON object"},
      {"{\"type\":\"CityJSON\",\"version\":\"2.0\",\"CityObjects\":{},\"vertices\":[[1e999,0,0]]}", "malformed JSON"},
      {R"({"type":"CityJSON","version":"2.0","transform":{"scale":[0,1,1],"translate":[0,0,0]},)" + one_triangle +
           R"("vertices":[[0,0,0],[1,0,0],[0,1,0]]})",
       "zero"},
      {R"({"type":"CityJSON","version":"2.0","transform":{"scale":["a",1,1],"translate":[0,0,0]},)" + one_triangle +
           R"("vertices":[[0,0,0],[1,0,0],[0,1,0]]})",
       "transform.scale"},
      {R"({"type":"CityJSON","version":"2.0","transform":{"translate":[0,0,0]},)" + one_triangle +
           R"("vertices":[[0,0,0],[1,0,0],[0,1,0]]})",
       "no \"scale\""},
      {ok_head + one_triangle + R"("vertices":[[0,0,0],[1,null,0],[0,1,0]]})", "null coordinate"},
      {ok_head + one_triangle + R"("vertices":[[0,0,0],[1,0,0]]})", "out of range"},
      {ok_head + one_triangle + R"("vertices":[[0,0,0],[1,0,0],[0,1]]})", "vertex 2"},
      {ok_head + R"("CityObjects":{"b":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"2","boundaries":[[[0,1,-2]]]}]}},"vertices":[[0,0,0],[1,0,0],[0,1,0]]})",
       "object 'b'"},
      {ok_head + R"("CityObjects":{"b":{"type":"Building","geometry":[{"type":"Sphere","lod":"2","boundaries":[]}]}},"vertices":[]})",
       "unknown geometry type"},
      {ok_head + R"("CityObjects":{"b":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"2","boundaries":[[[0,1,2]]],"semantics":{"surfaces":[{"type":"WallSurface"}],"values":[3]}}]}},"vertices":[[0,0,0],[1,0,0],[0,1,0]]})",
       "semantics value"},
      {ok_head + R"("CityObjects":{"b":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"x2","boundaries":[[[0,1,2]]]}]}},"vertices":[[0,0,0],[1,0,0],[0,1,0]]})",
       "invalid LoD"},
      {ok_head + R"("CityObjects":{},"vertices":[]})", "no building geometry"},
  };
  for (const auto& [text, expected] : cases) {
    try {
      parse_cityjson(text, "broken.json", tax, 0);
      ADD_FAILURE() << "no error for: " << text;
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("broken.json: ", 0), 0u) << what;
      EXPECT_NE(what.find(expected), std::string::npos) << "expected '" << expected << "' in: " << what;
    }
  }
}

TEST(CityJsonReader, BrokenSequenceNamesTheLine) {
  const Taxonomy tax = Taxonomy::builtin();
  const std::string header = R"({"type":"CityJSON","version":"2.0","transform":{"scale":[1,1,1],"translate":[0,0,0]},"CityObjects":{},"vertices":[]})";
  const std::string feature =
      R"({"type":"CityJSONFeature","id":"b","CityObjects":{"b":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"2","boundaries":[[[0,1,2]]]}]}},"vertices":[[0,0,0],[1,0,0],[0,1,0]]})";
  EXPECT_EQ(parse_cityjson_seq(header + "\n" + feature + "\n", "ok.jsonl", tax, 0).num_triangles(), 1u);
  try {
    parse_cityjson_seq(header + "\n" + feature + "\n" + feature.substr(0, 40) + "\n", "seq.jsonl", tax, 0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("seq.jsonl: line 3: malformed JSON"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_cityjson_seq(header + "\n" + header + "\n", "seq.jsonl", tax, 0), Error);
}

// cjval's sem.json is deliberately invalid (more semantics values than surfaces, vertex indices
// beyond the vertex list): it must be rejected, not half-read.
TEST(CityJsonReader, InvalidSampleIsRejected) {
  const std::string path = kData + "/citygml/cityjson/sem.json";
  try {
    read_cityjson(path, Taxonomy::builtin(), 0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
}
