#pragma once
// A 3D Tiles 1.1 tileset of one glTF content (export --format 3dtiles): the root tile's transform takes
// the content's frame, the city model's CRS minus an origin with z up (3D Tiles turns a glTF's y up to
// z up itself), to ECEF (EPSG:4978), so a client places it on the globe; its bounding volume is a box in
// that frame around every Gaussian's 3-sigma extent.
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/math.h"
#include "georef/proj_crs.h"

namespace cls {

// The local frame (CRS minus `origin`, z up) -> ECEF, column-major: the Jacobian of the CRS -> ECEF
// map at the origin (central differences over +-10 m: the projection's scale and grid convergence
// included) and the origin's ECEF position. cls::Error when PROJ cannot place the origin.
std::array<double, 16> ecef_tile_transform(const CrsToGeocentric& to_ecef, const Vec3d& origin);

// 3D Tiles' box (centre, then three half-axis vectors) around points of the local frame, each grown by
// its radius; axis-aligned.
std::array<double, 12> bounding_box(const std::vector<Vec3d>& points, const std::vector<double>& radii);

// tileset.json: asset 1.1, one root tile (refine ADD, geometricError 0: nothing finer) with the
// transform, the box and `content_uri`; the tileset's geometricError the box's diagonal (below that
// screen error the tile is drawn).
nlohmann::json tileset_json(const std::array<double, 16>& transform, const std::array<double, 12>& box,
                            const std::string& content_uri, const nlohmann::json& extras);

}  // namespace cls
