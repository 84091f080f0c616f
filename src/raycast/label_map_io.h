#pragma once
// Files of a view's label maps: 16-/8-bit PNG, PFM depth and a colour preview. Every writer goes
// through write_atomic, so a reader never sees a half-written file.
#include <array>
#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <vector>

#include "citymodel/taxonomy.h"
#include "raycast/label_maps.h"

namespace cls {

// Single-channel PNG, row-major width * height values.
void write_png_u16(const std::filesystem::path& path, const std::vector<uint16_t>& data, int width, int height);
void write_png_u8(const std::filesystem::path& path, const std::vector<uint8_t>& data, int width, int height);

// Single-channel PFM ("Pf"): little-endian floats (scale -1.0), rows stored bottom to top as the
// format prescribes; `data` is row-major top to bottom like every other map.
void write_pfm(const std::filesystem::path& path, const std::vector<float>& data, int width, int height);

// Reads one label-map PNG: `type` CV_16UC1 (level*.png, building.png) or CV_8UC1 (coverage.png) of
// width w and height h; cls::Error naming the file if it is missing, unreadable, of another type or size.
cv::Mat read_label_png(const std::filesystem::path& path, int type, int h, int w);

// The label maps' legend.json (written by `raycast`) must describe `taxonomy`: same classes in the same
// order, else the label ids would be read as other classes. cls::Error naming the legend otherwise; a
// directory without legend.json (hand-made label maps) passes.
void check_label_legend(const std::filesystem::path& labels_dir, const Taxonomy& taxonomy);

// Reads a view's object.npy: int32 H x W; cls::Error naming the file if it is missing or of another
// type or size (label maps written before object maps existed: run `raycast` again).
std::vector<int32_t> read_object_map(const std::filesystem::path& path, int h, int w);

struct FloatImage {
  int width = 0, height = 0;
  std::vector<float> data;  // row-major, top row first
};
// Reads a single-channel PFM of either byte order; cls::Error naming the file if it is malformed
// or truncated.
FloatImage read_pfm(const std::filesystem::path& path);

// What a view's label maps say of its first hits: the finest city object (object.npy) and the camera
// depth (depth.pfm, 0 where the ray hits nothing) per pixel, row-major; both checked against the view's
// size (cls::Error naming the file otherwise).
struct ViewHits {
  std::vector<int32_t> object;
  FloatImage depth;
};
ViewHits read_view_hits(const std::filesystem::path& dir, int width, int height);

// Label ids (row-major H x W, -1 or any negative = none) as a BGR image: colours[id] is the RGB colour
// of id, `none` the BGR colour where there is no label.
cv::Mat colourise(const std::vector<int32_t>& labels, int H, int W, const std::vector<std::array<unsigned char, 3>>& colours,
                  const cv::Vec3b& none);

// RGB preview: level-1 class colours, darkened where the level-1 class changes, black outlines
// where the building changes, dark grey where nothing is hit, mid grey for unlabelled hits.
void write_preview(const std::filesystem::path& path, const LabelMaps& maps, const Taxonomy& taxonomy);

// The per-view files: level1.png, level2.png, level3.png, building.png, coverage.png, depth.pfm,
// object.npy (int32 H x W, index into the export's objects.json, -1 none), preview.png in `dir`.
void write_label_maps(const std::filesystem::path& dir, const LabelMaps& maps, const Taxonomy& taxonomy);

}  // namespace cls
