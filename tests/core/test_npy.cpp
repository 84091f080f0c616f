#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/npy.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

// A .npy file assembled byte by byte, as the format spec describes it.
std::string npy_bytes(int major, const std::string& dict, const std::string& data) {
  std::string header = dict;
  const size_t len_bytes = major == 1 ? 2 : 4;
  while ((6 + 2 + len_bytes + header.size() + 1) % 64 != 0) header.push_back(' ');
  header.push_back('\n');
  std::string out = "\x93NUMPY";
  out.push_back(static_cast<char>(major));
  out.push_back(0);
  for (size_t k = 0; k < len_bytes; ++k) out.push_back(static_cast<char>((header.size() >> (8 * k)) & 0xff));
  return out + header + data;
}

template <typename T> std::string raw(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

std::string error_of(const std::string& bytes, const std::string& name = "x.npy") {
  try {
    parse_npy(bytes, name);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("cls_npy_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(Npy, ParsesHandBuiltVersion1) {
  const std::vector<float> v = {1.5f, -2.f, 3.25f, 0.f, 7.f, 1e-3f};
  const NpyArray a =
      parse_npy(npy_bytes(1, "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }", raw(v)), "a.npy");
  EXPECT_EQ(a.dtype, "<f4");
  EXPECT_EQ(a.shape, (std::vector<int64_t>{2, 3}));
  ASSERT_EQ(a.numel(), 6);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(a.as<float>()[i], v[i]);
  EXPECT_THROW(a.as<double>(), Error);  // typed view checks the dtype
}

TEST(Npy, ParsesVersions2And3AndKeyOrderAndScalars) {
  const std::vector<int64_t> v = {-5, 1LL << 40, 7};
  const NpyArray a =
      parse_npy(npy_bytes(2, "{\"shape\": (3,), \"fortran_order\": False, \"descr\": \"<i8\"}", raw(v)), "b.npy");
  EXPECT_EQ(a.shape, (std::vector<int64_t>{3}));
  EXPECT_EQ(a.as<int64_t>()[1], 1LL << 40);
  const std::vector<double> d = {2.5};
  const NpyArray s = parse_npy(npy_bytes(3, "{'descr': '<f8', 'fortran_order': False, 'shape': ()}", raw(d)), "c.npy");
  EXPECT_TRUE(s.shape.empty());
  EXPECT_EQ(s.numel(), 1);
  EXPECT_EQ(s.to_float()[0], 2.5f);
  // Zero-sized arrays are legal.
  const NpyArray z = parse_npy(npy_bytes(1, "{'descr': '|u1', 'fortran_order': False, 'shape': (0, 4), }", ""), "z.npy");
  EXPECT_EQ(z.numel(), 0);
}

TEST(Npy, HalfBoolAndU8ConvertToFloat) {
  // 1.0, -2.0, 65504 (max), 2^-24 (smallest subnormal) as IEEE half bits.
  const std::vector<uint16_t> h = {0x3c00, 0xc000, 0x7bff, 0x0001};
  const NpyArray a = parse_npy(npy_bytes(1, "{'descr': '<f2', 'fortran_order': False, 'shape': (4,), }", raw(h)), "h.npy");
  const std::vector<float> f = a.to_float();
  EXPECT_EQ(f[0], 1.f);
  EXPECT_EQ(f[1], -2.f);
  EXPECT_EQ(f[2], 65504.f);
  EXPECT_EQ(f[3], std::ldexp(1.f, -24));
  const NpyArray b = parse_npy(npy_bytes(1, "{'descr': '|b1', 'fortran_order': False, 'shape': (3,), }",
                                         std::string("\x01\x00\x01", 3)), "b.npy");
  EXPECT_EQ(b.to_double(), (std::vector<double>{1, 0, 1}));
  EXPECT_TRUE(b.as<bool>()[2]);
}

TEST(Npy, HalfConversionRoundsToNearestEven) {
  for (uint32_t bits = 0; bits < 0x10000; ++bits) {  // every finite half survives a round trip
    const uint16_t h = static_cast<uint16_t>(bits);
    if ((h & 0x7c00) == 0x7c00) continue;
    ASSERT_EQ(float_to_half(half_to_float(h)), h) << std::hex << bits;
  }
  EXPECT_EQ(float_to_half(1.f + std::ldexp(1.f, -11)), 0x3c00);      // tie -> even (down)
  EXPECT_EQ(float_to_half(1.f + 3 * std::ldexp(1.f, -11)), 0x3c02);  // tie -> even (up)
  EXPECT_EQ(float_to_half(70000.f), 0x7c00);                          // overflow -> inf
  EXPECT_EQ(float_to_half(std::ldexp(1.f, -26)), 0x0000);             // underflow -> 0
}

TEST(Npy, RoundTripThroughFileKeepsEverything) {
  const fs::path dir = temp_dir();
  const NpyArray f = make_npy<float>({2, 2, 3}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
  write_npy(dir / "f.npy", f);
  const NpyArray g = read_npy(dir / "f.npy");
  EXPECT_EQ(g.dtype, "<f4");
  EXPECT_EQ(g.shape, f.shape);
  EXPECT_EQ(g.data, f.data);
  // The header is the one NumPy writes: data 64-byte aligned, one-element tuples with a comma.
  const std::string bytes = encode_npy(make_npy<int32_t>({3}, {1, 2, 3}));
  EXPECT_EQ((bytes.size() - 12) % 64, 0u);
  EXPECT_NE(bytes.find("'shape': (3,), }"), std::string::npos);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  for (const auto& a : {make_npy<double>({1}, {1.25}), make_npy<int64_t>({2}, {-1, 9}),
                        make_npy<uint8_t>({2, 1}, {255, 0}), make_npy<bool>({2}, {true, false}),
                        make_npy<uint16_t>({1}, {0x3c00})}) {
    const NpyArray r = parse_npy(encode_npy(a), "r.npy");
    EXPECT_EQ(r.dtype, a.dtype);
    EXPECT_EQ(r.shape, a.shape);
    EXPECT_EQ(r.data, a.data);
  }
  // A header too long for version 1 switches to version 2.
  NpyArray wide;
  wide.dtype = "|u1";
  wide.shape = std::vector<int64_t>(30000, 1);
  wide.data = {42};
  const std::string big = encode_npy(wide);
  EXPECT_EQ(big[6], 2);
  EXPECT_EQ(parse_npy(big, "w.npy").shape.size(), 30000u);
  fs::remove_all(dir);
}

TEST(Npy, BadFilesGiveErrorsNamingTheFile) {
  const std::string ok_dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }";
  const std::string data = raw(std::vector<float>{1, 2});
  const std::string good = npy_bytes(1, ok_dict, data);
  // Every truncation of a valid file is rejected with the file's name (never a crash).
  for (size_t n = 0; n < good.size(); ++n) {
    const std::string e = error_of(good.substr(0, n), "cut.npy");
    ASSERT_EQ(e.rfind("cut.npy: ", 0), 0u) << n << ": " << e;
  }
  EXPECT_NE(error_of(good.substr(0, good.size() - 1)).find("truncated .npy data"), std::string::npos);
  EXPECT_NE(error_of(good + "x").find("trailing"), std::string::npos);
  EXPECT_NE(error_of("PK\x03\x04 not numpy").find("not a .npy file"), std::string::npos);
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': '<f4', 'fortran_order': True, 'shape': (2,), }", data)).find("Fortran"),
            std::string::npos);
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': '>f4', 'fortran_order': False, 'shape': (2,), }", data)).find("dtype '>f4'"),
            std::string::npos);
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': [('a', '<f4')], 'fortran_order': False, 'shape': (2,), }", data))
                .find("structured"),
            std::string::npos);
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': '<f4', 'shape': (2,), }", data)).find("lacks"), std::string::npos);
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': '<f4', 'fortran_order': False, 'shape': (-2,), }", data)).find("non-negative"),
            std::string::npos);
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': '<f4', 'fortran_order': False, 'shape': (2,), 'x': 1}", data))
                .find("unexpected header key"),
            std::string::npos);
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': '<f4', 'fortran_order': False, 'shape': (2,", data)).find("bad .npy header"),
            std::string::npos);
  // A shape whose element count overflows 64 bits (it once wrapped to 0 and read as empty) or merely
  // promises more than the file holds; a zero in the shape is an empty array whatever the rest says.
  const std::string huge = error_of(npy_bytes(1, "{'descr': '<f4', 'fortran_order': False, 'shape': (4294967296, 4294967296), }", ""));
  EXPECT_EQ(huge.rfind("x.npy: truncated .npy data: shape (4294967296, 4294967296) holds more elements", 0), 0u) << huge;
  EXPECT_NE(error_of(npy_bytes(1, "{'descr': '<f4', 'fortran_order': False, 'shape': (1000000, 3), }", data))
                .find("holds more elements than the file's 8 data bytes"),
            std::string::npos);
  EXPECT_EQ(parse_npy(npy_bytes(1, "{'descr': '<f4', 'fortran_order': False, 'shape': (4294967296, 0), }", ""), "e.npy")
                .numel(),
            0);
  std::string v9 = good;
  v9[6] = 9;
  EXPECT_NE(error_of(v9).find("version 9.0"), std::string::npos);
  try {
    read_npy("/nonexistent/dir/m.npy");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/m.npy"), std::string::npos);
  }
}

// A file written by numpy.save (the CLIP fixture's token ids): rows start with the start token
// 49406 and contain the end token 49407; the empty text (row 5) is [49406, 49407, 0, ...].
TEST(Npy, ReadsNumpyWrittenFixture) {
  const NpyArray t = read_npy(fs::path(CLS_TEST_FIXTURES) / "clip/models/tiny_gelu/tokens.npy");
  ASSERT_EQ(t.dtype, "<i8");
  ASSERT_EQ(t.shape, (std::vector<int64_t>{8, 77}));
  const int64_t* ids = t.as<int64_t>();
  for (int r = 0; r < 8; ++r) {
    EXPECT_EQ(ids[r * 77], 49406);
    EXPECT_NE(std::find(ids + r * 77, ids + (r + 1) * 77, 49407), ids + (r + 1) * 77);
  }
  EXPECT_EQ(ids[5 * 77 + 1], 49407);
  EXPECT_EQ(ids[5 * 77 + 2], 0);
  // The long text is truncated so its last position holds the end token.
  EXPECT_EQ(ids[6 * 77 + 76], 49407);
}
