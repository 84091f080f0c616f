#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace cls {

// Progress of a long stage: stage name, done/total, rate and ETA.
// On a terminal a live bar redrawn at most 10 times a second; otherwise (logs, CI) a plain
// line every `plain_interval_s` seconds and one at the end. Silent under --quiet.
// advance() is thread-safe and cheap (one atomic add; printing is rate-limited).
class Progress {
 public:
  Progress(std::string stage, uint64_t total, std::string unit = "items");
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(uint64_t n = 1);
  void finish();  // prints the final line once; called by the destructor if not called before
  // Free text shown after the counters (e.g. "loss 0.041 PSNR 27.1 dB"); thread-safe.
  void set_detail(std::string detail);

  uint64_t done() const { return done_.load(); }

  // Formats "12:03" / "1:02:03" (tested).
  static std::string format_duration(double seconds);
  // The line shown for the given state, without terminal control characters (tested).
  std::string status_line(uint64_t done, double elapsed_s) const;

  static double plain_interval_s;

 private:
  void maybe_print(bool final);

  std::string stage_, unit_;
  uint64_t total_;
  std::atomic<uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::mutex print_mutex_;
  mutable std::mutex detail_mutex_;
  std::string detail_;
  bool tty_;
  bool finished_ = false;
};

}  // namespace cls
