// Every test executable's main: GoogleTest's, after the heap set-up the CLI and benches make
// (core/heap_reuse.h), so tests run the library as the program runs it. Without it the strict SAM
// automatic-mask test spent 16.7 s of 191 s in the kernel clearing pages it had just freed.
#include <gtest/gtest.h>

#include "core/heap_reuse.h"

int main(int argc, char** argv) {
  cls::reuse_freed_memory();
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
