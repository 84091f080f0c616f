#pragma once
// `citylangsplat merge`: the tiles' language fields as one model in the common (district) frame.
// Each tile keeps only the Gaussians whose centre lies in its own cell of the partition
// (tile_plan.h), so a seam has no Gaussian twice and no gap; the tiles share one autoencoder and one
// city-object table, so their latents and provenance mean the same everywhere. Output, per method:
//   OUT/language/<method>/   a language model directory (language_model.h) that query, evaluate,
//                            render and view open as any other; its PLY gains an int32 "tile" property
//   OUT/merge.json           per tile: Gaussians trained, kept; the seam check (counted, not assumed)
#include <filesystem>
#include <nlohmann/json.hpp>

namespace cls {

// Returns merge.json's content. cls::Error when a tile has not finished training, or the tiles were
// trained with different autoencoders or city models (the file named).
nlohmann::json merge_tiles(const std::filesystem::path& tiles_dir, const std::filesystem::path& out_dir);

}  // namespace cls
