#include "scene/undistort.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace cls {

LensCamera lens_from_camera(const Camera& camera, double radial_k3) {
  const std::vector<double>& p = camera.params;
  auto need = [&](size_t n) {
    if (p.size() != n) throw Error("internal: camera " + std::to_string(camera.id) + " has a wrong parameter count");
  };
  LensCamera lens;
  lens.width = camera.width;
  lens.height = camera.height;
  switch (camera.model) {
    case CameraModel::SimplePinhole:
    case CameraModel::SimpleRadial:
    case CameraModel::Radial:
      need(camera.model == CameraModel::SimplePinhole ? 3 : camera.model == CameraModel::SimpleRadial ? 4 : 5);
      lens.fx = lens.fy = p[0];
      lens.cx = p[1];
      lens.cy = p[2];
      if (p.size() > 3) lens.distortion.k1 = p[3];
      if (p.size() > 4) lens.distortion.k2 = p[4];
      break;
    case CameraModel::Pinhole:
    case CameraModel::OpenCV:
      need(camera.model == CameraModel::Pinhole ? 4 : 8);
      lens.fx = p[0];
      lens.fy = p[1];
      lens.cx = p[2];
      lens.cy = p[3];
      if (p.size() == 8) {
        lens.distortion.k1 = p[4];
        lens.distortion.k2 = p[5];
        lens.distortion.p1 = p[6];
        lens.distortion.p2 = p[7];
      }
      break;
  }
  lens.distortion.k3 = radial_k3;
  return lens;
}

namespace {

// Undistorted pixel of a distorted pixel, for a target that keeps the lens' f and c (the first
// step of UndistortCamera).
bool undistort_keeping_intrinsics(const LensCamera& lens, double u, double v, double& tu, double& tv) {
  double x, y;
  if (!undistort_normalized(lens.distortion, (u - lens.cx) / lens.fx, (v - lens.cy) / lens.fy, x, y)) return false;
  tu = lens.fx * x + lens.cx;
  tv = lens.fy * y + lens.cy;
  return std::isfinite(tu) && std::isfinite(tv);
}

}  // namespace

PinholeCamera undistorted_pinhole(const LensCamera& lens, const std::string& source) {
  PinholeCamera out{lens.fx, lens.fy, lens.cx, lens.cy, lens.width, lens.height};
  if (lens.distortion.is_zero()) return out;  // COLMAP would still shave a pixel off; we keep the image as is

  // Only the innermost undistorted border matters for "no blank pixels" (COLMAP also tracks the
  // outermost one, for blank_pixels > 0).
  constexpr double kMax = std::numeric_limits<double>::max(), kLow = std::numeric_limits<double>::lowest();
  double left_max = kLow, right_min = kMax, top_max = kLow, bottom_min = kMax;
  double tu, tv;
  for (int y = 0; y < lens.height; ++y) {
    if (undistort_keeping_intrinsics(lens, 0.5, y + 0.5, tu, tv)) left_max = std::max(left_max, tu);
    if (undistort_keeping_intrinsics(lens, lens.width - 0.5, y + 0.5, tu, tv)) right_min = std::min(right_min, tu);
  }
  for (int x = 0; x < lens.width; ++x) {
    if (undistort_keeping_intrinsics(lens, x + 0.5, 0.5, tu, tv)) top_max = std::max(top_max, tv);
    if (undistort_keeping_intrinsics(lens, x + 0.5, lens.height - 0.5, tu, tv)) bottom_min = std::min(bottom_min, tv);
  }
  const double cx = lens.cx, cy = lens.cy, w = lens.width, h = lens.height;
  // Largest scale that keeps the undistorted border outside the image: no blank pixels
  // (COLMAP's max_scale_{x,y} with blank_pixels = 0).
  const double fit_x = std::max(cx / (cx - left_max), (w - 0.5 - cx) / (right_min - cx));
  const double fit_y = std::max(cy / (cy - top_max), (h - 0.5 - cy) / (bottom_min - cy));
  if (left_max == kLow || right_min == kMax || top_max == kLow || bottom_min == kMax || !std::isfinite(fit_x) ||
      !std::isfinite(fit_y) || !(fit_x > 0) || !(fit_y > 0))
    fail(source, "lens distortion is too strong to undistort the image border");
  const double scale_x = std::clamp(1.0 / fit_x, 0.2, 2.0);
  const double scale_y = std::clamp(1.0 / fit_y, 0.2, 2.0);
  out.width = static_cast<int>(std::max(1.0, scale_x * w));
  out.height = static_cast<int>(std::max(1.0, scale_y * h));
  out.cx = cx * out.width / w;
  out.cy = cy * out.height / h;
  return out;
}

bool undistort_pixel(const LensCamera& lens, const PinholeCamera& target, double u, double v, double& tu,
                     double& tv) {
  double x, y;
  if (!undistort_normalized(lens.distortion, (u - lens.cx) / lens.fx, (v - lens.cy) / lens.fy, x, y)) return false;
  tu = target.fx * x + target.cx;
  tv = target.fy * y + target.cy;
  return true;
}

void distort_pixel(const LensCamera& lens, const PinholeCamera& target, double tu, double tv, double& u, double& v) {
  double xd, yd;
  distort_normalized(lens.distortion, (tu - target.cx) / target.fx, (tv - target.cy) / target.fy, xd, yd);
  u = lens.fx * xd + lens.cx;
  v = lens.fy * yd + lens.cy;
}

UndistortMaps undistortion_maps(const LensCamera& lens, const PinholeCamera& target) {
  UndistortMaps maps;
  maps.map_x.create(target.height, target.width, CV_32FC1);
  maps.map_y.create(target.height, target.width, CV_32FC1);
#pragma omp parallel for schedule(static)
  for (int j = 0; j < target.height; ++j) {
    float* mx = maps.map_x.ptr<float>(j);
    float* my = maps.map_y.ptr<float>(j);
    for (int i = 0; i < target.width; ++i) {
      double u, v;
      distort_pixel(lens, target, i + 0.5, j + 0.5, u, v);
      mx[i] = static_cast<float>(u - 0.5);
      my[i] = static_cast<float>(v - 0.5);
    }
  }
  return maps;
}

cv::Mat undistort_image(const cv::Mat& image, const UndistortMaps& maps) {
  cv::Mat out;
  cv::remap(image, out, maps.map_x, maps.map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return out;
}

}  // namespace cls
