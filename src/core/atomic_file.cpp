#include "core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.h"

namespace cls {
namespace fs = std::filesystem;

void write_atomic(const fs::path& path, const std::function<void(const fs::path& tmp)>& writer) {
  static std::atomic<unsigned> counter{0};
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) fail(dir.string(), "cannot create directory: " + ec.message());
  const fs::path tmp = dir / ("." + path.stem().string() + ".tmp" + std::to_string(getpid()) + "_" +
                              std::to_string(counter++) + path.extension().string());
  try {
    writer(tmp);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  if (!fs::exists(tmp)) fail(path.string(), "writer produced no file");
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    fail(path.string(), "cannot move temporary file into place: " + ec.message());
  }
}

void write_text_atomic(const fs::path& path, const std::string& content) {
  write_atomic(path, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) fail(path.string(), "write failed");
  });
}

std::string read_text_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path.string(), "cannot open file");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) fail(path.string(), "read failed");
  return s.str();
}

}  // namespace cls
