#pragma once
// Camera paths for videos (pure geometry, no torch): an orbit around the scene and a smooth
// interpolation through the scene's own poses. Poses follow camera.h (world to camera, +z forward,
// y down).
#include <vector>

#include "scene/camera.h"

namespace cls {

// The circle the orbit runs on, derived from the scene's cameras (see orbit_circle).
struct OrbitCircle {
  Vec3d target;  // what every frame looks at
  Vec3d centre;  // the circle's centre: target + height * up
  Vec3d up;      // unit normal of the circle, the cameras' mean up direction
  Vec3d start;   // unit vector in the circle's plane from centre towards the first frame
  double radius = 0, height = 0;
};

// up = the normalised mean of the cameras' up vectors (-y of each camera in world coordinates);
// height / radius = the mean height above `target` along up / the mean horizontal distance from the
// axis through `target`; the orbit starts at the first camera's azimuth (the mean camera's when the
// first camera sits on the axis). cls::Error if `cameras` is empty or every camera is on the axis.
OrbitCircle orbit_circle(const std::vector<Pose>& cameras, Vec3d target);

// `frames` poses evenly spaced around the circle (angle 2 pi k / frames, counter-clockwise about up,
// the last frame one step before the first, so that the video loops), each looking at the target
// with the circle's up vector. cls::Error if frames < 1.
std::vector<Pose> orbit_path(const OrbitCircle& circle, int frames);

// Spherical linear interpolation of two rotations (world to camera) along the shorter arc:
// t = 0 gives a, t = 1 gives b.
Mat3d slerp(const Mat3d& a, const Mat3d& b, double t);

// `frames` poses through `keyframes` in order: frame k sits at the parameter s = k (K - 1) / (frames - 1)
// (so the first and last frames are the first and last keyframes, and with frames = m (K - 1) + 1 frame
// j m is keyframe j exactly); centres follow a uniform Catmull-Rom spline through the keyframe centres
// (end tangents from the nearest segment), rotations slerp between consecutive keyframes.
// cls::Error unless there are at least 2 keyframes and 2 frames.
std::vector<Pose> interpolate_path(const std::vector<Pose>& keyframes, int frames);

}  // namespace cls
