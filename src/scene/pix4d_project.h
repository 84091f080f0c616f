#pragma once
// What a PIX4Dmapper project holds beside its calibration (pix4d.h), as its outputs lay it out:
//   PROJECT/1_initial/params/PROJECT_calibrated_camera_parameters.txt   cameras, in the offset frame
//   PROJECT/1_initial/params/PROJECT_offset.xyz    "x y z": the offset frame = output CRS - offset
//   PROJECT/1_initial/params/PROJECT_wkt.prj       the output CRS (WKT)
//   PROJECT/2_densification/point_cloud/*.las|.ply  the densified cloud, in the output CRS (LAS; large
//                                                   clouds in parts) or offset by *_ply_offset.xyz (PLY)
// so that a scene starts from the project's points and knows where it lies without a hand-made
// transform.
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/point_cloud.h"

namespace cls {

struct Pix4dProject {
  std::string calibration;          // the calibrated_camera_parameters file
  std::string offset_file;          // "" when there is none (then the offset is 0)
  Vec3d offset{};
  std::string crs_file;             // "" when there is none
  std::string crs;                  // the output CRS as written (WKT)
  std::vector<std::string> clouds;  // the densified cloud's files: the LAS parts, else PLY; may be empty
};

// The project around the calibration `find_pix4d_calibration(dir)` finds ("" calibration: none).
// A malformed offset file is a cls::Error naming it.
Pix4dProject find_pix4d_project(const std::string& dir);

// "x y z" of an offset file (three finite numbers).
Vec3d read_pix4d_offset(const std::string& path);

// The project's densified cloud in the calibration's frame (LAS minus the offset; PLY plus its
// *_ply_offset.xyz, minus the offset), at most `max_points` (0: all).
PointCloud read_pix4d_cloud(const Pix4dProject& project, uint64_t max_points);

}  // namespace cls
