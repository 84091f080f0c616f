#pragma once
#include <filesystem>
#include <functional>
#include <string>

namespace cls {

// Writes `path` through a temporary file in the same directory, then rename(2)s it into place,
// so a reader (or a resumed job) never sees a half-written file. The temporary keeps the
// extension of `path`, so format-by-extension writers (cv::imwrite) work on it.
// If `writer` throws, the temporary is removed and the exception propagates.
void write_atomic(const std::filesystem::path& path,
                  const std::function<void(const std::filesystem::path& tmp)>& writer);

void write_text_atomic(const std::filesystem::path& path, const std::string& content);

// Reads a whole file; a cls::Error naming the path if it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace cls
