// The shared PLY vertex reader (core/ply.h): hand-made files in both encodings against the values
// written into them, the file and the buffer readers agreeing, and damaged headers refused before
// anything is allocated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>

#include "core/atomic_file.h"
#include "core/ply.h"
#include "error_of.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const std::string kHeaderTail =
    "element vertex 2\nproperty double x\nproperty float y\nproperty uchar red\nproperty int class\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

template <class T>
void append(std::string& s, T v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// Two vertices (x, y, red, class) = (1.5, -2.25, 200, -7) and (1e10, 0.125, 3, 41), and one face.
std::string binary_file(const std::string& newline = "\n") {
  std::string s = "ply" + newline + "format binary_little_endian 1.0" + newline + "comment made by hand" + newline;
  s += kHeaderTail;
  append(s, 1.5), append(s, -2.25f), append(s, uint8_t{200}), append(s, int32_t{-7});
  append(s, 1e10), append(s, 0.125f), append(s, uint8_t{3}), append(s, int32_t{41});
  append(s, uint8_t{3}), append(s, int32_t{0}), append(s, int32_t{1}), append(s, int32_t{0});
  return s;
}

std::string ascii_file() {
  return "ply\nformat ascii 1.0\ncomment made by hand\n" + kHeaderTail + "1.5 -2.25 200 -7\n1e10 0.125 3 41\n3 0 1 0\n";
}

void expect_the_hand_values(const PlyVertices& v) {
  ASSERT_EQ(v.count, 2u);
  ASSERT_EQ(v.properties.size(), 4u);
  EXPECT_EQ(v.stride, 8u + 4 + 1 + 4);
  ASSERT_EQ(v.comments.size(), 1u);
  EXPECT_EQ(v.comments[0], "made by hand");
  const double expected[2][4] = {{1.5, -2.25, 200, -7}, {1e10, 0.125, 3, 41}};
  const char* names[] = {"x", "y", "red", "class"};
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(v.value(r, v.require(names[k])), expected[r][k]) << r << " " << names[k];
  EXPECT_TRUE(v.require("class").is_int);
  EXPECT_FALSE(v.require("y").is_int);
}

}  // namespace

TEST(Ply, BinaryAsciiAndCrlfFilesGiveTheValuesWrittenIntoThem) {
  expect_the_hand_values(parse_ply_vertices(binary_file(), "hand.ply"));
  expect_the_hand_values(parse_ply_vertices(binary_file("\r\n"), "hand.ply"));
  expect_the_hand_values(parse_ply_vertices(ascii_file(), "hand.ply"));
  const fs::path dir = fs::temp_directory_path() / "cls_test_ply";
  fs::create_directories(dir);
  for (const auto& [name, bytes] : {std::pair{"b.ply", binary_file()}, std::pair{"a.ply", ascii_file()}}) {
    write_text_atomic(dir / name, bytes);
    expect_the_hand_values(read_ply_vertices((dir / name).string()));
  }
}

TEST(Ply, DamagedFilesAreRefusedNamingTheFileAndWhat) {
  const std::string good = binary_file();
  auto replaced = [](std::string s, const std::string& from, const std::string& to) {
    return s.replace(s.find(from), from.size(), to);
  };
  const std::map<std::string, std::string> cases = {
      {"the header promises 99999999999 vertices", replaced(good, "element vertex 2", "element vertex 99999999999")},
      {"malformed PLY element line", replaced(good, "element vertex 2", "element vertex -2")},
      {"truncated PLY", good.substr(0, good.size() - 20)},
      {"ends before end_header", replaced(good, "end_header", "end_heade")},
      {"no 'ply' magic", "PLY" + good.substr(3)},
      {"format 'binary_big_endian'", replaced(good, "binary_little_endian", "binary_big_endian")},
      {"appears twice", replaced(good, "property float y", "property float x")},
      {"unknown PLY property type", replaced(good, "property float y", "property half y")},
      {"list property in the vertex element", replaced(good, "property float y", "property list uchar int y")},
      {"unknown PLY header line", replaced(good, "comment made", "remark made")},
      {"before the vertices", replaced(good, "element vertex 2", "element camera 1\nelement vertex 2")},
      {"the header promises 99999999 vertices", replaced(ascii_file(), "element vertex 2", "element vertex 99999999")},
      {"does not fit its type uchar", replaced(ascii_file(), " 200 ", " 300 ")},
      {"malformed at vertex 1", replaced(ascii_file(), "1e10 0.125", "1e10 abc")},
  };
  for (const auto& [needle, bytes] : cases) {
    const std::string message = test::error_of([&] { parse_ply_vertices(bytes, "cloud.ply"); });
    EXPECT_EQ(message.rfind("cloud.ply: ", 0), 0u) << needle << ": " << message;
    EXPECT_NE(message.find(needle), std::string::npos) << needle << ": " << message;
  }
}

TEST(Ply, NonFiniteValuesAreNamedWhereTheReaderAsksForFiniteOnes) {
  std::string bytes = binary_file();
  const double nan = std::nan("");
  std::memcpy(&bytes[bytes.find("end_header\n") + 11 + 17], &nan, 8);  // vertex 1's x
  const PlyVertices v = parse_ply_vertices(bytes, "cloud.ply");
  EXPECT_TRUE(std::isnan(v.value(1, v.require("x"))));
  const std::string message = test::error_of([&] { v.finite_value(1, v.require("x")); });
  EXPECT_EQ(message.rfind("cloud.ply: vertex 1 has x = ", 0), 0u) << message;
  EXPECT_EQ(test::error_of([&] { v.require("z"); }), "cloud.ply: PLY has no vertex property 'z'");
}
