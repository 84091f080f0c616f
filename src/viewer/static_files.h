#pragma once
// Files a local web server may hand out: only those under a root directory. Hand-written because
// cpp-httplib's mount points follow symlinks out of their folder.
#include <filesystem>
#include <optional>
#include <string>

namespace cls {

// The regular file `relative` (a decoded URL path below a mount point) names under `root`, or nothing
// when it would leave the root: a '..' segment, an absolute or drive path, a backslash or NUL byte, or
// a symlink (anywhere on the way) whose target lies outside the root. Directories give nothing.
std::optional<std::filesystem::path> file_under(const std::filesystem::path& root, const std::string& relative);

// The Content-Type of a file by extension (application/octet-stream for unknown ones).
std::string content_type_of(const std::filesystem::path& file);

}  // namespace cls
