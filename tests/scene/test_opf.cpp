// OPF projects (scene/opf.h): a small consistent project written here from the specification's own
// definitions (omega-phi-kappa, the photogrammetric camera axes, glTF's column-major node matrix), each
// camera checked by projecting points with the specification's formula, not with our conversion; the
// specification's example files (data/opf/spec-examples) as fixtures; damaged projects.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/opf.h"
#include "scene/scene.h"
#include "scene_test_util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace cls;

namespace {

const fs::path kSpec = CLS_TEST_DATA "/opf/spec-examples";

struct OpfCamera {
  uint64_t id;
  std::array<double, 3> position, opk_deg;
};

// The OPF projection of world point X by a camera: the image CS is (x right, y up, z towards the camera),
// R = Rx(omega) Ry(phi) Rz(kappa) maps it into the world, so X_img = R^T (X - C); pixels from the top
// left corner, y down. R is composed here from axis-angle rotations, not with the reader's code.
std::array<double, 2> opf_projection(const OpfCamera& c, double f, double cx, double cy, Vec3d X) {
  const double d = M_PI / 180;
  const Mat3d R = axis_angle_to_rotation(Vec3d{c.opk_deg[0] * d, 0, 0}) * axis_angle_to_rotation(Vec3d{0, c.opk_deg[1] * d, 0}) *
                  axis_angle_to_rotation(Vec3d{0, 0, c.opk_deg[2] * d});
  const Vec3d p = transpose(R) * (X - Vec3d{c.position[0], c.position[1], c.position[2]});
  return {cx + f * p.x / -p.z, cy - f * p.y / -p.z};
}

void write_json(const fs::path& path, const json& j) { write_text_atomic(path, j.dump(2)); }

// A project of two perspective cameras looking down at the origin (80x60 images, f = 70 px), three tie
// points written through a node matrix that swaps y and z, as the specification's example does.
struct Project {
  fs::path dir;
  std::vector<OpfCamera> cameras = {{11, {2, -3, 20}, {5, -4, 30}}, {12, {-4, 2, 18}, {-8, 6, -120}}};
  double f = 70, cx = 41.5, cy = 29.25;
  std::vector<std::array<float, 3>> stored = {{1, 2, 3}, {-1.5f, 0.25f, 4}, {0, 0, 0}};  // glTF node coordinates
  json calibrated;

  explicit Project(const std::string& name) : dir(test::fresh_dir(name)) {
    fs::create_directories(dir / "images");
    json list = {{"format", "application/opf-camera-list+json"}, {"version", "1.0"}, {"cameras", json::array()}};
    for (const auto& c : cameras) {
      const std::string uri = "images/IMG_" + std::to_string(c.id) + ".png";
      test::photo_with_exif(dir / "images", "IMG_" + std::to_string(c.id) + ".png", {});
      list["cameras"].push_back({{"id", c.id}, {"uri", uri}});
    }
    write_json(dir / "camera_list.json", list);
    write_json(dir / "input_cameras.json",
               {{"format", "application/opf-input-cameras+json"}, {"version", "1.0"},
                {"sensors", {{{"id", 7}, {"image_size_px", {80, 60}}}}}, {"captures", json::array()}});
    calibrated = {{"format", "application/opf-calibrated-cameras+json"}, {"version", "1.0"},
                  {"sensors", {{{"id", 7},
                                {"internals", {{"type", "perspective"}, {"focal_length_px", f}, {"principal_point_px", {cx, cy}},
                                               {"radial_distortion", {0, 0, 0}}, {"tangential_distortion", {0, 0}}}}}}},
                  {"cameras", json::array()}};
    for (const auto& c : cameras)
      calibrated["cameras"].push_back({{"id", c.id}, {"sensor_id", 7}, {"position", c.position}, {"orientation_deg", c.opk_deg}});
    write_json(dir / "calibrated_cameras.json", calibrated);
    std::string bytes(stored.size() * 12, '\0');
    std::memcpy(bytes.data(), stored.data(), bytes.size());
    write_text_atomic(dir / "tracks" / "positions.bin", bytes);
    write_json(dir / "tracks" / "sparse.gltf",
               {{"asset", {{"version", "2.0"}}},
                {"buffers", {{{"uri", "positions.bin"}, {"byteLength", bytes.size()}}}},
                {"bufferViews", {{{"buffer", 0}, {"byteLength", bytes.size()}}}},
                {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", stored.size()}, {"type", "VEC3"}}}},
                {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 0}}}}}}},
                {"nodes", {{{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 10, 20, 30, 1}}}}},
                {"scene", 0},
                {"scenes", {{{"nodes", {0}}}}}});
    write_json(dir / "frame.json", {{"format", "application/opf-scene-reference-frame+json"}, {"version", "1.0"},
                                    {"crs", {{"definition", "EPSG:25832"}}},
                                    {"base_to_canonical", {{"scale", {1, 1, 1}}, {"shift", {-457800, -5439000, -110}},
                                                           {"swap_xy", false}}}});
    auto item = [](const std::string& type, json resources) {
      return json{{"id", type}, {"type", type}, {"resources", resources}, {"sources", json::array()}};
    };
    write_json(dir / "project.opf",
               {{"version", "1.0"}, {"format", "application/opf-project+json"}, {"name", "test"},
                {"items",
                 {item("camera_list", {{{"uri", "camera_list.json"}, {"format", "application/opf-camera-list+json"}}}),
                  item("input_cameras", {{{"uri", "input_cameras.json"}, {"format", "application/opf-input-cameras+json"}}}),
                  item("calibration", {{{"uri", "calibrated_cameras.json"}, {"format", "application/opf-calibrated-cameras+json"}},
                                       {{"uri", "tracks/sparse.gltf"}, {"format", "model/gltf+json"}},
                                       {{"uri", "tracks/positions.bin"}, {"format", "application/gltf-buffer+bin"}}}),
                  item("scene_reference_frame",
                       {{{"uri", "frame.json"}, {"format", "application/opf-scene-reference-frame+json"}}})}}});
  }
};

}  // namespace

TEST(Opf, CamerasProjectAsTheSpecificationDefines) {
  const Project p("opf_cameras");
  const Scene scene = load_scene(p.dir.string());
  EXPECT_EQ(scene.source, "opf");
  ASSERT_EQ(scene.views.size(), p.cameras.size());
  for (size_t i = 0; i < p.cameras.size(); ++i) {
    const SceneView& v = scene.views[i];
    EXPECT_EQ(v.name, "images/IMG_" + std::to_string(p.cameras[i].id) + ".png");
    EXPECT_EQ(fs::path(v.image_path), (p.dir / v.name).lexically_normal());
    EXPECT_EQ(v.camera.width, 80);
    const Vec3d C = v.pose.center();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(C[k], p.cameras[i].position[k], 1e-9);
    for (const Vec3d X : {Vec3d{0, 0, 0}, Vec3d{1.5, -2, 0.5}, Vec3d{-3, 1, 2}}) {
      const Vec3d x = v.pose.R * X + v.pose.t;
      ASSERT_GT(x.z, 0) << "in front of the camera";
      const std::array<double, 2> want = opf_projection(p.cameras[i], p.f, p.cx, p.cy, X);
      EXPECT_NEAR(v.camera.fx * x.x / x.z + v.camera.cx, want[0], 1e-9);
      EXPECT_NEAR(v.camera.fy * x.y / x.z + v.camera.cy, want[1], 1e-9);
    }
  }
  // Tie points through the node matrix (column-major: x, z, -y, plus the translation).
  ASSERT_EQ(scene.points.size(), p.stored.size());
  for (size_t i = 0; i < p.stored.size(); ++i) {
    const auto& s = p.stored[i];
    EXPECT_NEAR(scene.points[i].xyz.x, s[0] + 10, 1e-6);
    EXPECT_NEAR(scene.points[i].xyz.y, s[2] + 20, 1e-6);
    EXPECT_NEAR(scene.points[i].xyz.z, -s[1] + 30, 1e-6);
  }
  const OpfProject project = read_opf_project((p.dir / "project.opf").string());
  EXPECT_EQ(project.frame.crs, "EPSG:25832");
  EXPECT_EQ(project.frame.shift[1], -5439000);
}

TEST(Opf, TheSpecificationsSparsePointCloudReadsWithinItsDeclaredBounds) {
  // The spec's tie points under a project of our own cameras (its calibrated cameras are fisheye).
  const Project p("opf_spec_points");
  for (const char* f : {"sparse.gltf", "positions.bin", "partitioning.bin", "matchPointIndexRanges.bin", "matchCameraIds.bin",
                        "matchPixelCoordinates.bin", "matchFeatureIds.bin", "matchScales.bin", "matchDepths.bin"})
    fs::copy_file(kSpec / "point_cloud" / f, p.dir / "tracks" / f, fs::copy_options::overwrite_existing);
  const json gltf = json::parse(read_text_file(kSpec / "point_cloud" / "sparse.gltf"));
  const json& accessor = gltf["accessors"][0];
  const Scene scene = load_scene(p.dir.string());
  ASSERT_EQ(scene.points.size(), accessor["count"].get<size_t>());
  // The node matrix (columns (1,0,0), (0,0,-1), (0,1,0)) maps (x, y, z) to (x, z, -y): the bounds the
  // accessor declares, mapped the same way.
  const auto lo = accessor["min"].get<std::vector<double>>(), hi = accessor["max"].get<std::vector<double>>();
  const Vec3d want_lo{lo[0], lo[2], -hi[1]}, want_hi{hi[0], hi[2], -lo[1]};
  Vec3d got_lo{INFINITY, INFINITY, INFINITY}, got_hi = -1.0 * got_lo;
  for (const SparsePoint& q : scene.points)
    for (int k = 0; k < 3; ++k) got_lo[k] = std::min(got_lo[k], q.xyz[k]), got_hi[k] = std::max(got_hi[k], q.xyz[k]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(got_lo[k], want_lo[k], 1e-6) << k;
    EXPECT_NEAR(got_hi[k], want_hi[k], 1e-6) << k;
  }
}

TEST(Opf, DamagedProjectsNameTheFileAndWhatIsWrong) {
  {  // The specification's calibrated cameras: fisheye sensors.
    Project p("opf_fisheye");
    fs::copy_file(kSpec / "calibrated-cameras.json", p.dir / "calibrated_cameras.json", fs::copy_options::overwrite_existing);
    test::expect_error([&] { load_scene(p.dir.string()); }, {"calibrated_cameras.json", "not in the camera list"});
  }
  {
    Project p("opf_fisheye_sensor");
    p.calibrated["sensors"][0]["internals"]["type"] = "fisheye";
    write_json(p.dir / "calibrated_cameras.json", p.calibrated);
    test::expect_error([&] { load_scene(p.dir.string()); }, {"calibrated_cameras.json", "sensor 7 is a fisheye camera"});
  }
  {  // A buffer shorter than its accessor needs.
    Project p("opf_short_buffer");
    write_text_atomic(p.dir / "tracks" / "positions.bin", std::string(20, '\0'));
    test::expect_error([&] { load_scene(p.dir.string()); }, {"positions.bin", "holds 20 bytes"});
  }
  {  // NaN in the tie points.
    Project p("opf_nan");
    const float nan = NAN;
    std::string bytes = read_text_file(p.dir / "tracks" / "positions.bin");
    std::memcpy(bytes.data() + 12, &nan, 4);
    write_text_atomic(p.dir / "tracks" / "positions.bin", bytes);
    test::expect_error([&] { load_scene(p.dir.string()); }, {"sparse.gltf", "point 1 is not finite"});
  }
  {  // A value of the wrong type, and a missing item.
    Project p("opf_types");
    p.calibrated["cameras"][0]["position"] = "here";
    write_json(p.dir / "calibrated_cameras.json", p.calibrated);
    test::expect_error([&] { load_scene(p.dir.string()); }, {"calibrated_cameras.json", "\"position\""});
    json project = json::parse(read_text_file(p.dir / "project.opf"));
    project["items"].erase(0);
    write_json(p.dir / "project.opf", project);
    test::expect_error([&] { load_scene(p.dir.string()); }, {"project.opf", "no \"camera_list\" item"});
  }
}
