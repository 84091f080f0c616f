#pragma once
// Pix4D's Open Photogrammetry Format (OPF 1.0; Pix4Dmatic and PIX4Dcatch export it; the specification and
// its examples: github.com/Pix4D/opf-spec, CC BY 4.0): a project file (*.opf, JSON) whose items name the
// resources, of which a scene needs
//   camera_list          camera id -> image URI (relative to the camera list's folder)
//   input_cameras        sensors with their image size
//   calibration          calibrated cameras (application/opf-calibrated-cameras+json) and the sparse tie
//                        points (model/gltf+json: an OPF-glTF point cloud with its .bin buffers)
//   scene_reference_frame  the CRS and base_to_canonical (scale, shift, swap_xy) of the processing CRS
// Hand-written on nlohmann-json: no Debian package reads OPF, and the subset a scene needs is small.
//
// Conventions, converted here to ours (camera.h):
// - orientation_deg (omega, phi, kappa) is R = Rx(omega) Ry(phi) Rz(kappa) from the image CS (x right,
//   y up, z from the scene towards the camera) to the processing CRS; our world -> camera rotation is
//   diag(1, -1, -1) R^T, and t = -R_cv C for the position C.
// - Perspective internals (focal_length_px, principal_point_px from the top left corner of the top left
//   pixel, radial R1 R2 R3, tangential T1 T2) are PIX4Dmapper's (pix4d.h): OPENCV plus k3. Fisheye and
//   spherical sensors are refused with the sensor named.
// - Tie points: the glTF nodes' POSITION accessors (float32 VEC3) mapped by each node's matrix
//   (column-major) into the processing CRS; COLOR_0 when present (unsigned byte, normalised).
#include <array>
#include <string>
#include <vector>

#include "scene/pix4d.h"

namespace cls {

struct OpfPoint {
  std::array<double, 3> xyz{};
  std::array<uint8_t, 3> rgb{128, 128, 128};
};

struct OpfReferenceFrame {
  std::string crs;                          // crs.definition as written (EPSG:N, WKT, ...), "" when none
  std::array<double, 3> scale{1, 1, 1};     // base_to_canonical: canonical = scale * base (swapped) + shift
  std::array<double, 3> shift{0, 0, 0};
  bool swap_xy = false;
};

struct OpfProject {
  // name: the image's path relative to the project's folder (its file name when it lies outside)
  std::vector<Pix4dView> views;
  std::vector<std::string> images;    // absolute image path of each view
  std::vector<OpfPoint> points;       // in the processing CRS
  OpfReferenceFrame frame;
};

// cls::Error naming the file (the project or the resource) and what is wrong: a missing item or
// resource, malformed JSON, a camera whose sensor or image is unknown, a sensor model we cannot take,
// a buffer shorter than its accessor needs, non-finite values.
OpfProject read_opf_project(const std::string& path);

// The *.opf project file in `dir`, or "" if there is none; more than one is a cls::Error.
std::string find_opf_project(const std::string& dir);

}  // namespace cls
