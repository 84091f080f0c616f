#pragma once
// `citylangsplat merge`: the tiles' language fields as one model in the common (district) frame.
// Each tile keeps only the Gaussians whose centre lies in its own cell of the partition
// (tile_plan.h), so a seam has no Gaussian twice and no gap; the tiles share one autoencoder and one
// city-object table, so their latents and provenance mean the same everywhere. Output, per method:
//   OUT/language/<method>/   a language model directory (language_model.h) that query, evaluate,
//                            render and view open as any other; its PLY gains an int32 "tile" property
//   OUT/merge.json           per tile: Gaussians trained, kept; the seam check: the cells are checked to be
//                            disjoint, every kept Gaussian to lie in its own cell (so in no other)
#include <filesystem>
#include <nlohmann/json.hpp>

namespace cls {

// Returns merge.json's content. cls::Error naming the file when a tile has not finished training under
// the current plan and settings, a tile's autoencoder is not the shared one, the city-object tables
// differ, or the cells overlap.
nlohmann::json merge_tiles(const std::filesystem::path& tiles_dir, const std::filesystem::path& out_dir);

}  // namespace cls
