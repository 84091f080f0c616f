#pragma once
// Resumable, verified downloads of model files with libcurl (http(s) and file:// URLs).
// Data goes to "<dest>.part"; an interrupted download continues from the part file's size with an
// HTTP Range request; the size and sha256 are checked before the file is renamed into place.
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/error.h"

namespace cls {

struct DownloadRequest {
  std::string url;
  std::filesystem::path dest;
  uint64_t expected_size = 0;  // 0 = unknown
  std::string sha256;          // "" = not verified
  std::string label;           // progress label, e.g. the model name
  bool progress = true;
};

struct DownloadResult {
  std::filesystem::path path;
  std::string sha256;          // of the final file
  uint64_t bytes = 0;          // the final size
  uint64_t resumed_from = 0;   // bytes already present in the part file
  bool already_present = false;
};

// A download that could not reach or read its source (offline, DNS, refused, missing file,
// HTTP error). The part file is kept for a later resume.
class DownloadError : public Error {
 public:
  using Error::Error;
};

// Throws DownloadError for transfer failures and cls::Error for a size or checksum mismatch
// (the bad part file is removed so the next attempt starts over).
DownloadResult download_file(const DownloadRequest& request);

}  // namespace cls
