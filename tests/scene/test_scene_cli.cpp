// The `citylangsplat scene` command, run as a subprocess.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "cli_runner.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "scene/colmap.h"
#include "scene_test_util.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

test::CliResult run(const std::string& args) { return test::run_cli(args); }

fs::path model_scene(const std::string& name) {
  const fs::path dir = test::fresh_dir(name);
  ColmapModel m;
  m.cameras[1] = Camera{1, CameraModel::SimpleRadial, 400, 300, {350, 200, 150, -0.05}};
  m.cameras[2] = Camera{2, CameraModel::Pinhole, 400, 300, {350, 350, 200, 150}};
  for (uint32_t i = 1; i <= 3; ++i)
    m.images[i] = ColmapImage{i, {1, 0, 0, 0}, {0, 0, double(i)}, i == 3 ? 2u : 1u, "im" + std::to_string(i) + ".jpg",
                              {{10, 20, 7}, {30, 40, std::numeric_limits<uint64_t>::max()}}};
  m.points[7] = ColmapPoint3D{7, {1, 2, 3}, {1, 2, 3}, 0.25, {{1, 0}, {2, 0}}};
  write_colmap_binary((dir / "sparse" / "0").string(), m);
  return dir;
}

}  // namespace

TEST(SceneCli, InfoJson) {
  const fs::path dir = model_scene("cli_info");
  const test::CliResult r = run("scene info " + dir.string() + " --json --skip-image-check -r 2");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["source"], "colmap-bin");
  EXPECT_EQ(j["views"], 3);
  EXPECT_EQ(j["cameras"], 2);
  EXPECT_EQ(j["camera_models"]["SIMPLE_RADIAL"], 1);
  EXPECT_EQ(j["camera_models"]["PINHOLE"], 1);
  EXPECT_EQ(j["points"], 1);
  bool found_pinhole = false;
  for (const auto& s : j["image_sizes"])
    if (s["views"] == 1) {
      EXPECT_EQ(s["loaded"][0], 200);  // the PINHOLE view at -r 2
      found_pinhole = true;
    }
  EXPECT_TRUE(found_pinhole);
  // images are checked by default
  EXPECT_EQ(run("scene info " + dir.string()).status, 1);
  EXPECT_EQ(run("scene info " + dir.string() + " -r 3").status, 1);
  EXPECT_EQ(run("scene info").status, 2);
  fs::remove_all(dir);
}

TEST(SceneCli, VerifyImagesFindsACorruptImageByName) {
  const fs::path dir = model_scene("cli_verify");
  fs::create_directories(dir / "images");
  const cv::Mat grey(300, 400, CV_8UC3, cv::Scalar(90, 90, 90));
  for (const char* name : {"im1.jpg", "im2.jpg", "im3.jpg"}) ASSERT_TRUE(cv::imwrite((dir / "images" / name).string(), grey));
  EXPECT_EQ(run("scene info " + dir.string() + " --verify-images").status, 0);
  // A JPEG cut after its header: the file exists, so only decoding finds the damage.
  const std::string bytes = read_text_file(dir / "images" / "im2.jpg");
  write_text_atomic(dir / "images" / "im2.jpg", bytes.substr(0, 40));
  const test::CliResult r = test::run_cli("scene info " + dir.string() + " --verify-images");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("im2.jpg"), std::string::npos) << r.err;
  // Without --verify-images the pixels are not decoded, but the EXIF is read (GPS): a file cut inside
  // its header is found there too, by name.
  const test::CliResult info = run("scene info " + dir.string());
  EXPECT_EQ(info.status, 1);
  EXPECT_NE(info.err.find("im2.jpg: cannot read the image's metadata"), std::string::npos) << info.err;
  fs::remove_all(dir);
}

// scene info reports the photos' EXIF GPS (what georeferencing starts from), and a GPS tag out of range
// is an error naming the photo.
TEST(SceneCli, InfoReportsThePhotosGps) {
  const fs::path dir = model_scene("cli_gps");
  fs::create_directories(dir / "images");
  const auto fix = [](const std::string& lat) {
    return std::map<std::string, std::string>{{"Exif.GPSInfo.GPSLatitudeRef", "N"}, {"Exif.GPSInfo.GPSLatitude", lat},
                                              {"Exif.GPSInfo.GPSLongitudeRef", "E"},
                                              {"Exif.GPSInfo.GPSLongitude", "7/1 30/1 0/1"}};
  };
  test::photo_with_exif(dir / "images", "im1.jpg", fix("51/1 30/1 0/1"));  // 51.5 N, 7.5 E
  test::photo_with_exif(dir / "images", "im2.jpg", {});
  test::photo_with_exif(dir / "images", "im3.jpg", fix("51/1 45/1 0/1"));  // 51.75 N
  const test::CliResult r = run("scene info " + dir.string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto gps = nlohmann::json::parse(r.out)["gps"];
  EXPECT_EQ(gps["images"], 2);
  EXPECT_DOUBLE_EQ(gps["latitude"][0].get<double>(), 51.5);
  EXPECT_DOUBLE_EQ(gps["latitude"][1].get<double>(), 51.75);
  EXPECT_DOUBLE_EQ(gps["longitude"][1].get<double>(), 7.5);
  EXPECT_FALSE(gps.contains("altitude"));
  EXPECT_NE(run("scene info " + dir.string()).out.find("gps:     2 of 3 images, latitude 51.5000000..51.7500000"),
            std::string::npos);
  EXPECT_TRUE(nlohmann::json::parse(run("scene info " + dir.string() + " --json --skip-image-check").out)["gps"].is_null());
  // Against a city model, in its CRS (the NRW tile names an AdV URN: EPSG:25832): the photos' positions
  // in Germany lie within some hundred kilometres of the tile, and a model without a CRS needs --crs.
  const std::string tile = std::string(CLS_TEST_DATA) + "/citygml/nrw/LoD2_32_329_5730_1_NW.gml";
  const test::CliResult city = run("scene info " + dir.string() + " --json --city " + tile);
  ASSERT_EQ(city.status, 0) << city.err;
  const auto against = nlohmann::json::parse(city.out)["gps_against_city"];
  EXPECT_EQ(against["epsg"], 25832);
  EXPECT_EQ(against["fixes"], 2);
  EXPECT_GT(against["median_distance"].get<double>(), 1000);
  EXPECT_LT(against["max_distance"].get<double>(), 500000);
  const std::string no_crs = std::string(CLS_TEST_DATA) + "/citygml/cityjson/rotterdam_subset.json";
  const test::CliResult unnamed = run("scene info " + dir.string() + " --city " + no_crs);
  EXPECT_EQ(unnamed.status, 1);
  EXPECT_NE(unnamed.err.find("names no CRS (srsName / referenceSystem): give it with --crs EPSG:N"), std::string::npos) << unnamed.err;
  EXPECT_EQ(run("scene info " + dir.string() + " --city " + no_crs + " --crs EPSG:7415").status, 0);
  EXPECT_EQ(run("scene info " + dir.string() + " --city " + tile + " --skip-image-check").status, 2);
  test::photo_with_exif(dir / "images", "im2.jpg", fix("91/1 0/1 0/1"));
  const test::CliResult bad = run("scene info " + dir.string());
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("im2.jpg: EXIF Exif.GPSInfo.GPSLatitude is 91 degrees, more than 90"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}

TEST(SceneCli, ConvertRoundTripsLosslessly) {
  const fs::path dir = model_scene("cli_convert");
  ASSERT_EQ(run("scene convert " + dir.string() + " --out " + (dir / "txt").string() + " --format txt").status, 0);
  ASSERT_EQ(run("scene convert " + (dir / "txt").string() + " --out " + (dir / "bin").string()).status, 0);
  for (const char* f : {"cameras.bin", "images.bin", "points3D.bin"})
    EXPECT_EQ(read_text_file(dir / "bin" / f), read_text_file(dir / "sparse" / "0" / f)) << f;
  EXPECT_EQ(run("scene convert " + dir.string() + " --out " + (dir / "x").string() + " --format ply").status, 2);
  EXPECT_FALSE(fs::exists(dir / "x"));
  fs::remove_all(dir);
}

TEST(SceneCli, ConvertPix4d) {
  const fs::path dir = test::fresh_dir("cli_pix4d");
  const std::string view = "a.jpg 100 80\n90 0 50\n0 90 40\n0 0 1\n0.1 0 R3\n0 0\n1 2 3\n0 1 0\n-1 0 0\n0 0 1\n";
  auto with_r3 = [&](const std::string& r3) {
    std::string s = view;
    s.replace(s.find("R3"), 2, r3);
    return s;
  };
  write_text_atomic(dir / "calibrated_camera_parameters.txt", with_r3("0"));
  ASSERT_EQ(run("scene convert " + dir.string() + " --out " + (dir / "m").string() + " --format txt").status, 0);
  const ColmapModel m = read_colmap((dir / "m").string());
  ASSERT_EQ(m.images.size(), 1u);
  EXPECT_EQ(m.cameras.at(1).model, CameraModel::OpenCV);
  const Vec3d c = m.images.at(1).pose().center();  // the Pix4D camera position comes back
  EXPECT_NEAR(c.x, 1, 1e-12);
  EXPECT_NEAR(c.y, 2, 1e-12);
  EXPECT_NEAR(c.z, 3, 1e-12);
  write_text_atomic(dir / "calibrated_camera_parameters.txt", with_r3("0.01"));
  EXPECT_EQ(run("scene convert " + dir.string() + " --out " + (dir / "k3").string()).status, 1);
  EXPECT_FALSE(fs::exists(dir / "k3"));
  fs::remove_all(dir);
}

// What scene info says of a PIX4Dmapper project: its frame (offset and output CRS), and the photo in
// images/ that the calibration left out.
TEST(SceneCli, InfoNamesAPix4dFrameAndUnregisteredPhotos) {
  const fs::path dir = test::fresh_dir("cli_pix4d_frame");
  write_text_atomic(dir / "site_calibrated_camera_parameters.txt",
                    "a.jpg 100 80\n90 0 50\n0 90 40\n0 0 1\n0 0 0\n0 0\n1 2 3\n0 1 0\n-1 0 0\n0 0 1\n");
  write_text_atomic(dir / "site_offset.xyz", "356000.5 5645000.25 100\n");
  write_text_atomic(dir / "site_wkt.prj", "EPSG:25832\n");
  fs::create_directories(dir / "images");
  for (const char* name : {"a.jpg", "b.jpg"})
    cv::imwrite((dir / "images" / name).string(), cv::Mat(80, 100, CV_8UC3, cv::Scalar::all(90)));
  // Two cloud points beside the camera at (1, 2, 3), in the CRS.
  write_text_atomic(dir / "site_cloud.las", test::las_file({{356001.5, 5645002.25, 101}, {356002.5, 5645001.25, 99}}, 1));
  const test::CliResult r = run("scene info " + dir.string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], 2);
  EXPECT_EQ(j["unregistered_images"], 1);
  EXPECT_EQ(j["frame"]["crs"], "EPSG:25832");
  EXPECT_EQ(j["frame"]["shift"], nlohmann::json({-356000.5, -5645000.25, -100.0}));
  EXPECT_EQ(j["frame"]["source"], (dir / "site_offset.xyz").string());
  const test::CliResult text = run("scene info " + dir.string());
  EXPECT_NE(text.out.find("1 more photos in images/ are not in the calibration"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("frame:   scene = 1 x CRS + (-356000.500 -5645000.250 -100.000), CRS EPSG:25832"),
            std::string::npos) << text.out;
  // scene convert keeps the cloud, in the cameras' frame.
  ASSERT_EQ(run("scene convert " + dir.string() + " --out " + (dir / "m").string()).status, 0);
  const ColmapModel m = read_colmap((dir / "m").string());
  ASSERT_EQ(m.points.size(), 2u);
  EXPECT_NEAR(m.points.at(1).xyz[0], 1.0, 1e-6);
  EXPECT_NEAR(m.points.at(1).xyz[1], 2.0, 1e-6);
  EXPECT_NEAR(m.points.at(2).xyz[2], -1.0, 1e-6);
  fs::remove_all(dir);
}
