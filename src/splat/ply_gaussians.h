#pragma once
// The standard 3DGS PLY (as the original's GaussianModel.save_ply writes it): binary little-endian,
// one `vertex` element with float properties
//   x y z nx ny nz f_dc_0..2 f_rest_0..(3*(K-1)-1) opacity scale_0..2 rot_0..3
// where f_rest is channel-major (all red coefficients, then green, then blue), opacity is the logit,
// scale the log-scale and rot the (w, x, y, z) quaternion; the SH degree follows from the f_rest
// count (0, 9, 24, 45). Our additions are further properties that viewers ignore: latent_0..F-1
// (language features) and each extra by its name (float or int). Reading looks properties up by name
// in any order and accepts float/double/int/uint/short/ushort/char/uchar types.
#include <string>

#include "splat/gaussians.h"

namespace cls {

void write_gaussians_ply(const std::string& path, const GaussianModel& model);  // atomic
GaussianModel read_gaussians_ply(const std::string& path);

}  // namespace cls
