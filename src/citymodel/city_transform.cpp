#include "citymodel/city_transform.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

using json = nlohmann::json;

// Tolerance of the similarity check, relative to s^2.
constexpr double kSimilarityTolerance = 1e-6;

double number(const json& v, const std::string& name, const std::string& what) {
  if (!v.is_number()) fail(name, what + " must be a number, got " + v.dump());
  return v.get<double>();
}

std::vector<double> numbers(const json& v, size_t n, const std::string& name, const std::string& what) {
  if (!v.is_array() || v.size() != n) fail(name, what + " must be an array of " + std::to_string(n) + " numbers");
  std::vector<double> out;
  for (const json& x : v) out.push_back(number(x, name, what));
  return out;
}

// A row-major n x n matrix given as n rows of n numbers.
std::vector<std::vector<double>> square_matrix(const json& v, size_t n, const std::string& name,
                                               const std::string& what) {
  const std::string shape = what + " must be " + std::to_string(n) + " rows of " + std::to_string(n) + " numbers";
  if (!v.is_array() || v.size() != n) fail(name, shape);
  std::vector<std::vector<double>> rows;
  for (size_t r = 0; r < n; ++r) {
    if (!v[r].is_array() || v[r].size() != n) fail(name, shape);
    rows.push_back(numbers(v[r], n, name, what));
  }
  return rows;
}

}  // namespace

double CityTransform::scale() const {
  return std::sqrt(matrix[0][0] * matrix[0][0] + matrix[1][0] * matrix[1][0] + matrix[2][0] * matrix[2][0]);
}

Vec3d CityTransform::apply(const Vec3d& p) const {
  Vec3d r;
  for (int i = 0; i < 3; ++i) r[i] = matrix[i][0] * p.x + matrix[i][1] * p.y + matrix[i][2] * p.z + matrix[i][3];
  return r;
}

Mat3d CityTransform::rotation() const {
  const double s = scale();
  Mat3d R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R.m[i][j] = matrix[i][j] / s;
  return R;
}

CityTransform similarity_transform(double s, const Mat3d& R, Vec3d t) {
  CityTransform out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.matrix[i][j] = s * R.m[i][j];
    out.matrix[i][3] = t[i];
  }
  return out;
}

CityTransform operator*(const CityTransform& a, const CityTransform& b) {
  CityTransform out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += a.matrix[i][k] * b.matrix[k][j];
      out.matrix[i][j] = sum;
    }
  return out;
}

CityTransform inverse(const CityTransform& t) {
  const double s = t.scale();
  const Mat3d Rt = transpose(t.rotation());
  return similarity_transform(1 / s, Rt, (-1 / s) * (Rt * t.translation()));
}

std::string similarity_problem(const CityTransform& t) {
  const auto& m = t.matrix;
  for (const auto& row : m)
    for (double x : row)
      if (!std::isfinite(x)) return "matrix has a non-finite entry";
  if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1)
    return cat("last row must be 0 0 0 1, got ", m[3][0], " ", m[3][1], " ", m[3][2], " ", m[3][3]);
  // A = s R  <=>  A^T A = s^2 I with s^2 the mean of the diagonal of A^T A.
  double ata[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) ata[i][j] = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
  const double s2 = (ata[0][0] + ata[1][1] + ata[2][2]) / 3;
  if (!(s2 > 0)) return "the 3x3 part is zero";
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double deviation = std::abs(ata[i][j] - (i == j ? s2 : 0.0));
      if (deviation > kSimilarityTolerance * s2)
        return cat("the 3x3 part is not a scaled rotation: (A^T A)[", i, "][", j, "] = ", ata[i][j],
                   ", expected ", (i == j ? s2 : 0.0), " (shear or non-uniform scale)");
    }
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (det < 0) return "the 3x3 part is a reflection (negative determinant)";
  return "";
}

CityTransform parse_city_transform(const std::string& text, const std::string& name) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    fail(name, std::string("malformed JSON: ") + e.what());
  }
  if (!doc.is_object()) fail(name, "a city transform must be a JSON object");
  CityTransform t;
  const bool has_matrix = doc.contains("matrix");
  const bool has_parts = doc.contains("scale") || doc.contains("rotation") || doc.contains("translation");
  if (has_matrix && has_parts) fail(name, "give either \"matrix\" or \"scale\"/\"rotation\"/\"translation\", not both");
  if (has_matrix) {
    const auto rows = square_matrix(doc["matrix"], 4, name, "\"matrix\"");
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) t.matrix[r][c] = rows[r][c];
  } else if (has_parts) {
    const double s = doc.contains("scale") ? number(doc["scale"], name, "\"scale\"") : 1.0;
    if (!(s > 0)) fail(name, cat("\"scale\" must be positive, got ", s));
    std::vector<std::vector<double>> R{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (doc.contains("rotation")) R = square_matrix(doc["rotation"], 3, name, "\"rotation\"");
    std::vector<double> tr{0, 0, 0};
    if (doc.contains("translation")) tr = numbers(doc["translation"], 3, name, "\"translation\"");
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) t.matrix[r][c] = s * R[r][c];
      t.matrix[r][3] = tr[r];
    }
  } else {
    fail(name, "needs \"matrix\" (4x4) or \"scale\"/\"rotation\"/\"translation\"");
  }
  const std::string problem = similarity_problem(t);
  if (!problem.empty()) fail(name, "not a similarity transform: " + problem);
  return t;
}

CityTransform read_city_transform(const std::string& path) {
  return parse_city_transform(read_text_file(path), path);
}

void write_city_transform(const std::string& path, const CityTransform& t, const std::string& crs) {
  json rows = json::array();
  for (const auto& row : t.matrix) rows.push_back(json(std::vector<double>(row.begin(), row.end())));
  // nlohmann writes doubles with round-trip precision.
  json doc{{"matrix", rows}};
  if (!crs.empty()) doc["crs"] = crs;
  write_text_atomic(path, doc.dump(2) + "\n");
}

CityFrame read_city_frame(const std::string& path) {
  const std::string text = read_text_file(path);
  CityFrame frame{"", parse_city_transform(text, path)};
  const json doc = json::parse(text);
  if (doc.contains("crs")) {
    if (!doc["crs"].is_string()) fail(path, "\"crs\" must be a string");
    frame.crs = doc["crs"].get<std::string>();
  }
  return frame;
}

std::vector<Vec3f> scene_vertices(const SemanticMesh& mesh, const CityTransform& t) {
  std::vector<Vec3f> out;
  out.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) {
    const Vec3d source{v[0] + mesh.origin[0], v[1] + mesh.origin[1], v[2] + mesh.origin[2]};
    out.push_back(cast<float>(t.apply(source)));
  }
  return out;
}

}  // namespace cls
