#pragma once
// Every regular file under a directory, by relative path, with its bytes (for byte-identity tests).
#include <filesystem>
#include <map>
#include <string>

#include "core/atomic_file.h"

namespace cls::test {

inline std::map<std::string, std::string> read_tree(const std::filesystem::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root))
    if (e.is_regular_file()) files[std::filesystem::relative(e.path(), root).string()] = read_text_file(e.path());
  return files;
}

}  // namespace cls::test
