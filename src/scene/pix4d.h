#pragma once
// Pix4D's calibrated_camera_parameters.txt (PIX4Dmapper, 1_initial/params/): per image
//   NAME WIDTH HEIGHT
//   K (3 lines of 3)                       camera matrix, pixels
//   R1 R2 R3                               radial distortion
//   T1 T2                                  tangential distortion
//   C (3)                                  camera position in the (offset) world frame
//   R (3 lines of 3)                       world -> camera rotation
// with m = K [R | -R C] X, after a header that describes these fields.
//
// Conventions, converted here to ours (camera.h):
// - K and R are in the computer-vision frame (camera looks down +z, x right, y down; the example
//   in Pix4D's and SURE's documentation has the third row of R pointing down for a nadir view),
//   so the pose is R, t = -R C directly.
// - Pixel coordinates have their origin at the top-left corner of the image, like ours and
//   COLMAP's, so the principal point is taken as is. Source: Pix4D's Open Photogrammetry Format,
//   which carries the same internals ("principal point with respect to the top left corner in
//   pixels", pyopf PerspectiveInternals), and Pix4D's own OPF -> COLMAP converter (pyopf
//   opf_tools/opf2colmap) copies the principal point unchanged.
// - Distortion is the OpenCV / Brown polynomial on normalized coordinates with (R1, R2, R3) =
//   (k1, k2, k3) and (T1, T2) = (p1, p2): opf2colmap maps them so onto COLMAP's FULL_OPENCV, and
//   EasyIDP's Pix4D reader applies T1 as 2 T1 x y in x and T1 (r^2 + 2 y^2) in y on these
//   pixel coordinates. (Pix4D's knowledge-base article 202559089 writes the same formula in its
//   own photogrammetric frame.) Not yet checked against a real export with non-zero T1, T2.
// The distorted camera becomes an OPENCV Camera plus the extra k3 (SceneView::source_radial_k3),
// or PINHOLE when all coefficients are zero.
#include <string>
#include <string_view>
#include <vector>

#include "scene/camera.h"
#include "scene/colmap.h"

namespace cls {

struct Pix4dView {
  std::string name;
  Camera camera;          // PINHOLE or OPENCV at full resolution, id = 1-based view index
  double radial_k3 = 0;   // R3
  Pose pose;              // world -> camera
};

// Parses the file's text; `file` names it in error messages.
std::vector<Pix4dView> parse_pix4d_calibrated_cameras(std::string_view text, const std::string& file);
std::vector<Pix4dView> read_pix4d_calibrated_cameras(const std::string& path);

// A COLMAP model of the calibration: one camera per view (ids as in Pix4dView), no points. A
// view with R3 != 0 is a cls::Error naming `file`: COLMAP's OPENCV model has no k3.
ColmapModel pix4d_to_colmap(const std::vector<Pix4dView>& views, const std::string& file);

// The calibrated_camera_parameters file of a Pix4D project under `dir` (in DIR, DIR/params or
// DIR/1_initial/params; the name may carry the project prefix), or "" if there is none. More
// than one candidate is a cls::Error.
std::string find_pix4d_calibration(const std::string& dir);

}  // namespace cls
