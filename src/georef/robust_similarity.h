#pragma once
// The similarity that maps one point set onto another, robust to outliers: camera centres of an SfM
// model onto the photos' GPS positions, where phones put a tenth of the photos tens of metres off.
// Least median of squares (Rousseeuw 1984) over similarities of three pairs each, then least squares
// (Umeyama 1991, OpenCV's estimateAffine3D) over the pairs within the 99th percentile of the residuals
// that the noise estimated from the median would give.
// Hand-written around OpenCV: its RANSAC variant of estimateAffine3D fits an affine map (12 DoF, which
// GPS noise shears) and wants the inlier threshold in advance; LMedS finds it from the data.
#include <cstdint>
#include <vector>

#include "citymodel/city_transform.h"
#include "core/math.h"

namespace cls {

struct SimilarityFit {
  CityTransform transform;      // source -> target: target ~ transform.apply(source)
  std::vector<double> residuals;  // |transform(source_i) - target_i| for every pair
  std::vector<bool> inlier;       // within threshold
  size_t inliers = 0;
  double threshold = 0;  // inlier bound: 99% of 3D Gaussian errors of the median's standard deviation
  double rms = 0;        // root mean square of the inliers' residuals
};

// At least 3 pairs, of equal count. cls::Error when fewer than 3 pairs are given, or when the inlying
// source points lie (nearly) on a line: then the rotation about it is not determined (photos taken
// along a straight street; take some from across it). `seed` draws the hypotheses when there are more
// triples than are tried.
SimilarityFit robust_similarity(const std::vector<Vec3d>& source, const std::vector<Vec3d>& target, uint64_t seed = 1);

}  // namespace cls
