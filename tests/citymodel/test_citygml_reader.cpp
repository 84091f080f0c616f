#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "citymodel/mesh_area.h"
#include "citymodel/citygml_reader.h"
#include "core/error.h"

namespace fs = std::filesystem;
using namespace cls;
using cls::test::area_by_class;
using cls::test::total_area;
using cls::test::triangles_by_class;

namespace {

const std::string kData = std::string(CLS_TEST_DATA) + "/citygml/";
const std::string kFzk3v2 = kData + "fzk-haus/fzk_haus_lod3_v2.gml";
const std::string kFzk3v3 = kData + "fzk-haus/FZK-Haus-LoD3-KIT-IAI-KHH-B36-V1__v3.gml";
const std::string kFzk2v2 = kData + "fzk-haus/fzk_haus_lod2_v2.gml";
const std::string kFzk2v3 = kData + "fzk-haus/FZK-Haus-LoD2-KIT-IAI-KHH-B36-V1__v3.gml";

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "cls_test_citygml";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// The message of the cls::Error reading `text` from a file gives; it must name the file.
std::string read_error(const std::string& name, const std::string& text, int lod = 0) {
  const std::string path = write_temp(name, text);
  try {
    read_citygml(path, Taxonomy::builtin(), lod);
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    return msg;
  }
  ADD_FAILURE() << name << ": no error";
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// A CityGML 2.0 document with one building whose content is `building_body`.
std::string citygml2(const std::string& building_body) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
    xmlns:gml="http://www.opengis.net/gml" xmlns:xlink="http://www.w3.org/1999/xlink">
  <core:cityObjectMember><bldg:Building gml:id="B1">)" +
         building_body + R"(</bldg:Building></core:cityObjectMember>
</core:CityModel>
)";
}

// A wall with one LoD2 polygon given by its rings' posList texts (the first is the exterior).
std::string wall(const std::string& id, const std::vector<std::string>& rings, const std::string& extra = "") {
  std::string polygon = "<gml:Polygon gml:id=\"" + id + "\">";
  for (size_t i = 0; i < rings.size(); ++i) {
    const char* kind = i == 0 ? "exterior" : "interior";
    polygon += std::string("<gml:") + kind + "><gml:LinearRing><gml:posList>" + rings[i] +
               "</gml:posList></gml:LinearRing></gml:" + kind + ">";
  }
  polygon += "</gml:Polygon>";
  return "<bldg:boundedBy><bldg:WallSurface gml:id=\"W_" + id + "\"><bldg:lod2MultiSurface><gml:MultiSurface>" +
         "<gml:surfaceMember>" + polygon + "</gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface>" + extra +
         "</bldg:WallSurface></bldg:boundedBy>";
}

size_t count_entities(const SemanticMesh& m, const Taxonomy& tax, const std::string& cls) {
  return std::count_if(m.entities.begin(), m.entities.end(),
                       [&](const SemanticEntity& e) { return e.class_id == tax.find(cls); });
}

// Absolute triangle coordinates per source polygon id, for comparing two encodings.
std::map<std::string, std::vector<std::array<double, 9>>> triangles_by_polygon(const SemanticMesh& m) {
  std::map<std::string, std::vector<std::array<double, 9>>> out;
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    std::array<double, 9> c{};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) c[3 * k + d] = m.vertices[m.triangles[t][k]][d] + m.origin[d];
    out[m.polygon_ids[m.tri_polygon[t]]].push_back(c);
  }
  return out;
}

struct CityGml : ::testing::Test {
  Taxonomy tax = Taxonomy::builtin();
};

}  // namespace

// Per-class areas of FZK-Haus LoD3, computed independently (Python, Newell area of each exterior
// ring minus its holes over the 210 distinct polygons). data/citygml/README.md gives them rounded:
// wall 169, window 23, door 7, roof 165, ground 120.
TEST_F(CityGml, FzkHausLod3SameInCityGml2And3) {
  const SemanticMesh v2 = read_citygml(kFzk3v2, tax, 0);
  const SemanticMesh v3 = read_citygml(kFzk3v3, tax, 0);
  EXPECT_EQ(v2.format, "CityGML");
  EXPECT_EQ(v2.version, "2.0");
  EXPECT_EQ(v3.version, "3.0");
  EXPECT_EQ(v2.crs, "urn:adv:crs:ETRS89_UTM32*DE_DHHN92_NH");
  EXPECT_EQ(v3.crs, v2.crs);
  EXPECT_EQ(v2.lod, 3);
  EXPECT_EQ(v3.lod, 3);
  EXPECT_EQ(v2.origin, (std::array<double, 3>{457841, 5439082, 111}));
  EXPECT_EQ(v3.origin, v2.origin);

  const std::map<std::string, double> truth{
      {"wall", 169.3175}, {"window", 23.1688}, {"door", 6.8039}, {"roof", 165.1222}, {"ground", 120.0}};
  for (const SemanticMesh* m : {&v2, &v3}) {
    const auto areas = area_by_class(*m, tax);
    ASSERT_EQ(areas.size(), truth.size());
    for (const auto& [cls, area] : truth) EXPECT_NEAR(areas.at(cls), area, 0.005 * area) << cls;
    EXPECT_EQ(m->polygon_ids.size(), 210u);  // lod3Solid's 20 xlinks add no polygon twice
    EXPECT_EQ(count_entities(*m, tax, "window"), 11u);
    EXPECT_EQ(count_entities(*m, tax, "door"), 2u);
    EXPECT_EQ(count_entities(*m, tax, "wall"), 4u);
    EXPECT_EQ(count_entities(*m, tax, "roof"), 2u);
    EXPECT_EQ(count_entities(*m, tax, "ground"), 1u);
    EXPECT_EQ(m->buildings.size(), 1u);
  }
  EXPECT_EQ(triangles_by_class(v2, tax), triangles_by_class(v3, tax));
  EXPECT_EQ(triangles_by_polygon(v2), triangles_by_polygon(v3));  // the very same triangles
}

TEST_F(CityGml, FzkHausLod3Levels) {
  const SemanticMesh m = read_citygml(kFzk3v3, tax, 3);
  const int window = tax.find("window"), wall = tax.find("wall"), building = tax.find("building");
  size_t window_triangles = 0;
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    const auto& e = m.tri_entity[t];
    EXPECT_EQ(e[2], m.buildings[0]);
    EXPECT_EQ(m.tri_level_class[t][2], building);
    EXPECT_GE(e[1], 0);  // every face lies in a boundary surface
    if (m.tri_class[t] == window) {
      ++window_triangles;
      EXPECT_EQ(m.tri_level_class[t], (std::array<int32_t, 3>{window, wall, building}));
      EXPECT_EQ(m.entities[e[0]].parent, e[1]);
    } else if (m.tri_class[t] == wall) {
      EXPECT_EQ(m.tri_level_class[t], (std::array<int32_t, 3>{wall, wall, building}));
      EXPECT_EQ(e[0], -1);
    }
  }
  EXPECT_GT(window_triangles, 0u);
}

// LoD2 FZK-Haus by hand: footprint 12 x 10, eaves at +3.630940107676, ridge at +6.517691453624
// along x. Walls: 2 * 12 * 3.6309... + 2 * (10 * 3.6309... + 0.5 * 10 * 2.886751345948); roof:
// 2 * 12 * sqrt(5^2 + 2.886751345948^2).
TEST_F(CityGml, FzkHausLod2InBothVersions) {
  const double eave = 3.630940107676, rise = 6.517691453624 - eave;
  const double walls = 2 * 12 * eave + 2 * (10 * eave + 5 * rise), roof = 2 * 12 * std::hypot(5.0, rise);
  for (const std::string& path : {kFzk2v2, kFzk2v3}) {
    const SemanticMesh m = read_citygml(path, tax, 0);
    EXPECT_EQ(m.lod, 2);
    EXPECT_EQ(m.polygon_ids.size(), 7u);
    EXPECT_EQ(m.num_triangles(), 16u);
    const auto areas = area_by_class(m, tax);
    ASSERT_EQ(areas.size(), 3u) << path;  // no openings
    EXPECT_NEAR(areas.at("wall"), walls, 1e-6);
    EXPECT_NEAR(areas.at("roof"), roof, 1e-6);
    EXPECT_NEAR(areas.at("ground"), 120.0, 1e-6);
    EXPECT_EQ(count_entities(m, tax, "window") + count_entities(m, tax, "door"), 0u);
  }
}

TEST_F(CityGml, RequestedLodMissingIsAnError) {
  try {
    read_citygml(kFzk2v2, tax, 3);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), kFzk2v2 + ": no building geometry at LoD 3 (building LoDs in the file: 2)"))
        << e.what();
  }
  EXPECT_THROW(read_citygml(kFzk3v2, tax, 2), Error);
}

TEST_F(CityGml, Citygml4jLod3Building) {
  const SemanticMesh m = read_citygml(kData + "citygml4j/lod3_building_v2.gml", tax, 0);
  EXPECT_EQ(m.crs, "urn:ogc:def:crs,crs:EPSG:6.12:3068,crs:EPSG:6.12:5783");
  EXPECT_EQ(count_entities(m, tax, "window"), 21u);
  EXPECT_EQ(count_entities(m, tax, "door"), 2u);
  EXPECT_EQ(count_entities(m, tax, "installation"), 1u);
  // 3092 polygons; one (UUID_b20fe1ad-...) has three collinear points: zero area, no triangles.
  EXPECT_EQ(m.polygon_ids.size(), 3091u);
  EXPECT_EQ(std::count(m.polygon_ids.begin(), m.polygon_ids.end(), "UUID_b20fe1ad-a8c3-4d39-a0cb-97aed3f09e64"), 0);
  EXPECT_EQ(m.num_triangles(), 3091u);  // all polygons are triangles
  // 15 windows sit in walls, 6 in roof dormers.
  std::map<std::string, int> window_parents;
  for (const SemanticEntity& e : m.entities)
    if (e.class_id == tax.find("window")) ++window_parents[tax.classes[m.entities[e.parent].class_id].name];
  EXPECT_EQ(window_parents, (std::map<std::string, int>{{"roof", 6}, {"wall", 15}}));
  const int installation = tax.find("installation");
  for (size_t t = 0; t < m.num_triangles(); ++t)
    if (m.tri_class[t] == installation)
      EXPECT_EQ(m.tri_level_class[t], (std::array<int32_t, 3>{installation, installation, tax.find("building")}));
}

TEST_F(CityGml, Citygml4jHundredLod2Buildings) {
  const SemanticMesh m = read_citygml(kData + "citygml4j/lod2_buildings_v3.gml", tax, 0);
  EXPECT_EQ(m.version, "3.0");
  EXPECT_EQ(m.buildings.size(), 100u);
  EXPECT_EQ(m.polygon_ids.size(), 700u);  // each lod2Solid references its 7 surfaces' polygons
  const auto areas = area_by_class(m, tax);
  ASSERT_EQ(areas.size(), 3u);
  EXPECT_NEAR(areas.at("ground"), 4800, 0.005 * 4800);
  EXPECT_NEAR(areas.at("roof"), 9582, 0.005 * 9582);
  EXPECT_NEAR(areas.at("wall"), 16460, 0.005 * 16460);
  EXPECT_EQ(count_entities(m, tax, "ground"), 100u);
  EXPECT_EQ(count_entities(m, tax, "roof"), 200u);
  EXPECT_EQ(count_entities(m, tax, "wall"), 400u);
}

// The file's geometry is fine; what makes it invalid is a gml:id starting with a digit (xs:ID must
// be an NCName) and a Height status outside its enumeration (an attribute the reader does not use).
TEST_F(CityGml, InvalidBuildingIsReported) {
  const std::string path = kData + "citygml4j/invalid_building_v3.gml";
  try {
    read_citygml(path, tax, 0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), path + ": line 5: gml:id \"1F3E679D-E226-4535-926C-7390977FB25A\" is not a valid XML ID"))
        << e.what();
  }
}

TEST_F(CityGml, BrokenInputsGiveErrorsNamingTheFile) {
  const std::string lod2 = read_text(kFzk2v2);
  EXPECT_TRUE(contains(read_error("truncated.gml", lod2.substr(0, lod2.size() / 2)), "malformed XML"));
  EXPECT_TRUE(contains(read_error("empty.gml", ""), "malformed XML"));
  EXPECT_TRUE(contains(read_error("not_citygml.xml", "<a><b/></a>"), "not a CityGML file"));

  std::string dangling = lod2;
  const size_t href = dangling.find("xlink:href=\"#") + 13;
  dangling.insert(href, "missing_");
  const std::string dangling_msg = read_error("dangling.gml", dangling);
  EXPECT_TRUE(contains(dangling_msg, "dangling xlink:href \"#missing_")) << dangling_msg;

  std::string nan = lod2;
  const size_t pos = nan.find("<gml:pos>") + 9;
  nan.replace(pos, nan.find(' ', pos) - pos, "NaN");
  EXPECT_TRUE(contains(read_error("nan.gml", nan), "non-finite number \"NaN\""));

  EXPECT_TRUE(contains(read_error("two_points.gml", citygml2(wall("P", {"0 0 0 1 0 0 0 0 0"}))),
                       "a ring of polygon \"P\" has 2 point(s)"));
  EXPECT_TRUE(contains(read_error("bad_number.gml", citygml2(wall("P", {"0 0 0 1 0 0 1 1.2.3 0 0 0 0"}))),
                       "unparsable number \"1.2.3\""));
  EXPECT_TRUE(contains(read_error("inf.gml", citygml2(wall("P", {"0 0 0 1 0 0 1 INF 0 0 0 0"}))), "non-finite"));
  EXPECT_TRUE(contains(read_error("odd_count.gml", citygml2(wall("P", {"0 0 0 1 0 0 1 1 0 0 0"}))),
                       "not a multiple of its dimension 3"));
  EXPECT_TRUE(contains(read_error("dup_id.gml", citygml2(wall("P", {"0 0 0 1 0 0 1 1 0 0 0 0"}) +
                                                          wall("P", {"0 0 0 1 0 0 1 1 0 0 0 0"}))),
                       "duplicate gml:id"));
  std::string nested;
  for (int i = 0; i < 2000; ++i) nested += "<x>";
  for (int i = 0; i < 2000; ++i) nested += "</x>";
  std::string deep = citygml2(nested);
  EXPECT_TRUE(contains(read_error("deep.gml", deep), "nested deeper"));
  EXPECT_THROW(read_citygml("/nonexistent/file.gml", tax, 0), Error);
}

TEST_F(CityGml, HandMadeGeometryVariants) {
  const std::string square = "0 0 0 10 0 0 10 0 10 0 0 10 0 0 0";  // 10 x 10 in the xz plane
  const std::string hole = "3 0 3 3 0 5 5 0 5 5 0 3 3 0 3";         // 2 x 2
  // An opening in the hole of its wall (2.0 style), a 2D polygon, gml:coordinates and gml:pos,
  // a reversed OrientableSurface, a Triangle, and a BuildingPart with an lod2Solid of its own.
  const std::string window =
      "<bldg:opening><bldg:Window gml:id=\"Win\"><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember>"
      "<gml:Polygon gml:id=\"WinP\"><gml:exterior><gml:LinearRing><gml:posList>" +
      hole + "</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface>"
             "</bldg:lod2MultiSurface></bldg:Window></bldg:opening>";
  const std::string body =
      wall("P1", {square, hole}, window) +
      "<bldg:boundedBy><bldg:GroundSurface gml:id=\"G\"><bldg:lod2MultiSurface><gml:MultiSurface>"
      "<gml:surfaceMember><gml:Polygon gml:id=\"P2\"><gml:exterior><gml:LinearRing><gml:posList srsDimension=\"2\">0 0 4 0 4 3 0 0"
      "</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>"
      "<gml:surfaceMember><gml:Polygon gml:id=\"P3\"><gml:exterior><gml:LinearRing>"
      "<gml:coordinates>20,0,0 22,0,0 22,2,0 20,2,0</gml:coordinates></gml:LinearRing></gml:exterior></gml:Polygon>"
      "</gml:surfaceMember>"
      "<gml:surfaceMember><gml:OrientableSurface orientation=\"-\"><gml:baseSurface><gml:Polygon gml:id=\"P4\">"
      "<gml:exterior><gml:LinearRing><gml:pos>30 0 0</gml:pos><gml:pos>31 0 0</gml:pos><gml:pos>31 1 0</gml:pos>"
      "<gml:pos>30 1 0</gml:pos><gml:pos>30 0 0</gml:pos></gml:LinearRing></gml:exterior></gml:Polygon>"
      "</gml:baseSurface></gml:OrientableSurface></gml:surfaceMember>"
      "<gml:surfaceMember><gml:TriangulatedSurface><gml:trianglePatches><gml:Triangle><gml:exterior><gml:LinearRing>"
      "<gml:posList>40 0 0 42 0 0 40 2 0 40 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Triangle>"
      "</gml:trianglePatches></gml:TriangulatedSurface></gml:surfaceMember>"
      "</gml:MultiSurface></bldg:lod2MultiSurface></bldg:GroundSurface></bldg:boundedBy>"
      "<bldg:consistsOfBuildingPart><bldg:BuildingPart gml:id=\"Part\"><bldg:lod2Solid><gml:Solid><gml:exterior>"
      "<gml:CompositeSurface><gml:surfaceMember><gml:Polygon gml:id=\"P5\"><gml:exterior><gml:LinearRing><gml:posList>"
      "50 0 0 53 0 0 53 3 0 50 3 0 50 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>"
      "<gml:surfaceMember xlink:href=\"#P1\"/></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>"
      "</bldg:BuildingPart></bldg:consistsOfBuildingPart>";
  const std::string path = write_temp("variants.gml", citygml2(body));
  const SemanticMesh m = read_citygml(path, tax, 2);
  const auto areas = area_by_class(m, tax);
  EXPECT_DOUBLE_EQ(areas.at("wall"), 100.0 - 4.0);
  EXPECT_DOUBLE_EQ(areas.at("window"), 4.0);
  EXPECT_DOUBLE_EQ(areas.at("ground"), 6.0 + 4.0 + 1.0 + 2.0);
  EXPECT_DOUBLE_EQ(areas.at("surface"), 9.0);  // the part's own solid; P1 by xlink is not added twice
  EXPECT_EQ(m.polygon_ids.size(), 7u);  // the Triangle has no gml:id: it is named by its byte offset
  EXPECT_EQ(m.polygon_ids[5].rfind("@", 0), 0u);
  EXPECT_EQ(m.buildings.size(), 1u);  // the BuildingPart belongs to its Building
  for (size_t t = 0; t < m.num_triangles(); ++t) EXPECT_EQ(m.tri_entity[t][2], m.buildings[0]);
  // P4 is reversed by its OrientableSurface: its triangles face -z, the other ground faces +z.
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    const std::string& id = m.polygon_ids[m.tri_polygon[t]];
    if (id != "P2" && id != "P3" && id != "P4") continue;
    const auto &a = m.vertices[m.triangles[t][0]], &b = m.vertices[m.triangles[t][1]], &c = m.vertices[m.triangles[t][2]];
    const double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    EXPECT_EQ(nz > 0, id != "P4") << id;
  }
  // The window keeps its wall as level-2 class.
  for (size_t t = 0; t < m.num_triangles(); ++t)
    if (m.tri_class[t] == tax.find("window")) EXPECT_EQ(m.tri_level_class[t][1], tax.find("wall"));
}

TEST_F(CityGml, Citygml1AndBufferVariant) {
  std::string doc = citygml2(wall("P", {"0 0 0 2 0 0 2 0 2 0 0 2 0 0 0"}));
  for (const char* from : {"citygml/2.0", "citygml/building/2.0"}) {
    std::string to = from;
    to.replace(to.find("2.0"), 3, "1.0");
    doc.replace(doc.find(from), std::string(from).size(), to);
  }
  const SemanticMesh m = read_citygml_buffer(doc.data(), doc.size(), "memory.gml", tax, 0);
  EXPECT_EQ(m.version, "1.0");
  EXPECT_EQ(m.source_path, "memory.gml");
  EXPECT_EQ(m.crs, "");
  EXPECT_DOUBLE_EQ(total_area(m), 4.0);
  try {
    read_citygml_buffer(doc.data(), doc.size() / 2, "memory.gml", tax, 0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("memory.gml: malformed XML", 0), 0u) << e.what();
  }
}
