#include "viewer/static_files.h"

#include <map>
#include <system_error>

#include "core/strings.h"

namespace cls {
namespace fs = std::filesystem;

std::optional<fs::path> file_under(const fs::path& root, const std::string& relative) {
  if (relative.empty() || relative.find('\0') != std::string::npos || relative.find('\\') != std::string::npos ||
      relative.front() == '/' || relative.find(':') != std::string::npos)
    return std::nullopt;
  const fs::path rel(relative);
  for (const fs::path& part : rel)
    if (part == "..") return std::nullopt;
  std::error_code ec;
  const fs::path base = fs::canonical(root, ec);
  if (ec) return std::nullopt;
  // canonical resolves every symlink; the result must still lie under the root.
  const fs::path target = fs::canonical(base / rel, ec);
  if (ec || !fs::is_regular_file(target, ec)) return std::nullopt;
  auto b = base.begin(), t = target.begin();
  for (; b != base.end(); ++b, ++t)
    if (t == target.end() || *b != *t) return std::nullopt;
  return target;
}

std::string content_type_of(const fs::path& file) {
  static const std::map<std::string, std::string> types = {
      {".html", "text/html; charset=utf-8"}, {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"}, {".css", "text/css; charset=utf-8"},
      {".json", "application/json"}, {".png", "image/png"}, {".jpg", "image/jpeg"}, {".jpeg", "image/jpeg"},
      {".svg", "image/svg+xml"}, {".wasm", "application/wasm"}, {".md", "text/plain; charset=utf-8"},
      {".txt", "text/plain; charset=utf-8"}, {".csv", "text/csv; charset=utf-8"}, {".mp4", "video/mp4"}};
  const std::string ext = ascii_lower(file.extension().string());
  const auto it = types.find(ext);
  return it == types.end() ? "application/octet-stream" : it->second;
}

}  // namespace cls
