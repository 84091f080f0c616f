// PLY export: the header follows the PLY spec and the binary body holds what the mesh says.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "citymodel/mesh_ply.h"
#include "core/atomic_file.h"
#include "core/error.h"

using namespace cls;
namespace fs = std::filesystem;

namespace {

// Two triangles: a window (level-1 class window, in building 0) and a plain wall face.
SemanticMesh two_triangle_mesh(const Taxonomy& tax) {
  SemanticMesh m;
  m.source_path = "two.json";
  m.origin = {1000.0, 2000.0, 30.0};
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}};
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  m.entities = {{3, tax.find("building"), -1, "b"}, {2, tax.find("wall"), 0, "w"}, {1, tax.find("window"), 1, "o"}};
  m.buildings = {0};
  m.tri_class = {tax.find("window"), tax.find("wall")};
  m.tri_entity = {{2, 1, 0}, {-1, 1, 0}};
  m.tri_level_class = {{tax.find("window"), tax.find("wall"), tax.find("building")},
                       {tax.find("wall"), tax.find("wall"), tax.find("building")}};
  m.tri_polygon = {0, 1};
  m.polygon_ids = {"b/0/0", "b/0/1"};
  return m;
}

template <class T>
T read_le(const std::string& bytes, size_t& pos) {
  unsigned char b[sizeof(T)];
  for (size_t i = 0; i < sizeof(T); ++i) b[i] = static_cast<unsigned char>(bytes.at(pos + i));  // file is LE
  pos += sizeof(T);
  T v;
  std::memcpy(&v, b, sizeof(T));  // the test machine is little-endian like the file
  return v;
}

struct Ply {
  std::vector<std::string> header;
  std::string body;
};

Ply read_ply(const fs::path& path) {
  const std::string all = read_text_file(path);
  const std::string end = "end_header\n";
  const size_t e = all.find(end);
  EXPECT_NE(e, std::string::npos);
  Ply p;
  std::istringstream h(all.substr(0, e + end.size()));
  for (std::string line; std::getline(h, line);) p.header.push_back(line);
  p.body = all.substr(e + end.size());
  return p;
}

class MeshPly : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cls_ply_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

}  // namespace

TEST_F(MeshPly, HeaderAndBodyInLocalFrame) {
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = two_triangle_mesh(tax);
  write_mesh_ply((dir_ / "m.ply").string(), mesh, tax, nullptr);
  const Ply ply = read_ply(dir_ / "m.ply");
  const std::vector<std::string> expected_structure = {
      "ply", "format binary_little_endian 1.0", "element vertex 4", "property float x", "property float y",
      "property float z", "element face 2", "property list uchar int vertex_indices", "property uchar red",
      "property uchar green", "property uchar blue", "property int class_l1", "property int class_l2",
      "property int class_l3", "property int building", "end_header"};
  std::vector<std::string> structure;
  bool has_origin = false;
  for (const std::string& line : ply.header) {
    if (line.rfind("comment ", 0) == 0) {
      has_origin |= line == "comment origin 1000 2000 30";
      continue;
    }
    structure.push_back(line);
  }
  EXPECT_EQ(structure, expected_structure);
  EXPECT_TRUE(has_origin);
  ASSERT_EQ(ply.body.size(), 4u * 12 + 2u * (1 + 12 + 3 + 16));

  size_t pos = 0;
  for (const auto& v : mesh.vertices)
    for (double x : v) EXPECT_EQ(read_le<float>(ply.body, pos), static_cast<float>(x));
  for (size_t t = 0; t < 2; ++t) {
    EXPECT_EQ(read_le<uint8_t>(ply.body, pos), 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(read_le<int32_t>(ply.body, pos), static_cast<int32_t>(mesh.triangles[t][k]));
    const auto& colour = tax.classes[mesh.tri_level_class[t][0]].color;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(read_le<uint8_t>(ply.body, pos), colour[k]);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(read_le<int32_t>(ply.body, pos), mesh.tri_level_class[t][k]);
    EXPECT_EQ(read_le<int32_t>(ply.body, pos), 0);  // building 0
  }
  EXPECT_EQ(pos, ply.body.size());
  // The window face is blue-ish, the wall face beige: the colours come from the level-1 class.
  EXPECT_NE(tax.classes[tax.find("window")].color, tax.classes[tax.find("wall")].color);
}

TEST_F(MeshPly, SceneFrameWithTransform) {
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = two_triangle_mesh(tax);
  CityTransform t;  // scene = 2 * (source - (1000, 2000, 30))
  for (int i = 0; i < 3; ++i) t.matrix[i][i] = 2;
  t.matrix[0][3] = -2000;
  t.matrix[1][3] = -4000;
  t.matrix[2][3] = -60;
  write_mesh_ply((dir_ / "s.ply").string(), mesh, tax, &t);
  const Ply ply = read_ply(dir_ / "s.ply");
  size_t pos = 0;
  for (const auto& v : mesh.vertices)
    for (double x : v) EXPECT_FLOAT_EQ(read_le<float>(ply.body, pos), static_cast<float>(2 * x));
  // read_mesh_ply gives back what was written: scene-frame vertices, triangles, level-1 colours.
  const ColouredMesh back = read_mesh_ply((dir_ / "s.ply").string());
  ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int d = 0; d < 3; ++d) EXPECT_FLOAT_EQ(back.vertices[i][d], static_cast<float>(2 * mesh.vertices[i][d]));
  ASSERT_EQ(back.triangles.size(), 2u);
  for (size_t f = 0; f < 2; ++f) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(back.triangles[f][k], static_cast<int32_t>(mesh.triangles[f][k]));
    EXPECT_EQ(back.colours[f], tax.classes[mesh.tri_level_class[f][0]].color);
  }
  // A truncated file and one of another layout are refused with the file named.
  const std::string bytes = read_text_file(dir_ / "s.ply");
  write_text_atomic(dir_ / "cut.ply", bytes.substr(0, bytes.size() - 5));
  EXPECT_THROW(read_mesh_ply((dir_ / "cut.ply").string()), Error);
  std::string other = bytes;
  other.replace(other.find("property int building"), 20, "property int buildinX");
  write_text_atomic(dir_ / "other.ply", other);
  EXPECT_THROW(read_mesh_ply((dir_ / "other.ply").string()), Error);
  fs::remove(dir_ / "cut.ply");
  fs::remove(dir_ / "other.ply");
  // Nothing but the output file in the directory: the temporary was renamed into place.
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1u);
}
