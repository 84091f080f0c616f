#include "raycast/label_map_io.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/error.h"
#include "core/image_file.h"
#include "core/log.h"
#include "core/npy.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

void check_size(const fs::path& path, size_t size, int width, int height) {
  if (width <= 0 || height <= 0 || size != static_cast<size_t>(width) * height)
    fail(path.string(), cat("cannot write ", size, " values as a ", width, "x", height, " image"));
}

}  // namespace

cv::Mat read_label_png(const fs::path& p, int type, int h, int w) {
  if (!fs::is_regular_file(p)) fail(p.string(), "missing (run `citylangsplat raycast` to make the label maps)");
  cv::Mat m = cv::imread(p.string(), cv::IMREAD_UNCHANGED);
  if (m.empty()) fail(p.string(), "cannot be read as an image");
  if (m.type() != type)
    fail(p.string(), std::string("must be a ") + (type == CV_16UC1 ? "16-bit" : "8-bit") + " single-channel PNG");
  if (m.rows != h || m.cols != w)
    fail(p.string(), "is " + std::to_string(m.cols) + " x " + std::to_string(m.rows) + " but the view's image is " +
                         std::to_string(w) + " x " + std::to_string(h) + " (raycast with the same --resolution)");
  return m;
}

void check_label_legend(const fs::path& labels_dir, const Taxonomy& taxonomy) {
  const fs::path legend = labels_dir / "legend.json";
  if (!fs::is_regular_file(legend)) return;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(legend));
  } catch (const nlohmann::json::exception& e) {
    fail(legend.string(), std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_array() || j.size() != taxonomy.classes.size())
    fail(legend.string(), "the label maps were made with a different taxonomy (" + std::to_string(j.size()) +
                              " classes, this one has " + std::to_string(taxonomy.classes.size()) + "); pass --taxonomy");
  for (size_t k = 0; k < j.size(); ++k)
    if (!j[k].is_object() || j[k].value("name", std::string()) != taxonomy.classes[k].name)
      fail(legend.string(), "class " + std::to_string(k) + " is " + j[k].dump() + " but the taxonomy says '" +
                                taxonomy.classes[k].name + "'; pass --taxonomy");
}

void write_png_u16(const fs::path& path, const std::vector<uint16_t>& data, int width, int height) {
  check_size(path, data.size(), width, height);
  write_image(path, cv::Mat(height, width, CV_16UC1, const_cast<uint16_t*>(data.data())));
}

void write_png_u8(const fs::path& path, const std::vector<uint8_t>& data, int width, int height) {
  check_size(path, data.size(), width, height);
  write_image(path, cv::Mat(height, width, CV_8UC1, const_cast<uint8_t*>(data.data())));
}

void write_pfm(const fs::path& path, const std::vector<float>& data, int width, int height) {
  check_size(path, data.size(), width, height);
  if (!host_is_little_endian()) fail(path.string(), "PFM writer supports little-endian hosts only");
  write_atomic(path, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << "Pf\n" << width << " " << height << "\n-1.0\n";
    for (int j = height - 1; j >= 0; --j)
      out.write(reinterpret_cast<const char*>(data.data() + static_cast<size_t>(j) * width),
                static_cast<std::streamsize>(width * sizeof(float)));
    out.close();
    if (!out) fail(path.string(), "write failed");
  });
}

std::vector<int32_t> read_object_map(const fs::path& path, int h, int w) {
  if (!fs::exists(path))
    fail(path.string(), "missing (label maps from before city-object maps; run `raycast` again)");
  const NpyArray a = read_npy(path);
  if (a.dtype != npy_descr<int32_t>() || a.shape != std::vector<int64_t>{h, w})
    fail(path.string(), cat("expected int32 ", h, " x ", w, " (the view's size), got ", a.dtype, " of ", a.shape.size(),
                            " dimensions"));
  return std::vector<int32_t>(a.as<int32_t>(), a.as<int32_t>() + a.numel());
}

FloatImage read_pfm(const fs::path& path) {
  const std::string bytes = read_text_file(path);
  // Header: "Pf", width, height, scale, each followed by whitespace; exactly one whitespace
  // character separates the scale from the pixel data.
  size_t pos = 0;
  auto token = [&](const char* what) {
    while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    const size_t start = pos;
    while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    if (start == pos || pos >= bytes.size()) fail(path.string(), cat("truncated PFM header (no ", what, ")"));
    return bytes.substr(start, pos - start);
  };
  const std::string magic = token("magic");
  if (magic == "PF") fail(path.string(), "3-channel PFM; expected a single-channel depth map (Pf)");
  if (magic != "Pf") fail(path.string(), "not a PFM file (magic '" + magic.substr(0, 8) + "')");
  FloatImage img;
  double scale = 0;
  try {
    size_t used = 0;
    const std::string w = token("width"), h = token("height"), s = token("scale");
    img.width = std::stoi(w, &used);
    if (used != w.size()) throw std::invalid_argument(w);
    img.height = std::stoi(h, &used);
    if (used != h.size()) throw std::invalid_argument(h);
    scale = std::stod(s, &used);
    if (used != s.size()) throw std::invalid_argument(s);
  } catch (const std::logic_error&) {
    fail(path.string(), "malformed PFM header (width, height or scale is not a number)");
  }
  if (img.width <= 0 || img.height <= 0 || img.width > (1 << 20) || img.height > (1 << 20))
    fail(path.string(), cat("PFM size ", img.width, "x", img.height, " out of range"));
  if (!std::isfinite(scale) || scale == 0) fail(path.string(), "PFM scale must be a non-zero number");
  ++pos;  // the single whitespace character after the scale
  const size_t n = static_cast<size_t>(img.width) * img.height;
  if (bytes.size() - pos < n * sizeof(float))
    fail(path.string(), cat("truncated PFM: ", n * sizeof(float), " bytes of pixel data expected, ",
                            bytes.size() - pos, " found"));
  const bool swap = (scale < 0) != host_is_little_endian();
  img.data.resize(n);
  for (int j = 0; j < img.height; ++j) {
    const char* row = bytes.data() + pos + static_cast<size_t>(img.height - 1 - j) * img.width * sizeof(float);
    for (int i = 0; i < img.width; ++i) {
      char b[4];
      std::memcpy(b, row + 4 * i, 4);
      if (swap) {
        std::swap(b[0], b[3]);
        std::swap(b[1], b[2]);
      }
      std::memcpy(&img.data[static_cast<size_t>(j) * img.width + i], b, 4);
    }
  }
  return img;
}

cv::Mat colourise(const std::vector<int32_t>& labels, int H, int W, const std::vector<std::array<unsigned char, 3>>& colours,
                  const cv::Vec3b& none) {
  cv::Mat img(H, W, CV_8UC3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int32_t l = labels[size_t(y) * W + x];
      img.at<cv::Vec3b>(y, x) = l < 0 ? none : cv::Vec3b(colours[l][2], colours[l][1], colours[l][0]);  // BGR
    }
  return img;
}

void write_preview(const fs::path& path, const LabelMaps& maps, const Taxonomy& taxonomy) {
  const int W = maps.width, H = maps.height;
  check_size(path, maps.level[0].size(), W, H);
  cv::Mat image(H, W, CV_8UC3);
  const cv::Vec3b no_hit(40, 40, 40), unlabelled(128, 128, 128), outline(0, 0, 0);
#pragma omp parallel for schedule(static)
  for (int j = 0; j < H; ++j) {
    for (int i = 0; i < W; ++i) {
      const size_t p = static_cast<size_t>(j) * W + i;
      const uint16_t label = maps.level[0][p];
      cv::Vec3b c = maps.depth[p] > 0 ? unlabelled : no_hit;
      if (label > 0 && label <= taxonomy.classes.size()) {
        const auto& rgb = taxonomy.classes[label - 1].color;
        c = cv::Vec3b(rgb[2], rgb[1], rgb[0]);
      }
      // Outlines against the right and lower neighbours: buildings black, classes darkened.
      const size_t right = i + 1 < W ? p + 1 : p, down = j + 1 < H ? p + W : p;
      if (maps.building[p] != maps.building[right] || maps.building[p] != maps.building[down])
        c = outline;
      else if (label != maps.level[0][right] || label != maps.level[0][down])
        c = cv::Vec3b(c[0] / 2, c[1] / 2, c[2] / 2);
      image.at<cv::Vec3b>(j, i) = c;
    }
  }
  write_image(path, image);
}

void write_label_maps(const fs::path& dir, const LabelMaps& maps, const Taxonomy& taxonomy) {
  for (int l = 0; l < 3; ++l)
    write_png_u16(dir / cat("level", l + 1, ".png"), maps.level[l], maps.width, maps.height);
  write_png_u16(dir / "building.png", maps.building, maps.width, maps.height);
  write_png_u8(dir / "coverage.png", maps.coverage, maps.width, maps.height);
  write_pfm(dir / "depth.pfm", maps.depth, maps.width, maps.height);
  write_npy(dir / "object.npy", make_npy<int32_t>({maps.height, maps.width}, maps.object));
  write_preview(dir / "preview.png", maps, taxonomy);
}

ViewHits read_view_hits(const fs::path& dir, int width, int height) {
  ViewHits hits{read_object_map(dir / "object.npy", height, width), read_pfm(dir / "depth.pfm")};
  if (hits.depth.width != width || hits.depth.height != height)
    fail((dir / "depth.pfm").string(), cat(hits.depth.width, "x", hits.depth.height, ", but the view is ", width, "x", height));
  return hits;
}

}  // namespace cls
