#pragma once
// The COLMAP model of a synthetic scene: its cameras and poses, and sparse points sampled on the
// surfaces the views see, as an SfM reconstruction would give them.
#include <cstdint>
#include <vector>

#include "scene/colmap.h"
#include "synth/renderer.h"
#include "synth/uav_cameras.h"

namespace cls::synth {

struct SparsePointOptions {
  int samples_per_view = 300;  // jittered-grid pixel samples per view (sky samples are dropped)
  double noise_sigma = 0.01;   // standard deviation of the Gaussian noise on each point (scene units)
  int min_track = 2;           // points seen by fewer views are dropped
  uint64_t seed = 1;
};

// Camera 1 (PINHOLE, shared by all views), image i + 1 for view i, and the points: for each view,
// pixels on a jittered grid that see a surface give a surface point (from the depth map); its
// track is every view where the point is in the image and passes a depth test against that
// view's depth map (observation = the exact projection); the stored position gets Gaussian noise,
// the colour comes from the sampling view's image, `error` is the mean reprojection error.
ColmapModel make_colmap_model(const std::vector<SynthView>& views, const std::vector<RenderedView>& rendered,
                              const SparsePointOptions& options);

}  // namespace cls::synth
