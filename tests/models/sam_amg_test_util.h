#pragma once
// Helpers shared by the AMG tests: fixture paths, the seg-map .npy, mask comparison.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/sam_amg/binary_mask.h"

namespace amg_test {

inline std::string amg_fixture(const std::string& name) {
  return std::string(CLS_TEST_FIXTURES) + "/sam/amg/" + name;
}

// Minimal reader for the fixtures' little-endian float32 C-order NumPy v1 arrays.
struct NpyF32 {
  std::vector<int64_t> shape;
  std::vector<float> data;
};
inline NpyF32 read_npy_f32(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  char magic[8];
  in.read(magic, 8);
  if (std::memcmp(magic, "\x93NUMPY", 6) != 0 || magic[6] != 1) throw std::runtime_error("not npy v1: " + path);
  uint16_t header_len = 0;
  in.read(reinterpret_cast<char*>(&header_len), 2);
  std::string header(header_len, ' ');
  in.read(header.data(), header_len);
  if (header.find("'<f4'") == std::string::npos || header.find("'fortran_order': False") == std::string::npos)
    throw std::runtime_error("expected C-order <f4: " + path);
  NpyF32 a;
  const size_t open = header.find('(', header.find("'shape'")), close = header.find(')', open);
  std::string dims = header.substr(open + 1, close - open - 1);
  size_t pos = 0;
  int64_t count = 1;
  while (pos < dims.size()) {
    const size_t comma = dims.find(',', pos);
    const std::string tok = dims.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    if (tok.find_first_of("0123456789") != std::string::npos) a.shape.push_back(std::stoll(tok)), count *= a.shape.back();
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  a.data.resize(count);
  in.read(reinterpret_cast<char*>(a.data.data()), count * 4);
  if (!in) throw std::runtime_error("truncated " + path);
  return a;
}

inline double mask_iou(const cls::amg::BinaryMask& a, const cls::amg::BinaryMask& b) {
  int64_t inter = 0, uni = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) inter += a.pixels[i] && b.pixels[i], uni += a.pixels[i] || b.pixels[i];
  return uni == 0 ? 1.0 : static_cast<double>(inter) / uni;
}

}  // namespace amg_test
