#pragma once
// UAV-like oblique camera placement around a city model.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "synth/box.h"

namespace cls::synth {

struct SynthView {
  std::string name;  // image file name, "0000.png", ...
  PinholeCamera camera;
  Pose pose;  // world (scene frame) -> camera
};

struct CameraRigOptions {
  int views = 24;
  int width = 480, height = 360;
  double hfov_deg = 60;
  uint64_t seed = 1;
};

// Pitch range of the views (degrees below the horizon). The lowest ring (18 degrees) puts the top
// of a 4:3 frame with a 60-degree horizontal FoV (23.4 degrees half vertical FoV) above the
// horizon, so those views show sky, as low oblique UAV photos do.
constexpr double kMinPitchDeg = 15, kMaxPitchDeg = 60;

// Square pixels, principal point at the image centre, horizontal field of view `hfov_deg`.
PinholeCamera pinhole_from_fov(int width, int height, double hfov_deg);

// Views on rings around `city` at several altitudes (pitch 18..55 degrees, jittered by the seed,
// always within [kMinPitchDeg, kMaxPitchDeg]), looking at the model from a distance at which its
// bounding sphere fills most of the frame.
std::vector<SynthView> make_uav_views(const Box3d& city, const CameraRigOptions& options);

// A district: the views split evenly over the buildings (the first `views % buildings` get one more),
// each share on make_uav_views' rings around its own building, named in order over all buildings.
// Neighbours appear behind each building, as in a UAV survey flown building by building.
std::vector<SynthView> make_building_views(const std::vector<Box3d>& buildings, const CameraRigOptions& options);

}  // namespace cls::synth
