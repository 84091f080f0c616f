// City CRS -> scene frame similarity: parsing, validation, application in double.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "citymodel/city_transform.h"
#include "core/error.h"

using namespace cls;
namespace fs = std::filesystem;

namespace {

std::string error_of(const std::string& text) {
  try {
    parse_city_transform(text, "t.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// s = 2, R = rotation by 90 degrees about z ((x, y, z) -> (-y, x, z)), t = (10, 20, 30):
// (1, 2, 3) -> 2 * (-2, 1, 3) + t = (6, 22, 36).
TEST(CityTransform, HandComputedSimilarity) {
  const CityTransform a = parse_city_transform(
      R"({"scale": 2, "rotation": [[0,-1,0],[1,0,0],[0,0,1]], "translation": [10,20,30]})", "t.json");
  const Vec3d p = a.apply({1, 2, 3});
  EXPECT_DOUBLE_EQ(p.x, 6);
  EXPECT_DOUBLE_EQ(p.y, 22);
  EXPECT_DOUBLE_EQ(p.z, 36);
  EXPECT_DOUBLE_EQ(a.scale(), 2);
  const CityTransform b = parse_city_transform(
      R"({"matrix": [[0,-2,0,10],[2,0,0,20],[0,0,2,30],[0,0,0,1]]})", "t.json");
  EXPECT_EQ(a.matrix, b.matrix);
}

TEST(CityTransform, RejectsWhatIsNoSimilarity) {
  EXPECT_NE(error_of(R"({"matrix": [[1,0,0,0],[0,2,0,0],[0,0,1,0],[0,0,0,1]]})").find("not a similarity"),
            std::string::npos);  // non-uniform scale
  EXPECT_NE(error_of(R"({"matrix": [[1,0.1,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})").find("not a scaled rotation"),
            std::string::npos);  // shear
  EXPECT_NE(error_of(R"({"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,1,1]]})").find("last row"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"matrix": [[-1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})").find("reflection"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"matrix": [[1,0,0],[0,1,0],[0,0,1]]})").find("4 rows of 4 numbers"), std::string::npos);
  EXPECT_NE(error_of(R"({"scale": 0})").find("positive"), std::string::npos);
  EXPECT_NE(error_of(R"({"scale": 1, "matrix": []})").find("not both"), std::string::npos);
  EXPECT_NE(error_of(R"({"rotation": [[1,0,0],[0,1,0],[0,0,"x"]]})").find("number"), std::string::npos);
  EXPECT_NE(error_of("{\"matrix\": [[1,0,0,0],").find("malformed JSON"), std::string::npos);
  EXPECT_NE(error_of("{}").find("needs"), std::string::npos);
  EXPECT_EQ(error_of(R"({"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "comment": "x"})"), "");
  EXPECT_EQ(error_of(R"({"matrix": [[1,0,0,0],[0,2,0,0],[0,0,1,0],[0,0,0,1]]})").rfind("t.json: ", 0), 0u);
  // Within tolerance: a rotation written with 9 decimals.
  EXPECT_EQ(error_of(R"({"rotation": [[0.707106781,-0.707106781,0],[0.707106781,0.707106781,0],[0,0,1]]})"), "");
}

// UTM-sized coordinates: composing origin and translation in double keeps millimetres that a
// float conversion of the source coordinate would lose.
TEST(CityTransform, SceneVerticesComposeInDouble) {
  SemanticMesh mesh;
  mesh.origin = {457842.0, 5439083.0, 100.0};
  mesh.vertices = {{0.123, 0.456, 0.789}};
  CityTransform t;
  t.matrix[0][3] = -457842.0;
  t.matrix[1][3] = -5439083.0;
  t.matrix[2][3] = -100.0;
  const auto v = scene_vertices(mesh, t);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NEAR(v[0].x, 0.123f, 1e-6);
  EXPECT_NEAR(v[0].y, 0.456f, 1e-6);
  EXPECT_NEAR(v[0].z, 0.789f, 1e-6);
  EXPECT_EQ(scene_vertices(mesh, CityTransform::identity())[0].y, static_cast<float>(5439083.456));
}

TEST(CityTransform, WriteReadRoundTrip) {
  const fs::path dir = fs::temp_directory_path() / ("cls_transform_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const double c = std::cos(0.3), s = std::sin(0.3);
  CityTransform t;
  t.matrix = {{{1.5 * c, -1.5 * s, 0, -457842.125}, {1.5 * s, 1.5 * c, 0, -5439083.5}, {0, 0, 1.5, -98.25}, {0, 0, 0, 1}}};
  write_city_transform((dir / "t.json").string(), t);
  const CityTransform back = read_city_transform((dir / "t.json").string());
  EXPECT_EQ(back.matrix, t.matrix);  // bit-exact: doubles are written with round-trip precision
  EXPECT_THROW(read_city_transform((dir / "missing.json").string()), Error);
  fs::remove_all(dir);
}
