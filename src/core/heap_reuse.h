#pragma once
// Freed memory kept for reuse instead of returned to the kernel. glibc maps every block above its
// mmap threshold (128 KiB, raised as blocks are freed, at most 32 MiB) and unmaps it on free, and
// returns the heap's free top above its trim threshold: training and decoding loops that make and
// free the same large tensors every iteration then fault every page in again, and the kernel clears
// each. train-rgb at 480x360 took 12,500 page faults per iteration (docs/benchmarks.md).
// Threads other than the first get arenas of their own whose heaps hold at most 64 MiB: larger blocks
// are mapped whatever the thresholds say, and a heap that empties is unmapped. The SAM encoder's and
// the AMG decoder's worker threads spent 6 s of a 60 s run in the kernel that way; with one arena
// for all threads, under 1 s (docs/benchmarks.md).

#include <cstddef>

namespace cls {

// Blocks up to this size come from the heap and are reused after free.
constexpr std::size_t kHeapReuseMaxBlock = std::size_t(1) << 30;

// Raises glibc's mmap and trim thresholds to kHeapReuseMaxBlock (M_MMAP_THRESHOLD, M_TRIM_THRESHOLD)
// and gives every thread the main arena (M_ARENA_MAX 1). Call once at the start of a program, before
// large allocations and before any other thread allocates (a thread keeps the arena it has). Does
// nothing and returns false when the user set glibc's malloc tunables (GLIBC_TUNABLES with
// "glibc.malloc."): theirs win.
bool reuse_freed_memory();

}  // namespace cls
