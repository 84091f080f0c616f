#pragma once
// ASPRS LAS point clouds (versions 1.0-1.4, point data record formats 0-10, uncompressed, with extra
// bytes): the densified clouds PIX4Dmapper, Metashape and most LiDAR sources export, and labelled
// clouds (ZAHA, TUM-FACADE) whose label is the classification or an extra-bytes field. A small reader of our own:
// no Debian 12 package reads LAS (liblas left Debian; PDAL and LASzip are not among the packages
// apt finds here), and the format is a fixed binary layout (ASPRS LAS 1.4 R15, tables 3-17).
// Compressed LAZ is refused with what to run instead.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.h"

namespace cls {

// One field of the Extra Bytes VLR (LAS 1.4 R15 table 24) with a scalar type (data_type 1-10: uint8,
// int8, uint16, int16, uint32, int32, uint64, int64, float, double).
struct LasExtraField {
  std::string name;
  int data_type = 0;
  uint32_t offset = 0;            // byte offset in a point record
  double scale = 1, add = 0;      // value = stored * scale + add (1 and 0 unless the options say)
};

struct LasHeader {
  int version_major = 1, version_minor = 2;
  int point_format = 0;           // 0-10
  uint32_t record_length = 0;     // bytes per point (the format's minimum plus extra bytes)
  uint64_t point_count = 0;
  uint32_t point_offset = 0;      // byte offset of the first point
  Vec3d scale{}, offset{};        // coordinate = integer * scale + offset
  Vec3d min{}, max{};             // the header's bounding box
  bool has_rgb = false;
  std::vector<LasExtraField> extra_fields;  // the scalar extra-bytes fields, in record order
};

struct LasPoints {
  LasHeader header;
  std::vector<Vec3d> xyz;
  std::vector<std::array<uint8_t, 3>> rgb;  // 8 bit (16-bit LAS colours scaled); empty without colour
  std::vector<uint8_t> classification;      // ASPRS class per point
  std::vector<double> field;                 // the extra-bytes field asked for, per point (else empty)
};

// Parses a whole LAS file held in memory, keeping every `stride`-th point (1 = all); `name` (the
// file) prefixes every error. A header that promises more points than the file holds, an unknown
// point format, LAZ, or a coordinate that is not finite is a cls::Error. `field` names an extra-bytes
// field to read into LasPoints::field ("" none); a file without it is a cls::Error listing those it has.
LasPoints parse_las(std::string_view bytes, const std::string& name, uint64_t stride = 1, const std::string& field = "");
// Whether `path` names a LAS or LAZ file, by its extension (any case).
bool is_las_path(const std::string& path);
// Reads the header and its VLRs only, then the points as parse_las does.
LasHeader read_las_header(const std::string& path);
LasPoints read_las(const std::string& path, uint64_t stride = 1, const std::string& field = "");

}  // namespace cls
