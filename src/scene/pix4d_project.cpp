#include "scene/pix4d_project.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/strings.h"
#include "scene/path_query.h"
#include "scene/pix4d.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Files of `dir` whose name passes `keep`, sorted (the parts of a cloud in order).
template <class Keep>
std::vector<std::string> files_in(const fs::path& dir, Keep keep) {
  std::vector<std::string> found;
  std::error_code ec;
  if (!is_dir(dir)) return found;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && keep(entry.path().filename().string())) found.push_back(entry.path().string());
  std::sort(found.begin(), found.end());
  return found;
}

std::string one_of(const std::vector<std::string>& found, const fs::path& dir, const std::string& what) {
  if (found.size() > 1) fail(dir.string(), "more than one Pix4D " + what + " file; keep one");
  return found.empty() ? std::string() : found.front();
}

}  // namespace

Vec3d read_pix4d_offset(const std::string& path) {
  std::istringstream in(read_text_file(path));
  Vec3d v;
  std::string rest;
  if (!(in >> v.x >> v.y >> v.z) || (in >> rest) || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    fail(path, "a Pix4D offset file holds three finite numbers \"x y z\"");
  return v;
}

Pix4dProject find_pix4d_project(const std::string& dir) {
  Pix4dProject p;
  p.calibration = find_pix4d_calibration(dir);
  if (p.calibration.empty()) return p;
  const fs::path params = fs::path(p.calibration).parent_path();
  p.offset_file = one_of(files_in(params, [](const std::string& n) {
                           return (n == "offset.xyz" || ends_with(n, "_offset.xyz")) && !ends_with(n, "_ply_offset.xyz");
                         }),
                         params, "offset (*_offset.xyz)");
  if (!p.offset_file.empty()) p.offset = read_pix4d_offset(p.offset_file);
  p.crs_file = one_of(files_in(params, [](const std::string& n) { return n == "wkt.prj" || ends_with(n, "_wkt.prj"); }),
                      params, "output CRS (*_wkt.prj)");
  if (!p.crs_file.empty()) {
    p.crs = read_text_file(p.crs_file);
    p.crs.erase(p.crs.find_last_not_of(" \r\n\t") + 1);
  }
  // The project folder: above 1_initial/params, or the scene folder itself.
  const fs::path root = params.filename() == "params" && params.parent_path().filename() == "1_initial"
                            ? params.parent_path().parent_path()
                            : fs::path(dir);
  for (const fs::path& folder : {root / "2_densification" / "point_cloud", fs::path(dir)}) {
    for (const bool las : {true, false}) {  // LAS (or LAZ, which the reader refuses with advice) before PLY
      if (p.clouds.empty())
        p.clouds = files_in(folder, [las](const std::string& n) {
          const std::string l = ascii_lower(n);
          return las ? ends_with(l, ".las") || ends_with(l, ".laz") : ends_with(l, ".ply");
        });
    }
    if (!p.clouds.empty()) break;
  }
  return p;
}

PointCloud read_pix4d_cloud(const Pix4dProject& project, uint64_t max_points) {
  PointCloud all;
  for (const std::string& file : project.clouds) {
    PointCloud part = read_point_cloud(file, max_points);
    Vec3d shift = -project.offset;
    if (ascii_lower(fs::path(file).extension().string()) == ".ply") {
      // Pix4D writes PLY (float) offset by a sidecar: NAME_ply_offset.xyz beside NAME.ply.
      const fs::path sidecar = fs::path(file).replace_extension().string() + "_ply_offset.xyz";
      if (is_file(sidecar)) shift = shift + read_pix4d_offset(sidecar.string());
    }
    for (Vec3d& x : part.xyz) x = x + shift;
    all.total += part.total;
    all.xyz.insert(all.xyz.end(), part.xyz.begin(), part.xyz.end());
    all.rgb.insert(all.rgb.end(), part.rgb.begin(), part.rgb.end());
  }
  // Parts were thinned one by one: thin their union to the budget.
  if (max_points > 0 && all.xyz.size() > max_points) {
    const size_t stride = (all.xyz.size() + max_points - 1) / max_points;
    size_t kept = 0;
    for (size_t i = 0; i < all.xyz.size(); i += stride, ++kept) {
      all.xyz[kept] = all.xyz[i];
      all.rgb[kept] = all.rgb[i];
    }
    all.xyz.resize(kept);
    all.rgb.resize(kept);
  }
  return all;
}

}  // namespace cls
