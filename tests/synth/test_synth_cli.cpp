// End-to-end tests of `citylangsplat synth` on FZK-Haus LoD3 (tiny: 4 views of 96x72).
#include <gtest/gtest.h>

#include "synth/file_tree.h"
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "citymodel/city_model.h"
#include "citymodel/city_transform.h"
#include "core/atomic_file.h"
#include "raycast/alignment.h"
#include "raycast/raycaster.h"
#include "scene/colmap.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

fs::path temp_path(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cls_synth_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

// Exit status of `citylangsplat -q synth ARGS`.
int synth(const std::string& args) {
  const int status = std::system((std::string(CLS_BINARY) + " -q synth " + args + " 2>/dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string tiny(const fs::path& out, int seed = 1) {
  return "--city " + kFzk + " --out " + out.string() + " --views 4 --width 96 --height 72 --gt-density 50 --seed " +
         std::to_string(seed);
}


}  // namespace

TEST(SynthCli, SameSeedSameBytesOtherSeedDiffers) {
  const fs::path a = temp_path("a"), b = temp_path("b"), c = temp_path("c");
  ASSERT_EQ(synth(tiny(a)), 0);
  ASSERT_EQ(synth(tiny(b)), 0);
  ASSERT_EQ(synth(tiny(c, 2)), 0);
  const auto fa = test::read_tree(a), fb = test::read_tree(b), fc = test::read_tree(c);
  for (const char* f : {"scene.json", "city/fzk_haus_lod3_v2.gml", "city/transform.json", "images/0000.png",
                        "images/0003.png", "gt/labels/0003.png", "gt/legend.json", "gt/points.ply",
                        "sparse/0/cameras.bin", "sparse/0/images.bin", "sparse/0/points3D.bin",
                        "sparse/0/cameras.txt", "sparse/0/images.txt", "sparse/0/points3D.txt"})
    EXPECT_TRUE(fa.count(f)) << f;
  EXPECT_EQ(fa.size(), 19u);  // 4 images, 4 labels, 6 sparse, legend, ply, scene, model, transform
  EXPECT_TRUE(fa == fb);
  for (const char* f : {"images/0000.png", "images/0003.png", "gt/points.ply", "sparse/0/points3D.bin"})
    EXPECT_NE(fa.at(f), fc.at(f)) << f;
  for (const auto& d : {a, b, c}) fs::remove_all(d);
}

TEST(SynthCli, SceneJsonModelCopyAndTransform) {
  const fs::path out = temp_path("json");
  ASSERT_EQ(synth(tiny(out)), 0);
  const auto scene = nlohmann::json::parse(read_text_file(out / "scene.json"));
  EXPECT_EQ(scene.at("city_model"), "city/fzk_haus_lod3_v2.gml");
  EXPECT_EQ(scene.at("city_transform"), "city/transform.json");
  EXPECT_EQ(scene.at("lod"), 3);
  EXPECT_EQ(scene.at("generator").at("seed"), 1);
  EXPECT_EQ(scene.at("generator").at("views"), 4);
  EXPECT_EQ(read_text_file(out / "city/fzk_haus_lod3_v2.gml"), read_text_file(kFzk));
  // The transform maps source coordinates to the scene frame: a vertex + origin -> the vertex.
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = load_city_model(kFzk, tax, 3);
  const CityTransform t = read_city_transform((out / "city/transform.json").string());
  const auto& v = mesh.vertices[17];
  const Vec3d p = t.apply({v[0] + mesh.origin[0], v[1] + mesh.origin[1], v[2] + mesh.origin[2]});
  EXPECT_NEAR(p.x, v[0], 1e-6);
  EXPECT_NEAR(p.y, v[1], 1e-6);
  EXPECT_NEAR(p.z, v[2], 1e-6);
  // The COLMAP model lives in the same frame: every view sees the building's centre.
  const ColmapModel m = read_colmap((out / "sparse/0").string());
  ASSERT_EQ(m.images.size(), 4u);
  Vec3d centre{0, 0, 0};
  for (const auto& q : mesh.vertices) centre = centre + (1.0 / mesh.vertices.size()) * Vec3d{q[0], q[1], q[2]};
  const Camera& cam = m.cameras.at(1);
  for (const auto& [id, image] : m.images) {
    const Pose pose = image.pose();
    const Vec3d c = pose.R * centre + pose.t;
    ASSERT_GT(c.z, 0);
    const double x = cam.params[0] * c.x / c.z + cam.params[2], y = cam.params[1] * c.y / c.z + cam.params[3];
    EXPECT_TRUE(x > 0 && x < cam.width && y > 0 && y < cam.height) << image.name;
  }
  fs::remove_all(out);
}

// --city-error changes only what the pipeline is given: the transform, by exactly the requested
// amounts about the model's centre; the exact transform moves to city/transform_true.json.
TEST(SynthCli, CityErrorPerturbsOnlyTheGivenTransform) {
  const fs::path exact = temp_path("exact"), off = temp_path("off");
  ASSERT_EQ(synth(tiny(exact)), 0);
  ASSERT_EQ(synth(tiny(off) + " --city-error t=1,r=2,s=-0.01"), 0);
  const auto fe = test::read_tree(exact), fo = test::read_tree(off);
  EXPECT_EQ(fo.size(), fe.size() + 1);
  for (const auto& [name, bytes] : fe)
    if (name != "city/transform.json" && name != "scene.json") EXPECT_EQ(fo.at(name), bytes) << name;
  EXPECT_EQ(fo.at("city/transform_true.json"), fe.at("city/transform.json"));
  const auto generator = nlohmann::json::parse(fo.at("scene.json")).at("generator");
  EXPECT_EQ(generator.at("city_error").at("truth"), "city/transform_true.json");
  EXPECT_EQ(generator.at("city_error").at("r"), 2.0);

  const SemanticMesh mesh = load_city_model(kFzk, Taxonomy::builtin(), 3);
  const CityTransform given = read_city_transform((off / "city/transform.json").string());
  const CityTransform truth = read_city_transform((off / "city/transform_true.json").string());
  const TransformDifference d = transform_difference(given, truth, mesh);
  EXPECT_NEAR(d.centre, 1, 1e-9);
  EXPECT_NEAR(d.rotation_deg, 2, 1e-9);
  EXPECT_NEAR(d.scale, -0.01, 1e-12);
  EXPECT_GT(d.max_displacement, 1);  // the rotation and scale move the corners further
  EXPECT_NE(synth(tiny(temp_path("bad")) + " --city-error t=1,x=2"), 0);
  EXPECT_NE(synth(tiny(temp_path("bad")) + " --city-error r=-1"), 0);
  EXPECT_NE(synth(tiny(temp_path("bad")) + " --city-error t=1m"), 0);
  for (const auto& d : {exact, off}) fs::remove_all(d);
}

// --drop-openings and --given-city change only the model the pipeline is given: images, labels, points
// and the transform are those of the exact scene.
TEST(SynthCli, GivenModelPerturbationsChangeOnlyTheGivenModel) {
  const fs::path exact = temp_path("exact"), drop = temp_path("drop"), lod2 = temp_path("lod2");
  const std::string lod2_file = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod2_v2.gml";
  ASSERT_EQ(synth(tiny(exact)), 0);
  ASSERT_EQ(synth(tiny(drop) + " --drop-openings 0.3"), 0);
  ASSERT_EQ(synth(tiny(lod2) + " --given-city " + lod2_file), 0);
  const auto fe = test::read_tree(exact), fd = test::read_tree(drop), fl = test::read_tree(lod2);
  for (const auto& [name, bytes] : fe)
    if (name != "city/fzk_haus_lod3_v2.gml" && name != "scene.json") {
      EXPECT_EQ(fd.at(name), bytes) << name;
      EXPECT_EQ(fl.at(name), bytes) << name;
    }
  const auto drop_scene = nlohmann::json::parse(fd.at("scene.json"));
  const auto dropped = drop_scene.at("generator").at("drop_openings");
  const int total = dropped.at("of"), count = dropped.at("dropped");
  EXPECT_EQ(count, static_cast<int>(std::lround(0.3 * total)));
  EXPECT_NE(fd.at("city/fzk_haus_lod3_v2.gml"), fe.at("city/fzk_haus_lod3_v2.gml"));
  EXPECT_EQ(drop_scene.at("lod"), 3);

  const auto lod2_scene = nlohmann::json::parse(fl.at("scene.json"));
  EXPECT_EQ(lod2_scene.at("city_model"), "city/fzk_haus_lod2_v2.gml");
  EXPECT_EQ(lod2_scene.at("lod"), 2);
  EXPECT_EQ(fl.count("city/fzk_haus_lod3_v2.gml"), 0u);
  EXPECT_EQ(fl.at("city/fzk_haus_lod2_v2.gml"), read_text_file(lod2_file));
  EXPECT_NE(synth(tiny(temp_path("bad")) + " --drop-openings 2"), 0);
  EXPECT_NE(synth(tiny(temp_path("bad")) + " --given-city /nonexistent.gml"), 0);
  for (const auto& d : {exact, drop, lod2}) fs::remove_all(d);
}

// Label images on the real model agree with the test's own cast of the city mesh: a pixel is
// either the city label of that ray or 0 where clutter hides the building, which is rare.
TEST(SynthCli, LabelsMatchOwnProjectionOfFzkHaus) {
  const fs::path out = temp_path("labels");
  ASSERT_EQ(synth(tiny(out)), 0);
  const Taxonomy tax = Taxonomy::builtin();
  const SemanticMesh mesh = load_city_model(kFzk, tax, 3);
  std::vector<Vec3f> vertices;
  for (const auto& v : mesh.vertices) vertices.push_back({float(v[0]), float(v[1]), float(v[2])});
  std::vector<uint8_t> priority;
  for (const int c : mesh.tri_class) priority.push_back(tax.classes[c].level == 1);
  const Raycaster city(vertices, mesh.triangles, priority);
  const ColmapModel m = read_colmap((out / "sparse/0").string());
  const Camera& cam = m.cameras.at(1);
  const PinholeCamera pinhole{cam.params[0], cam.params[1], cam.params[2], cam.params[3], cam.width, cam.height};
  size_t city_pixels = 0, hidden = 0, wrong = 0, windows = 0;
  for (const auto& [id, image] : m.images) {
    const cv::Mat labels = cv::imread((out / "gt/labels" / (fs::path(image.name).stem().string() + ".png")).string(),
                                      cv::IMREAD_UNCHANGED);
    ASSERT_EQ(labels.type(), CV_16UC1);
    ASSERT_EQ(labels.cols, 96);
    std::vector<RayHit> hits;
    city.cast_view(pinhole, image.pose(), hits);
    for (int j = 0; j < labels.rows; ++j)
      for (int i = 0; i < labels.cols; ++i) {
        const RayHit& h = hits[static_cast<size_t>(j) * labels.cols + i];
        const int expected = h.prim == kNoHit ? 0 : mesh.tri_level_class[h.prim][0] + 1;
        const int got = labels.at<uint16_t>(j, i);
        city_pixels += expected != 0;
        hidden += expected != 0 && got == 0;
        wrong += got != 0 && got != expected;
        windows += got == tax.find("window") + 1;
      }
  }
  EXPECT_GT(city_pixels, 4u * 96 * 72 / 10);
  EXPECT_LE(wrong, city_pixels / 1000);
  EXPECT_LT(hidden, city_pixels / 5);
  EXPECT_GT(windows, 0u);
  fs::remove_all(out);
}

TEST(SynthCli, SkipIfSameAndOverwrite) {
  const fs::path out = temp_path("skip");
  ASSERT_EQ(synth(tiny(out)), 0);
  // Mark an output: a skipped run leaves it, a regeneration replaces it.
  write_text_atomic(out / "images/0000.png", "marker");
  EXPECT_EQ(synth(tiny(out) + " --skip-if-same"), 0);
  EXPECT_EQ(read_text_file(out / "images/0000.png"), "marker");
  EXPECT_EQ(synth(tiny(out, 5) + " --skip-if-same"), 1);  // other settings, no --overwrite
  EXPECT_EQ(read_text_file(out / "images/0000.png"), "marker");
  EXPECT_EQ(synth(tiny(out, 5) + " --skip-if-same --overwrite"), 0);
  EXPECT_NE(read_text_file(out / "images/0000.png"), "marker");
  EXPECT_EQ(nlohmann::json::parse(read_text_file(out / "scene.json")).at("generator").at("seed"), 5);
  fs::remove_all(out);
}

TEST(SynthCli, BadInputsFailBeforeWritingAnything) {
  const fs::path out = temp_path("bad");
  EXPECT_EQ(synth("--city /nonexistent/model.gml --out " + out.string()), 1);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(synth("--city " + std::string(CLS_TEST_FIXTURES) + "/broken/cityjson_truncated.json --out " + out.string()), 1);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(synth(tiny(out) + " --views 1"), 2);
  EXPECT_EQ(synth(tiny(out) + " --width 0"), 2);
  EXPECT_EQ(synth(tiny(out) + " --seed -3"), 2);
  EXPECT_EQ(synth(tiny(out) + " --lod 7"), 2);
  EXPECT_EQ(synth("--out " + out.string()), 2);  // no --city
  EXPECT_FALSE(fs::exists(out));
  // A directory that is not a synth output is never replaced, even with --overwrite.
  fs::create_directories(out);
  write_text_atomic(out / "precious.txt", "keep");
  EXPECT_EQ(synth(tiny(out) + " --overwrite"), 1);
  EXPECT_EQ(read_text_file(out / "precious.txt"), "keep");
  EXPECT_EQ(test::read_tree(out).size(), 1u);
  // No staging directory is left behind.
  for (const auto& e : fs::directory_iterator(out.parent_path()))
    EXPECT_EQ(e.path().filename().string().find("." + out.filename().string() + ".synth-tmp"), std::string::npos);
  fs::remove_all(out);
}
