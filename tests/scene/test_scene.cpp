#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.h"
#include "scene/colmap.h"
#include "scene/image_loader.h"
#include "scene/scene.h"
#include "scene/undistort.h"
#include "scene_test_util.h"

namespace fs = std::filesystem;
using namespace cls;
using cls::test::expect_error;

namespace {

const Camera kDistorted{1, CameraModel::OpenCV, 320, 240, {260, 262, 161, 119, -0.18, 0.03, 0.001, -0.0012}};
const Camera kPinhole{2, CameraModel::Pinhole, 160, 120, {150, 150, 80, 60}};

ColmapModel two_view_model() {
  ColmapModel m;
  m.cameras[1] = kDistorted;
  m.cameras[2] = kPinhole;
  m.images[5] = ColmapImage{5, {1, 0, 0, 0}, {0, 0, 2}, 1, "z_first_id.png", {}};
  m.images[3] = ColmapImage{3, {0, 1, 0, 0}, {1, 2, 3}, 2, "sub/a_second_id.png", {}};
  m.points[10] = ColmapPoint3D{10, {1, 2, 3}, {10, 20, 30}, 0.5, {{5, 0}}};
  return m;
}

// DIR/images with both images, model written by `write` into DIR/<model_sub>.
fs::path make_scene(const std::string& name, const std::string& model_sub, bool binary) {
  const fs::path dir = test::fresh_dir(name);
  const ColmapModel m = two_view_model();
  (binary ? write_colmap_binary : write_colmap_text)((dir / model_sub).string(), m);
  fs::create_directories(dir / "images" / "sub");
  cv::imwrite((dir / "images" / "z_first_id.png").string(), test::distorted_checkerboard(lens_from_camera(kDistorted)));
  cv::imwrite((dir / "images" / "sub" / "a_second_id.png").string(),
              test::distorted_checkerboard(lens_from_camera(kPinhole)));
  return dir;
}

}  // namespace

TEST(Scene, LoadsColmapBinaryFromSparse0) {
  const fs::path dir = make_scene("bin", "sparse/0", true);
  const Scene s = load_scene(dir.string());
  EXPECT_EQ(s.source, "colmap-bin");
  EXPECT_EQ(s.root, fs::absolute(dir).string());
  ASSERT_EQ(s.views.size(), 2u);
  // name order, not id order
  EXPECT_EQ(s.views[0].name, "sub/a_second_id.png");
  EXPECT_EQ(s.views[0].image_id, 3u);
  EXPECT_EQ(s.views[0].image_path, (fs::absolute(dir) / "images" / "sub" / "a_second_id.png").string());
  // a pinhole view keeps its intrinsics; its pose is the quaternion's
  EXPECT_EQ(s.views[0].camera.fx, 150);
  EXPECT_EQ(s.views[0].camera.width, 160);
  EXPECT_NEAR(s.views[0].pose.R.m[1][1], -1, 1e-15);  // q = (0, 1, 0, 0): 180 degrees about x
  // the distorted view becomes the undistorted pinhole camera
  const SceneView& v = s.views[1];
  EXPECT_EQ(v.source_camera.model, CameraModel::OpenCV);
  const PinholeCamera expected = undistorted_pinhole(lens_from_camera(kDistorted), "x");
  EXPECT_EQ(v.camera.width, expected.width);
  EXPECT_EQ(v.camera.height, expected.height);
  EXPECT_EQ(v.camera.cx, expected.cx);
  EXPECT_NE(v.camera.width, kDistorted.width);
  ASSERT_EQ(s.points.size(), 1u);
  EXPECT_EQ(s.points[0].xyz.y, 2);
  EXPECT_EQ(s.points[0].rgb[2], 30);
  fs::remove_all(dir);
}

TEST(Scene, FindsTextModelsInSparseOrTheDirectoryAndPrefersBinary) {
  fs::path dir = make_scene("txt_sparse", "sparse", false);
  EXPECT_EQ(load_scene(dir.string()).source, "colmap-txt");
  fs::remove_all(dir);
  dir = make_scene("txt_root", ".", false);
  EXPECT_EQ(load_scene(dir.string()).views.size(), 2u);
  write_colmap_binary(dir.string(), two_view_model());
  EXPECT_EQ(load_scene(dir.string()).source, "colmap-bin");
  fs::remove_all(dir);
}

// The synthetic photo of a checkerboard through a distorting lens, undistorted on load, is the
// checkerboard a pinhole camera with the new intrinsics sees.
TEST(ImageLoader, UndistortedCheckerboardMatchesAnalyticImage) {
  const fs::path dir = make_scene("checker", "sparse/0", true);
  const Scene s = load_scene(dir.string());
  ImageLoader loader;
  const cv::Mat img = loader.load(s.views[1]);
  EXPECT_GT(test::expect_matches_checkerboard(img, s.views[1].camera, 3.0, 0), 0.4);
  // the plain view passes through unchanged
  const cv::Mat plain = loader.load(s.views[0]);
  EXPECT_GT(test::expect_matches_checkerboard(plain, s.views[0].camera, 1.0, 0), 0.6);
  fs::remove_all(dir);
}

TEST(ImageLoader, DownscalesWithConsistentIntrinsics) {
  const fs::path dir = make_scene("downscale", "sparse/0", true);
  const PinholeCamera full = undistorted_pinhole(lens_from_camera(kDistorted), "x");
  SceneOptions r2;
  r2.resolution_factor = 2;
  const Scene s = load_scene(dir.string(), r2);
  const PinholeCamera& c = s.views[1].camera;
  EXPECT_EQ(c.width, static_cast<int>(std::nearbyint(full.width / 2.0)));
  EXPECT_NEAR(c.fx, full.fx * c.width / full.width, 1e-12);
  EXPECT_NEAR(c.cy, full.cy * c.height / full.height, 1e-12);
  ImageLoader loader;
  EXPECT_GT(test::expect_matches_checkerboard(loader.load(s.views[1]), c, 3.0, 1), 0.3);

  SceneOptions tw;
  tw.target_width = 100;
  const Scene t = load_scene(dir.string(), tw);
  EXPECT_EQ(t.views[0].camera.width, 100);
  EXPECT_EQ(t.views[0].camera.height, 75);  // 120 / (160 / 100)
  EXPECT_NEAR(t.views[0].camera.fx, 150 * 100.0 / 160, 1e-12);
  EXPECT_EQ(loader.load(t.views[0]).cols, 100);
  fs::remove_all(dir);
}

TEST(ImageLoader, ScaleFollows3dgsRounding) {
  const PinholeCamera full{1000, 1000, 500.5, 375.5, 1001, 751};
  SceneOptions o;
  o.resolution_factor = 2;
  const PinholeCamera h = scale_to_resolution(full, o);
  EXPECT_EQ(h.width, 500);   // 500.5 rounds to even
  EXPECT_EQ(h.height, 376);  // 375.5 rounds to even
  EXPECT_DOUBLE_EQ(h.cx, 500.5 * 500 / 1001);
  o.resolution_factor = 8;
  EXPECT_EQ(scale_to_resolution(full, o).width, 125);  // 125.125
  for (int bad : {0, 3, 16}) {
    o.resolution_factor = bad;
    expect_error([&] { scale_to_resolution(full, o); }, {"1, 2, 4 or 8"});
  }
  o.resolution_factor = 2;
  o.target_width = 100;
  expect_error([&] { scale_to_resolution(full, o); }, {"not both"});
}

// A phone's 4000x3000 photo under max_side 1600, as 3DGS's loader does it: global_down = 4000 / 1600 = 2.5,
// int(4000 / 2.5) x int(3000 / 2.5) = 1600 x 1200; a portrait 3000x4000 one by its long side; smaller photos,
// and any explicit -r, are left alone. max_height as LangSplat's preprocessing does it.
TEST(ImageLoader, MaxSideLoadsLargePhotosAtTheLongSideAndMaxHeightAtTheHeight) {
  SceneOptions o;
  o.max_side = 1600;
  const PinholeCamera landscape = scale_to_resolution({3000, 3000, 2000, 1500, 4000, 3000}, o);
  EXPECT_EQ(landscape.width, 1600);
  EXPECT_EQ(landscape.height, 1200);
  EXPECT_DOUBLE_EQ(landscape.fx, 3000 * 1600.0 / 4000);
  const PinholeCamera portrait = scale_to_resolution({3000, 3000, 1500, 2000, 3000, 4000}, o);
  EXPECT_EQ(portrait.width, 1200);
  EXPECT_EQ(portrait.height, 1600);
  EXPECT_EQ(scale_to_resolution({500, 500, 320, 240, 640, 480}, o).width, 640);
  // LangSplat's features: photos taller than 1080 at 1080 (global_down = 3000 / 1080), the stronger of
  // the two reductions: int(4000 / 2.777...) = 1440; a portrait one int(3000 / 3.7037) = 810 x 1080.
  o.max_height = 1080;
  const PinholeCamera features = scale_to_resolution({3000, 3000, 2000, 1500, 4000, 3000}, o);
  EXPECT_EQ(features.width, 1440);
  EXPECT_EQ(features.height, 1080);
  EXPECT_DOUBLE_EQ(features.fy, 3000 * 1080.0 / 3000);
  const PinholeCamera features_portrait = scale_to_resolution({3000, 3000, 1500, 2000, 3000, 4000}, o);
  EXPECT_EQ(features_portrait.width, 810);
  EXPECT_EQ(features_portrait.height, 1080);
  EXPECT_EQ(scale_to_resolution({500, 500, 320, 240, 640, 480}, o).height, 480);
  o.max_side = 0;
  EXPECT_EQ(scale_to_resolution({3000, 3000, 2000, 1500, 4000, 3000}, o).width, 1440);
  o.max_side = 1600;
  o.resolution_factor = 2;
  EXPECT_EQ(scale_to_resolution({3000, 3000, 2000, 1500, 4000, 3000}, o).width, 2000);
  o.max_side = -1;
  expect_error([&] { scale_to_resolution({3000, 3000, 2000, 1500, 4000, 3000}, o); }, {"must not be negative"});
}

TEST(Scene, MissingImageIsAnErrorNamingTheFile) {
  const fs::path dir = make_scene("missing_image", "sparse/0", true);
  const fs::path img = fs::absolute(dir) / "images" / "sub" / "a_second_id.png";
  fs::remove(img);
  expect_error([&] { load_scene(dir.string()); }, {img.string(), "not found"});
  SceneOptions lazy;
  lazy.check_images = false;
  const Scene s = load_scene(dir.string(), lazy);
  ImageLoader loader;
  expect_error([&] { loader.load(s.views[0]); }, {img.string(), "not found"});
  fs::remove_all(dir / "images");
  expect_error([&] { load_scene(dir.string()); }, {"images", "image folder not found"});
  fs::remove_all(dir);
}

TEST(Scene, CorruptOrWrongSizedImagesAreErrorsNamingTheFile) {
  const fs::path dir = make_scene("corrupt", "sparse/0", true);
  const Scene s = load_scene(dir.string());
  const std::string png = s.views[0].image_path;
  const std::string bytes = read_text_file(png);
  ImageLoader loader;
  write_text_atomic(png, bytes.substr(0, bytes.size() / 2));  // truncated PNG
  expect_error([&] { loader.load(s.views[0]); }, {png, "cannot decode"});
  write_text_atomic(png, std::string("\x89PNG\r\n\x1a\n", 8) + std::string(200, 'x'));  // garbage after the signature
  expect_error([&] { loader.load(s.views[0]); }, {png, "cannot decode"});
  cv::imwrite(png, cv::Mat(50, 60, CV_8UC3, cv::Scalar::all(7)));
  expect_error([&] { loader.load(s.views[0]); }, {png, "60x50", "160x120"});
  fs::remove_all(dir);
}

TEST(Scene, BadModelsAreErrorsNamingTheFile) {
  const fs::path dir = make_scene("bad_model", "sparse", false);
  const std::string cams = (dir / "sparse" / "cameras.txt").string();
  write_text_atomic(cams, "1 OPENCV_FISHEYE 320 240 260 262 161 119 0 0 0 0\n2 PINHOLE 160 120 150 150 80 60\n");
  expect_error([&] { load_scene(dir.string()); }, {cams, "OPENCV_FISHEYE", "supported"});
  fs::remove_all(dir / "sparse");
  expect_error([&] { load_scene(dir.string()); }, {dir.string(), "no camera model found"});
  expect_error([&] { load_scene((dir / "nope").string()); }, {"nope", "not found"});
  fs::remove_all(dir);
}

// A phone's portrait photo: stored landscape with EXIF Orientation 6 ("the 0th row is the visual right
// side": shown turned 90 degrees clockwise). COLMAP and Pix4D calibrate the stored pixels, so those are
// loaded; a calibration of the turned photo (a tool applied the tag first) gets the turned pixels.
TEST(ImageLoader, ExifOrientationFollowsTheCalibration) {
  const fs::path dir = test::fresh_dir("orientation");
  cv::Mat stored(48, 64, CV_8UC3, cv::Scalar(0, 0, 0));
  stored(cv::Rect(0, 0, 32, 48)).setTo(cv::Scalar(0, 0, 255));  // left half red (BGR)
  cv::imwrite((dir / "raw.jpg").string(), stored);
  {  // the photo's tag, as a phone writes it
    auto image = Exiv2::ImageFactory::open((dir / "raw.jpg").string());
    image->readMetadata();
    Exiv2::ExifData exif;
    exif["Exif.Image.Orientation"] = uint16_t(6);
    image->setExifData(exif);
    image->writeMetadata();
  }
  auto view_of = [&](int w, int h) {
    SceneView v;
    v.name = "raw.jpg";
    v.image_path = (dir / "raw.jpg").string();
    v.source_camera.id = 1;
    v.source_camera.model = CameraModel::Pinhole;
    v.source_camera.width = w;
    v.source_camera.height = h;
    v.source_camera.params = {50, 50, w / 2.0, h / 2.0};
    v.camera = PinholeCamera{50, 50, w / 2.0, h / 2.0, w, h};
    return v;
  };
  ImageLoader loader;
  const cv::Mat as_stored = loader.load(view_of(64, 48));
  ASSERT_EQ(as_stored.cols, 64);
  EXPECT_GT(as_stored.at<cv::Vec3b>(24, 5)[2], 200);  // red on the left, as stored
  EXPECT_LT(as_stored.at<cv::Vec3b>(24, 58)[2], 50);
  const cv::Mat turned = loader.load(view_of(48, 64));
  ASSERT_EQ(turned.cols, 48);
  ASSERT_EQ(turned.rows, 64);
  // Turned clockwise, the stored left half is the top half.
  EXPECT_GT(turned.at<cv::Vec3b>(5, 24)[2], 200);
  EXPECT_LT(turned.at<cv::Vec3b>(58, 24)[2], 50);
  expect_error([&] { loader.load(view_of(100, 100)); }, {"raw.jpg", "64x48", "100x100"});
  fs::remove_all(dir);
}
