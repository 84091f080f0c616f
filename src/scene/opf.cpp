#include "scene/opf.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;

static_assert(host_is_little_endian(), "glTF buffers are little-endian; a big-endian host would need swapping");

json read_json(const fs::path& path) {
  const std::string text = read_text_file(path);
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    fail(path.string(), std::string("not valid JSON: ") + e.what());
  }
}

// j[key] as T; cls::Error naming the file and where in it for a missing key or another type.
template <class T>
T get(const json& j, const char* key, const fs::path& file, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) fail(file.string(), where + ": no \"" + key + "\"");
  try {
    return j.at(key).get<T>();
  } catch (const json::exception&) {
    fail(file.string(), where + ": \"" + key + "\" is not " + (std::is_arithmetic_v<T> ? "a number" : "of the expected type"));
  }
}

template <size_t N>
std::array<double, N> finite_array(const json& j, const char* key, const fs::path& file, const std::string& where) {
  const auto v = get<std::vector<double>>(j, key, file, where);
  if (v.size() != N) fail(file.string(), cat(where, ": \"", key, "\" has ", v.size(), " numbers, expected ", N));
  std::array<double, N> a{};
  for (size_t i = 0; i < N; ++i) {
    if (!std::isfinite(v[i])) fail(file.string(), cat(where, ": \"", key, "\" is not finite"));
    a[i] = v[i];
  }
  return a;
}

// The resources of the project's item of `type` (the first such item), with their formats.
std::map<std::string, fs::path> item_resources(const json& project, const fs::path& path, const std::string& type) {
  for (const json& item : get<json>(project, "items", path, "project")) {
    if (!item.is_object() || item.value("type", "") != type) continue;
    std::map<std::string, fs::path> out;
    for (const json& r : get<json>(item, "resources", path, "item " + type))
      out[get<std::string>(r, "format", path, "item " + type + " resource")] =
          path.parent_path() / get<std::string>(r, "uri", path, "item " + type + " resource");
    return out;
  }
  fail(path.string(), "the project has no \"" + type + "\" item");
}

fs::path resource(const std::map<std::string, fs::path>& r, const std::string& format, const fs::path& project,
                  const std::string& type) {
  const auto it = r.find(format);
  if (it == r.end()) fail(project.string(), "item \"" + type + "\" has no resource of format " + format);
  return it->second;
}

// An image URI of the camera list as a path: file:// URIs as they are, others relative to the list's
// folder; a fragment (#page=0 of a multi-page TIFF) is dropped.
fs::path image_path(std::string uri, const fs::path& list) {
  if (const size_t hash = uri.find('#'); hash != std::string::npos) uri.resize(hash);
  if (uri.rfind("file://", 0) == 0) return fs::path(uri.substr(7));
  return list.parent_path() / uri;
}

// R_x(omega) R_y(phi) R_z(kappa), degrees.
Mat3d omega_phi_kappa(const std::array<double, 3>& deg) {
  const double o = deg[0] * M_PI / 180, p = deg[1] * M_PI / 180, k = deg[2] * M_PI / 180;
  Mat3d x = Mat3d::identity(), y = Mat3d::identity(), z = Mat3d::identity();
  x.m[1][1] = std::cos(o), x.m[1][2] = -std::sin(o), x.m[2][1] = std::sin(o), x.m[2][2] = std::cos(o);
  y.m[0][0] = std::cos(p), y.m[0][2] = std::sin(p), y.m[2][0] = -std::sin(p), y.m[2][2] = std::cos(p);
  z.m[0][0] = std::cos(k), z.m[0][1] = -std::sin(k), z.m[1][0] = std::sin(k), z.m[1][1] = std::cos(k);
  return x * y * z;
}

// The bytes an accessor reads: `components` values of `size` bytes per element, checked against its
// buffer view and the buffer file.
std::string accessor_bytes(const json& gltf, size_t index, const fs::path& file, int component_type, size_t size,
                           const std::vector<std::pair<std::string, size_t>>& types, size_t& count, size_t& components) {
  const std::string where = cat("accessor ", index);
  const json& accessors = get<json>(gltf, "accessors", file, "glTF");
  if (!accessors.is_array() || index >= accessors.size()) fail(file.string(), where + " does not exist");
  const json& a = accessors[index];
  if (a.contains("sparse")) fail(file.string(), where + ": sparse accessors are not allowed in OPF");
  if (get<int>(a, "componentType", file, where) != component_type)
    fail(file.string(), cat(where, ": componentType ", a["componentType"], ", expected ", component_type));
  const std::string type = get<std::string>(a, "type", file, where);
  components = 0;
  for (const auto& [name, n] : types)
    if (type == name) components = n;
  if (components == 0) fail(file.string(), where + ": type " + type + " is not one this attribute takes");
  count = get<size_t>(a, "count", file, where);
  const size_t view_index = get<size_t>(a, "bufferView", file, where);
  const json& views = get<json>(gltf, "bufferViews", file, "glTF");
  if (!views.is_array() || view_index >= views.size()) fail(file.string(), cat(where, ": buffer view ", view_index, " does not exist"));
  const json& view = views[view_index];
  const size_t offset = view.value("byteOffset", size_t{0}), length = get<size_t>(view, "byteLength", file, "buffer view");
  if (view.contains("byteStride")) fail(file.string(), cat("buffer view ", view_index, ": byteStride is not allowed in OPF"));
  if (count > length / (components * size))
    fail(file.string(), cat(where, ": ", count, " elements do not fit the ", length, " bytes of buffer view ", view_index));
  const size_t buffer_index = get<size_t>(view, "buffer", file, "buffer view");
  const json& buffers = get<json>(gltf, "buffers", file, "glTF");
  if (!buffers.is_array() || buffer_index >= buffers.size()) fail(file.string(), cat("buffer ", buffer_index, " does not exist"));
  const fs::path bin = file.parent_path() / get<std::string>(buffers[buffer_index], "uri", file, cat("buffer ", buffer_index));
  const std::string bytes = read_text_file(bin);
  if (offset > bytes.size() || length > bytes.size() - offset)
    fail(bin.string(), cat("holds ", bytes.size(), " bytes; buffer view ", view_index, " of ", file.filename().string(),
                           " reads ", length, " from byte ", offset));
  return bytes.substr(offset, count * components * size);
}

// The tie points of an OPF-glTF point cloud, in the processing CRS.
std::vector<OpfPoint> read_gltf_points(const fs::path& file) {
  const json gltf = read_json(file);
  std::vector<size_t> nodes;
  if (gltf.contains("scenes")) {
    const json& scenes = gltf["scenes"];
    const size_t scene = gltf.value("scene", size_t{0});
    if (!scenes.is_array() || scene >= scenes.size()) fail(file.string(), cat("scene ", scene, " does not exist"));
    nodes = get<std::vector<size_t>>(scenes[scene], "nodes", file, cat("scene ", scene));
  } else {
    for (size_t i = 0; i < get<json>(gltf, "nodes", file, "glTF").size(); ++i) nodes.push_back(i);
  }
  const json& all_nodes = get<json>(gltf, "nodes", file, "glTF");
  const json& meshes = get<json>(gltf, "meshes", file, "glTF");
  std::vector<OpfPoint> points;
  for (size_t n : nodes) {
    const std::string where = cat("node ", n);
    if (!all_nodes.is_array() || n >= all_nodes.size()) fail(file.string(), where + " does not exist");
    const json& node = all_nodes[n];
    if (!node.contains("mesh")) continue;
    std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // column-major
    if (node.contains("matrix")) m = finite_array<16>(node, "matrix", file, where);
    const size_t mesh = get<size_t>(node, "mesh", file, where);
    if (!meshes.is_array() || mesh >= meshes.size()) fail(file.string(), cat(where, ": mesh ", mesh, " does not exist"));
    for (const json& primitive : get<json>(meshes[mesh], "primitives", file, cat("mesh ", mesh))) {
      const json& attributes = get<json>(primitive, "attributes", file, cat("mesh ", mesh, " primitive"));
      size_t count = 0, components = 0;
      const std::string xyz = accessor_bytes(gltf, get<size_t>(attributes, "POSITION", file, "attributes"), file, 5126, 4,
                                             {{"VEC3", 3}}, count, components);
      std::string rgb;
      size_t colour_components = 0, colour_count = 0;
      if (attributes.contains("COLOR_0")) {
        rgb = accessor_bytes(gltf, get<size_t>(attributes, "COLOR_0", file, "attributes"), file, 5121, 1,
                             {{"VEC3", 3}, {"VEC4", 4}}, colour_count, colour_components);
        if (colour_count != count) fail(file.string(), cat(where, ": ", colour_count, " colours for ", count, " points"));
      }
      for (size_t i = 0; i < count; ++i) {
        float p[3];
        std::memcpy(p, xyz.data() + 12 * i, 12);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
          fail(file.string(), cat(where, ": point ", i, " is not finite"));
        OpfPoint q;
        for (int r = 0; r < 3; ++r) q.xyz[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
        if (!rgb.empty())
          for (int c = 0; c < 3; ++c) q.rgb[c] = static_cast<uint8_t>(rgb[colour_components * i + c]);
        points.push_back(q);
      }
    }
  }
  return points;
}

}  // namespace

namespace {

OpfProject read_project(const fs::path& path) {
  const json project = read_json(path);
  if (project.value("format", "") != "application/opf-project+json")
    fail(path.string(), "not an OPF project (format is not application/opf-project+json)");
  OpfProject out;

  // Camera id -> image.
  const fs::path list = resource(item_resources(project, path, "camera_list"), "application/opf-camera-list+json", path, "camera_list");
  std::map<uint64_t, std::string> uris;
  for (const json& c : get<json>(read_json(list), "cameras", list, "camera list"))
    uris[get<uint64_t>(c, "id", list, "camera")] = get<std::string>(c, "uri", list, "camera");

  // Sensor id -> image size.
  const fs::path inputs = resource(item_resources(project, path, "input_cameras"), "application/opf-input-cameras+json", path, "input_cameras");
  std::map<uint64_t, std::array<double, 2>> sizes;
  for (const json& s : get<json>(read_json(inputs), "sensors", inputs, "input cameras"))
    sizes[get<uint64_t>(s, "id", inputs, "sensor")] = finite_array<2>(s, "image_size_px", inputs, "sensor");

  // The calibration: sensors' internals, cameras' poses, tie points.
  const auto calibration = item_resources(project, path, "calibration");
  const fs::path calibrated = resource(calibration, "application/opf-calibrated-cameras+json", path, "calibration");
  const json cal = read_json(calibrated);
  std::map<uint64_t, json> internals;
  for (const json& s : get<json>(cal, "sensors", calibrated, "calibrated cameras"))
    internals[get<uint64_t>(s, "id", calibrated, "sensor")] = get<json>(s, "internals", calibrated, "sensor");
  for (const json& c : get<json>(cal, "cameras", calibrated, "calibrated cameras")) {
    const uint64_t id = get<uint64_t>(c, "id", calibrated, "camera"), sensor = get<uint64_t>(c, "sensor_id", calibrated, "camera");
    const std::string who = cat("camera ", id);
    if (!uris.count(id)) fail(calibrated.string(), who + " is not in the camera list " + list.filename().string());
    if (!internals.count(sensor)) fail(calibrated.string(), cat(who, ": sensor ", sensor, " is not calibrated"));
    if (!sizes.count(sensor)) fail(inputs.string(), cat("sensor ", sensor, " (of ", who, ") is not among the input sensors"));
    const json& in = internals.at(sensor);
    const std::string type = get<std::string>(in, "type", calibrated, cat("sensor ", sensor));
    if (type != "perspective")
      fail(calibrated.string(), cat("sensor ", sensor, " is a ", type, " camera; only perspective sensors are supported"));
    const double f = get<double>(in, "focal_length_px", calibrated, cat("sensor ", sensor));
    const auto pp = finite_array<2>(in, "principal_point_px", calibrated, cat("sensor ", sensor));
    const auto radial = finite_array<3>(in, "radial_distortion", calibrated, cat("sensor ", sensor));
    const auto tangential = finite_array<2>(in, "tangential_distortion", calibrated, cat("sensor ", sensor));
    if (!(f > 0) || !std::isfinite(f)) fail(calibrated.string(), cat("sensor ", sensor, ": focal_length_px must be positive"));

    Pix4dView view;
    const fs::path image = image_path(uris.at(id), list).lexically_normal();
    const fs::path relative = image.lexically_relative(path.parent_path());
    view.name = relative.empty() || *relative.begin() == ".." ? image.filename().string() : relative.string();
    const Mat3d R = omega_phi_kappa(finite_array<3>(c, "orientation_deg", calibrated, who));
    Mat3d flip = Mat3d::identity();
    flip.m[1][1] = flip.m[2][2] = -1;  // photogrammetric (y up, z backward) -> computer vision (y down, z forward)
    view.pose.R = flip * transpose(R);
    const auto C = finite_array<3>(c, "position", calibrated, who);
    view.pose.t = -(view.pose.R * Vec3d{C[0], C[1], C[2]});
    view.camera.id = static_cast<uint32_t>(out.views.size() + 1);
    view.camera.width = static_cast<int>(sizes.at(sensor)[0]);
    view.camera.height = static_cast<int>(sizes.at(sensor)[1]);
    if (view.camera.width <= 0 || view.camera.height <= 0)
      fail(inputs.string(), cat("sensor ", sensor, ": image_size_px must be positive"));
    const bool distorted = radial[0] != 0 || radial[1] != 0 || radial[2] != 0 || tangential[0] != 0 || tangential[1] != 0;
    view.camera.model = distorted ? CameraModel::OpenCV : CameraModel::Pinhole;
    view.camera.params = {f, f, pp[0], pp[1]};
    if (distorted) view.camera.params.insert(view.camera.params.end(), {radial[0], radial[1], tangential[0], tangential[1]});
    view.radial_k3 = radial[2];
    out.images.push_back(image.string());
    out.views.push_back(std::move(view));
  }
  if (out.views.empty()) fail(calibrated.string(), "no calibrated cameras");
  if (const auto gltf = calibration.find("model/gltf+json"); gltf != calibration.end())
    out.points = read_gltf_points(gltf->second);

  // The processing CRS.
  const auto frame_item = item_resources(project, path, "scene_reference_frame");
  const fs::path frame_file = resource(frame_item, "application/opf-scene-reference-frame+json", path, "scene_reference_frame");
  const json frame = read_json(frame_file);
  if (frame.contains("crs") && frame["crs"].contains("definition"))
    out.frame.crs = get<std::string>(frame["crs"], "definition", frame_file, "crs");
  const json& b2c = get<json>(frame, "base_to_canonical", frame_file, "scene reference frame");
  out.frame.scale = finite_array<3>(b2c, "scale", frame_file, "base_to_canonical");
  out.frame.shift = finite_array<3>(b2c, "shift", frame_file, "base_to_canonical");
  out.frame.swap_xy = get<bool>(b2c, "swap_xy", frame_file, "base_to_canonical");
  return out;
}

}  // namespace

OpfProject read_opf_project(const std::string& path_text) {
  const fs::path path = fs::absolute(path_text);
  try {
    return read_project(path);
  } catch (const json::exception& e) {  // a value of another type than the format says, deep in a resource
    fail(path.string(), std::string("malformed OPF project: ") + e.what());
  }
}

std::string find_opf_project(const std::string& dir) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && entry.path().extension() == ".opf") found.push_back(entry.path().string());
  if (found.size() > 1) {
    std::string list;
    for (const auto& f : found) list += "\n  " + f;
    fail(dir, "more than one OPF project file; keep one:" + list);
  }
  return found.empty() ? std::string() : found.front();
}

}  // namespace cls
