#pragma once
// From a distorted source camera to the undistorted pinhole camera every later stage uses, the
// way COLMAP's image_undistorter does it (src/colmap/image/undistortion.cc, UndistortCamera and
// UndistortImage, default options):
// - focal lengths are kept; the principal point and the image size are rescaled so that the
//   undistorted image has no blank pixels (blank_pixels = 0): the source border is undistorted,
//   and the new size is the largest rectangle around the principal point that stays inside it;
//   scale factors are clamped to COLMAP's [min_scale, max_scale] = [0.2, 2];
// - each undistorted pixel centre is mapped through the source lens and sampled bilinearly.
// Cameras without distortion (PINHOLE, SIMPLE_PINHOLE, or all coefficients zero) pass unchanged.
#include <string>

#include <opencv2/core.hpp>

#include "scene/camera.h"
#include "scene/distortion.h"

namespace cls {

// A source camera at full resolution in one form for every supported model.
struct LensCamera {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  int width = 0, height = 0;
  DistortionCoeffs<double> distortion;
};

// COLMAP camera -> lens. `radial_k3` is the third radial coefficient, which only Pix4D
// cameras carry (COLMAP's OPENCV has none).
LensCamera lens_from_camera(const Camera& camera, double radial_k3 = 0);

// COLMAP's UndistortCamera (see above). `source` names the camera in error messages (a lens
// too strong to undistort is a cls::Error).
PinholeCamera undistorted_pinhole(const LensCamera& lens, const std::string& source);

// Pixel (u, v) of the distorted image -> pixel of the undistorted image; false if the lens
// cannot be inverted there. Pixel coordinates as in camera.h (centre of pixel i at i + 0.5).
bool undistort_pixel(const LensCamera& lens, const PinholeCamera& target, double u, double v, double& tu,
                     double& tv);
// Pixel of the undistorted image -> pixel of the distorted image.
void distort_pixel(const LensCamera& lens, const PinholeCamera& target, double tu, double tv, double& u, double& v);

// cv::remap maps (CV_32FC1) that sample the distorted image for each pixel of `target`. OpenCV
// puts pixel centres at integers, hence the half-pixel shifts inside.
struct UndistortMaps {
  cv::Mat map_x, map_y;
};
UndistortMaps undistortion_maps(const LensCamera& lens, const PinholeCamera& target);

// Resamples a distorted image (of the lens' size) into `target` (bilinear, border replicated).
cv::Mat undistort_image(const cv::Mat& image, const UndistortMaps& maps);

}  // namespace cls
