#include "export/opening_proposals.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace cls {

namespace {

Vec3d vertex(const SemanticMesh& mesh, uint32_t i) { return {mesh.vertices[i][0], mesh.vertices[i][1], mesh.vertices[i][2]}; }

// Cell (i, j) of a plane's grid as one key, and back.
constexpr int64_t kSpan = 1 << 20;
int64_t cell_key(int64_t i, int64_t j) { return (i + kSpan / 2) * kSpan + (j + kSpan / 2); }
std::array<int64_t, 2> cell_of(int64_t key) { return {key / kSpan - kSpan / 2, key % kSpan - kSpan / 2}; }

}  // namespace

OpeningVotes::OpeningVotes(const CityObjects& objects, const SemanticMesh& mesh, std::vector<int> opening_classes,
                           const ProposalSettings& settings)
    : opening_classes_(std::move(opening_classes)), settings_(settings) {
  const size_t n = objects.objects.size();
  planes_.resize(n);
  cells_.resize(n);
  const std::vector<int32_t> finest = finest_object_of_triangles(mesh);
  std::vector<Vec3d> normal(n, Vec3d{0, 0, 0}), centroid(n, Vec3d{0, 0, 0});
  std::vector<double> area(n, 0.0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int32_t o = finest[t];
    if (o < 0 || objects.objects[o].level != 2) continue;
    const auto& tri = mesh.triangles[t];
    const Vec3d a = vertex(mesh, tri[0]), b = vertex(mesh, tri[1]), c = vertex(mesh, tri[2]);
    const Vec3d twice = cross(b - a, c - a);
    normal[o] = normal[o] + twice;
    area[o] += 0.5 * norm(twice);
    centroid[o] = centroid[o] + (norm(twice) / 6.0) * (a + b + c);
  }
  for (size_t o = 0; o < n; ++o) {
    if (!(area[o] > 0) || !(norm(normal[o]) > 1e-12)) continue;
    Plane& p = planes_[o];
    p.valid = true;
    p.normal = normalized(normal[o]);
    p.origin = (1.0 / area[o]) * centroid[o];
    const Vec3d horizontal{-p.normal.y, p.normal.x, 0};
    p.u = norm(horizontal) > 1e-6 ? normalized(horizontal) : Vec3d{1, 0, 0};
    p.v = cross(p.normal, p.u);
  }
  std::map<int32_t, std::array<double, 4>> boxes;  // modelled opening -> its box on its surface's plane
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int32_t o = finest[t];
    if (o < 0) continue;
    const int32_t surface = objects.objects[o].level == 1 ? objects.objects[o].parent : o;
    if (surface < 0 || !planes_[surface].valid) continue;
    Plane& p = planes_[surface];
    for (int k = 0; k < 3; ++k) {
      const auto q = at(p, vertex(mesh, mesh.triangles[t][k]));
      if (surface == o) {
        p.u0 = std::min(p.u0, q[0]), p.u1 = std::max(p.u1, q[0]), p.v0 = std::min(p.v0, q[1]), p.v1 = std::max(p.v1, q[1]);
      } else {
        auto [it, added] = boxes.emplace(o, std::array<double, 4>{1e300, -1e300, 1e300, -1e300});
        auto& b = it->second;
        b = {std::min(b[0], q[0]), std::max(b[1], q[0]), std::min(b[2], q[1]), std::max(b[3], q[1])};
      }
    }
  }
  for (const auto& [o, b] : boxes) planes_[objects.objects[o].parent].modelled.push_back(b);
}

bool OpeningVotes::add(int32_t surface, const Vec3d& point, int class_id) {
  if (!has_plane(surface)) return false;
  const Plane& p = planes_[surface];
  if (std::abs(dot(point - p.origin, p.normal)) > settings_.plane_distance) return false;
  const auto q = at(p, point);
  Cell& c = cells_[surface][cell_key(static_cast<int64_t>(std::floor(q[0] / settings_.cell)),
                                     static_cast<int64_t>(std::floor(q[1] / settings_.cell)))];
  ++c.votes;
  if (std::find(opening_classes_.begin(), opening_classes_.end(), class_id) != opening_classes_.end()) ++c.openings[class_id];
  return true;
}

std::vector<OpeningProposal> OpeningVotes::proposals() const {
  const ProposalSettings& s = settings_;
  std::vector<OpeningProposal> out;
  for (size_t o = 0; o < planes_.size(); ++o) {
    const Plane& p = planes_[o];
    if (!p.valid) continue;
    // Opening cells: enough votes, most of them one opening class, centre away from every modelled opening.
    std::map<int64_t, const Cell*> open;
    for (const auto& [key, c] : cells_[o]) {
      int64_t opening = 0;
      for (const auto& [cls, n] : c.openings) opening += n;
      if (c.votes < s.min_votes || opening <= s.opening_share * c.votes) continue;
      const auto ij = cell_of(key);
      const double u = (ij[0] + 0.5) * s.cell, v = (ij[1] + 0.5) * s.cell;
      const bool near = std::any_of(p.modelled.begin(), p.modelled.end(), [&](const auto& b) {
        return u >= b[0] - s.existing_margin && u <= b[1] + s.existing_margin && v >= b[2] - s.existing_margin &&
               v <= b[3] + s.existing_margin;
      });
      if (!near) open.emplace(key, &c);
    }
    // A closing (dilate, then erode, by one cell): an opening whose middle votes less clearly than its
    // edges (a door's panels, a window's bars) stays one region instead of several fragments.
    const auto neighbours = [](int64_t key, const auto& visit) {
      const auto ij = cell_of(key);
      for (int64_t di = -1; di <= 1; ++di)
        for (int64_t dj = -1; dj <= 1; ++dj)
          if (di || dj) visit(cell_key(ij[0] + di, ij[1] + dj));
    };
    std::set<int64_t> dilated;
    for (const auto& [key, unused] : open) {
      dilated.insert(key);
      neighbours(key, [&](int64_t n) { dilated.insert(n); });
    }
    std::map<int64_t, const Cell*> closed = open;
    static const Cell kNoVotes;
    for (const int64_t key : dilated) {
      bool inside = true;
      neighbours(key, [&](int64_t n) { inside = inside && dilated.count(n); });
      if (!inside || closed.count(key)) continue;
      const auto found = cells_[o].find(key);
      closed.emplace(key, found == cells_[o].end() ? &kNoVotes : &found->second);
    }
    // 8-connected regions, each a rectangle.
    std::vector<OpeningProposal> mine;
    std::map<int64_t, bool> done;
    for (const auto& [start, unused] : closed) {
      if (done[start]) continue;
      std::vector<int64_t> stack = {start}, region;
      done[start] = true;
      while (!stack.empty()) {
        const int64_t key = stack.back();
        stack.pop_back();
        region.push_back(key);
        const auto ij = cell_of(key);
        for (int64_t di = -1; di <= 1; ++di)
          for (int64_t dj = -1; dj <= 1; ++dj) {
            const int64_t next = cell_key(ij[0] + di, ij[1] + dj);
            if (closed.count(next) && !done[next]) done[next] = true, stack.push_back(next);
          }
      }
      double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
      std::map<int, int64_t> votes;
      int64_t total = 0;
      for (const int64_t key : region) {
        const auto ij = cell_of(key);
        u0 = std::min(u0, ij[0] * s.cell), u1 = std::max(u1, (ij[0] + 1) * s.cell);
        v0 = std::min(v0, ij[1] * s.cell), v1 = std::max(v1, (ij[1] + 1) * s.cell);
        const Cell& c = *closed.at(key);
        total += c.votes;
        for (const auto& [cls, n] : c.openings) votes[cls] += n;
      }
      u0 = std::max(u0, p.u0), u1 = std::min(u1, p.u1), v0 = std::max(v0, p.v0), v1 = std::min(v1, p.v1);
      if (!(u1 > u0 && v1 > v0) || (u1 - u0) * (v1 - v0) < s.min_area) continue;
      OpeningProposal prop;
      prop.surface = static_cast<int32_t>(o);
      const auto best = std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
      prop.class_id = best->first;
      const std::array<std::array<double, 2>, 4> uv = {{{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}};
      for (int k = 0; k < 4; ++k) prop.corners[k] = p.origin + uv[k][0] * p.u + uv[k][1] * p.v;
      prop.width = u1 - u0, prop.height = v1 - v0;
      prop.cells = static_cast<int64_t>(region.size());
      prop.votes = total;
      prop.confidence = total ? static_cast<double>(best->second) / total : 0.0;
      mine.push_back(prop);
    }
    std::sort(mine.begin(), mine.end(), [&](const OpeningProposal& a, const OpeningProposal& b) {
      return at(p, a.corners[0])[0] < at(p, b.corners[0])[0];
    });
    out.insert(out.end(), mine.begin(), mine.end());
  }
  return out;
}

}  // namespace cls
