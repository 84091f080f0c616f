#include "models/weights/download.h"

#include <curl/curl.h>

#include <cstdio>
#include <memory>
#include <mutex>

#include "core/log.h"
#include "core/progress.h"
#include "models/weights/sha256.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

void global_init() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

struct Transfer {
  std::FILE* out = nullptr;
  fs::path part;
  uint64_t offset = 0;       // bytes present before this transfer
  uint64_t written = 0;      // bytes written by this transfer
  bool restarted = false;    // the server ignored the Range request: started over
  CURL* curl = nullptr;
  std::unique_ptr<Progress> progress;
  uint64_t expected_size = 0;
  std::string label;
  bool show_progress = true;
};

size_t on_data(char* data, size_t size, size_t n, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const size_t bytes = size * n;
  if (t->written == 0) {
    long code = 0;
    curl_easy_getinfo(t->curl, CURLINFO_RESPONSE_CODE, &code);
    if (t->offset > 0 && code == 200) {  // full body despite Range: start the part file over
      if (std::freopen(t->part.c_str(), "wb", t->out) == nullptr) return 0;
      t->offset = 0;
      t->restarted = true;
    }
    if (t->show_progress) {
      curl_off_t length = -1;
      curl_easy_getinfo(t->curl, CURLINFO_CONTENT_LENGTH_DOWNLOAD_T, &length);
      const uint64_t total = t->expected_size ? t->expected_size
                                              : (length > 0 ? t->offset + static_cast<uint64_t>(length) : 0);
      t->progress = std::make_unique<Progress>("download " + t->label, total, "bytes");
      if (t->offset) t->progress->advance(t->offset);
    }
  }
  if (std::fwrite(data, 1, bytes, t->out) != bytes) return 0;  // aborts the transfer
  t->written += bytes;
  if (t->progress) t->progress->advance(bytes);
  return bytes;
}

uint64_t file_size_or_zero(const fs::path& p) {
  std::error_code ec;
  const auto s = fs::file_size(p, ec);
  return ec ? 0 : static_cast<uint64_t>(s);
}

}  // namespace

DownloadResult download_file(const DownloadRequest& r) {
  const std::string dest = r.dest.string();
  DownloadResult result;
  result.path = r.dest;
  std::error_code ec;
  if (fs::is_regular_file(r.dest, ec)) {
    const std::string sum = sha256_file(dest);
    if (r.sha256.empty() || sum == r.sha256) {
      result.sha256 = sum;
      result.bytes = file_size_or_zero(r.dest);
      result.already_present = true;
      return result;
    }
    fail(dest, "exists but its sha256 is " + sum + ", expected " + r.sha256 +
                   "; remove it (or move it away) and download again");
  }
  fs::create_directories(r.dest.parent_path().empty() ? fs::path(".") : r.dest.parent_path(), ec);
  if (ec) fail(r.dest.parent_path().string(), "cannot create directory: " + ec.message());

  Transfer t;
  t.part = r.dest;
  t.part += ".part";
  t.offset = file_size_or_zero(t.part);
  if (r.expected_size && t.offset > r.expected_size) {  // not a prefix of this file: start over
    fs::remove(t.part, ec);
    t.offset = 0;
  }
  result.resumed_from = t.offset;
  t.expected_size = r.expected_size;
  t.label = r.label.empty() ? r.dest.filename().string() : r.label;
  t.show_progress = r.progress;

  if (!(r.expected_size && t.offset == r.expected_size)) {
    global_init();
    t.out = std::fopen(t.part.c_str(), "ab");
    if (!t.out) fail(t.part.string(), "cannot open for writing");
    CURL* curl = curl_easy_init();
    if (!curl) {
      std::fclose(t.out);
      throw DownloadError("libcurl initialisation failed");
    }
    t.curl = curl;
    char errbuf[CURL_ERROR_SIZE] = {0};
    curl_easy_setopt(curl, CURLOPT_URL, r.url.c_str());
    curl_easy_setopt(curl, CURLOPT_FOLLOWLOCATION, 1L);
    curl_easy_setopt(curl, CURLOPT_FAILONERROR, 1L);
    curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, errbuf);
    curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, on_data);
    curl_easy_setopt(curl, CURLOPT_WRITEDATA, &t);
    curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT, 30L);
    curl_easy_setopt(curl, CURLOPT_LOW_SPEED_LIMIT, 1024L);  // abort below 1 KB/s for a minute
    curl_easy_setopt(curl, CURLOPT_LOW_SPEED_TIME, 60L);
    curl_easy_setopt(curl, CURLOPT_USERAGENT, "citylangsplat/" CLS_VERSION);
    if (t.offset) curl_easy_setopt(curl, CURLOPT_RESUME_FROM_LARGE, static_cast<curl_off_t>(t.offset));
    const CURLcode rc = curl_easy_perform(curl);
    long http = 0;
    curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &http);
    curl_easy_cleanup(curl);
    const bool closed = std::fclose(t.out) == 0;
    if (t.progress) t.progress->finish();
    if (rc == CURLE_RANGE_ERROR || http == 416) {
      // The part file is already complete (or the server refuses the range): verify below.
      if (!r.expected_size) {
        fs::remove(t.part, ec);
        throw DownloadError("cannot resume " + r.url + " (range refused); the partial file was removed, run again");
      }
    } else if (rc != CURLE_OK) {
      if (t.offset + t.written == 0) fs::remove(t.part, ec);  // nothing to resume from
      throw DownloadError("cannot download " + r.url + ": " + (errbuf[0] ? errbuf : curl_easy_strerror(rc)) +
                          (t.written + t.offset ? " (" + std::to_string(t.offset + t.written) +
                                                      " bytes kept in " + t.part.string() + " for resuming)"
                                                : ""));
    }
    if (!closed) fail(t.part.string(), "write failed");
    if (t.restarted) result.resumed_from = 0;
  }

  const uint64_t size = file_size_or_zero(t.part);
  if (r.expected_size && size != r.expected_size) {
    if (size > r.expected_size) fs::remove(t.part, ec);
    fail(dest, "downloaded " + std::to_string(size) + " bytes, expected " + std::to_string(r.expected_size) +
                   (size > r.expected_size ? " (removed; run again)" : " (kept for resuming; run again)"));
  }
  const std::string sum = sha256_file(t.part.string());
  if (!r.sha256.empty() && sum != r.sha256) {
    fs::remove(t.part, ec);
    fail(dest, "checksum mismatch: sha256 " + sum + ", expected " + r.sha256 +
                   " (the download was removed; run again)");
  }
  fs::rename(t.part, r.dest, ec);
  if (ec) fail(dest, "cannot move the download into place: " + ec.message());
  result.sha256 = sum;
  result.bytes = size;
  return result;
}

}  // namespace cls
