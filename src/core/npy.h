#pragma once
// NumPy .npy arrays (format versions 1.0, 2.0, 3.0), torch-free: the exchange format of the
// reference fixtures and of LangSplat's per-image feature files (<name>_s.npy / <name>_f.npy).
// Spec: numpy/lib/format.py — magic "\x93NUMPY", version, little-endian header length (uint16 in
// v1, uint32 in v2/v3), then a Python dict literal {'descr', 'fortran_order', 'shape'} padded
// with spaces and a newline, then the raw C-ordered data.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cls {

// The element types we read and write, by NumPy descr (little-endian; 1-byte types have '|').
enum class NpyType { F16, F32, F64, I32, I64, U8, Bool };

struct NpyArray {
  std::string dtype;            // NumPy descr, one of "<f2" "<f4" "<f8" "<i4" "<i8" "|u1" "|b1"
  std::vector<int64_t> shape;   // () for a scalar
  std::vector<uint8_t> data;    // C order, little-endian

  NpyType type() const;         // throws cls::Error for an unknown dtype
  size_t item_size() const;
  int64_t numel() const;

  // Typed view of the data; throws cls::Error unless T matches dtype exactly.
  template <typename T> const T* as() const;
  template <typename T> T* as();
  // Every element converted to float / double (any supported dtype; f16 widened exactly).
  std::vector<float> to_float() const;
  std::vector<double> to_double() const;
};

// The descr NumPy writes for T: float "<f4", double "<f8", int32_t "<i4", int64_t "<i8",
// uint8_t "|u1", bool "|b1".
template <typename T> const char* npy_descr();

// Builds an array of T with the given shape from `values` (numel must match).
template <typename T>
NpyArray make_npy(std::vector<int64_t> shape, const std::vector<T>& values);

// Parses a whole .npy file held in memory; `name` (the file) prefixes every error.
NpyArray parse_npy(const std::string& bytes, const std::string& name);
NpyArray read_npy(const std::filesystem::path& path);

// The .npy bytes of `a` (version 1.0, or 2.0 when the header needs more than 65535 bytes).
std::string encode_npy(const NpyArray& a);
// Atomic write (temporary file + rename); throws cls::Error naming the path.
void write_npy(const std::filesystem::path& path, const NpyArray& a);

// IEEE half <-> float (round to nearest even), for f16 arrays.
float half_to_float(uint16_t h);
uint16_t float_to_half(float f);

}  // namespace cls
