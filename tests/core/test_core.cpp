#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/args.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/math.h"
#include "core/progress.h"

namespace fs = std::filesystem;
using namespace cls;

TEST(Args, OptionsFlagsPositionalsAndDefaults) {
  Args a("demo", "a demo");
  a.option("width", "640", "image width").flag("fast", "go fast").positional("FILE", "input");
  ASSERT_TRUE(a.parse({"in.gml", "--width=320", "--fast"}));
  EXPECT_EQ(a.get("FILE"), "in.gml");
  EXPECT_EQ(a.get_int("width"), 320);
  EXPECT_TRUE(a.flag_set("fast"));
  Args b("demo", "a demo");
  b.option("width", "640", "image width").positional("FILE", "input");
  ASSERT_TRUE(b.parse({"x"}));
  EXPECT_EQ(b.get_int("width"), 640);
  EXPECT_NE(b.help().find("(default: 640)"), std::string::npos);
}

TEST(Args, UsageErrors) {
  Args a("demo", "");
  a.option("n", "1", "count").positional("FILE", "input");
  EXPECT_THROW(a.parse({}), UsageError);
  Args b("demo", "");
  b.option("n", "1", "count").positional("FILE", "input");
  EXPECT_THROW(b.parse({"f", "--bogus"}), UsageError);
  Args c("demo", "");
  c.option("n", "1", "count").positional("FILE", "input");
  ASSERT_TRUE(c.parse({"f", "--n", "x1"}));
  EXPECT_THROW(c.get_int("n"), UsageError);
  Args d("demo", "");
  d.option("n", "1", "count");
  EXPECT_THROW(d.parse({"--n"}), UsageError);
}

TEST(Args, NegativeNumbersAreValuesNotOptions) {
  Args a("demo", "");
  a.option("offset", "0", "offset");
  ASSERT_TRUE(a.parse({"--offset", "-2.5"}));
  EXPECT_DOUBLE_EQ(a.get_double("offset"), -2.5);
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
