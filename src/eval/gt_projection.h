#pragma once
// Ground-truth label images from a labelled point cloud (paper section 4: "ground-truth masks are
// obtained by projecting ZAHA labels into the image domain"): every point is splatted as a disk into the
// view, a z-buffer keeps the nearest point per pixel, and the pixel takes that point's class.
#include <opencv2/core.hpp>

#include "eval/labelled_points.h"
#include "scene/camera.h"

namespace cls {

struct GtProjectionOptions {
  // World-space radius of a point's footprint (scene units); 0 = spacing_factor x the cloud's median
  // nearest-neighbour spacing (estimate_point_spacing).
  double point_radius = 0;
  // Area-uniform random samples leave gaps of several times the median spacing; 2.5 agreed best with the
  // renderer's exact labels on the bundled example (0.984 of the pixels; 1.5: 0.941, 4: 0.975).
  double spacing_factor = 2.5;
  double min_radius_px = 1;     // the footprint radius in pixels, fx * radius / depth, is clamped to
  double max_radius_px = 8;     // [min_radius_px, max_radius_px]
  double near = 1e-3;           // points with camera depth <= near are ignored (behind the camera)
};

// Median distance from a point to its nearest neighbour, over up to `samples` points spread evenly over
// the cloud (0 for fewer than two points).
double estimate_point_spacing(const LabelledPoints& points, size_t samples = 2000);

// The footprint radius the options give for this cloud (point_radius or the estimate).
double footprint_radius(const LabelledPoints& points, const GtProjectionOptions& options);

// Label image CV_32SC1 (class id of the nearest point whose footprint covers the pixel centre; -1 where
// none does or the nearest point is unlabelled). Pixel (i, j)'s centre is (i + 0.5, j + 0.5); a point at
// camera coordinates (x, y, z) projects to (fx x / z + cx, fy y / z + cy) and covers the pixel centres
// within r = clamp(fx * radius / z) of it. `depth` (optional) receives the winning z (CV_32FC1, 0 = none),
// `winner` (optional) the winning point's index (CV_32SC1, -1 = none).
cv::Mat project_gt_labels(const LabelledPoints& points, const PinholeCamera& camera, const Pose& pose,
                          double radius, const GtProjectionOptions& options, cv::Mat* depth = nullptr,
                          cv::Mat* winner = nullptr);

}  // namespace cls
