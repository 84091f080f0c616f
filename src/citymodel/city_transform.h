#pragma once
// The similarity that maps the city model's CRS into the scene (SfM) frame, read from a small
// JSON file (`--city-transform`). Two spellings are accepted:
//   {"matrix": [[a,b,c,tx],[d,e,f,ty],[g,h,i,tz],[0,0,0,1]]}     row-major 4x4
//   {"scale": s, "rotation": [[3x3]], "translation": [tx,ty,tz]}   M = [s*R | t]
// applied to source-CRS coordinates: x_scene = M * [x_src, 1]. The upper 3x3 must be s times a
// rotation (s > 0, no reflection) within 1e-6 relative, the last row 0 0 0 1, all finite.
#include <array>
#include <string>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "core/math.h"

namespace cls {

struct CityTransform {
  std::array<std::array<double, 4>, 4> matrix{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

  static CityTransform identity() { return {}; }
  // Uniform scale of the similarity (the length of a column of the upper 3x3).
  double scale() const;
  // M * [p, 1] in double.
  Vec3d apply(const Vec3d& p) const;
  // The rotation R of M = [s R | t].
  Mat3d rotation() const;
  Vec3d translation() const { return {matrix[0][3], matrix[1][3], matrix[2][3]}; }
};

// [s R | t].
CityTransform similarity_transform(double s, const Mat3d& R, Vec3d t);
// a * b: b first, then a.
CityTransform operator*(const CityTransform& a, const CityTransform& b);
// The inverse similarity [R^T / s | -R^T t / s].
CityTransform inverse(const CityTransform& t);

// What keeps `t` from being a similarity ("" if it is one).
std::string similarity_problem(const CityTransform& t);

// Parses and validates; cls::Error naming `name` on malformed JSON or a non-similarity.
CityTransform parse_city_transform(const std::string& text, const std::string& name);
CityTransform read_city_transform(const std::string& path);
// Writes {"matrix": ...} with round-trip precision, atomically, and {"crs": crs} unless empty.
void write_city_transform(const std::string& path, const CityTransform& t, const std::string& crs = "");

// Where a scene frame lies: the city model's CRS as the model names it ("" for none) and the transform
// from it into the scene, as the label maps were made with it (labels/city_transform.json).
struct CityFrame {
  std::string crs;
  CityTransform transform;
};
CityFrame read_city_frame(const std::string& path);  // cls::Error naming the file, as read_city_transform

// Mesh vertices in the scene frame: M * (vertex + origin) composed in double before the
// conversion to float, so the large translation of projected (UTM) coordinates cancels exactly.
std::vector<Vec3f> scene_vertices(const SemanticMesh& mesh, const CityTransform& t);

}  // namespace cls
