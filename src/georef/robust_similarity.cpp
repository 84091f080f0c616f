#include "georef/robust_similarity.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <random>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

constexpr int kMaxHypotheses = 3000;
// The residuals are lengths of 3D errors: with isotropic Gaussian noise sigma they follow sigma times a
// chi distribution of 3 degrees of freedom, whose median is 1.5382 and whose 99th percentile is 3.3682.
constexpr double kChi3Median = 1.5382, kChi3Inlier = 3.3682;
// Below this ratio of the second to the first principal spread the points are a line.
constexpr double kLineRatio = 1e-3;

// Umeyama over the chosen pairs (least squares, scale included).
CityTransform umeyama(const std::vector<Vec3d>& source, const std::vector<Vec3d>& target, const std::vector<size_t>& pick) {
  cv::Mat src(static_cast<int>(pick.size()), 3, CV_64F), dst(static_cast<int>(pick.size()), 3, CV_64F);
  for (size_t i = 0; i < pick.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      src.at<double>(static_cast<int>(i), k) = source[pick[i]][k];
      dst.at<double>(static_cast<int>(i), k) = target[pick[i]][k];
    }
  double scale = 1;
  const cv::Mat m = cv::estimateAffine3D(src, dst, &scale, true);  // 3x4 [R | t], the scale apart
  CityTransform t;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t.matrix[r][c] = (c < 3 ? scale : 1.0) * m.at<double>(r, c);
  return t;
}

// Square roots of the eigenvalues of the points' covariance, largest first.
std::array<double, 3> principal_spread(const std::vector<Vec3d>& points, const std::vector<size_t>& pick) {
  Vec3d mean{};
  for (size_t i : pick) mean = mean + points[i];
  mean = (1.0 / pick.size()) * mean;
  cv::Matx33d cov = cv::Matx33d::zeros();
  for (size_t i : pick) {
    const Vec3d d = points[i] - mean;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) cov(r, c) += d[r] * d[c] / pick.size();
  }
  cv::Vec3d eigen;
  cv::eigen(cov, eigen);
  return {std::sqrt(std::max(eigen[0], 0.0)), std::sqrt(std::max(eigen[1], 0.0)), std::sqrt(std::max(eigen[2], 0.0))};
}

std::vector<double> residuals_of(const CityTransform& t, const std::vector<Vec3d>& source, const std::vector<Vec3d>& target) {
  std::vector<double> r(source.size());
  for (size_t i = 0; i < source.size(); ++i) r[i] = norm(t.apply(source[i]) - target[i]);
  return r;
}

double median_of(std::vector<double> v) {
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

}  // namespace

SimilarityFit robust_similarity(const std::vector<Vec3d>& source, const std::vector<Vec3d>& target, uint64_t seed) {
  const size_t n = source.size();
  if (n != target.size()) throw Error(cat("robust_similarity: ", n, " source points but ", target.size(), " targets"));
  if (n < 3) throw Error(cat("a similarity needs at least 3 positions, got ", n));
  std::vector<size_t> all(n);
  std::iota(all.begin(), all.end(), 0);
  const double spread = principal_spread(source, all)[0];

  // The hypotheses: every triple when there are few, random ones otherwise.
  std::vector<std::array<size_t, 3>> triples;
  if (n * (n - 1) * (n - 2) / 6 <= kMaxHypotheses) {
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b)
        for (size_t c = b + 1; c < n; ++c) triples.push_back({a, b, c});
  } else {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<size_t> pick(0, n - 1);
    while (triples.size() < kMaxHypotheses) {
      const std::array<size_t, 3> t{pick(rng), pick(rng), pick(rng)};
      if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triples.push_back(t);
    }
  }
  CityTransform best;
  double best_median = INFINITY;
  for (const auto& t : triples) {
    const Vec3d a = source[t[0]], b = source[t[1]], c = source[t[2]];
    if (norm(cross(b - a, c - a)) < kLineRatio * spread * spread) continue;  // a line fixes no rotation
    const CityTransform h = umeyama(source, target, {t[0], t[1], t[2]});
    if (!(h.scale() > 0)) continue;
    const double m = median_of(residuals_of(h, source, target));
    if (m < best_median) best_median = m, best = h;
  }
  if (!std::isfinite(best_median))
    throw Error(cat("the ", n, " positions lie on a line: the rotation about it is not determined"));

  // The noise's standard deviation from the median residual, with Rousseeuw's small-sample factor.
  const double sigma = (1 + 5.0 / std::max<double>(1, static_cast<double>(n) - 3)) * best_median / kChi3Median;
  SimilarityFit fit;
  fit.threshold = std::max(kChi3Inlier * sigma, 1e-9 * (1 + spread));
  fit.transform = best;
  // Refit on the inliers until they settle (a few rounds at most).
  for (int round = 0; round < 5; ++round) {
    fit.residuals = residuals_of(fit.transform, source, target);
    std::vector<bool> inlier(n);
    std::vector<size_t> pick;
    for (size_t i = 0; i < n; ++i)
      if ((inlier[i] = fit.residuals[i] <= fit.threshold)) pick.push_back(i);
    if (inlier == fit.inlier) break;
    fit.inlier = inlier;
    if (pick.size() < 3) break;
    const std::array<double, 3> s = principal_spread(source, pick);
    if (s[1] < kLineRatio * s[0])
      throw Error(cat("the ", pick.size(), " positions that agree lie on a line: the rotation about it is not determined"));
    fit.transform = umeyama(source, target, pick);
  }
  fit.residuals = residuals_of(fit.transform, source, target);
  for (size_t i = 0; i < n; ++i) fit.inlier[i] = fit.residuals[i] <= fit.threshold;
  fit.inliers = static_cast<size_t>(std::count(fit.inlier.begin(), fit.inlier.end(), true));
  double sum = 0;
  for (size_t i = 0; i < n; ++i)
    if (fit.inlier[i]) sum += fit.residuals[i] * fit.residuals[i];
  fit.rms = fit.inliers ? std::sqrt(sum / fit.inliers) : 0;
  return fit;
}

}  // namespace cls
