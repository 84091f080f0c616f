#include "core/npy.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/error.h"

namespace cls {
namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicLen = 6;

struct TypeInfo {
  NpyType type;
  size_t size;
};

// Accepted spellings: NumPy writes '|' for 1-byte types and '<' otherwise; '=' (native) is
// little-endian on every host we build for (checked below).
bool lookup_type(const std::string& descr, TypeInfo* out) {
  static const std::map<std::string, TypeInfo> kTypes = {
      {"<f2", {NpyType::F16, 2}}, {"<f4", {NpyType::F32, 4}}, {"<f8", {NpyType::F64, 8}},
      {"<i4", {NpyType::I32, 4}}, {"<i8", {NpyType::I64, 8}}, {"|u1", {NpyType::U8, 1}},
      {"|b1", {NpyType::Bool, 1}}};
  std::string d = descr;
  if (d.size() == 3 && host_is_little_endian() && (d[0] == '=' || (d[0] == '<' && d[2] == '1') ||
                                                   (d[0] == '|' && d[2] != '1'))) {
    d[0] = d[2] == '1' ? '|' : '<';
  }
  const auto it = kTypes.find(d);
  if (it == kTypes.end()) return false;
  *out = it->second;
  return true;
}

// The header is a Python literal; we parse exactly the subset NumPy writes: a dict of string keys
// to strings, True/False, and tuples of non-negative integers.
class HeaderParser {
 public:
  HeaderParser(const std::string& text, const std::string& name) : s_(text), name_(name) {}

  void parse(std::string* descr, bool* fortran_order, std::vector<int64_t>* shape) {
    bool have_descr = false, have_fortran = false, have_shape = false;
    expect('{');
    while (true) {
      skip_ws();
      if (peek() == '}') { ++i_; break; }
      const std::string key = parse_string();
      expect(':');
      skip_ws();
      if (key == "descr") {
        if (peek() != '\'' && peek() != '"') error("'descr' is not a simple type string (structured arrays are not supported)");
        *descr = parse_string();
        have_descr = true;
      } else if (key == "fortran_order") {
        *fortran_order = parse_bool();
        have_fortran = true;
      } else if (key == "shape") {
        *shape = parse_tuple();
        have_shape = true;
      } else {
        error("unexpected header key '" + key + "'");
      }
      skip_ws();
      if (peek() == ',') { ++i_; continue; }
      expect('}');
      break;
    }
    skip_ws();
    if (i_ != s_.size()) error("trailing characters after the header dict");
    if (!have_descr || !have_fortran || !have_shape)
      error("header lacks one of 'descr', 'fortran_order', 'shape'");
  }

 private:
  [[noreturn]] void error(const std::string& what) const {
    fail(name_, "bad .npy header (" + what + "): " + s_);
  }
  char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
  void skip_ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  void expect(char c) {
    skip_ws();
    if (peek() != c) error(std::string("expected '") + c + "'");
    ++i_;
  }
  std::string parse_string() {
    skip_ws();
    const char q = peek();
    if (q != '\'' && q != '"') error("expected a quoted string");
    const size_t end = s_.find(q, i_ + 1);
    if (end == std::string::npos) error("unterminated string");
    std::string out = s_.substr(i_ + 1, end - i_ - 1);
    i_ = end + 1;
    return out;
  }
  bool parse_bool() {
    if (s_.compare(i_, 4, "True") == 0) { i_ += 4; return true; }
    if (s_.compare(i_, 5, "False") == 0) { i_ += 5; return false; }
    error("expected True or False");
  }
  std::vector<int64_t> parse_tuple() {
    std::vector<int64_t> dims;
    expect('(');
    while (true) {
      skip_ws();
      if (peek() == ')') { ++i_; break; }
      if (!std::isdigit(static_cast<unsigned char>(peek()))) error("shape entries must be non-negative integers");
      int64_t v = 0;
      while (std::isdigit(static_cast<unsigned char>(peek()))) {
        if (v > (int64_t{1} << 50)) error("shape entry too large");
        v = v * 10 + (s_[i_++] - '0');
      }
      skip_ws();
      if (peek() == 'L') ++i_;  // Python 2 long suffix in old files
      dims.push_back(v);
      skip_ws();
      if (peek() == ',') { ++i_; continue; }
      expect(')');
      break;
    }
    return dims;
  }

  const std::string& s_;
  const std::string& name_;
  size_t i_ = 0;
};

uint32_t read_le(const std::string& b, size_t at, size_t n) {
  uint32_t v = 0;
  for (size_t k = 0; k < n; ++k) v |= uint32_t(static_cast<uint8_t>(b[at + k])) << (8 * k);
  return v;
}

}  // namespace

NpyType NpyArray::type() const {
  TypeInfo t;
  if (!lookup_type(dtype, &t)) throw Error("unsupported .npy dtype '" + dtype + "'");
  return t.type;
}

size_t NpyArray::item_size() const {
  TypeInfo t;
  if (!lookup_type(dtype, &t)) throw Error("unsupported .npy dtype '" + dtype + "'");
  return t.size;
}

int64_t NpyArray::numel() const {
  int64_t n = 1;
  for (const int64_t d : shape) n *= d;
  return n;
}

template <> const char* npy_descr<float>() { return "<f4"; }
template <> const char* npy_descr<double>() { return "<f8"; }
template <> const char* npy_descr<int32_t>() { return "<i4"; }
template <> const char* npy_descr<int64_t>() { return "<i8"; }
template <> const char* npy_descr<uint8_t>() { return "|u1"; }
template <> const char* npy_descr<bool>() { return "|b1"; }
template <> const char* npy_descr<uint16_t>() { return "<f2"; }  // raw half bits

template <typename T> const T* NpyArray::as() const {
  TypeInfo want, have;
  lookup_type(npy_descr<T>(), &want);
  if (!lookup_type(dtype, &have) || have.type != want.type)
    throw Error(std::string("array has dtype '") + dtype + "', not '" + npy_descr<T>() + "'");
  if (data.size() != static_cast<size_t>(numel()) * sizeof(T))
    throw Error("array data size does not match its shape");
  return reinterpret_cast<const T*>(data.data());
}

template <typename T> T* NpyArray::as() {
  return const_cast<T*>(static_cast<const NpyArray*>(this)->as<T>());
}

#define CLS_NPY_INSTANTIATE(T)                                                       \
  template const T* NpyArray::as<T>() const;                                        \
  template T* NpyArray::as<T>();                                                    \
  template NpyArray make_npy<T>(std::vector<int64_t> shape, const std::vector<T>& values);

template <typename T>
NpyArray make_npy(std::vector<int64_t> shape, const std::vector<T>& values) {
  NpyArray a;
  a.dtype = npy_descr<T>();
  a.shape = std::move(shape);
  if (a.numel() != static_cast<int64_t>(values.size()))
    throw Error("make_npy: " + std::to_string(values.size()) + " values for a shape of " +
                std::to_string(a.numel()) + " elements");
  a.data.resize(values.size() * sizeof(T));
  if constexpr (std::is_same_v<T, bool>) {
    for (size_t i = 0; i < values.size(); ++i) a.data[i] = values[i] ? 1 : 0;
  } else if (!values.empty()) {
    std::memcpy(a.data.data(), values.data(), a.data.size());
  }
  return a;
}

CLS_NPY_INSTANTIATE(float)
CLS_NPY_INSTANTIATE(double)
CLS_NPY_INSTANTIATE(int32_t)
CLS_NPY_INSTANTIATE(int64_t)
CLS_NPY_INSTANTIATE(uint8_t)
CLS_NPY_INSTANTIATE(uint16_t)
#undef CLS_NPY_INSTANTIATE
// std::vector<bool> has no data(): bool gets only the views.
template const bool* NpyArray::as<bool>() const;
template bool* NpyArray::as<bool>();
template NpyArray make_npy<bool>(std::vector<int64_t> shape, const std::vector<bool>& values);

namespace {
template <typename Out> std::vector<Out> convert_all(const NpyArray& a) {
  const int64_t n = a.numel();
  if (a.data.size() != static_cast<size_t>(n) * a.item_size())
    throw Error("array data size does not match its shape");
  std::vector<Out> out(static_cast<size_t>(n));
  const uint8_t* p = a.data.data();
  auto load = [&](auto tag, int64_t i) {
    using T = decltype(tag);
    T v;
    std::memcpy(&v, p + i * sizeof(T), sizeof(T));
    return v;
  };
  for (int64_t i = 0; i < n; ++i) {
    Out v{};
    switch (a.type()) {
      case NpyType::F16: v = static_cast<Out>(half_to_float(load(uint16_t{}, i))); break;
      case NpyType::F32: v = static_cast<Out>(load(float{}, i)); break;
      case NpyType::F64: v = static_cast<Out>(load(double{}, i)); break;
      case NpyType::I32: v = static_cast<Out>(load(int32_t{}, i)); break;
      case NpyType::I64: v = static_cast<Out>(load(int64_t{}, i)); break;
      case NpyType::U8: v = static_cast<Out>(p[i]); break;
      case NpyType::Bool: v = static_cast<Out>(p[i] != 0); break;
    }
    out[static_cast<size_t>(i)] = v;
  }
  return out;
}
}  // namespace

std::vector<float> NpyArray::to_float() const { return convert_all<float>(*this); }
std::vector<double> NpyArray::to_double() const { return convert_all<double>(*this); }

NpyArray parse_npy(const std::string& bytes, const std::string& name) {
  if (bytes.size() < kMagicLen + 2 || std::memcmp(bytes.data(), kMagic, kMagicLen) != 0)
    fail(name, "not a .npy file (no \\x93NUMPY magic)");
  const int major = static_cast<uint8_t>(bytes[6]);
  const int minor = static_cast<uint8_t>(bytes[7]);
  if (major < 1 || major > 3 || minor != 0)
    fail(name, "unsupported .npy format version " + std::to_string(major) + "." + std::to_string(minor));
  const size_t len_bytes = major == 1 ? 2 : 4;
  const size_t prefix = kMagicLen + 2 + len_bytes;
  if (bytes.size() < prefix) fail(name, "truncated .npy header");
  const size_t header_len = read_le(bytes, kMagicLen + 2, len_bytes);
  if (bytes.size() < prefix + header_len)
    fail(name, "truncated .npy header (needs " + std::to_string(header_len) + " bytes, file has " +
                   std::to_string(bytes.size() - prefix) + ")");
  const std::string header = bytes.substr(prefix, header_len);

  NpyArray a;
  bool fortran_order = false;
  HeaderParser(header, name).parse(&a.dtype, &fortran_order, &a.shape);
  TypeInfo t;
  if (!lookup_type(a.dtype, &t))
    fail(name, "unsupported .npy dtype '" + a.dtype +
                   "' (supported: <f2 <f4 <f8 <i4 <i8 |u1 |b1, little-endian)");
  // One spelling per type from here on.
  switch (t.type) {
    case NpyType::F16: a.dtype = "<f2"; break;
    case NpyType::F32: a.dtype = "<f4"; break;
    case NpyType::F64: a.dtype = "<f8"; break;
    case NpyType::I32: a.dtype = "<i4"; break;
    case NpyType::I64: a.dtype = "<i8"; break;
    case NpyType::U8: a.dtype = "|u1"; break;
    case NpyType::Bool: a.dtype = "|b1"; break;
  }
  if (fortran_order)
    fail(name, "Fortran-ordered .npy arrays are not supported (save with np.ascontiguousarray)");
  const size_t available = bytes.size() - prefix - header_len;
  // The shape's element count, stopped before it overflows: (2^32, 2^32) would wrap to 0 and pass as empty.
  size_t elements = std::find(a.shape.begin(), a.shape.end(), 0) == a.shape.end() ? 1 : 0;
  for (size_t k = 0; k < a.shape.size() && elements > 0; ++k)
    if (__builtin_mul_overflow(elements, static_cast<size_t>(a.shape[k]), &elements) || elements > available) {
      std::string shape;
      for (const int64_t d : a.shape) shape += (shape.empty() ? "" : ", ") + std::to_string(d);
      fail(name, "truncated .npy data: shape (" + shape + ") holds more elements than the file's " +
                     std::to_string(available) + " data bytes");
    }
  const size_t expected = elements * t.size;
  if (available < expected)
    fail(name, "truncated .npy data: shape needs " + std::to_string(expected) + " bytes, file has " +
                   std::to_string(available));
  if (available > expected)
    fail(name, "trailing bytes after .npy data (" + std::to_string(available - expected) + ")");
  a.data.assign(bytes.begin() + static_cast<std::ptrdiff_t>(prefix + header_len), bytes.end());
  if (!host_is_little_endian()) fail(name, "big-endian hosts are not supported");
  return a;
}

NpyArray read_npy(const std::filesystem::path& path) {
  return parse_npy(read_text_file(path), path.string());
}

std::string encode_npy(const NpyArray& a) {
  TypeInfo t;
  if (!lookup_type(a.dtype, &t)) throw Error("encode_npy: unsupported dtype '" + a.dtype + "'");
  if (a.data.size() != static_cast<size_t>(a.numel()) * t.size)
    throw Error("encode_npy: data size does not match the shape");
  std::ostringstream dict;
  dict << "{'descr': '" << a.dtype << "', 'fortran_order': False, 'shape': (";
  for (size_t i = 0; i < a.shape.size(); ++i) dict << (i ? ", " : "") << a.shape[i];
  if (a.shape.size() == 1) dict << ",";  // Python's one-element tuple
  dict << "), }";
  std::string header = dict.str();
  // Pad with spaces and a final newline so the data starts at a multiple of 64 bytes (NumPy >= 1.19).
  int major = 1;
  size_t prefix = kMagicLen + 2 + 2;
  if (prefix + header.size() + 1 > 65535) {
    major = 2;
    prefix = kMagicLen + 2 + 4;
  }
  const size_t total = (prefix + header.size() + 1 + 63) / 64 * 64;
  header.append(total - prefix - header.size() - 1, ' ');
  header.push_back('\n');

  std::string out(kMagic, kMagicLen);
  out.push_back(static_cast<char>(major));
  out.push_back(0);
  const uint32_t len = static_cast<uint32_t>(header.size());
  for (size_t k = 0; k < (major == 1 ? 2u : 4u); ++k) out.push_back(static_cast<char>((len >> (8 * k)) & 0xff));
  out += header;
  out.append(reinterpret_cast<const char*>(a.data.data()), a.data.size());
  return out;
}

void write_npy(const std::filesystem::path& path, const NpyArray& a) {
  std::string bytes;
  try {
    bytes = encode_npy(a);
  } catch (const Error& e) {
    fail(path.string(), e.what());
  }
  write_text_atomic(path, bytes);
}

// IEEE 754 binary16 <-> binary32.
float half_to_float(uint16_t h) {
  const uint32_t sign = uint32_t(h & 0x8000) << 16;
  uint32_t exp = (h >> 10) & 0x1f;
  uint32_t mant = h & 0x3ff;
  uint32_t bits;
  if (exp == 0) {
    if (mant == 0) {
      bits = sign;
    } else {  // subnormal: normalise
      exp = 127 - 15 + 1;
      while ((mant & 0x400) == 0) { mant <<= 1; --exp; }
      mant &= 0x3ff;
      bits = sign | (exp << 23) | (mant << 13);
    }
  } else if (exp == 0x1f) {
    bits = sign | 0x7f800000u | (mant << 13);
  } else {
    bits = sign | ((exp + 127 - 15) << 23) | (mant << 13);
  }
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

uint16_t float_to_half(float f) {
  uint32_t x;
  std::memcpy(&x, &f, 4);
  const uint16_t sign = static_cast<uint16_t>((x >> 16) & 0x8000);
  const uint32_t abs = x & 0x7fffffffu;
  if (abs >= 0x7f800000u)  // inf / nan
    return sign | 0x7c00 | (abs > 0x7f800000u ? 0x200 : 0);
  if (abs >= 0x477ff000u) return sign | 0x7c00;  // rounds past 65504: overflow to inf
  if (abs < 0x38800000u) {  // below the smallest normal half: subnormal or zero
    if (abs < 0x33000000u) return sign;  // < 2^-25 rounds to zero
    const uint32_t exp = abs >> 23;
    const uint32_t mant = (abs & 0x7fffff) | 0x800000;
    const uint32_t shift = 126 - exp;  // 14 - (exp - 127) + 13 - 1
    uint32_t h = mant >> (shift);
    const uint32_t rem = mant & ((1u << shift) - 1);
    const uint32_t half_way = 1u << (shift - 1);
    if (rem > half_way || (rem == half_way && (h & 1))) ++h;
    return sign | static_cast<uint16_t>(h);
  }
  uint32_t h = ((abs >> 13) - ((127 - 15) << 10));
  const uint32_t rem = abs & 0x1fff;
  if (rem > 0x1000 || (rem == 0x1000 && (h & 1))) ++h;
  return sign | static_cast<uint16_t>(h);
}

}  // namespace cls
