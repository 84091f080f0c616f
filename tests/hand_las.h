#pragma once
// LAS files written byte by byte from the ASPRS LAS 1.4 R15 tables (header table 3/4, records tables
// 7-17, the Extra Bytes VLR table 24), for tests of the reader: nothing of src/scene/las.cpp is used.
// Formats 0-5 as LAS 1.2 (227-byte header), 6-10 as LAS 1.4 (375 bytes).
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace cls::test {

struct HandLasPoint {
  int32_t x = 0, y = 0, z = 0;  // stored integers: coordinate = integer * scale + offset
  uint8_t classification = 0;   // formats 0-5 keep 5 bits; flags go into the byte's top bits
  uint8_t flag_bits = 0;        // formats 0-5: bits 5-7 of the classification byte (synthetic, key-point, withheld)
  std::array<uint16_t, 3> rgb{};
  uint16_t label = 0;           // the extra-bytes field "label" (uint16), when written
};

inline void hand_put(std::string& b, size_t at, const void* v, size_t n) { std::memcpy(b.data() + at, v, n); }

template <class T>
void hand_put(std::string& b, size_t at, T v) {
  hand_put(b, at, &v, sizeof v);
}

// With `extra_label`, each record ends with 2 undocumented bytes (data type 0) and then "label" (uint16),
// described by one Extra Bytes VLR.
inline std::string hand_las(int format, const std::vector<HandLasPoint>& points, const std::array<double, 3>& scale,
                            const std::array<double, 3>& offset, bool extra_label = false) {
  const bool v14 = format >= 6;
  const uint16_t header_size = v14 ? 375 : 227;
  const uint16_t base[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  const uint16_t record = uint16_t(base[format] + (extra_label ? 4 : 0));
  const size_t vlr = extra_label ? 54 + 2 * 192 : 0;
  const uint32_t point_offset = uint32_t(header_size + vlr);
  std::string b(point_offset + points.size() * record, '\0');
  hand_put(b, 0, "LASF", 4);
  b[24] = 1;
  b[25] = v14 ? 4 : 2;
  hand_put(b, 94, header_size);
  hand_put(b, 96, point_offset);
  hand_put(b, 100, uint32_t(extra_label ? 1 : 0));
  b[104] = char(format);
  hand_put(b, 105, record);
  hand_put(b, 107, uint32_t(v14 ? 0 : points.size()));  // the legacy count is 0 for formats 6-10
  for (int k = 0; k < 3; ++k) {
    hand_put(b, 131 + 8 * k, scale[k]);
    hand_put(b, 155 + 8 * k, offset[k]);
  }
  if (v14) hand_put(b, 247, uint64_t(points.size()));
  if (extra_label) {
    size_t at = header_size;
    hand_put(b, at + 2, "LASF_Spec", 9);
    hand_put(b, at + 18, uint16_t(4));
    hand_put(b, at + 20, uint16_t(2 * 192));
    at += 54;
    b[at + 2] = 0;  // undocumented bytes: options = their count
    b[at + 3] = 2;
    hand_put(b, at + 4, "padding", 7);
    at += 192;
    b[at + 2] = 3;  // uint16
    hand_put(b, at + 4, "label", 5);
  }
  const bool rgb = format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
  const size_t rgb_at = format == 2 ? 20 : format <= 5 ? 28 : 30;
  for (size_t i = 0; i < points.size(); ++i) {
    const HandLasPoint& p = points[i];
    const size_t r = point_offset + i * record;
    hand_put(b, r, p.x);
    hand_put(b, r + 4, p.y);
    hand_put(b, r + 8, p.z);
    hand_put(b, r + 12, uint16_t(1000 + i));  // intensity
    if (v14) {
      b[r + 14] = 0x11;  // return 1 of 1
      b[r + 16] = char(p.classification);
    } else {
      b[r + 14] = 0x09;
      b[r + 15] = char((p.classification & 0x1F) | (p.flag_bits << 5));
    }
    if (rgb)
      for (int c = 0; c < 3; ++c) hand_put(b, r + rgb_at + 2 * c, p.rgb[size_t(c)]);
    if (extra_label) hand_put(b, r + base[format] + 2, p.label);
  }
  return b;
}

}  // namespace cls::test
