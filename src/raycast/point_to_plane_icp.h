#pragma once
// Robust point-to-plane ICP that moves a point set onto a triangle mesh with a similarity (7 DoF:
// scale, rotation, translation) or a rigid motion (6 DoF): the refinement behind `align`.
// Hand-written: Debian's registration library (PCL) aligns point clouds to point clouds; this aligns to
// the mesh itself through Embree's closest-point queries and estimates the scale, in about 150 lines.
//
// Each iteration pairs every point with its nearest mesh point and minimises the Huber-weighted
// squared distances to the pairs' tangent planes, linearised about the current motion (Gauss-Newton).
// Pairs farther than a gate, or whose nearest mesh point is on an edge or corner rather than inside a
// face (the point lies beside the mesh, not over it: terrain around the footprint, trees and clutter
// the city model lacks), are left out. The gate shrinks from `capture` to `finest` by halves (coarse
// to fine), each stage iterated until the motion settles; the scale joins only afterwards, in a second
// pass from 4x the finest gate down: at coarse gates, pairs on the wrong surface bias the scale, which
// then drags more of them into the gate and runs away.
#include <cstddef>
#include <vector>

#include "citymodel/city_transform.h"
#include "core/math.h"
#include "raycast/closest_point.h"

namespace cls {

struct IcpOptions {
  bool rigid = false;                  // keep the scale: 6 DoF
  double capture = 2.0;                // first gate: pairs up to this far (mesh units)
  double finest = 0.1;                 // last gate (mesh units); the gates halve from capture down to it
  int max_iterations = 50;             // per gate
};

struct IcpStage {
  double gate = 0;
  bool scale = false;     // the scale is estimated in this stage
  int iterations = 0;
  size_t pairs = 0;       // pairs kept in the last iteration
  double rms = 0;         // their root-mean-square point-to-plane distance (mesh units)
};

// Below this conditioning the paired surfaces leave part of the motion unconstrained: `align` warns, and
// `run --align auto` keeps the given transform.
constexpr double kIcpWeakConditioning = 1e-6;

struct IcpResult {
  CityTransform motion;   // maps the points into the mesh's frame
  std::vector<IcpStage> stages;
  // Smallest over largest eigenvalue of the last normal matrix (parameters scaled to the points' extent):
  // near zero when the paired surfaces leave a motion unconstrained (e.g. only one plane).
  double conditioning = 0;
};

// What is wrong with the options ("" if nothing).
std::string icp_options_problem(const IcpOptions& options);

// The stages point_to_plane_icp runs: rigid gates from capture halving to finest, then (unless rigid)
// with scale from min(capture, 4 finest) halving to finest.
std::vector<IcpStage> icp_schedule(const IcpOptions& options);

// Starts from `start` (applied to the points). cls::Error when fewer pairs than parameters remain at a gate.
IcpResult point_to_plane_icp(const ClosestPointQuery& mesh, const std::vector<Vec3d>& points,
                             const IcpOptions& options, const CityTransform& start = CityTransform::identity());

}  // namespace cls
