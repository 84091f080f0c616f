#pragma once
#include <sstream>
#include <string>

namespace cls {

enum class LogLevel { Quiet = 0, Normal = 1, Verbose = 2 };

void set_log_level(LogLevel level);
LogLevel log_level();

// All diagnostics go to stderr, so stdout stays machine-readable (e.g. `citymodel stats --json`).
void log_warn(const std::string& msg);     // shown unless --quiet
void log_info(const std::string& msg);     // shown unless --quiet
void log_verbose(const std::string& msg);  // shown with -v

// Builds a message from streamable parts: log_info(cat("read ", n, " images")).
template <class... Ts>
std::string cat(const Ts&... parts) {
  std::ostringstream s;
  (s << ... << parts);
  return s.str();
}

}  // namespace cls
