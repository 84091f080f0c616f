#include "core/ply.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/endian.h"
#include "core/error.h"

namespace cls {
namespace {

static_assert(host_is_little_endian(), "the PLY reader keeps rows little-endian in memory");

constexpr size_t kMaxHeaderBytes = 1 << 20;

enum class Format { Ascii, BinaryLittleEndian };

struct Header {
  Format format = Format::Ascii;
  PlyVertices vertices;  // everything but the rows
  size_t body = 0;       // offset of the first vertex row in the file
};

// Size of a PLY scalar type, 0 if unknown.
int type_size(const std::string& t, bool& is_int) {
  is_int = true;
  if (t == "char" || t == "int8" || t == "uchar" || t == "uint8") return 1;
  if (t == "short" || t == "int16" || t == "ushort" || t == "uint16") return 2;
  if (t == "int" || t == "int32" || t == "uint" || t == "uint32") return 4;
  is_int = false;
  if (t == "float" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

// The offset just past "end_header\n" (or "\r\n"), or npos.
size_t header_end(std::string_view bytes) {
  for (size_t at = bytes.find("end_header"); at != std::string_view::npos; at = bytes.find("end_header", at + 1)) {
    if (at != 0 && bytes[at - 1] != '\n') continue;
    size_t next = at + std::strlen("end_header");
    if (next < bytes.size() && bytes[next] == '\r') ++next;
    if (next < bytes.size() && bytes[next] == '\n') return next + 1;
  }
  return std::string_view::npos;
}

Header parse_header(std::string_view bytes, const std::string& file) {
  if (bytes.substr(0, 4) != "ply\n" && bytes.substr(0, 5) != "ply\r\n") fail(file, "not a PLY file (no 'ply' magic)");
  Header h;
  h.body = header_end(bytes);
  if (h.body == std::string_view::npos) fail(file, "PLY header ends before end_header");
  PlyVertices& v = h.vertices;
  v.file = file;
  std::istringstream lines{std::string(bytes.substr(0, h.body))};
  std::string line;
  bool format_seen = false, in_vertex = false, vertex_seen = false;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string keyword;
    ls >> keyword;
    if (keyword == "comment" || keyword == "obj_info") {
      if (keyword == "comment") v.comments.push_back(line.size() > 8 ? line.substr(8) : "");
    } else if (keyword == "format") {
      std::string format;
      ls >> format;
      if (format == "ascii") h.format = Format::Ascii;
      else if (format == "binary_little_endian") h.format = Format::BinaryLittleEndian;
      else fail(file, "PLY format '" + format + "' is not supported (ascii or binary_little_endian)");
      format_seen = true;
    } else if (keyword == "element") {
      std::string name, count_text, rest;
      ls >> name >> count_text;
      char* end = nullptr;
      errno = 0;
      const unsigned long long count = std::strtoull(count_text.c_str(), &end, 10);
      if (name.empty() || count_text.empty() || count_text[0] == '-' || *end != '\0' || errno == ERANGE || (ls >> rest))
        fail(file, "malformed PLY element line: " + line);
      in_vertex = name == "vertex";
      if (in_vertex) {
        if (vertex_seen) fail(file, "PLY has two vertex elements");
        vertex_seen = true;
        v.count = count;
      } else if (!vertex_seen && count > 0) {
        fail(file, "PLY element '" + name + "' before the vertices is not supported");
      }
    } else if (keyword == "property") {
      if (!in_vertex) continue;  // properties of elements after the vertices
      PlyProperty p;
      ls >> p.type >> p.name;
      if (p.type == "list") fail(file, "list property in the vertex element is not supported");
      p.size = type_size(p.type, p.is_int);
      if (p.size == 0 || p.name.empty()) fail(file, "unknown PLY property type in: " + line);
      if (v.find(p.name)) fail(file, "PLY vertex property '" + p.name + "' appears twice");
      p.offset = v.stride;
      v.stride += p.size;
      v.properties.push_back(p);
    } else if (keyword != "ply" && keyword != "end_header" && !keyword.empty()) {
      fail(file, "unknown PLY header line: " + line);
    }
  }
  if (!format_seen) fail(file, "PLY header has no format line");
  if (!vertex_seen) fail(file, "PLY has no vertex element");
  if (v.count > 0 && v.stride == 0) fail(file, "PLY vertex element has no properties");
  return h;
}

// Stores `value` (from an ascii file) as the property's type in `out`.
void store(double value, const PlyProperty& p, char* out, uint64_t row, const std::string& file) {
  auto put = [&](auto typed) {
    using T = decltype(typed);
    if constexpr (std::is_integral_v<T>) {
      if (!(value >= static_cast<double>(std::numeric_limits<T>::min()) &&
            value <= static_cast<double>(std::numeric_limits<T>::max())))
        fail(file, "PLY vertex " + std::to_string(row) + ": " + p.name + " = " + std::to_string(value) +
                       " does not fit its type " + p.type);
    }
    typed = static_cast<T>(value);
    std::memcpy(out, &typed, sizeof typed);
  };
  const std::string& t = p.type;
  if (t == "char" || t == "int8") put(int8_t{});
  else if (t == "uchar" || t == "uint8") put(uint8_t{});
  else if (t == "short" || t == "int16") put(int16_t{});
  else if (t == "ushort" || t == "uint16") put(uint16_t{});
  else if (t == "int" || t == "int32") put(int32_t{});
  else if (t == "uint" || t == "uint32") put(uint32_t{});
  else if (t == "double" || t == "float64") put(double{});
  else if (std::isfinite(value) && std::fabs(value) > std::numeric_limits<float>::max())
    fail(file, "PLY vertex " + std::to_string(row) + ": " + p.name + " = " + std::to_string(value) + " overflows float");
  else put(float{});
}

// Converts the ascii body into little-endian rows.
void read_ascii_rows(std::string_view body, PlyVertices& v) {
  // A row of n values takes at least 2n characters: refuse a count the text cannot hold before
  // allocating for it.
  const uint64_t min_row = 2 * v.properties.size();
  if (v.count > 0 && v.count > (body.size() + 1) / min_row)
    fail(v.file, "truncated PLY: the header promises " + std::to_string(v.count) + " vertices, the text after the "
                     "header holds " + std::to_string(body.size()) + " bytes");
  v.rows.assign(v.count * v.stride, '\0');
  const std::string text(body);
  const char* at = text.c_str();
  for (uint64_t row = 0; row < v.count; ++row)
    for (const PlyProperty& p : v.properties) {
      char* end = nullptr;
      const double value = std::strtod(at, &end);
      if (end == at) fail(v.file, "PLY truncated or malformed at vertex " + std::to_string(row) + " (" + p.name + ")");
      at = end;
      store(value, p, v.rows.data() + row * v.stride + p.offset, row, v.file);
    }
}

void check_binary_size(const PlyVertices& v, uint64_t available) {
  if (v.stride > 0 && v.count > available / v.stride)
    fail(v.file, "truncated PLY: the header promises " + std::to_string(v.count) + " vertices of " +
                     std::to_string(v.stride) + " bytes, the file holds " + std::to_string(available) +
                     " bytes after the header");
}

}  // namespace

const PlyProperty* PlyVertices::find(const std::string& name) const {
  for (const auto& p : properties)
    if (p.name == name) return &p;
  return nullptr;
}

const PlyProperty& PlyVertices::require(const std::string& name) const {
  const PlyProperty* p = find(name);
  if (!p) fail(file, "PLY has no vertex property '" + name + "'");
  return *p;
}

double PlyVertices::value(uint64_t row, const PlyProperty& p) const {
  const char* at = rows.data() + row * stride + p.offset;
  auto get = [at](auto v) {
    std::memcpy(&v, at, sizeof v);
    return static_cast<double>(v);
  };
  const std::string& t = p.type;
  if (t == "float" || t == "float32") return get(float{});
  if (t == "double" || t == "float64") return get(double{});
  if (t == "char" || t == "int8") return get(int8_t{});
  if (t == "uchar" || t == "uint8") return get(uint8_t{});
  if (t == "short" || t == "int16") return get(int16_t{});
  if (t == "ushort" || t == "uint16") return get(uint16_t{});
  if (t == "int" || t == "int32") return get(int32_t{});
  return get(uint32_t{});
}

double PlyVertices::finite_value(uint64_t row, const PlyProperty& p) const {
  const double v = value(row, p);
  if (!std::isfinite(v))
    fail(file, "vertex " + std::to_string(row) + " has " + p.name + " = " + std::to_string(v) +
                   ": the file must hold finite numbers only");
  return v;
}

int PlyVertices::count_indexed(const std::string& prefix) const {
  int k = 0;
  while (find(prefix + std::to_string(k))) ++k;
  return k;
}

PlyVertices parse_ply_vertices(std::string_view bytes, const std::string& file) {
  Header h = parse_header(bytes, file);
  PlyVertices& v = h.vertices;
  const std::string_view body = bytes.substr(h.body);
  if (h.format == Format::Ascii) {
    read_ascii_rows(body, v);
  } else {
    check_binary_size(v, body.size());
    v.rows.assign(body.data(), v.count * v.stride);
  }
  return std::move(v);
}

PlyVertices read_ply_vertices(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) fail(path, "cannot open PLY file");
  // The header first (up to 1 MiB), so that a binary body is read once, straight into the rows.
  std::string head;
  size_t end = std::string::npos;
  char buffer[4096];
  while (end == std::string::npos && head.size() < kMaxHeaderBytes && f) {
    f.read(buffer, sizeof buffer);
    head.append(buffer, static_cast<size_t>(f.gcount()));
    end = header_end(head);
  }
  if (end == std::string::npos) {
    if (head.rfind("ply", 0) != 0) fail(path, "not a PLY file (no 'ply' magic)");
    fail(path, head.size() >= kMaxHeaderBytes ? "PLY header is longer than 1 MiB" : "PLY header ends before end_header");
  }
  Header h = parse_header(std::string_view(head).substr(0, end), path);
  PlyVertices& v = h.vertices;
  if (h.format == Format::Ascii) {
    std::ostringstream rest;
    rest << f.rdbuf();
    read_ascii_rows(head.substr(end) + rest.str(), v);
    return std::move(v);
  }
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  check_binary_size(v, ec || size < end ? 0 : size - end);
  v.rows.resize(v.count * v.stride);
  const size_t have = std::min(v.rows.size(), head.size() - end);
  std::memcpy(v.rows.data(), head.data() + end, have);
  f.clear();
  f.seekg(static_cast<std::streamoff>(end + have));
  f.read(v.rows.data() + have, static_cast<std::streamsize>(v.rows.size() - have));
  if (static_cast<size_t>(f.gcount()) != v.rows.size() - have)
    fail(path, "truncated PLY: " + std::to_string(v.count) + " vertices need " + std::to_string(v.rows.size()) +
                   " bytes after the header");
  return std::move(v);
}

}  // namespace cls
