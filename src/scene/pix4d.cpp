#include "scene/pix4d.h"

#include <charconv>
#include <cmath>
#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/path_query.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while ((i = s.find_first_not_of(" \t\r", i)) != std::string_view::npos) {
    size_t j = s.find_first_of(" \t\r", i);
    if (j == std::string_view::npos) j = s.size();
    out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

bool to_double(std::string_view tok, double& v) {
  if (!tok.empty() && tok[0] == '+') tok.remove_prefix(1);
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  return r.ec == std::errc() && r.ptr == tok.data() + tok.size();
}

bool to_size(std::string_view tok, int& v) {
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  return r.ec == std::errc() && r.ptr == tok.data() + tok.size() && v > 0 && v <= (1 << 20);
}

// Lines as token lists, blank lines dropped, with their 1-based line numbers.
struct Line {
  int number;
  std::vector<std::string_view> tokens;
};

std::vector<Line> tokenized_lines(std::string_view text) {
  std::vector<Line> lines;
  int number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    ++number;
    auto tokens = split(text.substr(pos, end - pos));
    if (!tokens.empty()) lines.push_back({number, std::move(tokens)});
    pos = end + 1;
  }
  return lines;
}

// "NAME WIDTH HEIGHT": the last two tokens are image sizes; the name may contain spaces.
bool is_view_header(const Line& line, std::string& name, int& width, int& height) {
  const auto& t = line.tokens;
  if (t.size() < 3 || !to_size(t[t.size() - 2], width) || !to_size(t.back(), height)) return false;
  const char* begin = t.front().data();
  const char* end = t[t.size() - 3].data() + t[t.size() - 3].size();
  name.assign(begin, end);
  return true;
}

}  // namespace

std::vector<Pix4dView> parse_pix4d_calibrated_cameras(std::string_view text, const std::string& file) {
  const std::vector<Line> lines = tokenized_lines(text);
  std::vector<Pix4dView> views;
  size_t i = 0;
  // The header lines describe the fields; the first "NAME W H" line starts the data.
  std::string name;
  int width = 0, height = 0;
  while (i < lines.size() && !is_view_header(lines[i], name, width, height)) ++i;
  constexpr int kBlockShape[] = {3, 3, 3, 3, 2, 3, 3, 3, 3};  // K rows, radial, tangential, C, R rows
  while (i < lines.size()) {
    const Line& head = lines[i];
    if (!is_view_header(head, name, width, height))
      fail(file, "line " + std::to_string(head.number) + ": expected 'IMAGE_NAME WIDTH HEIGHT'");
    double v[28];
    int n = 0;
    for (int row = 0; row < 9; ++row) {
      if (++i >= lines.size()) fail(file, "truncated: camera '" + name + "' ends early");
      const Line& l = lines[i];
      if (static_cast<int>(l.tokens.size()) != kBlockShape[row])
        fail(file, "line " + std::to_string(l.number) + ": expected " + std::to_string(kBlockShape[row]) +
                       " numbers for camera '" + name + "'");
      for (const auto& tok : l.tokens)
        if (!to_double(tok, v[n++]) || !std::isfinite(v[n - 1]))
          fail(file, "line " + std::to_string(l.number) + ": '" + std::string(tok) + "' is not a finite number");
    }
    ++i;
    const double* K = v;
    const double *radial = v + 9, *tangential = v + 12, *C = v + 14, *R = v + 17;
    const std::string who = "camera '" + name + "': ";
    if (!(K[0] > 0) || !(K[4] > 0)) fail(file, who + "focal length must be positive");
    if (K[1] != 0 || K[3] != 0 || K[6] != 0 || K[7] != 0 || K[8] != 1)
      fail(file, who + "K must be [fx 0 cx; 0 fy cy; 0 0 1] (skew is not supported)");

    Pix4dView view;
    view.name = name;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) view.pose.R.m[r][c] = R[3 * r + c];
    const Mat3d RRt = view.pose.R * transpose(view.pose.R);
    double off = 0;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) off = std::max(off, std::abs(RRt.m[r][c] - (r == c ? 1.0 : 0.0)));
    const double det = dot(view.pose.R.row(0), cross(view.pose.R.row(1), view.pose.R.row(2)));
    if (off > 1e-5 || det < 0) fail(file, who + "R is not a rotation matrix");
    view.pose.t = -(view.pose.R * Vec3d{C[0], C[1], C[2]});

    view.camera.id = static_cast<uint32_t>(views.size() + 1);
    view.camera.width = width;
    view.camera.height = height;
    const bool distorted = radial[0] != 0 || radial[1] != 0 || radial[2] != 0 || tangential[0] != 0 || tangential[1] != 0;
    if (distorted) {
      view.camera.model = CameraModel::OpenCV;
      view.camera.params = {K[0], K[4], K[2], K[5], radial[0], radial[1], tangential[0], tangential[1]};
      view.radial_k3 = radial[2];
    } else {
      view.camera.model = CameraModel::Pinhole;
      view.camera.params = {K[0], K[4], K[2], K[5]};
    }
    views.push_back(std::move(view));
  }
  if (views.empty()) fail(file, "no calibrated cameras found");
  return views;
}

std::vector<Pix4dView> read_pix4d_calibrated_cameras(const std::string& path) {
  if (!is_file(path)) fail(path, "file not found");
  return parse_pix4d_calibrated_cameras(read_text_file(path), path);
}

ColmapModel pix4d_to_colmap(const std::vector<Pix4dView>& views, const std::string& file) {
  ColmapModel model;
  for (const Pix4dView& v : views) {
    if (v.radial_k3 != 0)
      fail(file, "camera '" + v.name + "' has a third radial coefficient (R3 = " + std::to_string(v.radial_k3) +
                     "), which COLMAP's OPENCV model cannot hold");
    model.cameras[v.camera.id] = v.camera;
    ColmapImage im;
    im.id = v.camera.id;
    im.camera_id = v.camera.id;
    im.name = v.name;
    im.qvec = rotation_to_qvec(v.pose.R);
    im.tvec = {v.pose.t.x, v.pose.t.y, v.pose.t.z};
    model.images[im.id] = im;
  }
  return model;
}

std::string find_pix4d_calibration(const std::string& dir) {
  const std::string suffix = "calibrated_camera_parameters.txt";
  std::vector<std::string> found;
  for (const fs::path& sub : {fs::path(dir), fs::path(dir) / "params", fs::path(dir) / "1_initial" / "params"}) {
    std::error_code ec;
    if (!fs::is_directory(sub, ec)) continue;
    for (const auto& entry : fs::directory_iterator(sub, ec)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file(ec) && name.size() >= suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        found.push_back(entry.path().string());
    }
  }
  if (found.size() > 1) {
    std::string list;
    for (const auto& f : found) list += "\n  " + f;
    fail(dir, "more than one Pix4D calibration file; keep one:" + list);
  }
  return found.empty() ? std::string() : found.front();
}

}  // namespace cls
