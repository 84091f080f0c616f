// Library-level tests of the synthetic scene generator on a hand-built house (no file reader).
#include <gtest/gtest.h>

#include "synth/file_tree.h"
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/atomic_file.h"
#include "raycast/pixel_ray.h"
#include "raycast/raycaster.h"
#include "synth/geometry_util.h"
#include "synth/synth_scene.h"
#include "synth/toy_house.h"

namespace fs = std::filesystem;
using namespace cls;
using namespace cls::synth;

namespace {

SynthSettings tiny_settings(uint64_t seed) {
  SynthSettings s;
  s.views = 6;
  s.width = 96;
  s.height = 72;
  s.seed = seed;
  s.samples_per_view = 150;
  s.gt_density = 100;
  return s;
}

bool same_mat(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

class SynthSceneTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    taxonomy_ = new Taxonomy(Taxonomy::builtin());
    mesh_ = new SemanticMesh(test::toy_house(*taxonomy_));
    scene_ = new SynthScene(render_synth_scene(*mesh_, *taxonomy_, tiny_settings(7)));
  }
  static void TearDownTestSuite() {
    delete scene_;
    delete mesh_;
    delete taxonomy_;
  }
  static Taxonomy* taxonomy_;
  static SemanticMesh* mesh_;
  static SynthScene* scene_;
};
Taxonomy* SynthSceneTest::taxonomy_ = nullptr;
SemanticMesh* SynthSceneTest::mesh_ = nullptr;
SynthScene* SynthSceneTest::scene_ = nullptr;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cls_synth_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}


}  // namespace

TEST(UavCameras, IntrinsicsPitchAndAim) {
  Box3d city;
  city.extend({0, 0, 0});
  city.extend({12, 10, 9});
  const auto views = make_uav_views(city, {24, 480, 360, 60, 3});
  ASSERT_EQ(views.size(), 24u);
  std::set<std::string> names;
  for (const SynthView& v : views) {
    names.insert(v.name);
    // fx from a 60 degree horizontal field of view: 240 / tan(30 deg).
    EXPECT_NEAR(v.camera.fx, 240 / std::tan(M_PI / 6), 1e-9);
    EXPECT_EQ(v.camera.fy, v.camera.fx);
    EXPECT_EQ(v.camera.cx, 240);
    EXPECT_EQ(v.camera.cy, 180);
    // Optical axis (third row of R) points down by 25..60 degrees.
    const double pitch = std::asin(-v.pose.R.m[2][2]) * 180 / M_PI;
    EXPECT_GE(pitch, kMinPitchDeg);
    EXPECT_LE(pitch, kMaxPitchDeg);
    // No roll: the image x axis is horizontal.
    EXPECT_NEAR(v.pose.R.m[0][2], 0, 1e-12);
    // The model's centre is in the middle part of the image, in front of the camera.
    const Vec3d c = v.pose.R * city.center() + v.pose.t;
    ASSERT_GT(c.z, 0);
    EXPECT_LT(std::abs(v.camera.fx * c.x / c.z), 0.3 * 480);
    EXPECT_LT(std::abs(v.camera.fy * c.y / c.z), 0.3 * 360);
  }
  EXPECT_EQ(names.size(), 24u);
  EXPECT_EQ(*names.begin(), "0000.png");
  EXPECT_EQ(*names.rbegin(), "0023.png");
}

TEST(UavCameras, PerBuildingRigSplitsViewsAndAimsAtEachBuilding) {
  // Three 6 x 8 m houses 10 m apart; 11 views: 4, 4 and 3, each share centred on its own house.
  std::vector<Box3d> houses(3);
  for (int b = 0; b < 3; ++b) {
    houses[b].extend({10.0 * b, 0, 0});
    houses[b].extend({10.0 * b + 6, 8, 10});
  }
  const auto views = make_building_views(houses, {11, 320, 240, 60, 5});
  ASSERT_EQ(views.size(), 11u);
  const int first[] = {0, 4, 8, 11};
  std::set<std::string> names;
  for (int b = 0; b < 3; ++b)
    for (int i = first[b]; i < first[b + 1]; ++i) {
      const SynthView& v = views[i];
      names.insert(v.name);
      // Its own house projects near the image centre, nearer than either neighbour's centre.
      auto offset = [&](const Box3d& box) {
        const Vec3d c = v.pose.R * box.center() + v.pose.t;
        return c.z > 0 ? std::hypot(v.camera.fx * c.x / c.z, v.camera.fy * c.y / c.z) : 1e9;
      };
      EXPECT_LT(offset(houses[b]), 0.3 * 320) << v.name;
      for (int other = 0; other < 3; ++other)
        if (other != b) EXPECT_LT(offset(houses[b]), offset(houses[other])) << v.name;
    }
  EXPECT_EQ(names.size(), 11u);
  EXPECT_EQ(views.back().name, "0010.png");
}

TEST(SynthSettingsTest, RejectsBadValues) {
  EXPECT_EQ(settings_problem(SynthSettings{}), "");
  SynthSettings s;
  s.views = 1;
  EXPECT_NE(settings_problem(s), "");
  s = {};
  s.width = 8;
  EXPECT_NE(settings_problem(s), "");
  s = {};
  s.gt_density = 0;
  EXPECT_NE(settings_problem(s), "");
  s = {};
  s.point_noise = std::nan("");
  EXPECT_NE(settings_problem(s), "");
}

TEST_F(SynthSceneTest, SameSeedSameOutputIndependentOfThreads) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const SynthScene again = render_synth_scene(*mesh_, *taxonomy_, tiny_settings(7));
  omp_set_num_threads(threads);
  ASSERT_EQ(again.rendered.size(), scene_->rendered.size());
  for (size_t v = 0; v < again.rendered.size(); ++v) {
    EXPECT_TRUE(same_mat(again.rendered[v].image, scene_->rendered[v].image)) << v;
    EXPECT_TRUE(same_mat(again.rendered[v].labels, scene_->rendered[v].labels)) << v;
  }
  ASSERT_EQ(again.colmap.points.size(), scene_->colmap.points.size());
  EXPECT_EQ(encode_points3d_binary(again.colmap.points), encode_points3d_binary(scene_->colmap.points));
  EXPECT_EQ(encode_images_binary(again.colmap.images), encode_images_binary(scene_->colmap.images));
  ASSERT_EQ(again.gt_points.size(), scene_->gt_points.size());
  for (size_t i = 0; i < again.gt_points.size(); ++i) {
    ASSERT_EQ(again.gt_points[i].label, scene_->gt_points[i].label);
    ASSERT_EQ(again.gt_points[i].rgb, scene_->gt_points[i].rgb);
    ASSERT_EQ(norm(again.gt_points[i].position - scene_->gt_points[i].position), 0.0f);
  }

  const SynthScene other = render_synth_scene(*mesh_, *taxonomy_, tiny_settings(8));
  int differing = 0;
  for (size_t v = 0; v < other.rendered.size(); ++v)
    differing += !same_mat(other.rendered[v].image, scene_->rendered[v].image);
  EXPECT_EQ(differing, static_cast<int>(other.rendered.size()));
  EXPECT_NE(encode_points3d_binary(other.colmap.points), encode_points3d_binary(scene_->colmap.points));
}

TEST_F(SynthSceneTest, WrittenFilesAreByteIdenticalForTheSameSeed) {
  const fs::path a = fresh_dir("a"), b = fresh_dir("b");
  write_synth_outputs(a.string(), *scene_, *taxonomy_);
  write_synth_outputs(b.string(), render_synth_scene(*mesh_, *taxonomy_, tiny_settings(7)), *taxonomy_);
  const auto files_a = test::read_tree(a), files_b = test::read_tree(b);
  EXPECT_EQ(files_a.size(), 6u * 2 + 6 + 2);  // images, labels, sparse/0 x6, legend, points.ply
  EXPECT_TRUE(files_a == files_b);
  EXPECT_TRUE(files_a.count("images/0005.png") && files_a.count("gt/labels/0005.png") &&
              files_a.count("sparse/0/points3D.bin") && files_a.count("sparse/0/images.txt"));
  fs::remove_all(a);
  fs::remove_all(b);
}

// The label images against an independent projection: the city mesh alone, cast by the test
// with openings first; a pixel may only lose its city label where clutter is in front.
TEST_F(SynthSceneTest, LabelsAgreeWithIndependentProjection) {
  std::vector<Vec3f> vertices;
  for (const auto& v : mesh_->vertices) vertices.push_back({float(v[0]), float(v[1]), float(v[2])});
  std::vector<uint8_t> priority;
  for (const int c : mesh_->tri_class) priority.push_back(taxonomy_->classes[c].level == 1);
  const Raycaster city(vertices, mesh_->triangles, priority);
  // Clutter alone, taken from the scene.
  const SynthGeometry& g = scene_->geometry;
  std::vector<std::array<uint32_t, 3>> clutter_tris;
  for (size_t t = 0; t < g.triangles.size(); ++t)
    if (g.origins[t].source == SurfaceSource::Clutter) clutter_tris.push_back(g.triangles[t]);
  ASSERT_FALSE(clutter_tris.empty());
  const Raycaster clutter(g.vertices, clutter_tris);

  size_t pixels = 0, disagree = 0, city_pixels = 0, window_pixels = 0;
  for (size_t v = 0; v < scene_->views.size(); ++v) {
    const SynthView& view = scene_->views[v];
    std::vector<RayHit> city_hits, clutter_hits;
    city.cast_view(view.camera, view.pose, city_hits);
    clutter.cast_view(view.camera, view.pose, clutter_hits);
    const cv::Mat& labels = scene_->rendered[v].labels;
    for (int j = 0; j < labels.rows; ++j)
      for (int i = 0; i < labels.cols; ++i) {
        const size_t k = static_cast<size_t>(j) * labels.cols + i;
        const int expected = city_hits[k].prim == kNoHit ? 0 : mesh_->tri_level_class[city_hits[k].prim][0] + 1;
        const bool occluded = clutter_hits[k].prim != kNoHit &&
                              (city_hits[k].prim == kNoHit || clutter_hits[k].depth < city_hits[k].depth);
        const int got = labels.at<uint16_t>(j, i);
        ++pixels;
        disagree += got != (occluded ? 0 : expected);
        city_pixels += got != 0;
        window_pixels += got == taxonomy_->find("window") + 1;
      }
  }
  EXPECT_LE(disagree, pixels / 1000) << disagree << " of " << pixels;
  EXPECT_GT(city_pixels, pixels / 20);
  EXPECT_GT(window_pixels, 0u);
}

TEST_F(SynthSceneTest, CoverageIsNeitherEmptyNorEverything) {
  const SynthGeometry& g = scene_->geometry;
  EXPECT_GE(g.clutter.size(), 5u);
  // Clutter stands outside the building's footprint.
  for (size_t t = 0; t < g.triangles.size(); ++t) {
    if (g.origins[t].source != SurfaceSource::Clutter) continue;
    for (const uint32_t vi : g.triangles[t]) {
      const Vec3f p = g.vertices[vi];
      EXPECT_FALSE(p.x > g.city_bounds.lo.x && p.x < g.city_bounds.hi.x && p.y > g.city_bounds.lo.y &&
                   p.y < g.city_bounds.hi.y);
    }
  }
  size_t labelled = 0, background_surface = 0, total = 0;
  for (const RenderedView& r : scene_->rendered)
    for (int j = 0; j < r.labels.rows; ++j)
      for (int i = 0; i < r.labels.cols; ++i) {
        ++total;
        labelled += r.labels.at<uint16_t>(j, i) != 0;
        background_surface += r.labels.at<uint16_t>(j, i) == 0 && std::isfinite(r.depth[j * r.labels.cols + i]);
      }
  EXPECT_GT(labelled, total / 20);
  EXPECT_LT(labelled, total * 9 / 10);
  EXPECT_GT(background_surface, total / 10);
}

TEST_F(SynthSceneTest, ColmapModelReadsBackWithViewsAndIntrinsics) {
  const fs::path dir = fresh_dir("colmap");
  write_synth_outputs(dir.string(), *scene_, *taxonomy_);
  for (const bool binary : {true, false}) {
    const std::string sparse = (dir / "sparse" / "0").string();
    const ColmapModel m = binary ? read_colmap_binary(sparse) : read_colmap_text(sparse);
    ASSERT_EQ(m.cameras.size(), 1u);
    const Camera& cam = m.cameras.at(1);
    EXPECT_EQ(cam.model, CameraModel::Pinhole);
    EXPECT_EQ(cam.width, 96);
    EXPECT_EQ(cam.height, 72);
    ASSERT_EQ(cam.params.size(), 4u);
    EXPECT_NEAR(cam.params[0], 48 / std::tan(M_PI / 6), 1e-9);
    EXPECT_NEAR(cam.params[1], cam.params[0], 1e-12);
    EXPECT_NEAR(cam.params[2], 48, 1e-12);
    EXPECT_NEAR(cam.params[3], 36, 1e-12);
    ASSERT_EQ(m.images.size(), scene_->views.size());
    for (const auto& [id, image] : m.images) {
      const SynthView& view = scene_->views[id - 1];
      EXPECT_EQ(image.name, view.name);
      const Pose p = image.pose();
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(p.t[i], view.pose.t[i], 1e-9);
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(p.R.m[i][j], view.pose.R.m[i][j], 1e-9);
      }
      EXPECT_TRUE(fs::exists(dir / "images" / image.name));
    }
    EXPECT_EQ(m.points.size(), scene_->colmap.points.size());
  }
  fs::remove_all(dir);
}

// Sparse points lie on the scene's surfaces within the noise, on the city model and off it,
// and reproject into every view of their track.
TEST_F(SynthSceneTest, SparsePointsLieOnSurfacesAndReproject) {
  const SynthGeometry& g = scene_->geometry;
  const ColmapModel& m = scene_->colmap;
  ASSERT_GT(m.points.size(), 100u);
  size_t on_city = 0, off_city = 0;
  const double sigma = tiny_settings(7).point_noise;
  for (const auto& [id, point] : m.points) {
    const Vec3d X{point.xyz[0], point.xyz[1], point.xyz[2]};
    const auto [distance, tri] = test::nearest_triangle(X, g.vertices, g.triangles);
    // |noise| < 5 sigma (chi distribution with 3 dof: P > 5 sigma ~ 1e-5) plus float rounding.
    EXPECT_LT(distance, 5 * sigma + 1e-3) << id;
    (g.origins[tri].source == SurfaceSource::City ? on_city : off_city)++;
    ASSERT_GE(point.track.size(), 2u);
    for (const auto& [image_id, index] : point.track) {
      const ColmapImage& image = m.images.at(image_id);
      ASSERT_LT(index, image.points2d.size());
      EXPECT_EQ(image.points2d[index].point3d_id, id);
      const SynthView& view = scene_->views[image_id - 1];
      const Vec3d q = view.pose.R * X + view.pose.t;
      const double x = view.camera.fx * q.x / q.z + view.camera.cx, y = view.camera.fy * q.y / q.z + view.camera.cy;
      // 5 sigma of noise seen from >= 10 m away is below 1 pixel at fx = 83.
      EXPECT_LT(std::hypot(x - image.points2d[index].x, y - image.points2d[index].y), 1.0);
    }
  }
  EXPECT_GT(on_city, m.points.size() / 10);
  EXPECT_GT(off_city, m.points.size() / 10);
}

TEST_F(SynthSceneTest, GroundTruthCloudHasClassesAndDensity) {
  const fs::path dir = fresh_dir("gt");
  write_synth_outputs(dir.string(), *scene_, *taxonomy_);
  const std::string ply = read_text_file(dir / "gt" / "points.ply");
  const size_t end = ply.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  const std::string header = ply.substr(0, end);
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("property int class"), std::string::npos);
  const size_t n = scene_->gt_points.size();
  EXPECT_NE(header.find("element vertex " + std::to_string(n) + "\n"), std::string::npos);
  ASSERT_EQ(ply.size() - end - 11, n * 19);

  const SynthGeometry& g = scene_->geometry;
  const int window = taxonomy_->find("window");
  size_t windows = 0, non_city = 0;
  for (size_t i = 0; i < n; ++i) {
    const char* r = ply.data() + end + 11 + i * 19;
    float xyz[3];
    int32_t label;
    std::memcpy(xyz, r, 12);
    std::memcpy(&label, r + 15, 4);
    windows += label == window;
    non_city += label == -1;
    EXPECT_TRUE(label == -1 || (label >= 0 && label < static_cast<int>(taxonomy_->classes.size())));
    if (i % 97 != 0) continue;  // the distance check is brute force: a sample of the points
    const Vec3d X{xyz[0], xyz[1], xyz[2]};
    EXPECT_LT(test::nearest_triangle(X, g.vertices, g.triangles).first, 1e-3);
    // The label is the level-1 class of a surface the point lies on (-1 for terrain and clutter);
    // a window on top of an unholed wall lies on two.
    std::set<int> labels_here;
    for (size_t t = 0; t < g.triangles.size(); ++t) {
      const auto& tri = g.triangles[t];
      const double d = norm(X - closest_point_on_triangle(X, cast<double>(g.vertices[tri[0]]),
                                                          cast<double>(g.vertices[tri[1]]), cast<double>(g.vertices[tri[2]])));
      if (d > 1e-3) continue;
      const TriangleOrigin& o = g.origins[t];
      labels_here.insert(o.source == SurfaceSource::City ? mesh_->tri_level_class[o.index][0] : -1);
    }
    EXPECT_TRUE(labels_here.count(label)) << label;
  }
  // Window area of the toy house: 1.2 x 1.4 + 2.0 x 1.1 = 3.88 m², at 100 points per m².
  EXPECT_NEAR(static_cast<double>(windows), 388, 4 * std::sqrt(388.0) + 3);
  EXPECT_GT(non_city, 0u);
  fs::remove_all(dir);
}

// --occluders: extra trees close in front of the facades, clear of the building (no vertex inside its
// footprint box), the rest of the clutter unchanged; in the images they hide part of the building.
TEST_F(SynthSceneTest, OccludersStandInFrontOfTheFacadesAndHideSomeOfThem) {
  const SynthGeometry plain = build_synth_geometry(*mesh_, *taxonomy_, 7, 0);
  const SynthGeometry more = build_synth_geometry(*mesh_, *taxonomy_, 7, 6);
  ASSERT_EQ(more.clutter.size(), plain.clutter.size() + 6);
  for (size_t i = 0; i < plain.clutter.size(); ++i) {
    EXPECT_EQ(more.clutter[i].base.x, plain.clutter[i].base.x) << i;
    EXPECT_EQ(more.clutter[i].kind, plain.clutter[i].kind) << i;
  }
  const Box3d& box = more.city_bounds;
  for (size_t i = plain.clutter.size(); i < more.clutter.size(); ++i) {
    const ClutterObject& o = more.clutter[i];
    EXPECT_TRUE(o.kind == ClutterKind::Tree || o.kind == ClutterKind::Conifer);
    // Distance from the trunk to the footprint box: beyond the canopy, within 2.5 m of it.
    const double dx = std::max({box.lo.x - o.base.x, 0.0, o.base.x - box.hi.x});
    const double dy = std::max({box.lo.y - o.base.y, 0.0, o.base.y - box.hi.y});
    const double d = std::hypot(dx, dy);
    EXPECT_GT(d, o.radius) << i;
    EXPECT_LT(d, o.radius + 2.5 * std::sqrt(2.0) + 1e-9) << i;
  }
  for (size_t t = 0; t < more.triangles.size(); ++t) {
    if (more.origins[t].source != SurfaceSource::Clutter) continue;
    for (const uint32_t vi : more.triangles[t]) {
      const Vec3f p = more.vertices[vi];
      EXPECT_FALSE(p.x > box.lo.x && p.x < box.hi.x && p.y > box.lo.y && p.y < box.hi.y);
    }
  }
  SynthSettings s = tiny_settings(7);
  s.occluders = 6;
  const SynthScene occluded = render_synth_scene(*mesh_, *taxonomy_, s);
  size_t before = 0, after = 0;
  for (size_t v = 0; v < scene_->rendered.size(); ++v) {
    before += cv::countNonZero(scene_->rendered[v].labels);
    after += cv::countNonZero(occluded.rendered[v].labels);
  }
  EXPECT_LT(after, before);
  EXPECT_GT(after, before / 4);
  s.occluders = -1;
  EXPECT_NE(settings_problem(s), "");
}
