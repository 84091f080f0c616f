#include "core/heap_reuse.h"

#include <malloc.h>

#include <cstdlib>
#include <cstring>

namespace cls {

bool reuse_freed_memory() {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.")) return false;
  const int max_block = static_cast<int>(kHeapReuseMaxBlock);
  // both: a fixed trim threshold alone also fixes the mmap threshold at its 128 KiB start
  return mallopt(M_MMAP_THRESHOLD, max_block) == 1 && mallopt(M_TRIM_THRESHOLD, max_block) == 1 &&
         mallopt(M_ARENA_MAX, 1) == 1;
}

}  // namespace cls
