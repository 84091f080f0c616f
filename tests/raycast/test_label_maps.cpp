// Label maps on a hand-made scene (a wall with a coplanar window on top, a second building), and
// the PNG / PFM / preview writers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "citymodel/city_objects.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "raycast/label_map_io.h"
#include "raycast/label_maps.h"
#include "raycast/look_at.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

enum : int32_t { kWindow = 0, kWall = 1, kBuilding = 2 };

Taxonomy hand_taxonomy() {
  Taxonomy t;
  t.classes = {{"window", 1, {"Window"}, {"a window"}, {0, 0, 255}},
               {"wall", 2, {"WallSurface"}, {"a wall"}, {200, 200, 200}},
               {"building", 3, {"Building"}, {"a building"}, {255, 0, 0}}};
  return t;
}

// Adds an axis-aligned quad in the plane y = `y` (x in [x0, x1], z in [z0, z1]) as two triangles.
void add_quad(SemanticMesh& m, double y, double x0, double x1, double z0, double z1, int32_t face_class,
              std::array<int32_t, 3> entity, std::array<int32_t, 3> level_class) {
  const uint32_t k = static_cast<uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}});
  m.triangles.push_back({k, k + 1, k + 2});
  m.triangles.push_back({k, k + 2, k + 3});
  for (int n = 0; n < 2; ++n) {
    m.tri_class.push_back(face_class);
    m.tri_entity.push_back(entity);
    m.tri_level_class.push_back(level_class);
    m.tri_polygon.push_back(static_cast<int32_t>(m.polygon_ids.size()));
  }
  m.polygon_ids.push_back("quad" + std::to_string(k / 4));
}

// Building 0: wall 10 x 6 m in the plane y = 0 with a 2 x 2 m window ON TOP of it (no hole, the
// same plane). Building 1: a wall at y = 5 to the right. `window_first` flips the triangle order.
SemanticMesh wall_with_window(bool window_first) {
  SemanticMesh m;
  m.source_path = "hand-made";
  m.entities = {{3, kBuilding, -1, "b0"}, {2, kWall, 0, "b0-wall"}, {1, kWindow, 1, "b0-window"},
                {3, kBuilding, -1, "b1"}, {2, kWall, 3, "b1-wall"}};
  m.buildings = {0, 3};
  auto wall = [&] { add_quad(m, 0, 0, 10, 0, 6, kWall, {-1, 1, 0}, {kWall, kWall, kBuilding}); };
  auto window = [&] { add_quad(m, 0, 3, 5, 2, 4, kWindow, {2, 1, 0}, {kWindow, kWall, kBuilding}); };
  if (window_first) window(), wall();
  else wall(), window();
  add_quad(m, 5, 12, 16, 0, 6, kWall, {-1, 4, 3}, {kWall, kWall, kBuilding});
  return m;
}

std::vector<Vec3f> float_vertices(const SemanticMesh& m) {
  std::vector<Vec3f> v;
  for (const auto& p : m.vertices) v.push_back(Vec3f{float(p[0]), float(p[1]), float(p[2])});
  return v;
}

// 160x120, f = 100, at (5, -20, 3) looking along +y: pixel (i, j) sees the plane y = 0 at
// x = 5 + 0.2 (i - 79.5), z = 3 - 0.2 (j - 59.5) and the plane y = 5 at 0.25 instead of 0.2.
// So the wall covers pixels i 55..104, j 45..74; the window i 70..79, j 55..64; the second
// building i 108..123, j 48..71 (no pixel centre lies on an edge).
LabelMaps cast_hand_scene(const SemanticMesh& mesh) {
  const Raycaster rc(float_vertices(mesh), mesh.triangles, opening_priority(mesh));
  const PinholeCamera cam{100, 100, 80, 60, 160, 120};
  std::vector<RayHit> hits;
  rc.cast_view(cam, look_at({5, -20, 3}, {5, 0, 3}), hits);
  LabelMaps maps;
  LabelTable(mesh).fill(hits, cam.width, cam.height, maps);
  return maps;
}

TEST(LabelMaps, OpeningOnTopOfWallWinsAndLevelsFollowTheHierarchy) {
  for (bool window_first : {false, true}) {
    SCOPED_TRACE(window_first ? "window triangles first" : "wall triangles first");
    const LabelMaps maps = cast_hand_scene(wall_with_window(window_first));
    ASSERT_EQ(maps.width, 160);
    ASSERT_EQ(maps.height, 120);
    size_t window_pixels = 0, wall_pixels = 0, second_pixels = 0, empty_pixels = 0;
    for (int j = 0; j < 120; ++j)
      for (int i = 0; i < 160; ++i) {
        const size_t p = static_cast<size_t>(j) * 160 + i;
        const bool in_wall = i >= 55 && i <= 104 && j >= 45 && j <= 74;
        const bool in_window = i >= 70 && i <= 79 && j >= 55 && j <= 64;
        const bool in_second = i >= 108 && i <= 123 && j >= 48 && j <= 71;
        std::array<uint16_t, 3> expect{0, 0, 0};
        uint16_t building = 0;
        float depth = 0;
        int32_t object = -1;  // entities of wall_with_window: 2 the window, 1 its wall, 4 the second wall
        if (in_window) {
          expect = {kWindow + 1, kWall + 1, kBuilding + 1}, building = 1, depth = 20, object = 2, ++window_pixels;
        } else if (in_wall) {  // the subpart fallback: a plain wall is "wall" at level 1 too
          expect = {kWall + 1, kWall + 1, kBuilding + 1}, building = 1, depth = 20, object = 1, ++wall_pixels;
        } else if (in_second) {
          expect = {kWall + 1, kWall + 1, kBuilding + 1}, building = 2, depth = 25, object = 4, ++second_pixels;
        } else {
          ++empty_pixels;
        }
        ASSERT_EQ(maps.level[0][p], expect[0]) << i << "," << j;
        ASSERT_EQ(maps.level[1][p], expect[1]) << i << "," << j;
        ASSERT_EQ(maps.level[2][p], expect[2]) << i << "," << j;
        ASSERT_EQ(maps.building[p], building) << i << "," << j;
        ASSERT_EQ(maps.object[p], object) << i << "," << j;
        ASSERT_EQ(maps.coverage[p], depth > 0 ? 255 : 0) << i << "," << j;
        ASSERT_NEAR(maps.depth[p], depth, 1e-4) << i << "," << j;
      }
    EXPECT_EQ(window_pixels, 100u);
    EXPECT_EQ(wall_pixels, 50u * 30 - 100);
    EXPECT_EQ(second_pixels, 16u * 24);
    EXPECT_GT(empty_pixels, 0u);
  }
}

TEST(LabelMaps, UnclassifiedHitOccludesButIsNotCovered) {
  SemanticMesh m = wall_with_window(false);
  for (auto& lc : m.tri_level_class) lc = {-1, -1, -1};
  const LabelMaps maps = cast_hand_scene(m);
  const size_t p = 50 * 160 + 60;  // a wall pixel
  EXPECT_EQ(maps.level[0][p], 0);
  EXPECT_EQ(maps.coverage[p], 0);
  EXPECT_NEAR(maps.depth[p], 20, 1e-4);
}

TEST(LabelMaps, BuildingPartBelongsToItsBuilding) {
  SemanticMesh m = wall_with_window(false);
  // Entity 3 becomes a building part of building 0: its wall is building 1 in building.png.
  m.entities[3].parent = 0;
  m.buildings = {0};
  const LabelMaps maps = cast_hand_scene(m);
  EXPECT_EQ(maps.building[60 * 160 + 115], 1);
}

TEST(CityObjects, AnswerAtEachLevelAsTheLabelMapsDo) {
  const CityObjects t = city_objects(wall_with_window(false), hand_taxonomy());
  ASSERT_EQ(t.objects.size(), 5u);
  EXPECT_EQ(t.objects[2].id, "b0-window");
  EXPECT_EQ(t.class_name(2), "window");
  // The window answers for itself at level 1, as its wall at 2 and its building at 3; a plain wall
  // answers for itself at levels 1 and 2; a building has nothing finer.
  EXPECT_EQ(t.at_level(2, 1), 2);
  EXPECT_EQ(t.at_level(2, 2), 1);
  EXPECT_EQ(t.at_level(2, 3), 0);
  EXPECT_EQ(t.at_level(4, 1), 4);
  EXPECT_EQ(t.at_level(4, 3), 3);
  EXPECT_EQ(t.at_level(0, 1), 0);
  EXPECT_EQ(t.at_level(-1, 1), -1);
  EXPECT_EQ(finest_object_of_triangles(wall_with_window(false)), (std::vector<int32_t>{1, 1, 2, 2, 4, 4}));

  const CityObjects back = CityObjects::from_json(t.to_json(), "t.json");
  ASSERT_EQ(back.objects.size(), t.objects.size());
  for (size_t k = 0; k < t.objects.size(); ++k) {
    EXPECT_EQ(back.objects[k].id, t.objects[k].id);
    EXPECT_EQ(back.objects[k].parent, t.objects[k].parent);
    EXPECT_EQ(back.objects[k].level, t.objects[k].level);
    EXPECT_EQ(back.objects[k].class_id, t.objects[k].class_id);
  }
  nlohmann::json cycle = t.to_json();
  cycle["objects"][0]["parent"] = 2;  // a building inside its own window
  EXPECT_THROW(CityObjects::from_json(cycle, "t.json"), Error);
  nlohmann::json out_of_range = t.to_json();
  out_of_range["objects"][1]["class"] = 9;
  EXPECT_THROW(CityObjects::from_json(out_of_range, "t.json"), Error);
  EXPECT_THROW(CityObjects::from_json(nlohmann::json::object(), "t.json"), Error);
}

TEST(LabelMaps, RejectsInconsistentMesh) {
  SemanticMesh m = wall_with_window(false);
  m.tri_level_class.pop_back();
  EXPECT_THROW(LabelTable{m}, Error);
  SemanticMesh bad_building = wall_with_window(false);
  bad_building.buildings = {7};
  EXPECT_THROW(LabelTable{bad_building}, Error);
  const LabelTable table(wall_with_window(false));
  LabelMaps maps;
  EXPECT_THROW(table.fill(std::vector<RayHit>(10), 4, 4, maps), Error);
}

class LabelMapFiles : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cls_label_maps_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(LabelMapFiles, AllFilesWrittenAndReadBackExactly) {
  const LabelMaps maps = cast_hand_scene(wall_with_window(false));
  write_label_maps(dir_, maps, hand_taxonomy());
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"building.png", "coverage.png", "depth.pfm", "level1.png",
                                             "level2.png", "level3.png", "object.npy", "preview.png"}));
  EXPECT_EQ(read_object_map(dir_ / "object.npy", 120, 160), maps.object);
  EXPECT_THROW(read_object_map(dir_ / "object.npy", 160, 120), Error);  // another view's size
  EXPECT_THROW(read_object_map(dir_ / "none.npy", 120, 160), Error);
  for (int l = 0; l < 3; ++l) {
    const cv::Mat png = cv::imread((dir_ / ("level" + std::to_string(l + 1) + ".png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(png.type(), CV_16UC1);
    ASSERT_EQ(png.cols, 160);
    ASSERT_EQ(png.rows, 120);
    EXPECT_TRUE(std::equal(maps.level[l].begin(), maps.level[l].end(), png.ptr<uint16_t>(0)));
  }
  const cv::Mat coverage = cv::imread((dir_ / "coverage.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(coverage.type(), CV_8UC1);
  EXPECT_TRUE(std::equal(maps.coverage.begin(), maps.coverage.end(), coverage.ptr<uint8_t>(0)));
  const FloatImage depth = read_pfm(dir_ / "depth.pfm");
  ASSERT_EQ(depth.width, 160);
  ASSERT_EQ(depth.height, 120);
  EXPECT_EQ(depth.data, maps.depth);
  const cv::Mat preview = cv::imread((dir_ / "preview.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(preview.type(), CV_8UC3);
  EXPECT_EQ(preview.at<cv::Vec3b>(60, 75), cv::Vec3b(255, 0, 0));  // window: RGB (0, 0, 255) as BGR
  EXPECT_EQ(preview.at<cv::Vec3b>(5, 5), cv::Vec3b(40, 40, 40));   // nothing hit
}

TEST_F(LabelMapFiles, PfmRowsAreBottomToTopLittleEndian) {
  // 2x2 map, top row {1, 2}, bottom row {3, 4}: the file stores the bottom row first.
  write_pfm(dir_ / "d.pfm", {1, 2, 3, 4}, 2, 2);
  const std::string bytes = read_text_file(dir_ / "d.pfm");
  const std::string header = "Pf\n2 2\n-1.0\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  ASSERT_EQ(bytes.size(), header.size() + 16);
  float stored[4];
  std::memcpy(stored, bytes.data() + header.size(), 16);
  EXPECT_EQ(stored[0], 3.0f);
  EXPECT_EQ(stored[1], 4.0f);
  EXPECT_EQ(stored[2], 1.0f);
  EXPECT_EQ(stored[3], 2.0f);
}

TEST_F(LabelMapFiles, ReadsBigEndianPfmAndRejectsBrokenOnes) {
  fs::create_directories(dir_);
  auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    return dir_ / name;
  };
  // 1x1 big-endian (positive scale) 1.5f = 0x3FC00000.
  const FloatImage big = read_pfm(write("big.pfm", std::string("Pf\n1 1\n1.0\n") + std::string("\x3f\xc0\x00\x00", 4)));
  ASSERT_EQ(big.data.size(), 1u);
  EXPECT_EQ(big.data[0], 1.5f);
  EXPECT_THROW(read_pfm(write("trunc.pfm", "Pf\n4 4\n-1.0\n0123")), Error);
  EXPECT_THROW(read_pfm(write("magic.pfm", "P6\n1 1\n255\nabc")), Error);
  EXPECT_THROW(read_pfm(write("rgb.pfm", "PF\n1 1\n-1.0\n012345678901")), Error);
  EXPECT_THROW(read_pfm(write("size.pfm", "Pf\n-3 1\n-1.0\n0123")), Error);
  EXPECT_THROW(read_pfm(write("nan.pfm", "Pf\n1 1\nabc\n0123")), Error);
  EXPECT_THROW(read_pfm(dir_ / "missing.pfm"), Error);
  try {
    read_pfm(dir_ / "trunc.pfm");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("trunc.pfm"), std::string::npos) << e.what();
  }
}

TEST_F(LabelMapFiles, WriterRejectsSizeMismatchAndLeavesNothing) {
  EXPECT_THROW(write_png_u16(dir_ / "x.png", std::vector<uint16_t>(5), 2, 2), Error);
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

}  // namespace
}  // namespace cls
