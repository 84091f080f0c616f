// A PIX4Dmapper project whose lens has a third radial coefficient (R3 != 0, which COLMAP's OPENCV model
// lacks) through the stages that see pixels: its photos, made here by distorting a synth scene's renders
// with that lens, must load as the renders they came from, closer than with R3 dropped (the label maps
// are cast with the very pinhole camera the photos are undistorted to), and train-rgb must learn them
// as well as it learns the renders themselves (the same project with no lens distortion).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/atomic_file.h"
#include "models/temp_dir.h"
#include "scene/image_loader.h"
#include "scene/pix4d.h"
#include "scene/scene.h"
#include "scene/scene_test_util.h"
#include "scene/undistort.h"
#include "splat/train_rgb.h"
#include "synth/synth_job.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";
// R1 R2 R3: strong enough that R3 moves the corners of a 160x120 photo by about 4 pixels.
const char* kRadial = "-0.1 0.02 0.5";

const fs::path& root() {
  static const test::TempDir dir("cls_pix4d_lens_");
  return dir.path;
}

fs::path synth_scene() {
  synth::SynthJob job;
  job.city_path = kFzk;
  job.out_dir = (root() / "synth").string();
  job.settings.views = 16;
  job.settings.width = 160;
  job.settings.height = 120;
  job.settings.seed = 5;
  job.settings.gt_density = 5;
  synth::run_synth_job(job);
  return job.out_dir;
}

// The synth scene as a PIX4Dmapper project whose calibration gives `radial`; its photos distorted with
// `photo_radial` (what the lens really did), its densified cloud the synth scene's sparse points.
fs::path pix4d_project(const Scene& source, const std::string& name, const std::string& radial,
                       const std::string& photo_radial) {
  const fs::path dir = root() / name;
  fs::create_directories(dir / "1_initial" / "params");
  fs::create_directories(dir / "2_densification" / "point_cloud");
  fs::create_directories(dir / "images");
  auto calibration = [&](const std::string& r) {
    std::string text;
    for (const SceneView& v : source.views) {
      const PinholeCamera& k = v.camera;
      const Vec3d c = v.pose.center();
      char line[512];
      std::snprintf(line, sizeof line, "%s %d %d\n%.17g 0 %.17g\n0 %.17g %.17g\n0 0 1\n%s\n0 0\n%.17g %.17g %.17g\n",
                    v.name.c_str(), k.width, k.height, k.fx, k.cx, k.fy, k.cy, r.c_str(), c.x, c.y, c.z);
      text += line;
      for (int i = 0; i < 3; ++i) {
        std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", v.pose.R.m[i][0], v.pose.R.m[i][1], v.pose.R.m[i][2]);
        text += line;
      }
    }
    return text;
  };
  const std::string file = (dir / "1_initial" / "params" / (name + "_calibrated_camera_parameters.txt")).string();
  write_text_atomic(file, calibration(photo_radial));
  const std::vector<Pix4dView> lenses = read_pix4d_calibrated_cameras(file);
  for (size_t i = 0; i < source.views.size(); ++i) {
    // Each photo pixel shows what the pinhole render shows where the lens bends its ray from.
    const LensCamera lens = lens_from_camera(lenses[i].camera, lenses[i].radial_k3);
    const PinholeCamera ideal{lens.fx, lens.fy, lens.cx, lens.cy, lens.width, lens.height};
    cv::Mat map_x(lens.height, lens.width, CV_32F), map_y(lens.height, lens.width, CV_32F);
    for (int y = 0; y < lens.height; ++y)
      for (int x = 0; x < lens.width; ++x) {
        double tu = -1, tv = -1;
        undistort_pixel(lens, ideal, x + 0.5, y + 0.5, tu, tv);
        map_x.at<float>(y, x) = static_cast<float>(tu - 0.5);
        map_y.at<float>(y, x) = static_cast<float>(tv - 0.5);
      }
    cv::Mat photo;
    cv::remap(cv::imread(source.views[i].image_path), photo, map_x, map_y, cv::INTER_CUBIC, cv::BORDER_REPLICATE);
    cv::imwrite((dir / "images" / source.views[i].name).string(), photo);
  }
  write_text_atomic(file, calibration(radial));
  // The cloud in the output CRS, the cameras in it less the project's offset (near test::las_file's own).
  const Vec3d offset{356000, 5645000, 0};
  write_text_atomic(dir / "1_initial" / "params" / (name + "_offset.xyz"), "356000 5645000 0\n");
  std::vector<Vec3d> cloud;
  for (const SparsePoint& p : source.points) cloud.push_back(p.xyz + offset);
  write_text_atomic(dir / "2_densification" / "point_cloud" / (name + "_group1_densified_point_cloud.las"),
                    test::las_file(cloud, 0));
  return dir;
}

// Mean absolute difference (grey levels) between each loaded photo and its synth render at the same
// rays: the undistorted pinhole keeps fx, fy and moves the principal point with the image size.
double difference_to_renders(const Scene& scene, const Scene& source) {
  ImageLoader loader;
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < scene.views.size(); ++i) {
    const PinholeCamera& k = scene.views[i].camera;
    const PinholeCamera& s = source.views[i].camera;
    const cv::Mat loaded = loader.load(scene.views[i]);
    const cv::Mat render = cv::imread(source.views[i].image_path);
    cv::Mat expected;
    const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, s.cx - k.cx, 0, 1, s.cy - k.cy);
    cv::warpAffine(render, expected, m, cv::Size(k.width, k.height), cv::INTER_CUBIC | cv::WARP_INVERSE_MAP);
    const int margin = 4;
    for (int y = margin; y < k.height - margin; ++y)
      for (int x = margin; x < k.width - margin; ++x)
        for (int c = 0; c < 3; ++c, ++n)
          sum += std::abs(double(loaded.at<cv::Vec3b>(y, x)[c]) - double(expected.at<cv::Vec3b>(y, x)[c]));
  }
  return sum / n;
}

}  // namespace

TEST(Pix4dLens, PhotosWithR3LoadAsTheRendersAndTrain) {
  const Scene source = load_scene(synth_scene().string());
  const Scene with_r3 = load_scene(pix4d_project(source, "r3", kRadial, kRadial).string());
  const Scene without_r3 = load_scene(pix4d_project(source, "no_r3", "-0.1 0.02 0", kRadial).string());
  ASSERT_EQ(with_r3.views.size(), source.views.size());
  EXPECT_EQ(with_r3.views[0].source_radial_k3, 0.5);

  const double good = difference_to_renders(with_r3, source), bad = difference_to_renders(without_r3, source);
  std::printf("mean |loaded - render|: %.2f grey levels with R3, %.2f with R3 dropped\n", good, bad);
  EXPECT_LT(good, 0.6 * bad);

  RgbTrainOptions options;
  options.iterations = 300;
  options.sh_degree = 0;
  options.device = "cpu";
  options.out_dir = (root() / "train_r3").string();
  const RgbTrainReport good_fit = train_rgb(with_r3, options);
  options.out_dir = (root() / "train_pinhole").string();
  const Scene pinhole = load_scene(pix4d_project(source, "pinhole", "0 0 0", "0 0 0").string());
  const RgbTrainReport pinhole_fit = train_rgb(pinhole, options);
  std::printf("train-rgb held-out PSNR: %.2f dB from the distorted photos (R3), %.2f dB from the same project without distortion\n",
              good_fit.test_psnr, pinhole_fit.test_psnr);
  EXPECT_GT(good_fit.test_psnr, pinhole_fit.test_psnr - 0.5);
}
