#pragma once
// A 3D Tiles 1.1 tileset of Gaussian splat tiles (export --format 3dtiles; splat_tiles.h cuts them):
// the root tile's transform takes the contents' frame, the city model's CRS minus an origin with z up
// (3D Tiles turns a glTF's y up to z up itself), to ECEF (EPSG:4978), so a client places it on the
// globe; each tile's bounding volume is a box in that frame around its Gaussians' 3-sigma extents.
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/math.h"
#include "export/splat_tiles.h"
#include "georef/proj_crs.h"

namespace cls {

// The local frame (CRS minus `origin`, z up) -> ECEF, column-major: the Jacobian of the CRS -> ECEF
// map at the origin (central differences over +-10 m: the projection's scale and grid convergence
// included) and the origin's ECEF position. cls::Error when PROJ cannot place the origin.
std::array<double, 16> ecef_tile_transform(const CrsToGeocentric& to_ecef, const Vec3d& origin);

// Where a tile's content lies, relative to tileset.json: tiles/<name>.glb.
std::string splat_tile_uri(const SplatTile& tile);

// tileset.json: asset 1.1, the tree's tiles (refine ADD: a child adds to its parent) with their boxes,
// geometric errors and contents, the root with the transform; the tileset's geometricError the root
// box's diagonal, or the root's error where that is larger (below it the root is drawn).
nlohmann::json tileset_json(const std::array<double, 16>& transform, const SplatTileTree& tree,
                            const nlohmann::json& extras);

// Adds the glTF extensions `gltf` uses and requires to the tileset's 3DTILES_content_gltf lists (each
// once): clients decide from them how to load the contents before reading any (CesiumJS loads a tile as
// Gaussian splats only when KHR_gaussian_splatting and its SPZ compression are listed as required).
void declare_gltf_extensions(nlohmann::json& tileset, const nlohmann::json& gltf);

}  // namespace cls
