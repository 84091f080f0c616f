#pragma once
// Byte order of the host, for the binary formats we write little-endian (PLY, PFM, COLMAP).

namespace cls {

constexpr bool host_is_little_endian() { return __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__; }

}  // namespace cls
