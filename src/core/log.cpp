#include "core/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace cls {
namespace {
std::atomic<int> g_level{static_cast<int>(LogLevel::Normal)};
std::mutex g_mutex;

void emit(const char* prefix, const std::string& msg) {
  std::lock_guard<std::mutex> lock(g_mutex);
  std::fprintf(stderr, "%s%s\n", prefix, msg.c_str());
  std::fflush(stderr);
}
}  // namespace

void set_log_level(LogLevel level) { g_level = static_cast<int>(level); }
LogLevel log_level() { return static_cast<LogLevel>(g_level.load()); }

void log_warn(const std::string& msg) {
  if (g_level >= static_cast<int>(LogLevel::Normal)) emit("warning: ", msg);
}
void log_info(const std::string& msg) {
  if (g_level >= static_cast<int>(LogLevel::Normal)) emit("", msg);
}
void log_verbose(const std::string& msg) {
  if (g_level >= static_cast<int>(LogLevel::Verbose)) emit("", msg);
}

}  // namespace cls
