// COLMAP sparse models (https://colmap.github.io/format.html), binary and text.
//
// Binary layout (little-endian), as COLMAP's reconstruction_io writes it:
//   cameras.bin   u64 count, then per camera: u32 id, i32 model id, u64 width, u64 height,
//                 f64 params[model's count]
//   images.bin    u64 count, then per image: u32 id, f64 qvec[4] (w,x,y,z), f64 tvec[3],
//                 u32 camera id, name bytes + NUL, u64 point count, per point: f64 x, f64 y,
//                 u64 point3D id (2^64-1 = none)
//   points3D.bin  u64 count, then per point: u64 id, f64 xyz[3], u8 rgb[3], f64 error,
//                 u64 track length, per element: u32 image id, u32 point2D index
// The text files hold the same fields, one camera / point per line and two lines per image
// (the second one lists the 2D points as X Y POINT3D_ID triples, -1 = none); '#' starts a comment.
#include "scene/colmap.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <type_traits>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/error.h"
#include "scene/path_query.h"
#include "core/log.h"

namespace cls {
namespace fs = std::filesystem;

static_assert(host_is_little_endian(), "COLMAP binary I/O assumes a little-endian host");

namespace {

constexpr uint64_t kInvalidPoint3D = std::numeric_limits<uint64_t>::max();
constexpr uint64_t kMaxImageSide = 1u << 20;  // larger sides mean a corrupt file, not a camera

// Every camera model COLMAP knows, so that an unsupported one is reported by name.
struct ModelInfo {
  int id;
  const char* name;
  int num_params;
  bool supported;
};
constexpr ModelInfo kModels[] = {
    {0, "SIMPLE_PINHOLE", 3, true},
    {1, "PINHOLE", 4, true},
    {2, "SIMPLE_RADIAL", 4, true},
    {3, "RADIAL", 5, true},
    {4, "OPENCV", 8, true},
    {5, "OPENCV_FISHEYE", 8, false},
    {6, "FULL_OPENCV", 12, false},
    {7, "FOV", 5, false},
    {8, "SIMPLE_RADIAL_FISHEYE", 4, false},
    {9, "RADIAL_FISHEYE", 5, false},
    {10, "THIN_PRISM_FISHEYE", 12, false},
    {11, "RAD_TAN_THIN_PRISM_FISHEYE", 16, false},
};

const ModelInfo& model_info(CameraModel model) {
  for (const auto& m : kModels)
    if (m.id == static_cast<int>(model) && m.supported) return m;
  throw Error("internal: camera model id " + std::to_string(static_cast<int>(model)) + " has no entry");
}

std::string supported_models() {
  std::string s;
  for (const auto& m : kModels)
    if (m.supported) s += std::string(s.empty() ? "" : ", ") + m.name;
  return s;
}

[[noreturn]] void fail_unsupported(const std::string& file, const std::string& what) {
  fail(file, "camera model " + what + " is not supported (supported: " + supported_models() +
                 "; undistort the images with COLMAP's image_undistorter first)");
}

// ---- validation shared by readers and writers ----------------------------------------------

bool finite(double v) { return std::isfinite(v); }

void check_camera(const Camera& c, const std::string& file) {
  const std::string who = "camera " + std::to_string(c.id) + ": ";
  const int n = camera_model_num_params(c.model);
  if (static_cast<int>(c.params.size()) != n)
    fail(file, who + camera_model_name(c.model) + " needs " + std::to_string(n) + " parameters, got " +
                   std::to_string(c.params.size()));
  if (c.width <= 0 || c.height <= 0 || uint64_t(c.width) > kMaxImageSide || uint64_t(c.height) > kMaxImageSide)
    fail(file, who + "implausible image size " + std::to_string(c.width) + "x" + std::to_string(c.height));
  for (double p : c.params)
    if (!finite(p)) fail(file, who + "non-finite parameter");
  const bool two_focals = c.model == CameraModel::Pinhole || c.model == CameraModel::OpenCV;
  if (c.params[0] <= 0 || (two_focals && c.params[1] <= 0)) fail(file, who + "focal length must be positive");
}

void check_image(const ColmapImage& im, const std::string& file) {
  const std::string who = "image " + std::to_string(im.id) + ": ";
  double qn = 0;
  for (double q : im.qvec) {
    if (!finite(q)) fail(file, who + "non-finite rotation quaternion");
    qn += q * q;
  }
  if (qn < 1e-12) fail(file, who + "zero rotation quaternion");
  for (double t : im.tvec)
    if (!finite(t)) fail(file, who + "non-finite translation");
  if (im.name.empty()) fail(file, who + "empty image name");
  if (im.name.find_first_of(std::string("\0\n\r", 3)) != std::string::npos)
    fail(file, who + "image name contains a NUL or line break");
}

void check_point(const ColmapPoint3D& p, const std::string& file) {
  for (double v : p.xyz)
    if (!finite(v)) fail(file, "point3D " + std::to_string(p.id) + ": non-finite coordinates");
}

template <class Map, class Value>
void insert_unique(Map& map, const typename Map::key_type& id, Value&& value, const std::string& file,
                   const char* what) {
  if (!map.emplace(id, std::forward<Value>(value)).second)
    fail(file, std::string("duplicate ") + what + " id " + std::to_string(id));
}

// ---- binary ---------------------------------------------------------------------------------

// Bounds-checked little-endian reader: a truncated or lying file is an error, never a read past
// the end or an allocation larger than the file could describe.
class ByteReader {
 public:
  ByteReader(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  template <class T>
  T read() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string read_cstring() {
    const size_t end = bytes_.find('\0', pos_);
    if (end == std::string_view::npos) fail(file_, "truncated: unterminated image name at byte " + std::to_string(pos_));
    std::string s(bytes_.substr(pos_, end - pos_));
    pos_ = end + 1;
    return s;
  }
  // A record count; each record takes at least `min_bytes`, so a count the rest of the file
  // cannot hold is reported before anything is allocated.
  uint64_t read_count(size_t min_bytes, const char* what) {
    const uint64_t n = read<uint64_t>();
    if (n > remaining() / min_bytes)
      fail(file_, "truncated or corrupt: " + std::to_string(n) + " " + what + " announced at byte " +
                      std::to_string(pos_ - 8) + " but only " + std::to_string(remaining()) + " bytes follow");
    return n;
  }
  void expect_end() const {
    if (pos_ != bytes_.size())
      fail(file_, std::to_string(bytes_.size() - pos_) + " unexpected trailing bytes after the last record");
  }
  size_t remaining() const { return bytes_.size() - pos_; }

 private:
  void need(size_t n) const {
    if (remaining() < n)
      fail(file_, "truncated: needs " + std::to_string(n) + " more bytes at byte " + std::to_string(pos_) + " of " +
                      std::to_string(bytes_.size()));
  }
  std::string_view bytes_;
  const std::string& file_;
  size_t pos_ = 0;
};

class ByteWriter {
 public:
  template <class T>
  void write(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void write_cstring(const std::string& s) { out_.append(s.c_str(), s.size() + 1); }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

// ---- text -----------------------------------------------------------------------------------

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (true) {
    i = s.find_first_not_of(" \t\r", i);
    if (i == std::string_view::npos) break;
    size_t j = s.find_first_of(" \t\r", i);
    if (j == std::string_view::npos) j = s.size();
    out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

// Walks the lines of a text file, keeping the line number for error messages.
class LineReader {
 public:
  LineReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}
  // Next line, raw; false at the end.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_no_;
    return true;
  }
  // Next line that is neither empty nor a comment.
  bool next_data(std::string_view& line) {
    while (next(line)) {
      line = trim(line);
      if (!line.empty() && line[0] != '#') return true;
    }
    return false;
  }
  [[noreturn]] void fail_line(const std::string& what) const {
    fail(file_, "line " + std::to_string(line_no_) + ": " + what);
  }
  const std::string& file() const { return file_; }

 private:
  std::string_view text_;
  const std::string& file_;
  size_t pos_ = 0;
  int line_no_ = 0;
};

double parse_double(std::string_view tok, const LineReader& lr) {
  if (!tok.empty() && tok[0] == '+') tok.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (r.ec != std::errc() || r.ptr != tok.data() + tok.size()) lr.fail_line("'" + std::string(tok) + "' is not a number");
  return v;
}

uint64_t parse_uint(std::string_view tok, uint64_t max, const LineReader& lr) {
  uint64_t v = 0;
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (r.ec != std::errc() || r.ptr != tok.data() + tok.size() || v > max)
    lr.fail_line("'" + std::string(tok) + "' is not an integer in [0, " + std::to_string(max) + "]");
  return v;
}

uint32_t parse_id32(std::string_view tok, const LineReader& lr) {
  return static_cast<uint32_t>(parse_uint(tok, std::numeric_limits<uint32_t>::max(), lr));
}

// COLMAP writes "no 3D point" as -1 in text.
uint64_t parse_point3d_id(std::string_view tok, const LineReader& lr) {
  if (tok == "-1") return kInvalidPoint3D;
  return parse_uint(tok, kInvalidPoint3D - 1, lr);
}

// Shortest text that reads back to exactly the same double (std::to_chars' guarantee).
void append_double(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  out.append(buf, r.ptr);
}

// " v1 v2 ..." for a fixed-size array of doubles.
template <size_t N>
void append_doubles(std::string& out, const std::array<double, N>& values) {
  for (double v : values) {
    out += ' ';
    append_double(out, v);
  }
}

void append_point3d_id(std::string& out, uint64_t id) {
  out += id == kInvalidPoint3D ? std::string("-1") : std::to_string(id);
}

// ---- files ----------------------------------------------------------------------------------

std::string read_file(const fs::path& path) {
  if (!is_file(path)) fail(path.string(), "file not found");
  return read_text_file(path);
}

}  // namespace

// ---- camera models ------------------------------------------------------------------------

std::string camera_model_name(CameraModel model) { return model_info(model).name; }

int camera_model_num_params(CameraModel model) { return model_info(model).num_params; }

CameraModel camera_model_from_name(const std::string& name, const std::string& file) {
  for (const auto& m : kModels)
    if (name == m.name) {
      if (!m.supported) fail_unsupported(file, name);
      return static_cast<CameraModel>(m.id);
    }
  fail_unsupported(file, "'" + name + "' (unknown)");
}

CameraModel camera_model_from_id(int id, const std::string& file) {
  for (const auto& m : kModels)
    if (id == m.id) {
      if (!m.supported) fail_unsupported(file, std::string(m.name) + " (id " + std::to_string(id) + ")");
      return static_cast<CameraModel>(m.id);
    }
  fail_unsupported(file, "id " + std::to_string(id) + " (unknown)");
}

Pose ColmapImage::pose() const {
  Pose p;
  p.R = quat_to_rotation(qvec[0], qvec[1], qvec[2], qvec[3]);
  p.t = {tvec[0], tvec[1], tvec[2]};
  return p;
}

std::array<double, 4> rotation_to_qvec(const Mat3d& R) {
  // Shepperd's method: take the square root of the largest of 4w^2, 4x^2, 4y^2, 4z^2, so that the
  // division below is well conditioned.
  const auto& m = R.m;
  const double tr = m[0][0] + m[1][1] + m[2][2];
  std::array<double, 4> q;
  if (tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2]) {
    const double s = 2 * std::sqrt(1 + tr);
    q = {s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
  } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
    const double s = 2 * std::sqrt(1 + m[0][0] - m[1][1] - m[2][2]);
    q = {(m[2][1] - m[1][2]) / s, s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
  } else if (m[1][1] >= m[2][2]) {
    const double s = 2 * std::sqrt(1 - m[0][0] + m[1][1] - m[2][2]);
    q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s};
  } else {
    const double s = 2 * std::sqrt(1 - m[0][0] - m[1][1] + m[2][2]);
    q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) * (q[0] < 0 ? -1 : 1);
  for (double& c : q) c /= n;
  return q;
}

// ---- binary parsers -----------------------------------------------------------------------

std::map<uint32_t, Camera> parse_cameras_binary(std::string_view bytes, const std::string& file) {
  ByteReader in(bytes, file);
  std::map<uint32_t, Camera> cameras;
  const uint64_t n = in.read_count(4 + 4 + 8 + 8 + 3 * 8, "cameras");
  for (uint64_t i = 0; i < n; ++i) {
    Camera c;
    c.id = in.read<uint32_t>();
    c.model = camera_model_from_id(in.read<int32_t>(), file);
    const uint64_t w = in.read<uint64_t>(), h = in.read<uint64_t>();
    if (w == 0 || h == 0 || w > kMaxImageSide || h > kMaxImageSide)
      fail(file, "camera " + std::to_string(c.id) + ": implausible image size " + std::to_string(w) + "x" +
                     std::to_string(h));
    c.width = static_cast<int>(w);
    c.height = static_cast<int>(h);
    c.params.resize(camera_model_num_params(c.model));
    for (double& p : c.params) p = in.read<double>();
    check_camera(c, file);
    insert_unique(cameras, c.id, std::move(c), file, "camera");
  }
  in.expect_end();
  return cameras;
}

std::map<uint32_t, ColmapImage> parse_images_binary(std::string_view bytes, const std::string& file) {
  ByteReader in(bytes, file);
  std::map<uint32_t, ColmapImage> images;
  const uint64_t n = in.read_count(4 + 7 * 8 + 4 + 2 + 8, "images");
  for (uint64_t i = 0; i < n; ++i) {
    ColmapImage im;
    im.id = in.read<uint32_t>();
    for (double& q : im.qvec) q = in.read<double>();
    for (double& t : im.tvec) t = in.read<double>();
    im.camera_id = in.read<uint32_t>();
    im.name = in.read_cstring();
    const uint64_t np = in.read_count(3 * 8, "2D points");
    im.points2d.resize(np);
    for (auto& p : im.points2d) {
      p.x = in.read<double>();
      p.y = in.read<double>();
      p.point3d_id = in.read<uint64_t>();
    }
    check_image(im, file);
    insert_unique(images, im.id, std::move(im), file, "image");
  }
  in.expect_end();
  return images;
}

std::map<uint64_t, ColmapPoint3D> parse_points3d_binary(std::string_view bytes, const std::string& file) {
  ByteReader in(bytes, file);
  std::map<uint64_t, ColmapPoint3D> points;
  const uint64_t n = in.read_count(8 + 3 * 8 + 3 + 8 + 8, "3D points");
  for (uint64_t i = 0; i < n; ++i) {
    ColmapPoint3D p;
    p.id = in.read<uint64_t>();
    for (double& v : p.xyz) v = in.read<double>();
    for (uint8_t& c : p.rgb) c = in.read<uint8_t>();
    p.error = in.read<double>();
    const uint64_t nt = in.read_count(2 * 4, "track elements");
    p.track.resize(nt);
    for (auto& [image_id, point2d_idx] : p.track) {
      image_id = in.read<uint32_t>();
      point2d_idx = in.read<uint32_t>();
    }
    check_point(p, file);
    insert_unique(points, p.id, std::move(p), file, "point3D");
  }
  in.expect_end();
  return points;
}

// ---- text parsers -------------------------------------------------------------------------

std::map<uint32_t, Camera> parse_cameras_text(std::string_view text, const std::string& file) {
  LineReader lr(text, file);
  std::map<uint32_t, Camera> cameras;
  std::string_view line;
  while (lr.next_data(line)) {
    const auto tok = split(line);
    if (tok.size() < 4) lr.fail_line("expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS...");
    Camera c;
    c.id = parse_id32(tok[0], lr);
    c.model = camera_model_from_name(std::string(tok[1]), file);
    c.width = static_cast<int>(parse_uint(tok[2], kMaxImageSide, lr));
    c.height = static_cast<int>(parse_uint(tok[3], kMaxImageSide, lr));
    for (size_t i = 4; i < tok.size(); ++i) c.params.push_back(parse_double(tok[i], lr));
    check_camera(c, file);
    insert_unique(cameras, c.id, std::move(c), file, "camera");
  }
  return cameras;
}

std::map<uint32_t, ColmapImage> parse_images_text(std::string_view text, const std::string& file) {
  LineReader lr(text, file);
  std::map<uint32_t, ColmapImage> images;
  std::string_view line;
  while (lr.next_data(line)) {
    // The name is the rest of the line after nine fields, so names with spaces survive.
    std::string_view rest = line;
    std::vector<std::string_view> tok;
    for (int i = 0; i < 9; ++i) {
      rest = trim(rest);
      const size_t end = rest.find_first_of(" \t");
      if (end == std::string_view::npos) lr.fail_line("expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME");
      tok.push_back(rest.substr(0, end));
      rest = rest.substr(end);
    }
    ColmapImage im;
    im.id = parse_id32(tok[0], lr);
    for (int i = 0; i < 4; ++i) im.qvec[i] = parse_double(tok[1 + i], lr);
    for (int i = 0; i < 3; ++i) im.tvec[i] = parse_double(tok[5 + i], lr);
    im.camera_id = parse_id32(tok[8], lr);
    im.name = std::string(trim(rest));
    // The next line lists the 2D points; it is empty (or missing at the end) when there are none.
    std::string_view points_line;
    if (lr.next(points_line)) {
      const auto pt = split(points_line);
      if (pt.size() % 3 != 0) lr.fail_line("expected X Y POINT3D_ID triples");
      im.points2d.resize(pt.size() / 3);
      for (size_t i = 0; i < im.points2d.size(); ++i) {
        im.points2d[i].x = parse_double(pt[3 * i], lr);
        im.points2d[i].y = parse_double(pt[3 * i + 1], lr);
        im.points2d[i].point3d_id = parse_point3d_id(pt[3 * i + 2], lr);
      }
    }
    check_image(im, file);
    insert_unique(images, im.id, std::move(im), file, "image");
  }
  return images;
}

std::map<uint64_t, ColmapPoint3D> parse_points3d_text(std::string_view text, const std::string& file) {
  LineReader lr(text, file);
  std::map<uint64_t, ColmapPoint3D> points;
  std::string_view line;
  while (lr.next_data(line)) {
    const auto tok = split(line);
    if (tok.size() < 8 || (tok.size() - 8) % 2 != 0)
      lr.fail_line("expected POINT3D_ID X Y Z R G B ERROR (IMAGE_ID POINT2D_IDX)...");
    ColmapPoint3D p;
    p.id = parse_uint(tok[0], kInvalidPoint3D - 1, lr);
    for (int i = 0; i < 3; ++i) p.xyz[i] = parse_double(tok[1 + i], lr);
    for (int i = 0; i < 3; ++i) p.rgb[i] = static_cast<uint8_t>(parse_uint(tok[4 + i], 255, lr));
    p.error = parse_double(tok[7], lr);
    for (size_t i = 8; i < tok.size(); i += 2)
      p.track.emplace_back(parse_id32(tok[i], lr), parse_id32(tok[i + 1], lr));
    check_point(p, file);
    insert_unique(points, p.id, std::move(p), file, "point3D");
  }
  return points;
}

// ---- encoders -------------------------------------------------------------------------------

std::string encode_cameras_binary(const std::map<uint32_t, Camera>& cameras) {
  ByteWriter out;
  out.write<uint64_t>(cameras.size());
  for (const auto& [id, c] : cameras) {
    out.write<uint32_t>(id);
    out.write<int32_t>(static_cast<int32_t>(c.model));
    out.write<uint64_t>(static_cast<uint64_t>(c.width));
    out.write<uint64_t>(static_cast<uint64_t>(c.height));
    for (double p : c.params) out.write<double>(p);
  }
  return out.take();
}

std::string encode_images_binary(const std::map<uint32_t, ColmapImage>& images) {
  ByteWriter out;
  out.write<uint64_t>(images.size());
  for (const auto& [id, im] : images) {
    out.write<uint32_t>(id);
    for (double q : im.qvec) out.write<double>(q);
    for (double t : im.tvec) out.write<double>(t);
    out.write<uint32_t>(im.camera_id);
    out.write_cstring(im.name);
    out.write<uint64_t>(im.points2d.size());
    for (const auto& p : im.points2d) {
      out.write<double>(p.x);
      out.write<double>(p.y);
      out.write<uint64_t>(p.point3d_id);
    }
  }
  return out.take();
}

std::string encode_points3d_binary(const std::map<uint64_t, ColmapPoint3D>& points) {
  ByteWriter out;
  out.write<uint64_t>(points.size());
  for (const auto& [id, p] : points) {
    out.write<uint64_t>(id);
    for (double v : p.xyz) out.write<double>(v);
    for (uint8_t c : p.rgb) out.write<uint8_t>(c);
    out.write<double>(p.error);
    out.write<uint64_t>(p.track.size());
    for (const auto& [image_id, point2d_idx] : p.track) {
      out.write<uint32_t>(image_id);
      out.write<uint32_t>(point2d_idx);
    }
  }
  return out.take();
}

std::string encode_cameras_text(const std::map<uint32_t, Camera>& cameras) {
  std::string out =
      "# Camera list with one line of data per camera:\n"
      "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
      "# Number of cameras: " + std::to_string(cameras.size()) + "\n";
  for (const auto& [id, c] : cameras) {
    out += std::to_string(id) + " " + camera_model_name(c.model) + " " + std::to_string(c.width) + " " +
           std::to_string(c.height);
    for (double p : c.params) {
      out += ' ';
      append_double(out, p);
    }
    out += '\n';
  }
  return out;
}

std::string encode_images_text(const std::map<uint32_t, ColmapImage>& images) {
  size_t observations = 0;
  for (const auto& [id, im] : images) observations += im.points2d.size();
  std::string out =
      "# Image list with two lines of data per image:\n"
      "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
      "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
      "# Number of images: " + std::to_string(images.size()) + ", mean observations per image: " +
      cat(images.empty() ? 0.0 : double(observations) / double(images.size())) + "\n";
  for (const auto& [id, im] : images) {
    out += std::to_string(id);
    append_doubles(out, im.qvec);
    append_doubles(out, im.tvec);
    out += " " + std::to_string(im.camera_id) + " " + im.name + "\n";
    for (size_t i = 0; i < im.points2d.size(); ++i) {
      const auto& p = im.points2d[i];
      if (i) out += ' ';
      append_double(out, p.x);
      out += ' ';
      append_double(out, p.y);
      out += ' ';
      append_point3d_id(out, p.point3d_id);
    }
    out += '\n';
  }
  return out;
}

std::string encode_points3d_text(const std::map<uint64_t, ColmapPoint3D>& points) {
  size_t track_elements = 0;
  for (const auto& [id, p] : points) track_elements += p.track.size();
  std::string out =
      "# 3D point list with one line of data per point:\n"
      "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
      "# Number of points: " + std::to_string(points.size()) + ", mean track length: " +
      cat(points.empty() ? 0.0 : double(track_elements) / double(points.size())) + "\n";
  for (const auto& [id, p] : points) {
    out += std::to_string(id);
    append_doubles(out, p.xyz);
    for (uint8_t c : p.rgb) out += " " + std::to_string(c);
    out += ' ';
    append_double(out, p.error);
    for (const auto& [image_id, point2d_idx] : p.track)
      out += " " + std::to_string(image_id) + " " + std::to_string(point2d_idx);
    out += '\n';
  }
  return out;
}

// ---- whole models -------------------------------------------------------------------------

void validate_colmap(const ColmapModel& model, const std::string& dir) {
  for (const auto& [id, im] : model.images)
    if (!model.cameras.count(im.camera_id))
      fail((fs::path(dir) / "images").string(), "image " + std::to_string(id) + " (" + im.name +
                                                    ") refers to camera " + std::to_string(im.camera_id) +
                                                    ", which cameras does not define");
  // Tracks are not cross-checked against images: hand-pruned models often keep points of removed
  // images, and nothing downstream follows tracks.
}

ColmapModel read_colmap_binary(const std::string& dir) {
  const fs::path d(dir);
  ColmapModel m;
  const fs::path cams = d / "cameras.bin", ims = d / "images.bin", pts = d / "points3D.bin";
  m.cameras = parse_cameras_binary(read_file(cams), cams.string());
  m.images = parse_images_binary(read_file(ims), ims.string());
  m.points = parse_points3d_binary(read_file(pts), pts.string());
  validate_colmap(m, dir);
  return m;
}

ColmapModel read_colmap_text(const std::string& dir) {
  const fs::path d(dir);
  ColmapModel m;
  const fs::path cams = d / "cameras.txt", ims = d / "images.txt", pts = d / "points3D.txt";
  m.cameras = parse_cameras_text(read_file(cams), cams.string());
  m.images = parse_images_text(read_file(ims), ims.string());
  m.points = parse_points3d_text(read_file(pts), pts.string());
  validate_colmap(m, dir);
  return m;
}

std::string find_colmap_model(const std::string& scene_dir) {
  const fs::path root(scene_dir);
  for (const fs::path& d : {root / "sparse" / "0", root / "sparse", root})
    if (is_file(d / "cameras.bin") || is_file(d / "cameras.txt")) return d.string();
  return "";
}

ColmapModel read_colmap(const std::string& dir) {
  if (is_file(fs::path(dir) / "cameras.bin")) return read_colmap_binary(dir);
  if (is_file(fs::path(dir) / "cameras.txt")) return read_colmap_text(dir);
  fail(dir, "no COLMAP model here (neither cameras.bin nor cameras.txt)");
}

namespace {

// Everything a writer needs to hold, checked before any file is touched.
void validate_for_writing(const ColmapModel& model, const std::string& dir) {
  for (const auto& [id, c] : model.cameras) {
    if (c.id != id) fail(dir, "camera stored under id " + std::to_string(id) + " has id " + std::to_string(c.id));
    check_camera(c, dir);
  }
  for (const auto& [id, im] : model.images) {
    if (im.id != id) fail(dir, "image stored under id " + std::to_string(id) + " has id " + std::to_string(im.id));
    check_image(im, dir);
  }
  for (const auto& [id, p] : model.points) {
    if (p.id != id) fail(dir, "point stored under id " + std::to_string(id) + " has id " + std::to_string(p.id));
    if (id == kInvalidPoint3D) fail(dir, "point3D id 2^64-1 is reserved for 'no point'");
    check_point(p, dir);
  }
  validate_colmap(model, dir);
}

void write_model(const std::string& dir, const ColmapModel& model, const char* ext, bool binary) {
  validate_for_writing(model, dir);
  const std::string files[3][2] = {
      {"cameras", binary ? encode_cameras_binary(model.cameras) : encode_cameras_text(model.cameras)},
      {"images", binary ? encode_images_binary(model.images) : encode_images_text(model.images)},
      {"points3D", binary ? encode_points3d_binary(model.points) : encode_points3d_text(model.points)}};
  for (const auto& [name, content] : files) write_text_atomic(fs::path(dir) / (name + ext), content);
}

}  // namespace

void write_colmap_binary(const std::string& dir, const ColmapModel& model) { write_model(dir, model, ".bin", true); }

void write_colmap_text(const std::string& dir, const ColmapModel& model) { write_model(dir, model, ".txt", false); }

}  // namespace cls
