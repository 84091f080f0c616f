#include "core/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <exception>

#include "core/log.h"

namespace cls {

double Progress::plain_interval_s = 5.0;

Progress::Progress(std::string stage, uint64_t total, std::string unit)
    : stage_(std::move(stage)),
      unit_(std::move(unit)),
      total_(total),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_),
      tty_(isatty(fileno(stderr)) != 0) {}

// A stage that is unwinding on an error prints no final line: the error is the last word.
Progress::~Progress() {
  if (std::uncaught_exceptions() > 0) finished_ = true;
  finish();
}

void Progress::advance(uint64_t n) {
  done_.fetch_add(n);
  maybe_print(false);
}

void Progress::finish() {
  if (finished_) return;
  maybe_print(true);
  finished_ = true;
}

void Progress::set_detail(std::string detail) {
  std::lock_guard<std::mutex> lock(detail_mutex_);
  detail_ = std::move(detail);
}

std::string Progress::format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  auto s = static_cast<long long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%02lld:%02lld", s / 60, s % 60);
  return buf;
}

std::string Progress::status_line(uint64_t done, double elapsed_s) const {
  const double rate = elapsed_s > 0 ? static_cast<double>(done) / elapsed_s : 0.0;
  char buf[256];
  if (total_ > 0) {
    const double frac = std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
    const double eta = rate > 0 ? static_cast<double>(total_ - std::min(done, total_)) / rate : -1;
    std::snprintf(buf, sizeof buf, "[%s] %llu/%llu (%.0f%%) %.3g %s/s elapsed %s ETA %s",
                  stage_.c_str(), static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total_), 100.0 * frac, rate, unit_.c_str(),
                  format_duration(elapsed_s).c_str(), format_duration(eta).c_str());
  } else {
    std::snprintf(buf, sizeof buf, "[%s] %llu %s %.3g %s/s elapsed %s", stage_.c_str(),
                  static_cast<unsigned long long>(done), unit_.c_str(), rate, unit_.c_str(),
                  format_duration(elapsed_s).c_str());
  }
  std::lock_guard<std::mutex> lock(detail_mutex_);
  return detail_.empty() ? std::string(buf) : std::string(buf) + " " + detail_;
}

void Progress::maybe_print(bool final) {
  if (log_level() == LogLevel::Quiet || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since_last = std::chrono::duration<double>(now - last_print_).count();
  const double min_gap = tty_ ? 0.1 : plain_interval_s;
  if (!final && since_last < min_gap) return;
  std::unique_lock<std::mutex> lock(print_mutex_, std::try_to_lock);
  if (!lock.owns_lock() && !final) return;
  if (!lock.owns_lock()) lock.lock();
  last_print_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const uint64_t done = done_.load();
  std::string line = status_line(done, elapsed);
  if (tty_) {
    constexpr int kWidth = 24;
    const int filled = total_ > 0 ? static_cast<int>(kWidth * std::min<double>(1.0, double(done) / double(total_))) : 0;
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r\033[K%s |%s|%s", line.c_str(), bar.c_str(), final ? "\n" : "");
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
}

}  // namespace cls
