#pragma once
// SPZ version 2: Niantic's compressed Gaussians (github.com/nianticlabs/spz, MIT), the payload that
// KHR_gaussian_splatting_compression_spz_2 puts in a glTF buffer view and CesiumJS requires of splats
// in 3D Tiles. Hand-written: Debian packages no SPZ library, and version 2 is a gzip stream (zlib) of a
// 16-byte header and six arrays:
//   header   magic "NGSP" (0x5053474e), version 2, point count (u32), SH degree, fractional bits,
//            flags, reserved (u8 each)
//   positions  24-bit signed fixed point per coordinate, `fractional bits` after the point
//   alphas     sigmoid(opacity) * 255                   scales  (log scale + 10) * 16
//   colors     DC * 0.15 * 255 + 127.5 per channel      rotations  x, y, z of the unit quaternion with
//                                                                  w >= 0, * 127.5 + 127.5
//   sh         per point the coefficients of degree >= 1 (3DGS's order), RGB inner, * 128 + 128,
//              rounded to buckets of 8 (degree 1) and 16 (higher), as SPZ's packer does by default
// all bytes rounded and clamped to [0, 255]. SPZ stores right-up-back (RUB) axes; a glTF's are
// left-up-front (LUF), so x and z flip, with the quaternion and the SH coefficients that change sign.
#include <string>

#include "splat/gaussians.h"

namespace cls {

constexpr int kSpzVersion = 2;

// The axes the payload's coordinates are packed from. Luf: the extension's text ("specify a
// Left-Up-Front coordinate system in the SPZ PackOptions"), x and z flip into SPZ's RUB. AsStored: the
// primitive's coordinates go in unchanged, which is how CesiumJS 1.145, the extension's one known
// implementation, reads a payload (spz-loader's coordinateSystem "UNSPECIFIED", no conversion): a
// payload packed from LUF shows there turned half about the vertical (KhronosGroup/glTF#2509).
enum class SpzAxes { Luf, AsStored };

// The compressed stream of `g`, whose coordinates are a glTF primitive's. cls::Error when a value is
// not finite or a coordinate lies beyond 2^23 (what 24-bit fixed point holds).
std::string spz_v2(const GaussianModel& g, SpzAxes axes = SpzAxes::Luf);

// The sign a SH coefficient k (3DGS's order, 0 the DC term) takes when x and z flip: the parity of
// its basis function under (x, y, z) -> (-x, y, -z).
int spz_flip_sign(int k);

}  // namespace cls
