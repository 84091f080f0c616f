#pragma once
// Filesystem queries that answer false instead of throwing (permission denied, overlong path):
// callers then report the path as missing with a cls::Error, never a std::filesystem_error.
#include <filesystem>
#include <system_error>

namespace cls {

inline bool is_file(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec);
}

inline bool is_dir(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_directory(p, ec);
}

}  // namespace cls
