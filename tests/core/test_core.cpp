#include <gtest/gtest.h>
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "core/args.h"
#include "core/atomic_file.h"
#include "core/cpu_threads.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/heap_reuse.h"
#include "core/math.h"
#include "core/progress.h"

namespace fs = std::filesystem;
using namespace cls;

TEST(Args, OptionsFlagsPositionalsAndDefaults) {
  int width = 640;
  bool fast = false;
  std::string file;
  Args a("demo", "a demo");
  a.bind("width", width, "image width").flag("fast", fast, "go fast").positional("FILE", file, "input");
  ASSERT_TRUE(a.parse({"in.gml", "--width=320", "--fast"}));
  EXPECT_EQ(file, "in.gml");
  EXPECT_EQ(width, 320);
  EXPECT_TRUE(fast);
  int width_b = 640;
  bool fast_b = false;
  std::string file_b;
  Args b("demo", "a demo");
  b.bind("width", width_b, "image width\nin pixels").flag("fast", fast_b, "go fast").positional("FILE", file_b, "input");
  ASSERT_TRUE(b.parse({"x"}));
  EXPECT_EQ(file_b, "x");
  EXPECT_EQ(width_b, 640);
  EXPECT_FALSE(fast_b);
  EXPECT_NE(b.help().find("(default: 640)"), std::string::npos) << b.help();
  EXPECT_NE(b.help().find("      image width\n      in pixels (default: 640)\n"), std::string::npos) << b.help();  // indented on
  EXPECT_NE(b.help().find("--fast"), std::string::npos) << b.help();
  EXPECT_NE(b.help().find("FILE"), std::string::npos) << b.help();
}

// The UsageError's message (empty when none was thrown).
template <class F>
std::string usage_error_of(F f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Args, UsageErrors) {
  int n = 1;
  std::string file;
  Args a("demo", "");
  a.bind("n", n, "count").positional("FILE", file, "input");
  EXPECT_EQ(usage_error_of([&] { a.parse(std::vector<std::string>{}); }), "demo: missing argument FILE (see --help)");
  Args b("demo", "");
  b.bind("n", n, "count").positional("FILE", file, "input");
  EXPECT_EQ(usage_error_of([&] { b.parse({"f", "--bogus"}); }), "demo: unknown option '--bogus' (see --help)");
  Args c("demo", "");
  c.bind("n", n, "count").positional("FILE", file, "input");
  EXPECT_EQ(usage_error_of([&] { c.parse({"f", "--n", "x1"}); }), "demo: --n expects an integer, got 'x1'");
  EXPECT_EQ(n, 1);  // a bad value leaves the field as it was
  Args d("demo", "");
  d.bind("n", n, "count");
  EXPECT_EQ(usage_error_of([&] { d.parse({"--n"}); }), "demo: option --n needs a value");
}

TEST(Args, RequiredOptionsAndOneDeclarationPerName) {
  std::string out;
  int n = 1;
  Args a("demo", "");
  a.bind("out", out, "output directory").required().bind("n", n, "count");
  EXPECT_NE(a.help().find("output directory (required)"), std::string::npos) << a.help();
  EXPECT_EQ(usage_error_of([&] { a.parse({"--n", "2"}); }), "demo: --out is required (see --help)");
  Args b("demo", "");
  b.bind("out", out, "output directory").required();
  ASSERT_TRUE(b.parse({"--out", "dir"}));
  EXPECT_EQ(out, "dir");
  Args c("demo", "");
  c.bind("n", n, "count");
  EXPECT_THROW(c.bind("n", out, "count again"), std::logic_error);
  bool flag = false;
  EXPECT_THROW(c.flag("n", flag, "a flag of the same name"), std::logic_error);
}

// An empty value is no value: an unset shell variable keeps the default, or fails a required option,
// instead of naming the working directory.
TEST(Args, AnEmptyValueIsNoValue) {
  std::string out = "default", dir;
  int n = 1;
  Args a("demo", "");
  a.bind("out", out, "output").bind("n", n, "count").bind("dir", dir, "where").required();
  EXPECT_EQ(usage_error_of([&] { a.parse({"--dir", "", "--out", ""}); }), "demo: --dir is required (see --help)");
  Args b("demo", "");
  b.bind("out", out, "output").bind("n", n, "count");
  ASSERT_TRUE(b.parse({"--out=", "--n", ""}));
  EXPECT_EQ(out, "default");
  EXPECT_EQ(n, 1);
  EXPECT_FALSE(b.given("out"));
}

// A number from a file is held to the command line's rules.
TEST(OptionCodec, NumbersFromJsonPassTheSameChecksAsText) {
  EXPECT_EQ(default_codec<int>().from_json(nlohmann::json(7)), 7);
  EXPECT_THROW(default_codec<int>().from_json(nlohmann::json(1.5)), std::invalid_argument);
  EXPECT_THROW(default_codec<int>().from_json(nlohmann::json("7")), std::invalid_argument);
  EXPECT_THROW(default_codec<int>().from_json(nlohmann::json(int64_t(1) << 40)), std::invalid_argument);
  EXPECT_EQ(default_codec<uint64_t>().from_json(nlohmann::json(3)), 3u);
  EXPECT_THROW(default_codec<uint64_t>().from_json(nlohmann::json(-1)), std::invalid_argument);
  EXPECT_THROW(default_codec<uint64_t>().parse(" -5"), std::invalid_argument);
  EXPECT_DOUBLE_EQ(default_codec<double>().from_json(nlohmann::json(0.1)), 0.1);
  EXPECT_EQ(default_codec<double>().text(0.0001), "0.0001");
}

TEST(Args, NegativeNumbersAreValuesNotOptions) {
  double offset = 0;
  int shift = 0;
  Args a("demo", "");
  a.bind("offset", offset, "offset").bind("shift", shift, "shift");
  ASSERT_TRUE(a.parse({"--offset", "-2.5", "--shift", "-3"}));
  EXPECT_DOUBLE_EQ(offset, -2.5);
  EXPECT_EQ(shift, -3);
}

TEST(AtomicFile, WritesAndLeavesNoTemporaryOnFailure) {
  const fs::path dir = fs::temp_directory_path() / "cls_atomic_test";
  fs::remove_all(dir);
  write_text_atomic(dir / "a.txt", "hello");
  EXPECT_EQ(read_text_file(dir / "a.txt"), "hello");
  EXPECT_THROW(write_atomic(dir / "b.txt",
                            [](const fs::path& tmp) {
                              std::ofstream(tmp) << "partial";
                              throw Error("boom");
                            }),
               Error);
  EXPECT_FALSE(fs::exists(dir / "b.txt"));
  int files = 0;
  for (auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);  // only a.txt: the failed write's temporary is gone
  EXPECT_THROW(read_text_file(dir / "missing.txt"), Error);
  fs::remove_all(dir);
}

TEST(Progress, StatusLineHasRateAndEta) {
  Progress p("raycast", 100, "views");
  const std::string line = p.status_line(25, 5.0);  // 5 views/s, 75 left -> 15 s
  EXPECT_NE(line.find("[raycast] 25/100 (25%)"), std::string::npos) << line;
  EXPECT_NE(line.find("5 views/s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 00:15"), std::string::npos) << line;
  EXPECT_EQ(Progress::format_duration(3723), "1:02:03");
  EXPECT_EQ(Progress::format_duration(-1), "--:--");
}

TEST(Math, QuaternionRotationMatchesHandComputedCases) {
  // 90 degrees about z: (w, x, y, z) = (cos45, 0, 0, sin45) maps x -> y.
  const double h = std::sqrt(0.5);
  const Mat3d R = quat_to_rotation(h, 0.0, 0.0, h);
  const Vec3d y = R * Vec3d{1, 0, 0};
  EXPECT_NEAR(y.x, 0, 1e-12);
  EXPECT_NEAR(y.y, 1, 1e-12);
  EXPECT_NEAR(y.z, 0, 1e-12);
  const Mat3d I = transpose(R) * R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(I.m[i][j], i == j ? 1.0 : 0.0, 1e-12);
}

namespace cls {
namespace {

// The CPUs in /proc/self/status's Cpus_allowed_list ("0-3,6"): the kernel's own account of the mask.
int cpus_allowed_by_proc() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("Cpus_allowed_list:", 0) != 0) continue;
    std::stringstream list(line.substr(line.find(':') + 1));
    std::string range;
    int count = 0;
    while (std::getline(list, range, ',')) {
      const size_t dash = range.find('-');
      count += dash == std::string::npos ? 1 : std::stoi(range.substr(dash + 1)) - std::stoi(range.substr(0, dash)) + 1;
    }
    return count;
  }
  return -1;
}

TEST(CpuThreads, OmpNumThreadsElseTheAffinityMask) {
  const char* env = std::getenv("OMP_NUM_THREADS");
  const std::string saved = env ? env : "";
  EXPECT_EQ(available_cpus(), cpus_allowed_by_proc());
  ::unsetenv("OMP_NUM_THREADS");
  EXPECT_EQ(default_cpu_threads(), available_cpus());
  for (const char* three : {"3", " 3 ", "3,2"}) {  // OpenMP's nested list: the first entry is the outer level
    ::setenv("OMP_NUM_THREADS", three, 1);
    EXPECT_EQ(default_cpu_threads(), 3) << "OMP_NUM_THREADS='" << three << "'";
  }
  for (const char* bad : {"0", "-2", "2x", "", "many", ",3", "99999999999"}) {
    ::setenv("OMP_NUM_THREADS", bad, 1);
    EXPECT_EQ(default_cpu_threads(), available_cpus()) << "OMP_NUM_THREADS='" << bad << "'";
  }
  if (env) ::setenv("OMP_NUM_THREADS", saved.c_str(), 1);
  else ::unsetenv("OMP_NUM_THREADS");
}

TEST(CpuThreads, GlobalFlagSetsThemOrIsAUsageError) {
  const test::CliResult ok = test::run_cli("-v --threads 3 scene --help");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.err.find("CPU threads: 3"), std::string::npos) << ok.err;
  for (const char* bad : {"--threads 0 scene --help", "--threads 2x scene --help", "--threads"}) {
    const test::CliResult r = test::run_cli(bad);
    EXPECT_EQ(r.status, kExitUsage) << bad;
    EXPECT_NE(r.err.find("--threads needs a positive integer"), std::string::npos) << bad << ": " << r.err;
  }
}

// Minor page faults of this process so far (the kernel's count).
long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// Faults taken writing every page of a fresh block of `bytes`, which is then freed.
long faults_to_fill_and_free(std::size_t bytes) {
  const long before = minor_faults();
  char* p = static_cast<char*>(std::malloc(bytes));
  if (!p) return -1;
  std::memset(p, 1, bytes);
  asm volatile("" : : "r"(p) : "memory");  // the block is used: the compiler keeps the malloc and the writes
  std::free(p);
  return minor_faults() - before;
}

// 64 MiB is above glibc's largest dynamic mmap threshold (32 MiB): without reuse_freed_memory every
// such block is mapped afresh and faults each of its 16,384 pages in again.
TEST(HeapReuse, AFreedLargeBlockIsReusedWithoutPageFaults) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.")) GTEST_SKIP() << "GLIBC_TUNABLES sets malloc: " << tunables;
  const std::size_t bytes = std::size_t(64) << 20;
  const long pages = static_cast<long>(bytes / static_cast<std::size_t>(sysconf(_SC_PAGESIZE)));
  ASSERT_GE(faults_to_fill_and_free(bytes), pages / 2) << "a fresh block faults its pages in";
  ASSERT_TRUE(reuse_freed_memory());
  faults_to_fill_and_free(bytes);  // now from the heap, which keeps it
  EXPECT_LT(faults_to_fill_and_free(bytes), pages / 100);
  malloc_trim(0);  // the block back to the kernel: a repeat, or the test below, wants a fresh one
}

// Another thread's arena keeps heaps of at most 64 MiB: there a 64 MiB block is mapped afresh on every
// malloc whatever the thresholds, unless every thread shares the main arena.
TEST(HeapReuse, AFreedLargeBlockIsReusedOnAnotherThread) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.")) GTEST_SKIP() << "GLIBC_TUNABLES sets malloc: " << tunables;
  const std::size_t bytes = std::size_t(64) << 20;
  const long pages = static_cast<long>(bytes / static_cast<std::size_t>(sysconf(_SC_PAGESIZE)));
  ASSERT_TRUE(reuse_freed_memory());
  long first = -1, again = -1;
  std::thread worker([&] {
    first = faults_to_fill_and_free(bytes);
    again = faults_to_fill_and_free(bytes);
  });
  worker.join();
  ASSERT_GE(first, 0);
  EXPECT_LT(again, pages / 100);
  malloc_trim(0);  // the block back to the kernel: the test above wants a fresh one
}

TEST(HeapReuse, TheUsersMallocTunablesWin) {
  const char* env = std::getenv("GLIBC_TUNABLES");
  const std::string saved = env ? env : "";
  ::setenv("GLIBC_TUNABLES", "glibc.malloc.trim_threshold=4096", 1);
  EXPECT_FALSE(reuse_freed_memory());
  if (env) ::setenv("GLIBC_TUNABLES", saved.c_str(), 1);
  else ::unsetenv("GLIBC_TUNABLES");
}

}  // namespace
}  // namespace cls
