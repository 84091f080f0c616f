// Format detection and loading by content.
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

#include "citymodel/city_model.h"
#include "citymodel/mesh_stats.h"
#include "core/error.h"

using namespace cls;

TEST(CityModel, DetectsTheFormatByContent) {
  EXPECT_EQ(detect_city_format("\xEF\xBB\xBF  <?xml version=\"1.0\"?>"), CityFormat::CityGML);
  EXPECT_EQ(detect_city_format("{\"type\":\"CityJSON\"}"), CityFormat::CityJSON);
  EXPECT_EQ(detect_city_format("{\n  \"type\": \"CityJSON\"\n}\n"), CityFormat::CityJSON);
  EXPECT_EQ(detect_city_format("{\"a\":1}\n{\"b\":2}"), CityFormat::CityJSONSeq);
  EXPECT_EQ(detect_city_format("ply\nformat ascii 1.0"), CityFormat::Unknown);
  EXPECT_EQ(detect_city_format("   \n"), CityFormat::Unknown);
}

TEST(CityModel, LodOption) {
  const Codec<int> lod = lod_codec();
  EXPECT_EQ(lod.parse("highest"), 0);
  EXPECT_EQ(lod.parse("0"), 0);
  EXPECT_EQ(lod.parse("2"), 2);
  EXPECT_THROW(lod.parse("4"), std::invalid_argument);
  EXPECT_THROW(lod.parse("2.2"), std::invalid_argument);
  EXPECT_EQ(lod.text(0), "highest");
  EXPECT_EQ(lod.text(2), "2");
}

// The same 100 LoD2 buildings as CityGML 3.0, CityJSON 2.0 and CityJSONSeq: the README's counts
// and areas (100 ground 4800 m2, 200 roof 9582 m2, 400 wall 16460 m2) in all three, and the three
// agree with each other.
TEST(CityModel, ThreeEncodingsOfTheSameBuildingsAgree) {
  const Taxonomy tax = Taxonomy::builtin();
  const std::string dir = std::string(CLS_TEST_DATA) + "/citygml/citygml4j/";
  const std::vector<std::pair<std::string, std::string>> files = {
      {"lod2_buildings_v3.gml", "CityGML"},
      {"lod2_buildings_v2.json", "CityJSON"},
      {"lod2_buildings_as_CityJSON_features.jsonl", "CityJSON"}};
  const std::map<std::string, std::pair<size_t, double>> readme = {
      {"ground", {100, 4800}}, {"roof", {200, 9582}}, {"wall", {400, 16460}}};
  std::vector<MeshStats> all;
  for (const auto& [file, format] : files) {
    const SemanticMesh mesh = load_city_model(dir + file, tax, 0);
    EXPECT_EQ(mesh.source_path, dir + file);
    EXPECT_EQ(mesh.format, format) << file;
    all.push_back(compute_mesh_stats(mesh, tax));
    const MeshStats& s = all.back();
    EXPECT_EQ(s.buildings, 100u) << file;
    for (const ClassStats& c : s.classes) {
      if (c.name == "building") continue;
      ASSERT_TRUE(readme.count(c.name)) << file << ": unexpected class " << c.name;
      EXPECT_EQ(c.objects, readme.at(c.name).first) << file << " " << c.name;
      EXPECT_NEAR(c.area, readme.at(c.name).second, 0.005 * readme.at(c.name).second) << file << " " << c.name;
    }
  }
  for (size_t i = 1; i < all.size(); ++i) {
    ASSERT_EQ(all[i].classes.size(), all[0].classes.size()) << files[i].first;
    for (size_t c = 0; c < all[0].classes.size(); ++c) {
      EXPECT_EQ(all[i].classes[c].name, all[0].classes[c].name);
      EXPECT_EQ(all[i].classes[c].objects, all[0].classes[c].objects) << files[i].first;
      EXPECT_NEAR(all[i].classes[c].area, all[0].classes[c].area, 1e-6 * all[0].classes[c].area + 1e-9)
          << files[i].first << " " << all[0].classes[c].name;
    }
    EXPECT_EQ(all[i].triangles, all[0].triangles) << files[i].first;
  }
}

TEST(CityModel, UnknownAndEmptyFilesAreErrors) {
  const std::string broken = std::string(CLS_TEST_FIXTURES) + "/broken/";
  const Taxonomy tax = Taxonomy::builtin();
  try {
    load_city_model(broken + "unknown_format.stl", tax, 0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), broken + "unknown_format.stl: unknown format: expected CityGML (XML) or "
                                              "CityJSON / CityJSONSeq (JSON)");
  }
  EXPECT_THROW(load_city_model(broken + "no_such_file.json", tax, 0), Error);
}
