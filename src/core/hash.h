#pragma once
// FNV-1a, 64 bit: identifies input content in stage records (scene.json, run stamps). Not
// cryptographic; it only has to notice that an input changed.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/atomic_file.h"

namespace cls {

inline uint64_t fnv1a64(const std::string& bytes, uint64_t h = 0xcbf29ce484222325ULL) {
  for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

inline std::string hex64(uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

inline std::string fnv1a64_hex(const std::string& bytes) { return hex64(fnv1a64(bytes)); }

// The hash of a whole file's bytes (cls::Error naming the file if it cannot be read).
inline std::string file_fnv1a64_hex(const std::filesystem::path& path) { return fnv1a64_hex(read_text_file(path)); }

}  // namespace cls
