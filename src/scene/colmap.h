#pragma once
// COLMAP sparse models: readers and writers for the binary and text formats
// (cameras.{bin,txt}, images.{bin,txt}, points3D.{bin,txt}), byte-compatible with COLMAP.
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/camera.h"

namespace cls {

struct ColmapPoint2D {
  double x = 0, y = 0;
  uint64_t point3d_id = std::numeric_limits<uint64_t>::max();  // COLMAP's invalid id: -1 as uint64
};

struct ColmapImage {
  uint32_t id = 0;
  std::array<double, 4> qvec{1, 0, 0, 0};  // world-to-camera rotation (w, x, y, z)
  std::array<double, 3> tvec{0, 0, 0};
  uint32_t camera_id = 0;
  std::string name;
  std::vector<ColmapPoint2D> points2d;
  Pose pose() const;
};

// The qvec (w, x, y, z; w >= 0) of a rotation matrix, the inverse of quat_to_rotation.
std::array<double, 4> rotation_to_qvec(const Mat3d& R);

struct ColmapPoint3D {
  uint64_t id = 0;
  std::array<double, 3> xyz{};
  std::array<uint8_t, 3> rgb{};
  double error = 0;
  std::vector<std::pair<uint32_t, uint32_t>> track;  // (image id, point2D index)
};

struct ColmapModel {
  std::map<uint32_t, Camera> cameras;
  std::map<uint32_t, ColmapImage> images;
  std::map<uint64_t, ColmapPoint3D> points;
};

// Name of a camera model as COLMAP writes it ("PINHOLE", ...) and back. Unknown names/ids are a
// cls::Error that names the model and lists the supported ones.
std::string camera_model_name(CameraModel model);
CameraModel camera_model_from_name(const std::string& name, const std::string& file);
CameraModel camera_model_from_id(int id, const std::string& file);
int camera_model_num_params(CameraModel model);

// The COLMAP model folder of a scene directory: DIR/sparse/0, DIR/sparse or DIR itself, the
// first that holds cameras.bin or cameras.txt; "" if none does.
std::string find_colmap_model(const std::string& scene_dir);

// `dir` holds the three files. read_colmap picks binary if cameras.bin exists, else text.
ColmapModel read_colmap(const std::string& dir);
ColmapModel read_colmap_binary(const std::string& dir);
ColmapModel read_colmap_text(const std::string& dir);
// Writers validate the whole model first (nothing is written for an invalid model), then write
// each file atomically.
void write_colmap_binary(const std::string& dir, const ColmapModel& model);
void write_colmap_text(const std::string& dir, const ColmapModel& model);

// Buffer-level parsers and encoders behind the file functions (also the fuzzers' entry points).
// `file` only names the source in error messages. Every malformed input is a cls::Error.
std::map<uint32_t, Camera> parse_cameras_binary(std::string_view bytes, const std::string& file);
std::map<uint32_t, ColmapImage> parse_images_binary(std::string_view bytes, const std::string& file);
std::map<uint64_t, ColmapPoint3D> parse_points3d_binary(std::string_view bytes, const std::string& file);
std::map<uint32_t, Camera> parse_cameras_text(std::string_view text, const std::string& file);
std::map<uint32_t, ColmapImage> parse_images_text(std::string_view text, const std::string& file);
std::map<uint64_t, ColmapPoint3D> parse_points3d_text(std::string_view text, const std::string& file);

std::string encode_cameras_binary(const std::map<uint32_t, Camera>& cameras);
std::string encode_images_binary(const std::map<uint32_t, ColmapImage>& images);
std::string encode_points3d_binary(const std::map<uint64_t, ColmapPoint3D>& points);
std::string encode_cameras_text(const std::map<uint32_t, Camera>& cameras);
std::string encode_images_text(const std::map<uint32_t, ColmapImage>& images);
std::string encode_points3d_text(const std::map<uint64_t, ColmapPoint3D>& points);

// Checks what a parsed model must satisfy as a whole: every image's camera exists. `dir` names
// the model in error messages.
void validate_colmap(const ColmapModel& model, const std::string& dir);

}  // namespace cls
