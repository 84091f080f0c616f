#pragma once
// What the city model lacks (issue 35 §3): openings the photos, through the language field, show on a
// surface where the city model has none. Every view's rendered level-1 field votes per pixel: where the
// label map's first hit is a surface of the model (a wall, a roof: not one of its openings), the pixel's
// best class (window, door, or a surface class) goes to a cell of that surface's plane at the hit point.
// Cells most of whose votes are an opening, away from the openings the model has (the field's window edges
// blur onto the wall around them), are grouped into 8-connected regions; each region's bounding rectangle on
// the plane is a proposed opening. Dense per pixel and over views: one Gaussian covers a whole window at
// the photos' resolution, so the Gaussians themselves are too few to vote.
//
// The plane and its axes: the area-weighted normal and centroid of the surface's own triangles; u
// horizontal (the CRS's z is up; a flat roof takes x), v = n x u. Confidence: the opening class's share of
// the votes in the region's cells.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "citymodel/city_objects.h"
#include "citymodel/semantic_mesh.h"
#include "core/math.h"

namespace cls {

struct ProposalSettings {
  double cell = 0.1;              // metres: the vote grid on each surface's plane
  int64_t min_votes = 3;          // a cell needs this many votes to count
  double opening_share = 0.5;     // a cell is an opening where more than this share of its votes is one
  double min_area = 0.15;         // square metres: smaller regions are noise
  double existing_margin = 0.2;   // metres around an opening the model has where cells do not count
  double plane_distance = 0.3;    // metres: votes farther from the surface's plane are dropped
};

struct OpeningProposal {
  int32_t surface = -1;            // the city object (wall, roof, ...) it lies on
  int class_id = -1;               // the opening class most of its votes name
  std::array<Vec3d, 4> corners{};  // CRS minus the mesh's origin, counter-clockwise about the surface's normal
  double width = 0, height = 0;    // metres along u and v
  int64_t cells = 0, votes = 0;    // opening cells of the region, and the votes in them
  double confidence = 0;           // [0, 1]: the class's share of those votes
};

class OpeningVotes {
 public:
  // `mesh` in the CRS minus its origin (as read), `objects` = city_objects(mesh); `opening_classes` the
  // taxonomy's window and door ids.
  OpeningVotes(const CityObjects& objects, const SemanticMesh& mesh, std::vector<int> opening_classes,
               const ProposalSettings& settings = {});
  bool has_plane(int32_t surface) const { return surface >= 0 && static_cast<size_t>(surface) < planes_.size() && planes_[surface].valid; }
  // One pixel's vote: the hit `point` (CRS minus origin) on `surface`, its best class. Votes for objects
  // that are no surface with a plane, or farther than plane_distance from it, are ignored; returns whether counted.
  bool add(int32_t surface, const Vec3d& point, int class_id);
  // The proposals, in surface order, then by u.
  std::vector<OpeningProposal> proposals() const;

 private:
  struct Plane {
    bool valid = false;
    Vec3d origin{}, normal{}, u{}, v{};
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;  // the surface's extent
    std::vector<std::array<double, 4>> modelled;                // its openings' boxes (u0, u1, v0, v1)
  };
  struct Cell {
    int64_t votes = 0;
    std::unordered_map<int, int64_t> openings;  // class -> votes
  };
  std::array<double, 2> at(const Plane& p, const Vec3d& x) const { return {dot(x - p.origin, p.u), dot(x - p.origin, p.v)}; }

  std::vector<int> opening_classes_;
  ProposalSettings settings_;
  std::vector<Plane> planes_;
  std::vector<std::unordered_map<int64_t, Cell>> cells_;  // per surface: cell key -> votes
};

}  // namespace cls
