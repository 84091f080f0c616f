#pragma once
// SHA-256 (FIPS 180-4) for verifying downloaded model files. Torch-free.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace cls {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, size_t size);
  void update(const std::string& s) { update(s.data(), s.size()); }
  std::string hex_digest();  // finishes the hash; lower-case hex

 private:
  void block(const uint8_t* p);
  std::array<uint32_t, 8> h_;
  std::array<uint8_t, 64> buf_{};
  size_t buf_len_ = 0;
  uint64_t total_ = 0;
};

std::string sha256_hex(const std::string& bytes);
// Hashes a file in chunks; cls::Error naming the file if it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace cls
