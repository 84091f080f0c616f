#include "core/cpu_threads.h"

#include <sched.h>

#include <cstdlib>
#include <string>

namespace cls {

int available_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return 1;
  const int n = CPU_COUNT(&set);
  return n > 0 ? n : 1;
}

int default_cpu_threads() {
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    try {
      size_t used = 0;
      const std::string s = env;
      const int n = std::stoi(s, &used);
      if (used == s.size() && n > 0) return n;
    } catch (const std::exception&) {
    }
  }
  return available_cpus();
}

}  // namespace cls
