#include "core/cpu_threads.h"

#include <sched.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace cls {

int available_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  // A fixed set holds 1024 CPUs; on a larger machine the call fails and the online count stands in.
  const int n = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  return n > 0 ? n : 1;
}

int default_cpu_threads() {
  // OpenMP's form: a positive integer, or a nested list "4,2" whose first entry is the outer level.
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    std::string s = env;
    s = s.substr(0, s.find(','));
    const size_t first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
    s = first == std::string::npos ? "" : s.substr(first, last - first + 1);
    if (!s.empty() && s.size() < 7 && s.find_first_not_of("0123456789") == std::string::npos && std::stoi(s) > 0)
      return std::stoi(s);
  }
  return available_cpus();
}

}  // namespace cls
