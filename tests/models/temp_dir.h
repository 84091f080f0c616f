#pragma once
// A fresh temporary directory per instance, removed with it, and a raw byte writer for hand-made
// (often deliberately broken) weight files.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace cls::test {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& prefix = "cls_models_test_") {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           (prefix + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

inline void write_bytes(const std::filesystem::path& p, const char* data, size_t size) {
  std::ofstream(p, std::ios::binary).write(data, static_cast<std::streamsize>(size));
}
inline void write_bytes(const std::filesystem::path& p, const std::string& bytes) {
  write_bytes(p, bytes.data(), bytes.size());
}
inline void write_bytes(const std::filesystem::path& p, const std::vector<char>& bytes) {
  write_bytes(p, bytes.data(), bytes.size());
}

}  // namespace cls::test
