#include "scene/las.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/endian.h"
#include "core/error.h"
#include "core/strings.h"

namespace cls {
namespace {

static_assert(host_is_little_endian(), "the LAS reader assumes a little-endian host");

template <class T>
T get(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

constexpr size_t kMinHeaderSize = 227;  // LAS 1.0-1.2; 1.3 adds 8 bytes, 1.4 another 140
// Bytes of each point data record format 0-10 without extra bytes (LAS 1.4 R15, tables 7-17).
constexpr uint32_t kMinRecordLength[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
// Where the red/green/blue uint16 triple starts in a record, 0 for formats without colour.
constexpr uint32_t kRgbOffset[] = {0, 0, 20, 28, 0, 28, 0, 30, 30, 0, 30};

// Bytes of an extra-bytes data type: 0 is `options` undocumented bytes, 1-10 scalars, 11-30 the
// deprecated arrays of two and three of them.
uint32_t extra_size(int type, int options) {
  constexpr uint32_t kScalar[] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
  if (type == 0) return uint32_t(options);
  if (type <= 10) return kScalar[type];
  if (type <= 30) return kScalar[(type - 1) % 10 + 1] * (type <= 20 ? 2 : 3);
  return 0;
}

// The Extra Bytes VLR (user "LASF_Spec", record 4: 192-byte descriptors, LAS 1.4 R15 table 24) among the
// VLRs in `region` (the bytes before the points); the fields follow the format's own bytes in order.
// Unnamed fields and fields of other types only advance the offset; a VLR chain that leaves the region
// ends it.
void parse_extra_bytes(std::string_view region, uint16_t header_size, LasHeader& h, const std::string& name) {
  const uint32_t vlr_count = get<uint32_t>(region.data() + 100);
  size_t at = header_size;
  constexpr size_t kVlrHeader = 54, kDescriptor = 192;
  for (uint32_t v = 0; v < vlr_count && at + kVlrHeader <= region.size(); ++v) {
    const char* p = region.data() + at;
    const std::string user(p + 2, strnlen(p + 2, 16));
    const uint16_t record = get<uint16_t>(p + 18), length = get<uint16_t>(p + 20);
    if (at + kVlrHeader + length > region.size()) break;
    if (user == "LASF_Spec" && record == 4) {
      if (length % kDescriptor != 0)
        fail(name, "LAS Extra Bytes VLR of " + std::to_string(length) + " bytes is not a multiple of 192");
      uint32_t offset = kMinRecordLength[h.point_format];
      for (size_t d = 0; d < length / kDescriptor; ++d) {
        const char* e = p + kVlrHeader + d * kDescriptor;
        const int type = static_cast<uint8_t>(e[2]), options = static_cast<uint8_t>(e[3]);
        const uint32_t size = extra_size(type, options);
        if (type > 30 || size == 0)
          fail(name, "LAS Extra Bytes field " + std::to_string(d) + " has the unknown data type " + std::to_string(type));
        const std::string field_name(e + 4, strnlen(e + 4, 32));
        if (type >= 1 && type <= 10 && !field_name.empty()) {  // an unnamed field cannot be asked for
          LasExtraField f;
          f.name = field_name;
          f.data_type = type;
          f.offset = offset;
          if (options & 8) f.scale = get<double>(e + 112);
          if (options & 16) f.add = get<double>(e + 136);
          h.extra_fields.push_back(f);
        }
        offset += size;
      }
      if (offset > h.record_length)
        fail(name, "LAS Extra Bytes fields need " + std::to_string(offset) + " bytes per point, the records have " +
                       std::to_string(h.record_length));
    }
    at += kVlrHeader + length;
  }
}

LasHeader parse_header(std::string_view bytes, const std::string& name) {
  if (bytes.size() < 4 || bytes.substr(0, 4) != "LASF") fail(name, "not a LAS file (no 'LASF' signature)");
  if (bytes.size() < kMinHeaderSize)
    fail(name, "LAS header truncated: " + std::to_string(bytes.size()) + " bytes, at least 227 expected");
  const char* p = bytes.data();
  LasHeader h;
  h.version_major = static_cast<uint8_t>(p[24]);
  h.version_minor = static_cast<uint8_t>(p[25]);
  if (h.version_major != 1 || h.version_minor > 4)
    fail(name, "LAS version " + std::to_string(h.version_major) + "." + std::to_string(h.version_minor) +
                   " is not supported (1.0-1.4)");
  const uint16_t header_size = get<uint16_t>(p + 94);
  h.point_offset = get<uint32_t>(p + 96);
  const uint8_t format_byte = static_cast<uint8_t>(p[104]);
  h.record_length = get<uint16_t>(p + 105);
  if (header_size < kMinHeaderSize || h.point_offset < header_size)
    fail(name, "LAS header size " + std::to_string(header_size) + " or point data offset " +
                   std::to_string(h.point_offset) + " is invalid");
  // LASzip marks compressed point data by setting bit 7 (and 6) of the format byte.
  if (format_byte & 0xC0)
    fail(name, "compressed LAZ point data is not read: export LAS instead, or decompress it (e.g. `laszip -i "
               "in.laz -o out.las` or `pdal translate in.laz out.las`)");
  if (format_byte > 10) fail(name, "LAS point data record format " + std::to_string(format_byte) + " is unknown (0-10)");
  h.point_format = format_byte;
  if (h.record_length < kMinRecordLength[h.point_format])
    fail(name, "LAS point record length " + std::to_string(h.record_length) + " is shorter than format " +
                   std::to_string(h.point_format) + "'s " + std::to_string(kMinRecordLength[h.point_format]) +
                   " bytes");
  h.point_count = get<uint32_t>(p + 107);
  if (h.version_minor >= 4 && header_size >= 255 && bytes.size() >= 255) {
    const uint64_t count64 = get<uint64_t>(p + 247);
    if (h.point_count == 0 || count64 != 0) h.point_count = count64;
  }
  for (int k = 0; k < 3; ++k) {
    h.scale[k] = get<double>(p + 131 + 8 * k);
    h.offset[k] = get<double>(p + 155 + 8 * k);
    h.max[k] = get<double>(p + 179 + 16 * k);
    h.min[k] = get<double>(p + 187 + 16 * k);
    if (!std::isfinite(h.scale[k]) || h.scale[k] == 0 || !std::isfinite(h.offset[k]))
      fail(name, "LAS scale or offset of axis " + std::to_string(k) + " is zero or not finite");
  }
  h.has_rgb = kRgbOffset[h.point_format] != 0;
  parse_extra_bytes(bytes.substr(0, std::min<size_t>(bytes.size(), h.point_offset)), header_size, h, name);
  return h;
}

// Checks that the points the header promises fit in `available` bytes after the point offset.
void check_size(const LasHeader& h, uint64_t available, const std::string& name) {
  if (h.point_count > available / h.record_length)
    fail(name, "truncated LAS: the header promises " + std::to_string(h.point_count) + " points of " +
                   std::to_string(h.record_length) + " bytes, the file holds " + std::to_string(available) +
                   " bytes of point data");
}

// Appends the point record at `r` to `out` (16-bit colours kept in `rgb16` until all are read).
double extra_value(const char* r, const LasExtraField& f) {
  const char* v = r + f.offset;
  double x = 0;
  switch (f.data_type) {
    case 1: x = get<uint8_t>(v); break;
    case 2: x = get<int8_t>(v); break;
    case 3: x = get<uint16_t>(v); break;
    case 4: x = get<int16_t>(v); break;
    case 5: x = get<uint32_t>(v); break;
    case 6: x = get<int32_t>(v); break;
    case 7: x = double(get<uint64_t>(v)); break;
    case 8: x = double(get<int64_t>(v)); break;
    case 9: x = get<float>(v); break;
    default: x = get<double>(v); break;
  }
  return x * f.scale + f.add;
}

// The extra-bytes field named `field` (nullptr for ""); cls::Error listing the file's fields if absent.
const LasExtraField* find_field(const LasHeader& h, const std::string& field, const std::string& name) {
  if (field.empty()) return nullptr;
  std::string names;
  for (const LasExtraField& f : h.extra_fields) {
    if (f.name == field) return &f;
    names += (names.empty() ? "" : ", ") + f.name;
  }
  fail(name, "LAS file has no extra-bytes field '" + field + "' (it has: " + (names.empty() ? "none" : names) +
                 "; the ASPRS class is 'classification')");
}

void decode_point(const char* r, const LasHeader& h, const LasExtraField* field, LasPoints& out,
                  std::vector<std::array<uint16_t, 3>>& rgb16, const std::string& name) {
  Vec3d xyz;
  for (int k = 0; k < 3; ++k) xyz[k] = get<int32_t>(r + 4 * k) * h.scale[k] + h.offset[k];
  if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
    fail(name, "LAS point " + std::to_string(out.xyz.size()) + " has a coordinate that is not finite");
  out.xyz.push_back(xyz);
  out.classification.push_back(h.point_format < 6 ? static_cast<uint8_t>(r[15]) & 0x1F : static_cast<uint8_t>(r[16]));
  if (field) out.field.push_back(extra_value(r, *field));
  if (h.has_rgb) {
    const char* c = r + kRgbOffset[h.point_format];
    rgb16.push_back({get<uint16_t>(c), get<uint16_t>(c + 2), get<uint16_t>(c + 4)});
  }
}

// LAS colours are 16 bit, but many writers store 8-bit values unscaled: scale only when a value
// exceeds 255 (as CloudCompare and PDAL's readers guess too).
void finish_colours(LasPoints& out, const std::vector<std::array<uint16_t, 3>>& rgb16) {
  uint16_t peak = 0;
  for (const auto& c : rgb16) peak = std::max({peak, c[0], c[1], c[2]});
  const bool wide = peak > 255;
  out.rgb.reserve(rgb16.size());
  for (const auto& c : rgb16) {
    std::array<uint8_t, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = static_cast<uint8_t>(wide ? (c[k] + 128) / 257 : c[k]);
    out.rgb.push_back(v);
  }
}

void check_stride(uint64_t stride, const std::string& name) {
  if (stride == 0) fail(name, "LAS stride must be at least 1");
}

}  // namespace

LasPoints parse_las(std::string_view bytes, const std::string& name, uint64_t stride, const std::string& field) {
  check_stride(stride, name);
  LasPoints out;
  out.header = parse_header(bytes, name);
  const LasHeader& h = out.header;
  const LasExtraField* extra = find_field(h, field, name);
  if (h.point_offset > bytes.size()) fail(name, "LAS point data offset lies beyond the end of the file");
  check_size(h, bytes.size() - h.point_offset, name);
  std::vector<std::array<uint16_t, 3>> rgb16;
  const uint64_t kept = (h.point_count + stride - 1) / stride;
  out.xyz.reserve(kept);
  for (uint64_t i = 0; i < h.point_count; i += stride)
    decode_point(bytes.data() + h.point_offset + i * h.record_length, h, extra, out, rgb16, name);
  finish_colours(out, rgb16);
  return out;
}

bool is_las_path(const std::string& path) {
  const std::string ext = ascii_lower(std::filesystem::path(path).extension().string());
  return ext == ".las" || ext == ".laz";
}

LasHeader read_las_header(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) fail(path, "cannot open LAS file");
  std::string head(375, '\0');
  f.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(f.gcount()));
  LasHeader h = parse_header(head, path);
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || h.point_offset > size) fail(path, "LAS point data offset lies beyond the end of the file");
  if (h.point_offset > head.size()) {  // the VLRs (extra bytes) lie between the header and the points
    head.resize(h.point_offset);
    f.clear();
    f.seekg(0);
    if (!f.read(head.data(), static_cast<std::streamsize>(head.size()))) fail(path, "cannot read the LAS header's VLRs");
    h = parse_header(head, path);
  }
  check_size(h, size - h.point_offset, path);
  return h;
}

LasPoints read_las(const std::string& path, uint64_t stride, const std::string& field) {
  check_stride(stride, path);
  LasPoints out;
  out.header = read_las_header(path);
  const LasHeader& h = out.header;
  const LasExtraField* extra = find_field(h, field, path);
  std::ifstream f(path, std::ios::binary);
  f.seekg(h.point_offset);
  // Chunks of records: a densified cloud of 50 M points is read without holding its bytes.
  constexpr uint64_t kChunk = 1 << 16;
  std::string chunk;
  std::vector<std::array<uint16_t, 3>> rgb16;
  out.xyz.reserve((h.point_count + stride - 1) / stride);
  for (uint64_t first = 0; first < h.point_count; first += kChunk) {
    const uint64_t n = std::min(kChunk, h.point_count - first);
    chunk.resize(n * h.record_length);
    if (!f.read(chunk.data(), static_cast<std::streamsize>(chunk.size())))
      fail(path, "LAS file ends inside point " + std::to_string(first));
    // the first index in this chunk that the stride keeps
    for (uint64_t i = (first + stride - 1) / stride * stride; i < first + n; i += stride)
      decode_point(chunk.data() + (i - first) * h.record_length, h, extra, out, rgb16, path);
  }
  finish_colours(out, rgb16);
  return out;
}

}  // namespace cls
