// `citylangsplat raycast` and `align-check` end to end on a small COLMAP scene of FZK-Haus.
#include <gtest/gtest.h>

#include "cli_runner.h"
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "citymodel/city_model.h"
#include "citymodel/city_transform.h"
#include "core/atomic_file.h"
#include "core/exit_codes.h"
#include "raycast/label_maps.h"
#include "raycast/look_at.h"
#include "scene/colmap.h"
#include "scene/scene.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

// A COLMAP text scene in the FZK-Haus local frame (source minus the mesh origin): two oblique
// 160x120 views with blank images, and sparse points = the centroids of 80 mesh triangles plus
// 20 points 1 km above the house. The city transform maps the source CRS into that frame.
class CliScene : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cls_raycast_cli_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "scene" / "images");
    fs::create_directories(dir_ / "scene" / "sparse" / "0");
    mesh_ = load_city_model(kFzk, Taxonomy::builtin(), 0);
    CityTransform to_local;
    for (int k = 0; k < 3; ++k) to_local.matrix[k][3] = -mesh_.origin[k];
    write_city_transform((dir_ / "transform.json").string(), to_local);

    Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const auto& p : mesh_.vertices)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    ColmapModel model;
    model.cameras[1] = Camera{1, CameraModel::Pinhole, 160, 120, {cam_.fx, cam_.fy, cam_.cx, cam_.cy}};
    const char* names[] = {"view_a.png", "view_b.png"};
    for (uint32_t k = 0; k < 2; ++k) {
      poses_.push_back(frame_box(lo, hi, cam_, 0.4 + 2.0 * k, 0.5, 1.3));
      ColmapImage im;
      im.id = k + 1;
      im.camera_id = 1;
      im.name = names[k];
      im.qvec = rotation_to_qvec(poses_[k].R);
      im.tvec = {poses_[k].t.x, poses_[k].t.y, poses_[k].t.z};
      model.images[im.id] = im;
      cv::imwrite((dir_ / "scene" / "images" / names[k]).string(), cv::Mat(120, 160, CV_8UC3, cv::Scalar(90, 90, 90)));
    }
    for (uint64_t k = 0; k < 100; ++k) {
      ColmapPoint3D p;
      p.id = k + 1;
      if (k < 80) {
        const auto& t = mesh_.triangles[k * 7 % mesh_.num_triangles()];
        for (int c = 0; c < 3; ++c)
          p.xyz[c] = (mesh_.vertices[t[0]][c] + mesh_.vertices[t[1]][c] + mesh_.vertices[t[2]][c]) / 3;
      } else {
        p.xyz = {0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), hi.z + 1000};
      }
      model.points[p.id] = p;
    }
    write_colmap_text((dir_ / "scene" / "sparse" / "0").string(), model);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string scene_args() const {
    return "--scene " + (dir_ / "scene").string() + " --city " + kFzk + " --city-transform " +
           (dir_ / "transform.json").string();
  }

  fs::path dir_;
  SemanticMesh mesh_;
  PinholeCamera cam_{140, 140, 80, 60, 160, 120};
  std::vector<Pose> poses_;
};

TEST_F(CliScene, RaycastWritesEveryMapAndMatchesTheLibrary) {
  const fs::path out = dir_ / "out";
  const test::CliResult r = test::run_cli("raycast " + scene_args() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << "stdout must stay clean: " << r.out;

  const auto legend = nlohmann::json::parse(read_text_file(out / "legend.json"));
  ASSERT_EQ(legend.size(), Taxonomy::builtin().classes.size());

  // The same cast in-process, with the pose as the scene reader returns it.
  std::vector<Vec3f> vertices;
  for (const auto& p : mesh_.vertices) vertices.push_back(Vec3f{float(p[0]), float(p[1]), float(p[2])});
  const Raycaster rc(vertices, mesh_.triangles, opening_priority(mesh_));
  const Scene scene = load_scene((dir_ / "scene").string());
  ASSERT_EQ(scene.views.size(), 2u);
  for (const SceneView& view : scene.views) {
    const fs::path vdir = out / fs::path(view.name).stem();
    SCOPED_TRACE(vdir.string());
    for (const char* f : {"level1.png", "level2.png", "level3.png", "building.png", "coverage.png", "depth.pfm",
                          "preview.png"})
      EXPECT_TRUE(fs::exists(vdir / f)) << f;
    std::vector<RayHit> hits;
    rc.cast_view(view.camera, view.pose, hits);
    LabelMaps want;
    LabelTable(mesh_).fill(hits, view.camera.width, view.camera.height, want);
    for (int l = 0; l < 3; ++l) {
      const cv::Mat got = cv::imread((vdir / ("level" + std::to_string(l + 1) + ".png")).string(), cv::IMREAD_UNCHANGED);
      ASSERT_EQ(got.type(), CV_16UC1);
      ASSERT_EQ(got.total(), want.level[l].size());
      size_t agree = 0;
      for (size_t p = 0; p < got.total(); ++p) agree += got.ptr<uint16_t>(0)[p] == want.level[l][p];
      EXPECT_GE(agree, 0.999 * got.total()) << "level " << l + 1;
    }
    const cv::Mat coverage = cv::imread((vdir / "coverage.png").string(), cv::IMREAD_UNCHANGED);
    EXPECT_GT(cv::countNonZero(coverage), 160 * 120 / 3);
  }
}

TEST_F(CliScene, RaycastValidatesBeforeWriting) {
  const fs::path out = dir_ / "out";
  const std::string broken = CLS_TEST_FIXTURES "/broken/city_transform_not_similarity.json";
  test::CliResult r = test::run_cli("raycast --scene " + (dir_ / "scene").string() + " --city " + kFzk + " --city-transform " + broken +
                      " --out " + out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("city_transform_not_similarity.json"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  const std::string invalid = CLS_TEST_DATA "/citygml/citygml4j/invalid_building_v3.gml";
  r = test::run_cli("raycast --scene " + (dir_ / "scene").string() + " --city " + invalid + " --out " + out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("invalid_building_v3.gml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  fs::remove(dir_ / "scene" / "images" / "view_b.png");
  r = test::run_cli("raycast " + scene_args() + " --out " + out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("view_b.png"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  r = test::run_cli("raycast --scene " + (dir_ / "scene").string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2);  // --city missing: a usage error
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CliScene, AlignCheckReportsTheShareOnTheMesh) {
  test::CliResult r = test::run_cli("align-check " + scene_args() + " -d 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // exactly one JSON object
  EXPECT_EQ(j["points"], 100);
  EXPECT_EQ(j["triangles"], mesh_.num_triangles());
  EXPECT_DOUBLE_EQ(j["fraction_within"].get<double>(), 0.8);
  EXPECT_LT(j["median"].get<double>(), 1e-3);
  EXPECT_NEAR(j["mean"].get<double>(), 200.7, 0.8);  // 20 points 1000 to 1007 m above the mesh
  EXPECT_TRUE(j["aligned"].get<bool>());
  EXPECT_EQ(r.err.find("misaligned"), std::string::npos) << r.err;

  // --min-fraction: 80 of the 100 points lie on the mesh, so 0.8 passes and 0.81 fails with exit 5.
  r = test::run_cli("align-check " + scene_args() + " -d 0.5 --json --min-fraction 0.8");
  EXPECT_EQ(r.status, 0) << r.err;
  r = test::run_cli("align-check " + scene_args() + " -d 0.5 --json --min-fraction 0.81");
  EXPECT_EQ(r.status, kExitMisaligned) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out)["aligned"].get<bool>());
  EXPECT_NE(r.err.find("--min-fraction 0.81"), std::string::npos) << r.err;

  // The model shifted by 30 m: nothing lies on it any more, and the command says so.
  CityTransform shifted = read_city_transform((dir_ / "transform.json").string());
  shifted.matrix[0][3] += 30;
  write_city_transform((dir_ / "transform.json").string(), shifted);
  r = test::run_cli("align-check " + scene_args() + " --json");
  ASSERT_EQ(r.status, kExitMisaligned) << r.err;  // below the default --min-fraction
  const auto bad = nlohmann::json::parse(r.out);
  EXPECT_EQ(bad["fraction_within"].get<double>(), 0.0);
  EXPECT_FALSE(bad["aligned"].get<bool>());
  EXPECT_NE(r.err.find("misaligned"), std::string::npos) << r.err;
}

TEST_F(CliScene, AlignCheckReportsDistancesInModelUnits) {
  // Scene frame = 2x the local frame: scene distances double, reported metres do not.
  CityTransform scaled = read_city_transform((dir_ / "transform.json").string());
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) scaled.matrix[r][c] *= 2;
  write_city_transform((dir_ / "transform.json").string(), scaled);
  ColmapModel model = read_colmap((dir_ / "scene" / "sparse" / "0").string());
  for (auto& [id, p] : model.points)
    for (double& x : p.xyz) x *= 2;
  write_colmap_text((dir_ / "scene" / "sparse" / "0").string(), model);
  const test::CliResult r = test::run_cli("align-check " + scene_args() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["fraction_within"].get<double>(), 0.8);
  EXPECT_NEAR(j["mean"].get<double>(), 200.7, 0.8);  // 1 km, not 2 km
}

}  // namespace
}  // namespace cls
