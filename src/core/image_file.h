#pragma once
// Writing images atomically: cv::imwrite through write_atomic (the temporary keeps the extension, so
// the format follows the name); OpenCV's exceptions and failures become cls::Error naming the file.
#include <filesystem>

#include <opencv2/core/mat.hpp>

namespace cls {

void write_image(const std::filesystem::path& path, const cv::Mat& image);

}  // namespace cls
