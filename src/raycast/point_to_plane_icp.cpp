#include "raycast/point_to_plane_icp.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

constexpr int kParameters = 7;  // translation 3, rotation 3, log-scale 1
// The scale pass starts at this many times the finest gate (see icp_schedule).
constexpr double kScaleGates = 4;

struct Pair {
  Vec3d point;   // moved point
  Vec3d normal;  // of the mesh's tangent plane at the nearest point
  double residual = 0;
};

// Median of |x|: the Huber threshold's robust scale.
double median_abs(std::vector<double> x) {
  for (double& v : x) v = std::fabs(v);
  const size_t mid = x.size() / 2;
  std::nth_element(x.begin(), x.begin() + mid, x.end());
  return x[mid];
}

// Eigen-decomposition solve of the symmetric system A x = b, dropping directions whose eigenvalue is
// below 1e-8 of the largest (a motion the pairs do not constrain stays put instead of following the
// noise). Returns min/max eigenvalue.
double solve_symmetric(const cv::Matx<double, kParameters, kParameters>& A, const cv::Vec<double, kParameters>& b,
                       int n, cv::Vec<double, kParameters>& x) {
  const cv::Mat a = cv::Mat(A)(cv::Range(0, n), cv::Range(0, n)).clone();
  cv::Mat values, vectors;  // eigenvalues descending, eigenvectors as rows
  cv::eigen(a, values, vectors);
  const double largest = values.at<double>(0);
  x = cv::Vec<double, kParameters>::all(0);
  if (!(largest > 0)) return 0;
  for (int k = 0; k < n; ++k) {
    const double lambda = values.at<double>(k);
    if (!(lambda > 1e-8 * largest)) continue;
    double vb = 0;
    for (int i = 0; i < n; ++i) vb += vectors.at<double>(k, i) * b[i];
    for (int i = 0; i < n; ++i) x[i] += vb / lambda * vectors.at<double>(k, i);
  }
  return std::max(0.0, values.at<double>(n - 1)) / largest;
}

}  // namespace

std::string icp_options_problem(const IcpOptions& o) {
  if (!(o.capture > 0) || !std::isfinite(o.capture)) return "the capture distance must be a positive number";
  if (!(o.finest > 0) || !(o.finest <= o.capture)) return "the finest gate must be positive and at most the capture distance";
  if (o.max_iterations < 1) return "the iterations per gate must be at least 1";
  return "";
}

std::vector<IcpStage> icp_schedule(const IcpOptions& o) {
  std::vector<IcpStage> stages;
  auto halve_down = [&](double from, bool scale) {
    for (double gate = from;; gate = std::max(gate / 2, o.finest)) {
      IcpStage s;
      s.gate = gate;
      s.scale = scale;
      stages.push_back(s);
      if (gate <= o.finest) break;
    }
  };
  halve_down(o.capture, false);
  if (!o.rigid) halve_down(std::min(o.capture, kScaleGates * o.finest), true);
  return stages;
}

IcpResult point_to_plane_icp(const ClosestPointQuery& mesh, const std::vector<Vec3d>& points,
                             const IcpOptions& options, const CityTransform& start) {
  const std::string problem = icp_options_problem(options);
  if (!problem.empty()) throw Error("ICP: " + problem);
  if (points.size() < static_cast<size_t>(kParameters))
    throw Error(cat("ICP needs at least ", kParameters, " points, got ", points.size()));

  // Rotation and scale act about the points' centre, their columns scaled by the points' spread, so
  // the normal matrix is well conditioned whatever the scene's units and offset.
  Vec3d centre{};
  for (const auto& p : points) centre = centre + p;
  centre = (1.0 / points.size()) * centre;
  double spread2 = 0;
  for (const auto& p : points) spread2 += dot(p - centre, p - centre);
  const double spread = std::max(std::sqrt(spread2 / points.size()), 1e-12);

  IcpResult result;
  result.motion = start;
  std::vector<Pair> pairs(points.size());
  std::vector<char> kept(points.size());
  for (const IcpStage& planned : icp_schedule(options)) {
    IcpStage stage = planned;
    const double gate = stage.gate;
    const int n = stage.scale ? 7 : 6;
    for (stage.iterations = 1; stage.iterations <= options.max_iterations; ++stage.iterations) {
#pragma omp parallel for schedule(dynamic, 256)
      for (int64_t i = 0; i < static_cast<int64_t>(points.size()); ++i) {
        const Vec3d p = result.motion.apply(points[i]);
        const MeshPoint q = mesh.nearest(p);
        const double along = dot(q.normal, p - q.point);
        kept[i] = q.distance <= gate && q.on_face && dot(q.normal, q.normal) > 0;
        pairs[i] = {p, q.normal, along};
      }
      std::vector<double> residuals;
      for (size_t i = 0; i < points.size(); ++i)
        if (kept[i]) residuals.push_back(pairs[i].residual);
      stage.pairs = residuals.size();
      if (stage.pairs < static_cast<size_t>(n))
        throw Error(cat("ICP: only ", stage.pairs, " of ", points.size(), " points lie within ", gate,
                        " of the mesh; the start is too far off (raise the capture distance or fix the start transform)"));
      // Huber weights with the usual 1.345 sigma threshold, sigma from the median absolute residual.
      const double delta = std::max(1.345 * 1.4826 * median_abs(residuals), 1e-9 * gate);
      cv::Matx<double, kParameters, kParameters> A = cv::Matx<double, kParameters, kParameters>::zeros();
      cv::Vec<double, kParameters> b = cv::Vec<double, kParameters>::all(0);
      double sum2 = 0;
      for (size_t i = 0; i < points.size(); ++i) {
        if (!kept[i]) continue;
        const Pair& pr = pairs[i];
        const Vec3d arm = (1 / spread) * (pr.point - centre);
        const Vec3d moment = cross(arm, pr.normal);
        // d residual / d (translation, rotation * spread, log-scale * spread)
        const double J[kParameters] = {pr.normal.x, pr.normal.y, pr.normal.z, moment.x, moment.y, moment.z,
                                       dot(pr.normal, arm)};
        const double r = pr.residual;
        const double w = std::fabs(r) <= delta ? 1.0 : delta / std::fabs(r);
        sum2 += r * r;
        for (int a = 0; a < n; ++a) {
          b[a] -= w * J[a] * r;
          for (int c = 0; c < n; ++c) A(a, c) += w * J[a] * J[c];
        }
      }
      stage.rms = std::sqrt(sum2 / stage.pairs);
      cv::Vec<double, kParameters> x;
      result.conditioning = solve_symmetric(A, b, n, x);
      const Vec3d translation{x[0], x[1], x[2]};
      const Vec3d rotation = (1 / spread) * Vec3d{x[3], x[4], x[5]};
      const double log_scale = stage.scale ? x[6] / spread : 0.0;
      // The step about the centre: p -> centre + s R (p - centre) + translation.
      const double s = std::exp(log_scale);
      const Mat3d R = axis_angle_to_rotation(rotation);
      const CityTransform step = similarity_transform(s, R, centre + translation - s * (R * centre));
      result.motion = step * result.motion;
      // Settled when no point of the set moves by more than a thousandth of the gate.
      const double moved = norm(translation) + spread * (norm(rotation) + std::fabs(log_scale));
      if (moved < 1e-3 * gate) break;
    }
    stage.iterations = std::min(stage.iterations, options.max_iterations);
    result.stages.push_back(stage);
    log_verbose(cat("ICP gate ", gate, stage.scale ? " (with scale)" : "", ": ", stage.iterations, " iterations, ",
                    stage.pairs, " pairs, rms ", stage.rms));
  }
  return result;
}

}  // namespace cls
